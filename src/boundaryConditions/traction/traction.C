/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "traction.H"
#include "checkedInput.H"
#include "acousticFormulas.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(traction, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, traction, dictionary);
}
}


Foam::solidBoundaryConditions::traction::traction
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    solidBoundaryCondition(dual, patchi, dict)
,
    traction_
    (
        dict.found("traction")
      ? Function1<vector>::New("traction", dict)
      : autoPtr<Function1<vector>>
        (
            new Function1Types::Constant<vector>("traction", Zero)
        )
    )
{
    checkFiniteAtStart(dict, "traction", patchName(), traction_->value(0));
}


Foam::scalar Foam::solidBoundaryConditions::traction::contactState
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
    tC = traction_->value(t);
    vC = acousticFormulas::tractionVelocity(tL, v, tC, n, w.Zp, w.Zs);
    return tC & vC;
}


void Foam::solidBoundaryConditions::traction::describe(Ostream& os) const
{
    os  << "traction " << traction_->value(0) << " (at t = 0)";
}


// ************************************************************************* //
