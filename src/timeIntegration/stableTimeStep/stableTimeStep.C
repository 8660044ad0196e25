/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "stableTimeStep.H"
#include "dualMesh.H"
#include "materialModel.H"
#include "solidBoundaryCondition.H"
#include "DynamicList.H"
#include "acousticFormulas.H"

#include <Eigen/Eigenvalues>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The stable step (cfl = 1) of a point of rate r (the bound r dt = 2; the
// constructor, the state's step and the per-point field all take it here)
inline Foam::scalar stepOfRate(const Foam::scalar r)
{
    return 2/Foam::max(r, Foam::VSMALL);
}

// Largest eigenvalue of a symmetric tensor.  (OpenFOAM v1912's eigenValues
// solves the general cubic: with the repeated roots of a symmetric stencil
// its round-off gives "complex eigenvalues" warnings.)
Foam::scalar maxEigenValue(const Foam::symmTensor& t)
{
    Eigen::Matrix3d m;
    m << t.xx(), t.xy(), t.xz(),
         t.xy(), t.yy(), t.yz(),
         t.xz(), t.yz(), t.zz();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig
    (
        m, Eigen::EigenvaluesOnly
    );
    return eig.eigenvalues().maxCoeff();
}

// The J rate's weight of a boundary sub-face whose Riemann velocity follows
// the traction (a free surface, a contact face).  There v* = v + (t -
// t*)/Z enters J' = H : D with the full impedance, so a boundary face
// drains Sigma_J like an interior face of the J stabilisation, and the
// two add up.  The per-point rate k S/(rho c_p V) is exact for the
// checkerboard of an interior lattice (4 s/h in 1D, s = k|C|/(2 Z)); at
// a boundary the fastest mode of the chain (half cell at the face) decays
// at (2 + 2 sqrt5) s/h, which the point's own rate reaches with the
// boundary face weighted (sqrt5 - 1)/2.  Without it the J rate at the
// corners of hexahedral bars was 1.6 times too slow: nearly
// incompressible hexahedral bars stopped with J < 0 at their corners
// from cfl 0.85 (second order) and 0.75 (first order) (doc/results.md,
// "The time step")
const Foam::scalar boundaryJWeight = 0.5*(Foam::sqrt(5.0) - 1);

// The margin of a held point's own damping rate with the central F flux
// (stableTimeStep.H): that of the upwind flux's 1D wall chain over the
// estimate r_i, 0.949/0.5
const Foam::scalar heldMargin = 1.9;

