/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    Test-riemannSolvers

Description
    Riemann and boundary formulas against hand-computed cases
    (doc/method.md, section 3):
      - acoustic contact stick between different impedances (normal and
        tangential), its symmetric (homogeneous) limit, and the interior
        faces' impedances scaled by their compression max(1, |H N|);
      - the pressure-dominated contact stick: only the Sigma_J jump moves
        the velocity, the traction is acoustic; with volumetric tractions
        (t_n = Sigma_J Lambda) it is the acoustic state;
      - the Hugoniot check: two identical bars, c = 100, rho0 = 0.01,
        v0 = 100, s = 1: v^C = 50, t_n^C = -75; s -> 0 gives the acoustic
        answer; an expansive jump uses the acoustic solver;
      - the Hugoniot rigid wall: a bar at 50 into a fixed wall gives the
        check's -75 (the wall is the mirror plane of the two-bar check);
        for any compressive state it equals the two-body solver against the
        state's mirror image (v^C = 0 there); an expansive jump is
        acoustic;
      - the Hugoniot impedance match that shares a pair's closing speed
        between its bodies (contactPair::hugoniotShare): 50 each for A3,
        A4's exact plateau velocity 100 (sqrt(2) - 1), equal pressures;
      - one-sided formulas: prescribed traction (free surface), prescribed
        velocity (rigid), symmetry (mixed), frictionless slip, Coulomb
        stick and slip on a rigid wall.
    Exits non-zero if a check fails.

\*---------------------------------------------------------------------------*/

#include "Pstream.H"
#include "acousticFormulas.H"
#include "acoustic.H"
#include "hugoniot.H"
#include "pressureDominated.H"
#include "interiorHugoniot.H"
#include "materialModel.H"
#include "contactPair.H"
#include "IStringStream.H"

using namespace Foam;

label nFailed = 0;

void check(const string& what, const scalar value, const scalar exact)
{
    const scalar err = mag(value - exact)/max(mag(exact), scalar(1));
    const bool ok = err < 1e-12;
    Info<< "    " << (ok ? "PASS " : "FAIL ") << what.c_str() << ": " << value
        << " (exact " << exact << ")" << endl;
    if (!ok) ++nFailed;
}


