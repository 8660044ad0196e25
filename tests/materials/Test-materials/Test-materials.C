/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    Test-materials

Description
    Checks every hyperelastic material against invariants and exact values:
      - P is the derivative of W(F, cof F, det F) (central differences through
        the chain with H and J) for random deformations;
      - objectivity: P(Q F) = Q P(F) for a rotation Q;
      - small strain: P(I + eps G) / eps -> the linear elastic stress;
      - wave speeds from (E, nu) as in doc/method.md;
      - Hugoniot pressure p_H(J) = rho c^2 (J-1)/[1 - s(1-J)]^2 in compression.
    The tensor cross product is checked against H = cof F, J = H:F/3.
    Exits non-zero if a check fails.

\*---------------------------------------------------------------------------*/

#include "materialModel.H"
#include "tensorCross.H"
#include "Random.H"
#include "IStringStream.H"
#include "quaternion.H"

using namespace Foam;

label nFailed = 0;

void check(const bool ok, const string& what, const scalar value, const scalar tol)
{
    Info<< "    " << (ok ? "PASS " : "FAIL ") << what.c_str() << ": " << value
        << " (tolerance " << tol << ")" << endl;
    if (!ok) ++nFailed;
}


// Energy and stresses with an independent (conserved) J, H = cof F
scalar energyFJ(const materialModel& m, const tensor& F, const scalar J)
{
    List<tensor> Fl(1, F), Hl(1, cofactor(F));
    List<scalar> Jl(1, J), W(1);
    m.energy(Fl, Hl, Jl, W);
    return W[0];
}


void stressFJ
(
    const materialModel& m, const tensor& F, const scalar J,
    tensor& P, scalar& SigmaJ
)
{
    List<tensor> Fl(1, F), Hl(1, cofactor(F));
    List<scalar> Jl(1, J);
    List<fluxState> q(1);
    m.stress(Fl, Hl, Jl, q);
    P = fluxStress(q[0]);
    SigmaJ = fluxSigmaJ(q[0]);
}


scalar totalEnergy(const materialModel& m, const tensor& F)
{
    List<tensor> Fl(1, F), Hl(1, cofactor(F));
    List<scalar> Jl(1, det(F)), W(1);
    m.energy(Fl, Hl, Jl, W);
    return W[0];
}


tensor stressOf(const materialModel& m, const tensor& F)
{
    List<tensor> Fl(1, F), Hl(1, cofactor(F));
    List<scalar> Jl(1, det(F));
    List<fluxState> q(1);
    m.stress(Fl, Hl, Jl, q);
    return fluxStress(q[0]);
}