// A face's J drain, area times |H N|^2/max(1, |H N|) (from its area ratio
// squared): the flux divides by the face's impedance Z max(1, |H N|),
// interior faces and boundary sub-faces alike
inline Foam::scalar JDrain(const Foam::scalar area, const Foam::scalar hN2)
{
    return
        area*hN2/Foam::acousticFormulas::compressedFaceFactor(std::sqrt(hN2));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stableTimeStep::stableTimeStep
(
    const dualMesh& dual,
    const materialModel& material,
    const PtrList<solidBoundaryCondition>& bcs,
    const bool JLaw
)
:
    dual_(dual),
    material_(material),
    largeStrain_(!material.smallStrain()),
    sJ_(),
    stretch2_(),
    limitingPoint_(-1),
    rMomentum_(),
    dtRefMin_(GREAT),
    stateImpedanceJ_(false),
    heldPoint_(),
    heldRate_()
{
    const label nPts = dual.nPoints();

    // S_i (all faces), T_i (their normal parts that carry a mode) and the
    // faces that drain J (the interior ones and, weighted, the boundary
    // faces whose velocity follows the traction) for the J rate
    scalarField S(nPts, 0.0);
    scalarField Sint(nPts, 0.0);
    symmTensorField T(nPts, Zero);

    const labelList& start = dual.edgeStart();
    const labelList& end = dual.edgeEnd();
    const scalarField& magSf = dual.edgeMagSf();
    const vectorField& n = dual.edgeNormals();
    forAll(start, e)
    {
        const label i = start[e], j = end[e];
        const symmTensor nn(magSf[e]*sqr(n[e]));
        Sint[i] += magSf[e];
        Sint[j] += magSf[e];
        T[i] += nn;
        T[j] += nn;
    }

    S = Sint;

    boolList normalConstrained(dual.mesh().boundaryMesh().size(), false);
    boolList holdsVelocity(normalConstrained.size(), false);
    for (const solidBoundaryCondition& bc : bcs)
    {
        normalConstrained[bc.patchi()] = bc.constrainsNormal();
        holdsVelocity[bc.patchi()] = bc.holdsVelocity();
    }
    const scalar cp = material.cp();
    const scalar cs = material.cs();

    // A held point's own damping (times V): half its interior faces'
    // impedances (as T, S), the holding faces' normal part in full
    symmTensorField heldDamping(nPts, Zero);
    List<bool> held(nPts, false);
    forAll(holdsVelocity, patchi)
    {
        if (holdsVelocity[patchi])
        {
            const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
            forAll(sf.point, s)
            {
                const scalar magA = mag(sf.area[s]);
                if (magA > VSMALL)
                {
                    held[sf.point[s]] = true;
                    heldDamping[sf.point[s]] += cp*sqr(sf.area[s])/magA;
                }
            }
        }
    }
    DynamicList<label> bPoint;
    DynamicList<scalar> bMagA;
    DynamicList<vector> bNormal;
    DynamicList<bool> bDrainsJ;
    forAll(normalConstrained, patchi)
    {
        const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
        forAll(sf.point, s)
        {
            const label i = sf.point[s];
            const scalar magA = mag(sf.area[s]);
            if (magA < VSMALL)
            {
                continue;
            }
            const symmTensor nn(sqr(sf.area[s])/magA);
            S[i] += magA;
            bPoint.append(i);
            bMagA.append(magA);
            bNormal.append(sf.area[s]/magA);
            bDrainsJ.append(!normalConstrained[patchi]);
            if (!normalConstrained[patchi])
            {
                T[i] += nn;
                Sint[i] += boundaryJWeight*magA;
            }
        }
    }

    if (Pstream::parRun())
    {
        const polyMesh& mesh = dual.mesh();
        syncTools::syncPointList
        (
            mesh, heldDamping, plusEqOp<symmTensor>(), symmTensor(Zero)
        );
        syncTools::syncPointList(mesh, held, orEqOp<bool>(), false);
        syncTools::syncPointList(mesh, S, plusEqOp<scalar>(), 0.0);
        syncTools::syncPointList(mesh, Sint, plusEqOp<scalar>(), 0.0);
        syncTools::syncPointList
        (
            mesh, T, plusEqOp<symmTensor>(), symmTensor(Zero)
        );
    }

    const scalarField& V = dual.volumes();

    // Momentum: r = [c_s S + (c_p - c_s) lambda_max(T)]/V
    rMomentum_.setSize(nPts);
    forAll(rMomentum_, i)
    {
        rMomentum_[i] =
            (cs*S[i] + (cp - cs)*maxEigenValue(T[i]))/V[i];
    }

    // The held points' rate with the central F flux, heldMargin d_i, kept
    // where it exceeds r_i (the edges summed again for these points: S
    // and T hold the boundary faces too).  (Every processor takes part in
    // the synchronisation, held points or not)
    {
        symmTensorField interior(nPts, Zero);
        forAll(start, e)
        {
            const label i = start[e], j = end[e];
            if (held[i] || held[j])
            {
                const symmTensor d
                (
                    0.5*magSf[e]*(cs*I + (cp - cs)*sqr(n[e]))
                );
                interior[i] += d;
                interior[j] += d;
            }
        }
        if (Pstream::parRun())
        {
            syncTools::syncPointList
            (
                dual.mesh(), interior, plusEqOp<symmTensor>(),
                symmTensor(Zero)
            );
        }
        DynamicList<label> heldPoint;
        DynamicList<scalar> heldRate;
        forAll(held, i)
        {
            if (!held[i])
            {
                continue;
            }
            const scalar rate =
                heldMargin*maxEigenValue(interior[i] + heldDamping[i])/V[i];
            if (rate > rMomentum_[i])
            {
                heldPoint.append(i);
                heldRate.append(rate);
            }
        }
        heldPoint_.transfer(heldPoint);
        heldRate_.transfer(heldRate);
    }

    // J stabilisation: Omega dJ/dt gains sum_j S_ij (Sigma_J,j - Sigma_J,i)
    // with S_ij = |C|/(2 rho c_p) (undeformed) and dSigma_J/dJ = k = kappa
    // + tie (the volumetric stiffness and the det F - J tie): a
    // checkerboard of J decays at r = k S_int/(rho c_p V), S_int with the
    // draining boundary faces weighted by boundaryJWeight.  A small-strain
    // material takes its pressure from tr F, not from J: J is then carried
    // along without acting back, and sets no limit.  deltaT() evaluates the
    // rate from the state's coefficients (sJ_); here only the undeformed
    // step of a material whose step never changes is kept
    const bool JRate = JLaw && largeStrain_;
    if (JRate)
    {
        sJ_.setSize(nPts);
    }
    if (largeStrain_)
    {
        stretch2_.setSize(nPts);
        bPoint_.transfer(bPoint);
        bMagA_.transfer(bMagA);
        bNormal_.transfer(bNormal);
        bDrainsJ_.assign(bDrainsJ);
    }
    const scalar k = material.kappa() + material.tieModulus();
    forAll(rMomentum_, i)
    {
        const scalar rJ =
            JRate ? k*Sint[i]/(material.rho()*cp*V[i]) : 0;
        const scalar dti = stepOfRate(max(rMomentum_[i], rJ));
        if (dti < dtRefMin_)
        {
            dtRefMin_ = dti;
            limitingPoint_ = i;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::stableTimeStep::anticipatedWaveFactor
(
    const materialModel& material,
    const scalar vMax,
    scalar* Jstar
)
{
    if (Jstar)
    {
        *Jstar = 1;
    }
    if (!material.hugoniot())
    {
        return 1;
    }
    const scalar cp = material.cp();
    const scalar s = material.hugoniotS();
    const scalar J = 1 - vMax/(cp + s*vMax);
    if (Jstar)
    {
        *Jstar = J;
    }
    return max(1 + s*vMax/cp, material.tangentWaveSpeed(J)/cp);
}


void Foam::stableTimeStep::useCentralFFlux(const bool central)
{
    if (!central)
    {
        heldPoint_.clear();
        heldRate_.clear();
    }
    // The upwind F flux of a Hugoniot material divides the traction jump
    // by the edge's normal impedance, at least rho0 times the chord speed
    // of the pressure between the two points' volume ratios
    // (interiorRiemannSolvers::hugoniot::normalImpedance), and a boundary
    // face's Riemann velocity by rho0 times the point's tangent speed: the
    // J drain of compressed material is that many times slower than with
    // the reference impedance
    stateImpedanceJ_ = !central && material_.hugoniot();
}


template<class WaveFactor>
void Foam::stableTimeStep::limitHeldPoints
(
    const UList<bool>& closed,
    const WaveFactor& waveFactor,
    scalar& dt,
    UList<scalar>* pointDeltaT
) const
{
    forAll(heldPoint_, k)
    {
        const label i = heldPoint_[k];
        if (!closed[i])
        {
            continue;
        }
        const scalar dti = stepOfRate(heldRate_[k]*waveFactor(i));
        if (pointDeltaT)
        {
            (*pointDeltaT)[i] = min((*pointDeltaT)[i], dti);
        }
        if (dti < dt)
        {
            dt = dti;
            limitingPoint_ = i;
        }
    }
}


Foam::scalar Foam::stableTimeStep::deltaT
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    const scalar vMax,
    UList<scalar>* pointDeltaT,
    const UList<bool>* closed
) const
{
    const bool hugoniot = material_.hugoniot();
    const bool heldClosed = closed && heldPoint_.size();
    if (!largeStrain_ && !hugoniot)
    {
        // Small strain without a Hugoniot pressure: constant stiffness (its
        // point found with it, in the constructor; such a material sets no
        // J rate)
        if (pointDeltaT)
        {
            forAll(rMomentum_, i)
            {
                (*pointDeltaT)[i] = stepOfRate(rMomentum_[i]);
            }
        }
        scalar dt = dtRefMin_;
        if (heldClosed)
        {
            limitHeldPoints
            (
                *closed, [](const label) { return 1.0; }, dt, pointDeltaT
            );
        }
        return dt;
    }

    const scalar cp = material_.cp();
    // The wave speed a Hugoniot material's points must be stepped for
    // ahead of an impact: a point struck at the body's impact speed vMax
    // (the fastest closing on its walls, its pairs or within it:
    // contactPair::anticipateImpacts) reaches,
    // within the first steps of contact, the shocked state of that jump,
    // 1 - J = vMax/(c_p + s vMax), whose tangent speed exceeds the shock
    // speed c_p + s vMax (sqrt(12) against 2 c_p at vMax = c_p, s = 1).
    // Stepped for the shock speed alone, the struck point ran beyond its
    // limit until the step had followed its state, and its stress rang at
    // onset (a bar on a wall at v0 = c_p: 3.7 % beyond the plateau against
    // 2.9 %; doc/results.md, "The J rate of compressed Hugoniot material")
    const scalar shockFactor = anticipatedWaveFactor(material_, vMax);

    const scalar kRef = material_.kappa() + material_.tieModulus();
    const scalar rhoCp2 = material_.rho()*sqr(cp);
    const scalarField& V = dual_.volumes();

    // The faces' state: the largest area ratio |H_i n|^2 over each point's
    // faces (the stretch of its fastest direction), and the J
    // stabilisation's own coefficients, S_ij = |C| |H_ave n|^2/(2 Z) with
    // H averaged over the edge's two points and the face's impedance Z =
    // Z_p max(1, |H_ave n|), as in the flux
    if (largeStrain_)
    {
        const labelList& start = dual_.edgeStart();
        const labelList& end = dual_.edgeEnd();
        const vectorField& n = dual_.edgeNormals();
        const scalarField& magSf = dual_.edgeMagSf();
        const bool JRate = !sJ_.empty();
        stretch2_ = 0;
        if (JRate)
        {
            sJ_ = 0;
        }
        forAll(start, e)
        {
            const label i = start[e], j = end[e];
            // The face's own area ratio (H averaged over the edge, as in
            // the flux's impedance) counts at both ends: next to a crushed
            // point a mildly deformed one is damped through it
            const vector hNi(H[i] & n[e]), hNj(H[j] & n[e]);
            const scalar hN2 = magSqr(0.5*(hNi + hNj));
            stretch2_[i] = max(stretch2_[i], max(magSqr(hNi), hN2));
            stretch2_[j] = max(stretch2_[j], max(magSqr(hNj), hN2));
            if (JRate)
            {
                // (the Hugoniot flux's impedance max(Zstate, Zp + ...)
                // carries no factor max(1, |H N|))
                const scalar w =
                    stateImpedanceJ_
                  ? magSf[e]*hN2
                   /max(material_.chordWaveSpeed(J[i], J[j])/cp, 1.0)
                  : JDrain(magSf[e], hN2);
                sJ_[i] += w;
                sJ_[j] += w;
            }
        }
        forAll(bPoint_, b)
        {
            const label i = bPoint_[b];
            const scalar hN2 = magSqr(H[i] & bNormal_[b]);
            stretch2_[i] = max(stretch2_[i], hN2);
            if (JRate && bDrainsJ_.test(b))
            {
                // (the boundary's Riemann velocity divides by the face's
                // impedance too: solidBoundaryCondition::solveState)
                sJ_[i] +=
                    JDrain(boundaryJWeight*bMagA_[b], hN2)
                   /(
                        stateImpedanceJ_
                      ? max(material_.tangentWaveSpeed(J[i])/cp, 1.0)
                      : 1.0
                    );
            }
        }
        if (Pstream::parRun())
        {
            syncTools::syncPointList
            (
                dual_.mesh(), stretch2_, maxEqOp<scalar>(), 0.0
            );
            if (JRate)
            {
                syncTools::syncPointList
                (
                    dual_.mesh(), sJ_, plusEqOp<scalar>(), 0.0
                );
            }
        }
    }
    const scalar JFactor = 1/(material_.rho()*cp);

    // Each point's wave speed relative to c_p and the state's stretch:
    // the factor of its undeformed momentum rate
    // (cState: the state's own speed, c: at least the anticipated one)
    auto waveFactor = [&](const label i, scalar& c, scalar& cState)
    {
        // Wave speed of the state relative to c_p
        cState = J[i] < 1 ? material_.tangentWaveSpeed(J[i])/cp : 1.0;
        c = max(shockFactor, cState);

        // The stretch of the point's fastest direction: the largest
        // |F^-T n|^2 = |H n|^2/det(F)^2 over its faces.  A volume grown
        // beyond its reference one (det F > 1) does not slow the
        // volumetric wave down: its Lagrangian stiffness along N is
        // dSigma_J/dJ |H N|^2 whatever det F is (with the J law det F is
        // held to J only by the weak tie), so det F counts only below one
        scalar stretch2 = 1;
        if (largeStrain_)
        {
            const scalar detF2 = sqr((H[i] && F[i])/3);
            stretch2 =
                max(stretch2_[i]/max(min(detF2, 1.0), VSMALL), 1.0);
        }
        return c*sqrt(stretch2);
    };

    scalar dt = GREAT;
    forAll(rMomentum_, i)
    {
        // Momentum: the wave speed times the stretch; J stabilisation:
        // k sum_j 2 S_ij/V with the state's tangent k
        scalar c, cState;
        scalar r = rMomentum_[i]*waveFactor(i, c, cState);
        if (!sJ_.empty())
        {
            // With the state's impedances in sJ_ (stateImpedanceJ_): the
            // state's stiffness over them, and ahead of a shock (the
            // state's speed below the anticipated one) that rate times
            // the ratio of the two speeds: the stiffness and the impedance
            // of the shocked state grow together, and the J rate with the
            // wave speed, as the momentum's.  (The anticipated speed
            // squared over the reference impedance held the step of a
            // Hugoniot bar 2.2 (Mach 1) to 6.7 (Mach 5) times below the
            // momentum's: doc/results.md, "The J rate of compressed
            // Hugoniot material.")  Otherwise the anticipated speed's
            // stiffness over the reference impedance
            const scalar cJ = stateImpedanceJ_ ? cState : c;
            const scalar ahead = stateImpedanceJ_ ? max(c/cState, 1.0) : 1.0;
            const scalar k = (sqr(cJ)*rhoCp2 - 4.0/3.0*material_.mu()
              + material_.tieModulus())/kRef;
            r = max(r, max(k, 1.0)*ahead*kRef*JFactor*sJ_[i]/V[i]);
        }
        const scalar dti = stepOfRate(r);
        if (pointDeltaT)
        {
            (*pointDeltaT)[i] = dti;
        }
        if (dti < dt)
        {
            dt = dti;
            limitingPoint_ = i;
        }
    }
    if (heldClosed)
    {
        limitHeldPoints
        (
            *closed,
            [&](const label i)
            {
                scalar c, cState;
                return waveFactor(i, c, cState);
            },
            dt, pointDeltaT
        );
    }
    return dt;
}


// ************************************************************************* //
