/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "velocity.H"
#include "checkedInput.H"
#include "acousticFormulas.H"
#include "hugoniot.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(velocity, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, velocity, dictionary);
}
}


Foam::solidBoundaryConditions::velocity::velocity
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    solidBoundaryCondition(dual, patchi, dict)
,
    velocity_(Function1<vector>::New("velocity", dict))
{
    checkFiniteAtStart(dict, "velocity", patchName(), velocity_->value(0));
}


Foam::scalar Foam::solidBoundaryConditions::velocity::strikeSpeed
(
    const boundBox& v,
    const UList<vector>& u,
    const UList<fluxState>& q,
    const scalar t,
    const scalar window
) const
{
    const vector vb(velocity_->value(t));
    return largestAtCorners
    (
        v, [&vb](const vector& vi) { return mag(vb - vi); }
    );
}


Foam::scalar Foam::solidBoundaryConditions::velocity::contactState
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
    vC = velocity_->value(t);
    tC = acousticFormulas::velocityTraction(tL, v, vC, n, w.Zp, w.Zs);
    // A Hugoniot body driven into compression: the shock relation of its
    // side, t^C = t + Zp dv_n - shockMass dv_n^2 (doc/method.md, section
    // 3), as at a rigid wall; with the acoustic relation alone the face's
    // traction lags the shock's while the face point takes the prescribed
    // velocity, and the face overshoots (a piston at twice the wave speed
    // into A3's material: 6.4 % beyond the shocked stress)
    tC -= contactRiemannSolvers::hugoniot::rigidShockTerm
    (
        (vC - v) & n, w.shockMass
    )*n;
    return tC & vC;
}


void Foam::solidBoundaryConditions::velocity::describe(Ostream& os) const
{
    os  << "velocity " << velocity_->value(0) << " (at t = 0)";
}


// ************************************************************************* //
