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
    approaching_(false),
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


Foam::scalar Foam::solidBoundaryConditions::rigidWall::closingAllowance
(
    const scalar d0,
    const scalar d,
    const stageStep& step
) const
{
    if (d0 <= touch_)
    {
        return 0;
    }
    return max(step.second ? d0 + d : d0, scalar(0))/step.h;
}


Foam::scalar Foam::solidBoundaryConditions::rigidWall::contactState
(
    const vector& n,
    const vector& N,
    const point& x,
    const point& x0,
    const vector& v,
    const vector& tL,
    const waveData& w,
    const scalar t,
    const stageStep& step,
    vector& tC,
    vector& vC
) const
{
    // Gaps at the start of the step and now; a point that touched the
    // wall at the start of the step is held on it (allowance zero), an
    // open one may approach it at its closing allowance
    const scalar d0 = gap(x0, step.t0(t));
    const scalar allowance = closingAllowance(d0, gap(x, t), step);

    // Contact normal: out of the body, into the wall.  The normal
    // velocity the contact allows: the wall's, plus the allowance
    const vector nc(-normal_);
    const scalar vWallN = velocity_ & nc;
    const scalar vContactN = vWallN + allowance;

    // Normal velocity jump from the body to the contact (negative when the
    // body moves into it faster).  In compression the Hugoniot relation of
    // the body's side, t^C = t + Zp dv - rho0 s Lambda dv^2 (doc/method.md,
    // section 3), adds the shock term; an expansive jump is acoustic
    const scalar dvn = vContactN - (v & nc);
    const scalar shockTerm = contactRiemannSolvers::hugoniot::rigidShockTerm
    (
        dvn, hugoniot_ ? w.shockMass : scalar(0)
    );
    const scalar tnTrial = (tL & nc) + w.Zp*dvn - shockTerm;

    if (tnTrial >= 0)
    {
        // Tension, or an open point that does not reach the wall within
        // the step: traction-free.  Along the wall's normal its velocity
        // then approaches at most at the allowance where the sub-face's
        // normal n is the wall's (tnTrial >= 0 says so).  Where it is not
        // (a curved surface meeting the wall at an angle), the traction-
        // free velocity of n has a part from the tangential traction (Zs,
        // not Zp) that may still carry the point into the wall: that part
        // is held to the allowance, and the point reaches the wall at the
        // end of the step without a traction
        tC = Zero;
        vC = acousticFormulas::tractionVelocity(tL, v, tC, n, w.Zp, w.Zs);
        const scalar excess = (vC & nc) - vContactN;
        if (excess > 0)
        {
            vC -= excess*nc;
        }
        return 0;
    }

    // The stick state (the wall's velocity, shifted by the allowance); the
    // friction law decides whether it holds or the point slips with the
    // traction it allows
    const vector vStick(velocity_ + allowance*nc);
    const vector tStick
    (
        acousticFormulas::velocityTraction(tL, v, vStick, nc, w.Zp, w.Zs)
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
        vC = vStick;
    }
    else
    {
        acousticFormulas::mixedState
        (
            tL, v, vContactN, ttC, nc, w.Zp, w.Zs, tC, vC
        );
        tC -= shockTerm*nc;
    }

    // The wall's work: the allowance's part, t_n^C times it (<= 0), is
    // numerical dissipation, not work of the wall
    return tC & (vC - allowance*nc);
}


void Foam::solidBoundaryConditions::rigidWall::prescribeDisplacements
(
    const UList<vector>& u,
    const UList<fluxState>& q,
    const scalar t,
    const stageStep& step,
    stageResidual& R,
    const labelUList* points
) const
{
    const pointField& X = dual_.mesh().points();
    const scalar t0 = step.t0(t);
    followStates
    (
        R, points,
        [&](const label i)
        {
            maxDepth_ = max(maxDepth_, -gap(X[i] + u[i], t));
        },
        [&](const label k)
        {
            return (stateT_[k] & normal_) > 0;
        },
        [&](const label i)
        {
            // Without a loaded state: a point touching at the start of the
            // step leaves at its traction-free velocity; an open one does
            // so only if its nodal velocity would approach the wall faster
            // than its allowance (its traction-free one does not)
            const scalar d0 = gap(X[i] + step.u0[i], t0);
            if (d0 <= touch_)
            {
                return true;
            }
            const scalar approach =
                -((fluxVelocity(q[i]) - velocity_) & normal_);
            return approach > closingAllowance(d0, gap(X[i] + u[i], t), step);
        }
    );
}


void Foam::solidBoundaryConditions::rigidWall::markClosing
(
    const UList<vector>& u,
    const UList<fluxState>& q,
    const scalar t,
    const scalar dt,
    UList<bool>& closing
) const
{
    const pointField& X = dual_.mesh().points();
    for (const label i : dual_.subFaces(patchi()).point)
    {
        const scalar approach =
            -((fluxVelocity(q[i]) - velocity_) & normal_);
        if (approach*dt >= gap(X[i] + u[i], t) - touch_)
        {
            closing[i] = true;
        }
    }
}


Foam::scalar Foam::solidBoundaryConditions::rigidWall::strikeSpeed
(
    const boundBox& v,
    const UList<vector>& u,
    const UList<fluxState>& q,
    const scalar t,
    const scalar window
) const
{
    // Struck once a point touches the wall or reaches it within the
    // window, and then while one closes on it (approachCounts)
    const pointField& X = dual_.mesh().points();
    bool near = false, closing = false;
    for (const label i : dual_.subFaces(patchi()).point)
    {
        const scalar gapi = gap(X[i] + u[i], t) - touch_;
        const scalar approach = closingSpeed(fluxVelocity(q[i]));
        near = near || gapi <= approach*window;
        closing = closing || approach > 0;
    }
    reduce(near, orOp<bool>());
    reduce(closing, orOp<bool>());
    if (!approachCounts(approaching_, near, closing, window))
    {
        return 0;
    }
    return largestAtCorners
    (
        v, [this](const vector& vi) { return closingSpeed(vi); }
    );
}


void Foam::solidBoundaryConditions::rigidWall::writeSummary
(
    Ostream& os,
    const word& body
) const
{
    // (mag: a point exactly on the wall leaves -0)
    const scalar depth = mag(returnReduce(maxDepth_, maxOp<scalar>()));
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
