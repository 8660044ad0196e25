/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "rigidWall.H"
#include "checkedInput.H"
#include "acousticFormulas.H"
#include "hugoniot.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(rigidWall, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, rigidWall, dictionary);
}
}


Foam::solidBoundaryConditions::rigidWall::rigidWall
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    solidBoundaryCondition(dual, patchi, dict),
    point_(getFinite<point>(dict, "point")),
    normal_(getFinite<vector>(dict, "normal")),
    velocity_(getFiniteOrDefault<vector>(dict, "velocity", Zero)),
    friction_(frictionLaw::New(dict, "patch '" + patchName() + "'")),
    hugoniot_(true),
    touch_(0),
    maxDepth_(0)
{
    {
        const scalarField l(dual.lengths());
        scalar lMin = GREAT;
        for (const label i : dual.subFaces(patchi).point)
        {
            lMin = min(lMin, l[i]);
        }
        touch_ = 1e-6*returnReduce(lMin, minOp<scalar>());
    }
    const word solver(dict.getOrDefault<word>("riemannSolver", "hugoniot"));
    if (solver == "acoustic")
    {
        hugoniot_ = false;
    }
    else if (solver != "hugoniot")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown riemannSolver '" << solver << "' for patch '"
            << patchName() << "'" << nl
            << "Valid solvers: (acoustic hugoniot)" << exit(FatalIOError);
    }
    if (mag(normal_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'normal' of patch '" << patchName()
            << "' must be a non-zero vector" << exit(FatalIOError);
    }
    normal_ /= mag(normal_);
}


void Foam::solidBoundaryConditions::rigidWall::contactState
(
    const vector& n,
    const vector& N,
    const point& x,
    const vector& v,
    const vector& tL,
    const waveData& w,
    const scalar t,
    vector& tC,
    vector& vC
) const
{
    const point wallPoint(point_ + t*velocity_);
    const scalar gap = (x - wallPoint) & normal_;

    // Contact normal: out of the body, into the wall
    const vector nc(-normal_);
    const scalar vWallN = velocity_ & nc;

    // Normal velocity jump from the body to the wall (negative when the
    // body moves into it).  In compression the Hugoniot relation of the
    // body's side, t^C = t + Zp dv - rho0 s Lambda dv^2 (doc/method.md,
    // section 3), adds the shock term; an expansive jump is acoustic
    const scalar dvn = vWallN - (v & nc);
    const scalar shockTerm = contactRiemannSolvers::hugoniot::rigidShockTerm
    (
        dvn, hugoniot_ ? w.shockMass : scalar(0)
    );
    const scalar tnTrial = (tL & nc) + w.Zp*dvn - shockTerm;

    if (gap > touch_ || tnTrial >= 0)
    {
        // Open gap or tension: traction-free
        tC = Zero;
        vC = acousticFormulas::tractionVelocity(tL, v, tC, n, w.Zp, w.Zs);
        return;
    }

    // The stick state (the wall's velocity); the friction law decides
    // whether it holds or the point slips with the traction it allows
    const vector tStick
    (
        acousticFormulas::velocityTraction(tL, v, velocity_, nc, w.Zp, w.Zs)
      - shockTerm*nc
    );
    bool stick = false;
    const vector ttC
    (
        friction_->tangentialTraction
        (
            acousticFormulas::tangential(tStick, nc), tnTrial, stick
        )
    );
    if (stick)
    {
        tC = tStick;
        vC = velocity_;
    }
    else
    {
        acousticFormulas::mixedState(tL, v, vWallN, ttC, nc, w.Zp, w.Zs, tC, vC);
        tC -= shockTerm*nc;
    }
}


void Foam::solidBoundaryConditions::rigidWall::prescribeDisplacements
(
    const UList<vector>& u,
    const scalar t,
    stageResidual& R,
    const labelUList* points
) const
{
    const pointField& X = dual_.mesh().points();
    const point wallPoint(point_ + t*velocity_);
    followStates
    (
        R, points,
        [&](const label i)
        {
            const scalar gap = (X[i] + u[i] - wallPoint) & normal_;
            maxDepth_ = max(maxDepth_, -gap);
            return gap <= touch_;
        },
        [&](const label k)
        {
            return (stateT_[k] & normal_) > 0;
        }
    );
}


void Foam::solidBoundaryConditions::rigidWall::writeSummary
(
    Ostream& os,
    const word& body
) const
{
    const scalar depth = returnReduce(maxDepth_, maxOp<scalar>());
    os  << "Body " << body << ", wall " << patchName()
        << ": largest depth behind the wall "
        << depth << " (" << depth*1e-6/touch_
        << " of the patch's shortest edge)" << nl;
}


void Foam::solidBoundaryConditions::rigidWall::describe(Ostream& os) const
{
    os  << "rigid wall at " << point_ << ", normal " << normal_
        << ", velocity " << velocity_ << ", riemannSolver "
        << (hugoniot_ ? "hugoniot (the material's slope; acoustic without one)" : "acoustic")
        << ", friction ";
    friction_->describe(os);
}


// ************************************************************************* //