int main(int argc, char *argv[])
{
    Random rnd(12345);

    // Tensor algebra
    {
        scalar err = 0;
        for (label k = 0; k < 20; ++k)
        {
            tensor F(I);
            for (direction c = 0; c < 9; ++c) F[c] += 0.3*(rnd.sample01<scalar>() - 0.5);
            const tensor H(cofactor(F));
            err = max(err, mag(H - det(F)*inv(F).T())/mag(H));
            err = max(err, mag((H && F)/3 - det(F))/mag(det(F)));
            const tensor A(F), B(F + I);
            err = max(err, mag(tensorCross(A, B) - tensorCross(B, A)));
        }
        Info<< "tensor cross product" << endl;
        check(err < 1e-13, "H = cof F = J F^-T, J = H:F/3, AxB = BxA", err, 1e-13);
    }

    const char* dicts[] =
    {
        "type linearElastic; rho 1000; E 1e6; nu 0.3;",
        "type neoHookean; rho 1000; E 1e6; nu 0.3;",
        "type neoHookean; rho 8930; E 5.85e8; nu 0.495;",
        "type mooneyRivlin; rho 1000; E 1e6; nu 0.3; xi 5e4;",
        "type neoHookean; rho 0.01; kappa 100; mu 0; hugoniot { s 1; }",
        "type neoHookean; rho 1000; E 1e6; nu 0.3; hugoniot { s 1.5; }"
    };

    for (const char* text : dicts)
    {
        const dictionary dict((IStringStream(text))());
        autoPtr<materialModel> model(materialModel::New(dict, 1));
        const materialModel& m = model();
        const word type(dict.get<word>("type"));
        const bool finiteStrain = (type != "linearElastic");
        Info<< nl << text << endl;

        // Wave speeds
        {
            const scalar lambda = m.kappa() - 2*m.mu()/3;
            const scalar cpExact = Foam::sqrt((lambda + 2*m.mu())/m.rho());
            check(mag(m.cp() - cpExact)/cpExact < 1e-14, "c_p", m.cp(), 1e-14);
            if (dict.found("E"))
            {
                const scalar E = dict.get<scalar>("E");
                const scalar nu = dict.get<scalar>("nu");
                const scalar mu = E/(2*(1 + nu));
                const scalar lam = E*nu/((1 + nu)*(1 - 2*nu));
                check
                (
                    mag(m.cp() - Foam::sqrt((lam + 2*mu)/m.rho()))/m.cp() < 1e-12
                 && mag(m.cs() - Foam::sqrt(mu/m.rho()))/max(m.cs(), SMALL) < 1e-12,
                    "c_p, c_s from (E, nu)", m.cs(), 1e-12
                );
            }
        }

        // P = dW/dF through the chain with H = cof F, J = det F
        {
            const scalar amp = finiteStrain ? 0.4 : 0.02;
            scalar err = 0;
            for (label k = 0; k < 20; ++k)
            {
                tensor F(I);
                for (direction c = 0; c < 9; ++c) F[c] += amp*(rnd.sample01<scalar>() - 0.5);
                if (m.hugoniot() && k % 2 == 0)
                {
                    F = 0.85*F;     // compression: the Hugoniot branch
                }
                const tensor P(stressOf(m, F));
                tensor dW(Zero);
                const scalar h = 1e-6;
                for (direction c = 0; c < 9; ++c)
                {
                    tensor Fp(F), Fm(F);
                    Fp[c] += h; Fm[c] -= h;
                    dW[c] = (totalEnergy(m, Fp) - totalEnergy(m, Fm))/(2*h);
                }
                const scalar scale = max(mag(P), m.kappa()*1e-3);
                err = max(err, mag(P - dW)/scale);
            }
            // (the Hugoniot branch too: its energy is the potential of
            // p_H, not the jump-condition energy, so that the numerical
            // dissipation is measured against the equations' energy)
            check(err < 1e-6, "P = dW/dF (central differences)", err, 1e-6);
        }

        // Independent J (J law): P = dW/dF|J + Sigma_J cof F with Sigma_J
        // = dW/dJ, the J-conjugate stress the J stabilisation uses.  With
        // both, the semi-discrete energy balance is exact and the scheme
        // only dissipates (doc/method.md, section 7; the tie energy in
        // materialModel.H is built for this)
        if (finiteStrain)
        {
            scalar err = 0;
            for (label k = 0; k < 20; ++k)
            {
                tensor F(I);
                for (direction c = 0; c < 9; ++c) F[c] += 0.4*(rnd.sample01<scalar>() - 0.5);
                scalar J = det(F)*(0.8 + 0.4*rnd.sample01<scalar>());
                if (m.hugoniot() && k % 2 == 0)
                {
                    J = min(J, 0.85);   // compression: the Hugoniot branch
                }
                tensor P;
                scalar SJ;
                stressFJ(m, F, J, P, SJ);
                const scalar h = 1e-6;
                tensor dW(Zero);
                for (direction c = 0; c < 9; ++c)
                {
                    tensor Fp(F), Fm(F);
                    Fp[c] += h; Fm[c] -= h;
                    dW[c] = (energyFJ(m, Fp, J) - energyFJ(m, Fm, J))/(2*h);
                }
                const scalar dWdJ =
                    (energyFJ(m, F, J + h) - energyFJ(m, F, J - h))/(2*h);
                const scalar scale = max(mag(P), m.kappa()*1e-3);
                err = max(err, mag(P - dW - SJ*cofactor(F))/scale);
                err = max(err, mag(SJ - dWdJ)/scale);
            }
            check
            (
                err < 1e-6,
                "J != det F: P = dW/dF|J + Sigma_J cof F, Sigma_J = dW/dJ",
                err, 1e-6
            );
        }

        // Objectivity
        if (finiteStrain)
        {
            scalar err = 0;
            for (label k = 0; k < 10; ++k)
            {
                tensor F(I);
                for (direction c = 0; c < 9; ++c) F[c] += 0.4*(rnd.sample01<scalar>() - 0.5);
                const vector axis(rnd.sample01<vector>() - vector::uniform(0.5));
                const tensor Q
                (
                    quaternion(axis/mag(axis), 2.1*rnd.sample01<scalar>()).R()
                );
                err = max
                (
                    err,
                    mag(stressOf(m, Q & F) - (Q & stressOf(m, F)))
                   /mag(stressOf(m, F))
                );
            }
            check(err < 1e-12, "objectivity P(QF) = Q P(F)", err, 1e-12);
        }

        // Small strain: linear elasticity
        if (m.mu() > 0)
        {
            const scalar eps = 1e-7;
            tensor G(Zero);
            for (direction c = 0; c < 9; ++c) G[c] = rnd.sample01<scalar>() - 0.5;
            const tensor P(stressOf(m, I + eps*G)/eps);
            const tensor Plin
            (
                m.mu()*(G + G.T()) + m.lambda()*tr(G)*I
            );
            const scalar err = mag(P - Plin)/mag(Plin);
            check(err < 1e-5, "small strain -> linear elasticity", err, 1e-5);
        }

        // Hugoniot pressure (uniaxial strain: P_xx = p_H(J) when mu = 0)
        if (m.hugoniot() && m.mu() == 0)
        {
            const scalar s = m.hugoniotS();
            const scalar J = 0.6;
            const tensor F(J, 0, 0, 0, 1, 0, 0, 0, 1);
            const scalar pH = m.rho()*sqr(m.cp())*(J - 1)/sqr(1 - s*(1 - J));
            const scalar err = mag(stressOf(m, F).xx() - pH)/mag(pH);
            check(err < 1e-13, "Hugoniot P_xx = p_H(J) in compression", err, 1e-13);

            // Wave speeds in compressed material: the chord from the
            // undeformed state to J is the shock's, U = c + s v with
            // v = U (1 - J), i.e. U = c/(1 - s (1 - J)); the tangent one
            // is c sqrt((1 + s x)/(1 - s x)^3), x = 1 - J; and the chord
            // between two equal states is the tangent
            const scalar c = m.cp(), x = 1 - J;
            const scalar U = c/(1 - s*x);
            scalar e = mag(m.chordWaveSpeed(1, J) - U)/U;
            check(e < 1e-13, "chord wave speed from J = 1: the shock speed", e, 1e-13);
            e = mag(m.chordWaveSpeed(J, 1) - U)/U;
            check(e < 1e-13, "chord wave speed, symmetric", e, 1e-13);
            const scalar cT = c*std::sqrt((1 + s*x)/pow3(1 - s*x));
            e = mag(m.tangentWaveSpeed(J) - cT)/cT;
            check(e < 1e-13, "tangent wave speed at J", e, 1e-13);
            e = mag(m.chordWaveSpeed(J, J) - cT)/cT;
            check(e < 1e-13, "chord wave speed of equal states: the tangent", e, 1e-13);
            e = mag(m.chordWaveSpeed(1.2, 1.1) - c)/c;
            check(e < 1e-13, "chord wave speed in tension: c", e, 1e-13);
            // A contact point's speed from its volumetric stress Sigma_J =
            // p_H(J) (the Hugoniot pressure inverted): the tangent one at J
            e = mag(m.tangentWaveSpeedAtSigmaJ(pH) - cT)/cT;
            check(e < 1e-12, "tangent wave speed from Sigma_J", e, 1e-12);
            e = mag(m.tangentWaveSpeedAtSigmaJ(0.5) - c)/c;
            check(e < 1e-13, "wave speed from a tensile Sigma_J: c", e, 1e-13);
        }
    }

    // von Mises plasticity (Hencky, linear isotropic hardening)
    {
        const char* text =
            "type vonMisesPlasticity; rho 8930; E 117e9; nu 0.35;"
            " yieldStress 0.4e9; hardening 0.1e9;";
        Info<< nl << text << endl;
        const dictionary dict((IStringStream(text))());
        autoPtr<materialModel> model(materialModel::New(dict, 1));
        materialModel& m = model.ref();
        const scalar E = m.E(), ty = 0.4e9, Hh = 0.1e9;

        // Elastic range: P = dW/dF
        {
            scalar err = 0;
            for (label k = 0; k < 10; ++k)
            {
                tensor F(I);
                for (direction c = 0; c < 9; ++c) F[c] += 2e-3*(rnd.sample01<scalar>() - 0.5);
                const tensor P(stressOf(m, F));
                tensor dW(Zero);
                const scalar h = 1e-8;
                for (direction c = 0; c < 9; ++c)
                {
                    tensor Fp(F), Fm(F);
                    Fp[c] += h; Fm[c] -= h;
                    dW[c] = (totalEnergy(m, Fp) - totalEnergy(m, Fm))/(2*h);
                }
                err = max(err, mag(P - dW)/mag(P));
            }
            check(err < 1e-5, "elastic range: P = dW/dF", err, 1e-5);
        }

        // Elastic range with an independent J (J law): P = dW/dF|J
        // + Sigma_J cof F and Sigma_J = dW/dJ, as for the hyperelastic
        // models; without it the det F - J tie exchanges energy with
        // nothing (the plastic car's dissipation fell by 0.004 % of E0)
        {
            scalar err = 0;
            for (label k = 0; k < 10; ++k)
            {
                tensor F(I);
                for (direction c = 0; c < 9; ++c) F[c] += 2e-3*(rnd.sample01<scalar>() - 0.5);
                const scalar J = det(F)*(1 + 2e-3*(rnd.sample01<scalar>() - 0.5));
                tensor P;
                scalar SJ;
                stressFJ(m, F, J, P, SJ);
                const scalar h = 1e-8;
                tensor dW(Zero);
                for (direction c = 0; c < 9; ++c)
                {
                    tensor Fp(F), Fm(F);
                    Fp[c] += h; Fm[c] -= h;
                    dW[c] = (energyFJ(m, Fp, J) - energyFJ(m, Fm, J))/(2*h);
                }
                const scalar dWdJ =
                    (energyFJ(m, F, J + h) - energyFJ(m, F, J - h))/(2*h);
                err = max(err, mag(P - dW - SJ*cofactor(F))/mag(P));
                err = max(err, mag(SJ - dWdJ)/mag(P));
            }
            check
            (
                err < 1e-5,
                "elastic range, J != det F: P = dW/dF|J + Sigma_J cof F,"
                " Sigma_J = dW/dJ",
                err, 1e-5
            );
        }

        // Uniaxial stress at log strain eps (monotonic, from the virgin
        // state): find the lateral stretch with zero lateral stress;
        // exact tau_xx = E (tau_y0 + Hh eps)/(E + Hh)
        const scalar eps = 0.05;
        const scalar lx = Foam::exp(eps);
        scalar lo = 0.9, hi = 1.0;
        tensor F(I), P(Zero);
        for (label it = 0; it < 200; ++it)
        {
            const scalar lt = 0.5*(lo + hi);
            F = tensor(lx, 0, 0, 0, lt, 0, 0, 0, lt);
            P = stressOf(m, F);
            if (P.yy() > 0) hi = lt; else lo = lt;
        }
        const scalar tauxx = P.xx()*F.xx();
        const scalar exact = E*(ty + Hh*eps)/(E + Hh);
        check
        (
            mag(tauxx - exact)/exact < 1e-6,
            "uniaxial Kirchhoff stress = E (tau_y0 + H eps)/(E + H)",
            mag(tauxx - exact)/exact, 1e-6
        );

        // Yield condition after return: f = 0 on the returned state
        List<tensor> Fl(1, F);
        List<scalar> Jl(1, det(F)), dD(1, 0.0);
        m.updateState(Fl, Jl, dD);
        const tensor P2(stressOf(m, F));
        const tensor tau(P2 & F.T());
        const scalar seq = Foam::sqrt(1.5)*mag(dev(tau));
        const scalar f = seq - (ty + Hh*m.epsP()[0]);
        check(mag(f)/ty < 1e-10, "yield condition after return |f|/tau_y0",
            mag(f)/ty, 1e-10);
        check(mag(P2 - P)/mag(P) < 1e-10,
            "stress unchanged by storing the returned state",
            mag(P2 - P)/mag(P), 1e-10);
        const scalar epsPexact = eps - exact/E;
        check(mag(m.epsP()[0] - epsPexact)/epsPexact < 1e-6,
            "plastic strain = eps - tau/E", m.epsP()[0], 1e-6);
        check(dD[0] > 0, "plastic dissipation increment > 0", dD[0], 0);
    }

    // von Mises plasticity's logarithm of be: summed as a series within
    // a radius of the identity, by the eigen-solve beyond it.  An
    // isochoric stretch diag(l, l^-1/2, l^-1/2) in the elastic range (a
    // yield stress beyond reach) has tau' = 2 mu ln(l) diag(1, -1/2, -1/2)
    // exactly, so P_xx = 2 mu ln(l)/l and P_yy = -mu ln(l) l^1/2, on both
    // sides of the series' radii (|X| = 0.03 and 0.12 near ln l = 0.015
    // and 0.06) and beyond them
    {
        const char* text =
            "type vonMisesPlasticity; rho 8930; E 117e9; nu 0.35;"
            " yieldStress 1e15; hardening 0;";
        Info<< nl << text << endl;
        const dictionary dict((IStringStream(text))());
        autoPtr<materialModel> model(materialModel::New(dict, 1));
        const materialModel& m = model();
        const scalar mu = m.mu();
        scalar err = 0;
        for (const scalar lnl : {1e-4, 3e-3, 0.0149, 0.0151, 0.03, 0.0599, 0.0601, 0.1, 0.3})
        {
            const scalar l = Foam::exp(lnl), lt = 1/Foam::sqrt(l);
            const tensor P(stressOf(m, tensor(l, 0, 0, 0, lt, 0, 0, 0, lt)));
            const scalar Pxx = 2*mu*lnl/l, Pyy = -mu*lnl/lt;
            err = max(err, mag(P.xx() - Pxx)/mag(Pxx));
            err = max(err, mag(P.yy() - Pyy)/mag(Pxx));
            err = max(err, mag(P.xy())/mag(Pxx));
        }
        check
        (
            err < 1e-12,
            "isochoric stretch: tau' = 2 mu dev(ln V) (series and eigen-solve)",
            err, 1e-12
        );
    }

    // Bad input is rejected with FatalIOError: checked by the test script

    Info<< nl << (nFailed ? "FAILED " : "All checks passed ")
        << "(" << nFailed << " failed)" << endl;
    // (OpenFOAM v1912 ends a run with status 0 when the argList is
    // destroyed after main returns, whatever main returned: leave here)
    Pstream::exit(nFailed ? 1 : 0);
    return 0;
}


// ************************************************************************* //