int main(int argc, char *argv[])
{
    typedef contactRiemannSolver::side side;

    Info<< "Acoustic contact stick, Z_L = 2, Z_R = 3" << endl;
    {
        // L: rho 1, c 2, v 5, t -1;  R: rho 1, c 3, v 1, t -2
        side L{-1, 5, 1, 2, 1}, R{-2, 1, 1, 3, 1};
        scalar v, t;
        contactRiemannSolvers::acoustic::solve(L, R, v, t);
        // v = (2*5 + 3*1 + (-2) - (-1))/5 = 12/5; t = 6/5 (-1/2 - 2/3 + 1 - 5)
        check("v_n^C", v, 12.0/5.0);
        check("t_n^C", t, 6.0/5.0*(-0.5 - 2.0/3.0 - 4.0));
        // Characteristics: t^C - t_L = Z_L (v^C - v_L), t^C - t_R = -Z_R (v^C - v_R)
        check("L characteristic", t - L.tn, 2*(v - L.vn));
        check("R characteristic", t - R.tn, -3*(v - R.vn));
    }

    Info<< "Homogeneous limit (interior flux), Zp = 2, Zs = 1" << endl;
    {
        const vector n(1, 0, 0);
        const vector tL(-1, 0.5, 0), tR(-3, 1.5, 0);
        const vector vL(2, 1, 0), vR(0, 3, 0);
        const vector tC(acousticFormulas::stickTraction(tL, tR, vL, vR, n, 2, 1));
        // 1/2 (tL + tR) + Zp/2 dv_n n + Zs/2 dv_t
        check("t_x", tC.x(), -2 + 1*(-2));
        check("t_y", tC.y(), 1 + 0.5*2);

        // A face compressed to the area ratio Lambda = |H N| = 2.5 has the
        // Lagrangian impedances 2.5 Zp, 2.5 Zs; an expanded one (0.7) keeps
        // the reference ones
        check("compression factor, Lambda 2.5",
            acousticFormulas::compressedFaceFactor(2.5), 2.5);
        check("compression factor, Lambda 0.7",
            acousticFormulas::compressedFaceFactor(0.7), 1);
        const vector tCc
        (
            acousticFormulas::interiorStickTraction(tL, tR, vL, vR, n, 2.5, 2, 1)
        );
        check("compressed face t_x", tCc.x(), -2 + 2.5*(-2));
        check("compressed face t_y", tCc.y(), 1 + 2.5*0.5*2);

        // The interior flux's tangential impedance: the material's, or
        // for a shear-free one (Zs = 0) the normal wave's (Rusanov), whose
        // traction then damps a transverse jump [v_t] = 2 with Zp/2 [v_t]
        check("interior tangential impedance, Zs = 1",
            acousticFormulas::interiorShearImpedance(2, 1), 1);
        check("interior tangential impedance, shear-free",
            acousticFormulas::interiorShearImpedance(2, 0), 2);
        const vector tFree
        (
            acousticFormulas::interiorStickTraction
            (
                tL, tR, vL, vR, n, 1, 2,
                acousticFormulas::interiorShearImpedance(2, 0)
            )
        );
        check("shear-free interior t_y", tFree.y(), 1 + 1*2);

        // The interior Hugoniot solver of a shear-free body (A3's material:
        // Zp = rho c = 1, Zs = 0, s = 1): on a face compressed to Lambda =
        // 2.5 its tangential impedance is Lambda Zp as the acoustic
        // solver's; the normal one is the shock's, Zp + rho s Lambda
        // closing = 1 + 0.01*2.5*2 = 1.05 for the closing speed 2
        const dictionary dict
        (
            (IStringStream("type neoHookean; rho 0.01; kappa 100; mu 0; hugoniot { s 1; }"))()
        );
        autoPtr<materialModel> A3(materialModel::New(dict, 1));
        const interiorRiemannSolvers::hugoniot interiorShock(A3());
        const vector tH(interiorShock.traction(tL, tR, vL, vR, n, 2.5, 1));
        check("interior Hugoniot, compressed face t_x", tH.x(), -2 + 0.5*1.05*(-2));
        check("interior Hugoniot, compressed face t_y", tH.y(), 1 + 0.5*2.5*1*2);
        // Between compressed states (the chord of their pressure with the
        // impedance 2, above the shock's 1.05) the normal impedance is the
        // states'; the tangential one does not change
        const vector tHc(interiorShock.traction(tL, tR, vL, vR, n, 2.5, 2));
        check("interior Hugoniot, compressed states t_x", tHc.x(), -2 + 0.5*2*(-2));
        check("interior Hugoniot, compressed states t_y", tHc.y(), 1 + 0.5*2.5*1*2);

        // The upwind F flux's share of its traction-jump term, Z = 2: a
        // wave ([t] = -Z [v]) keeps all of it, and so does a jump slower
        // than a wave; a shock at twice the wave speed ([t] = 2 Z [v]) gets
        // half (its own impedance 2 Z); a slow mode with [t] = 40 Z [v]
        // gets 1/40; no velocity jump, nothing
        check("slow-mode factor, a wave",
            acousticFormulas::jumpUpwindFactor(-0.6, 0.3, 2, 1), 1);
        check("slow-mode factor, a jump slower than a wave",
            acousticFormulas::jumpUpwindFactor(0.1, 0.3, 2, 1), 1);
        check("slow-mode factor, a shock at 2 c",
            acousticFormulas::jumpUpwindFactor(1.2, -0.3, 2, 1), 0.5);
        check("slow-mode factor, a slow mode",
            acousticFormulas::jumpUpwindFactor(24, 0.3, 2, 1), 1.0/40.0);
        check("slow-mode factor, no velocity jump",
            acousticFormulas::jumpUpwindFactor(1, 0, 2, 1), 0);
    }

    Info<< "Oblique plane p-wave across an edge (nu = 0, rho 1, E 1)" << endl;
    {
        // A compressive p-wave along d, [v] = a d (a < 0: the edge's points
        // close), crosses an edge of normal n at cos(theta) = 0.6 from L to
        // R; its jumps [sigma] = -(a/c_p) 2 mu d d (lambda = 0), [t] =
        // [sigma] n.  The edge's Riemann solution must be the upstream
        // state L: with the jump's own impedances (0.6 Z_p in the normal
        // part, 0.6 sqrt(2) Z_s in the tangential one, both within
        // [Z/2, Z]) the stick traction is t^L and the F flux's upwind
        // velocity v^L; with the wave impedances neither is
        const scalar rho = 1, E = 1, mu = E/2;
        const scalar cp = std::sqrt(E/rho), cs = std::sqrt(mu/rho);
        const scalar Zp = rho*cp, Zs = rho*cs;
        const vector n(1, 0, 0);
        const vector d(0.6, 0.8, 0);
        const scalar a = -0.1;
        const vector vL(0.3, -0.2, 0.1), tL(-0.05, 0.02, 0.01);
        const vector dv(a*d);
        const vector dt(-(a/cp)*2*mu*(d & n)*d);
        const vector vR(vL + dv), tR(tL + dt);
        const scalar dtn = dt & n, dvn = dv & n;
        const scalar dtt = mag(dt - dtn*n), dvt = mag(dv - dvn*n);

        const scalar fn =
            acousticFormulas::jumpTractionFactor
            (
                dtn, dvn, Zp, acousticFormulas::compressiveJumpLowerBound
            );
        const scalar ft =
            acousticFormulas::jumpTractionFactor
            (
                dtt, dvt, Zs, acousticFormulas::compressiveJumpLowerBound
            );
        check("traction factor, normal part (cos theta)", fn, 0.6);
        check("traction factor, tangential part", ft, 0.6*std::sqrt(2.0));
        const vector tC = acousticFormulas::stickTraction
        (
            tL, tR, vL, vR, n, fn*Zp, ft*Zs
        );
        check("own impedances: t_x = t^L_x", tC.x(), tL.x());
        check("own impedances: t_y = t^L_y", tC.y(), tL.y());
        check("own impedances: t_z = t^L_z", tC.z(), tL.z());
        const vector tWave = acousticFormulas::stickTraction
        (
            tL, tR, vL, vR, n, Zp, Zs
        );
        const bool waveOff = mag(tWave - tL) > 0.01*mag(dt);
        Info<< "    " << (waveOff ? "PASS" : "FAIL")
            << " wave impedances: t^C off t^L by " << mag(tWave - tL)
            << " (more than 1 % of |[t]| " << mag(dt) << ")" << endl;
        if (!waveOff) ++nFailed;

        // The F flux's velocity 1/2 (v^L + v^R) + the traction-jump term
        // with each part divided by Z/factor: v^L
        const scalar gn =
            acousticFormulas::jumpUpwindFactor
            (
                dtn, dvn, Zp, acousticFormulas::compressiveJumpLowerBound
            );
        const scalar gt =
            acousticFormulas::jumpUpwindFactor
            (
                dtt, dvt, Zs, acousticFormulas::compressiveJumpLowerBound
            );
        const vector vC
        (
            0.5*(vL + vR) + (gn/(2*Zp))*dtn*n
          + (gt/(2*Zs))*(dt - dtn*n)
        );
        check("own impedances: F flux velocity x = v^L_x", vC.x(), vL.x());
        check("own impedances: F flux velocity y = v^L_y", vC.y(), vL.y());

        // The bounds: a jump of a quarter of the wave's impedance takes
        // half of it; one above the wave's takes the wave's in the
        // traction and its own in the F flux (the slow-mode rule)
        // (an opening edge, lower bound 1: the wave's impedance in the
        // traction, the slow-mode factor in the F flux)
        const scalar lower = acousticFormulas::compressiveJumpLowerBound;
        check("traction factor, own impedance Z/4",
            acousticFormulas::jumpTractionFactor(0.05, -0.1, 2, lower), 0.5);
        check("traction factor, own impedance 3 Z",
            acousticFormulas::jumpTractionFactor(0.6, -0.1, 2, lower), 1);
        check("traction factor, own impedance Z/4, lower bound 1",
            acousticFormulas::jumpTractionFactor(0.05, -0.1, 2, 1), 1);
        check("F flux factor, own impedance Z/4",
            acousticFormulas::jumpUpwindFactor(0.05, -0.1, 2, lower), 2);
        check("F flux factor, own impedance 3 Z",
            acousticFormulas::jumpUpwindFactor(0.6, -0.1, 2, lower), 1.0/3.0);
        check("F flux factor, own impedance Z/4, lower bound 1",
            acousticFormulas::jumpUpwindFactor(0.05, -0.1, 2, 1), 1);
    }

    Info<< "Pressure-dominated contact stick, Z_L = 2, Z_R = 3" << endl;
    {
        // The acoustic case above with area ratios 1.2 / 0.8 and volumetric
        // stresses Sigma_J -0.8 / -2.5: only their jump moves the velocity,
        // v = (2*5 + 3*1 + (-2.5 + 0.8)*(1.2 + 0.8)/2)/5 = 11.3/5; the
        // traction is the acoustic one
        side L{-1, 5, 1, 2, 1.2, 0, -0.8}, R{-2, 1, 1, 3, 0.8, 0, -2.5};
        scalar v, t;
        contactRiemannSolvers::pressureDominated::solve(L, R, v, t);
        check("v_n^C", v, 11.3/5.0);
        check("t_n^C", t, 6.0/5.0*(-0.5 - 2.0/3.0 - 4.0));

        // Volumetric tractions (t_n = Sigma_J Lambda, the same Lambda): the
        // acoustic state, velocity and traction
        const scalar Lambda = 1.1;
        side Lp{-2*Lambda, 3, 2, 1.5, Lambda, 0, -2};
        side Rp{-0.5*Lambda, -1, 1, 2, Lambda, 0, -0.5};
        scalar va, ta;
        contactRiemannSolvers::acoustic::solve(Lp, Rp, va, ta);
        contactRiemannSolvers::pressureDominated::solve(Lp, Rp, v, t);
        check("volumetric tractions: v_n^C acoustic", v, va);
        check("volumetric tractions: t_n^C acoustic", t, ta);

        const dictionary dict;
        check
        (
            "stick velocity without the tangential traction jump",
            contactRiemannSolvers::pressureDominated(dict)
           .tangentialTractionJump(),
            0
        );
        check
        (
            "acoustic stick velocity with it",
            contactRiemannSolvers::acoustic(dict).tangentialTractionJump(),
            1
        );
    }

    Info<< "Hugoniot check: identical bars, c 100, rho 0.01, v0 100, s 1" << endl;
    {
        const dictionary dict;
        contactRiemannSolvers::hugoniot solver(dict);
        side L{0, 100, 0.01, 100, 1, 1}, R{0, 0, 0.01, 100, 1, 1};
        scalar v, t;
        solver.normalState(L, R, v, t);
        check("v^C", v, 50);
        check("t_n^C", t, -75);

        side L0{0, 100, 0.01, 100, 1, 0}, R0{0, 0, 0.01, 100, 1, 0};
        solver.normalState(L0, R0, v, t);
        check("s = 0: v^C (acoustic)", v, 50);
        check("s = 0: t_n^C (acoustic)", t, -50);

        // Expansive jump: acoustic answer
        side Le{0, 0, 0.01, 100, 1, 1}, Re{0, 100, 0.01, 100, 1, 1};
        solver.normalState(Le, Re, v, t);
        check("expansive: t_n^C (acoustic)", t, 50);

        // Dissimilar (A4): rho_R = 0.02, c_R = 100/sqrt2; the root satisfies
        // the quadratic and the R-side Hugoniot
        side Rd{0, 0, 0.02, 100/Foam::sqrt(2.0), 1, 1};
        solver.normalState(L, Rd, v, t);
        // R side: t^C = t_R - rho_R c_R (v^C - v_R) - s rho_R (v^C - v_R)^2
        check
        (
            "dissimilar: R-side Hugoniot",
            t,
            -0.02*(100/Foam::sqrt(2.0))*v - 0.02*sqr(v)
        );

        // Different slopes (s_L = 1, s_R = 0.5, each from its material):
        // the state lies on both sides' Hugoniots
        side Rs{0, 0, 0.02, 100/Foam::sqrt(2.0), 1, 0.5};
        solver.normalState(L, Rs, v, t);
        check("slopes 1 / 0.5: L-side Hugoniot", t, 0.01*100*(v - 100) - 0.01*sqr(v - 100));
        check
        (
            "slopes 1 / 0.5: R-side Hugoniot",
            t,
            -0.02*(100/Foam::sqrt(2.0))*v - 0.5*0.02*sqr(v)
        );
    }

    Info<< "Hugoniot rigid wall (rho 0.01, c 100, s 1)" << endl;
    {
        typedef contactRiemannSolvers::hugoniot hugoniot;
        // Bar at 50 into a fixed wall: dv = 0 - 50, Zp = 1, m = rho s Lam
        const scalar dv = -50, Zp = 0.01*100, m = 0.01*1*1;
        check("bar at 50 on a wall: t_n^C", Zp*dv - hugoniot::rigidShockTerm(dv, m), -75);

        // A general compressive state against its mirror image: the
        // two-body solver gives v^C = 0 and the rigid-wall traction
        const dictionary dict;
        hugoniot solver(dict);
        const scalar tn = -3, vn = 20, Lam = 1.2, s = 0.7;
        side L{tn, vn, 0.01, 100, Lam, s}, R{tn, -vn, 0.01, 100, Lam, s};
        scalar v, t;
        solver.normalState(L, R, v, t);
        const scalar mL = 0.01*s*Lam;
        check("mirror image: v^C", v, 0);
        check
        (
            "mirror image: t_n^C = rigid-wall traction",
            t,
            tn + Zp*(0 - vn) - hugoniot::rigidShockTerm(0 - vn, mL)
        );
        check("expansive jump: no shock term", hugoniot::rigidShockTerm(5, mL), 0);

        // The inverse (a prescribed traction): a bar pressed by the shocked
        // stress of 2 c (-600 = -rho0 (c + s v) v at v = 200) takes the
        // shock's velocity jump, not the acoustic -600/Zp
        check("traction of 2 c's shock: dv", hugoniot::rigidShockJump(-600, Zp, m), -200);
        // round trip through the rigid form, at another state
        const scalar dvT = hugoniot::rigidShockJump(-3.7, 1.3, mL);
        check
        (
            "traction jump -3.7: rho0 c dv - m dv^2",
            1.3*dvT - hugoniot::rigidShockTerm(dvT, mL), -3.7
        );
        check("tensile traction jump: acoustic", hugoniot::rigidShockJump(2.6, 1.3, mL), 2.0);
        check("no shock mass: acoustic", hugoniot::rigidShockJump(-2.6, 1.3, 0), -2.0);
    }

    Info<< "Hugoniot impedance match of a pair's closing speed" << endl;
    {
        // contactPair::hugoniotShare: the jump each side takes, at equal
        // shock pressures rho0 (c_p + s u) u on both sides
        auto material = [](const char* text)
        {
            const dictionary dict((IStringStream(text))());
            return materialModel::New(dict, 1);
        };
        autoPtr<materialModel> one
        (
            material("type neoHookean; rho 0.01; kappa 100; mu 0; hugoniot { s 1; }")
        );
        autoPtr<materialModel> two
        (
            material("type neoHookean; rho 0.02; kappa 100; mu 0; hugoniot { s 1; }")
        );
        autoPtr<materialModel> elastic
        (
            material("type neoHookean; rho 0.02; kappa 100; mu 0;")
        );
        // A3: identical bars at 100 take 50 each
        check("A3: each side's jump", contactPair::hugoniotShare(one(), one(), 100), 50);
        // A4 (rho0 0.01, c_p 100 against 0.02, 70.71; 100 apart): the
        // exact plateau velocity is 100 (sqrt(2) - 1)
        const scalar uOne = contactPair::hugoniotShare(one(), two(), 100);
        const scalar uTwo = contactPair::hugoniotShare(two(), one(), 100);
        check("A4: Bar Two's jump", uTwo, 100*(Foam::sqrt(2.0) - 1));
        check("A4: Bar One's jump", uOne, 100*(2 - Foam::sqrt(2.0)));
        check
        (
            "A4: equal shock pressures",
            0.01*(100 + uOne)*uOne,
            0.02*(Foam::sqrt(100/0.02) + uTwo)*uTwo
        );
        // A partner without a Hugoniot pressure bounds as a rigid one
        check("elastic partner: the whole speed", contactPair::hugoniotShare(one(), elastic(), 100), 100);
        check("at rest", contactPair::hugoniotShare(one(), two(), 0), 0);
    }

    Info<< "One-sided formulas, Zp = 2, Zs = 1, n = x" << endl;
    {
        const vector n(1, 0, 0);
        const vector tL(-3, 1, 0), vL(1, 2, 0);

        // Traction-free: v^C = v - t_n/Zp n - t_t/Zs
        const vector vFree(acousticFormulas::tractionVelocity(tL, vL, Zero, n, 2, 1));
        check("free surface v_x", vFree.x(), 1 + 1.5);
        check("free surface v_y", vFree.y(), 2 - 1);

        // Rigid (prescribed velocity zero): t^C = t + Z (0 - v)
        const vector tRigid(acousticFormulas::velocityTraction(tL, vL, Zero, n, 2, 1));
        check("rigid t_x", tRigid.x(), -3 - 2*1);
        check("rigid t_y", tRigid.y(), 1 - 1*2);

        // Symmetry / frictionless wall: v_n = 0, t_t = 0
        vector tC, vC;
        acousticFormulas::mixedState(tL, vL, 0, Zero, n, 2, 1, tC, vC);
        check("symmetry t_n", tC.x(), -3 - 2*1);
        check("symmetry t_t", tC.y(), 0);
        check("symmetry v_n", vC.x(), 0);
        check("symmetry v_t (slip)", vC.y(), 2 - 1);

        // Coulomb on a wall, k = 0.5: trial stick t_t = 1 - 2 = -1,
        // |t_t| = 1 <= 0.5 |t_n| = 2.5: stick
        // k = 0.1: limit 0.5 < 1: slip with t_t = -0.5, v_t = v - (t - t^C)/Zs
        acousticFormulas::mixedState(tL, vL, 0, vector(0, -0.5, 0), n, 2, 1, tC, vC);
        check("Coulomb slip t_t", tC.y(), -0.5);
        check("Coulomb slip v_t", vC.y(), 2 - (1 - (-0.5))/1);
    }

    Info<< nl << (nFailed ? "FAILED " : "All checks passed ")
        << "(" << nFailed << " failed)" << endl;
    // (OpenFOAM v1912 ends a run with status 0 when the argList is
    // destroyed after main returns, whatever main returned: leave here)
    Pstream::exit(nFailed ? 1 : 0);
    return 0;
}


// ************************************************************************* //
