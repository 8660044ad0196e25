/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "rigidWall.H"
#include "checkedInput.H"
#include "acousticFormulas.H"
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
    friction_(frictionLaw::New(dict, "patch '" + patchName() + "'"))
{
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
    const scalar Zp,
    const scalar Zs,
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
    const scalar tnTrial = (tL & nc) + Zp*(vWallN - (v & nc));

    if (gap > 0 || tnTrial >= 0)
    {
        // Open gap or tension: traction-free
        tC = Zero;
        vC = acousticFormulas::tractionVelocity(tL, v, tC, n, Zp, Zs);
        return;
    }

    // The stick state (the wall's velocity); the friction law decides
    // whether it holds or the point slips with the traction it allows
    const vector tStick
    (
        acousticFormulas::velocityTraction(tL, v, velocity_, nc, Zp, Zs)
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
        acousticFormulas::mixedState(tL, v, vWallN, ttC, nc, Zp, Zs, tC, vC);
    }
}


void Foam::solidBoundaryConditions::rigidWall::describe(Ostream& os) const
{
    os  << "rigid wall at " << point_ << ", normal " << normal_
        << ", velocity " << velocity_ << ", friction ";
    friction_->describe(os);
}


// ************************************************************************* //
