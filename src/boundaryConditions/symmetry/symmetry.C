/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "symmetry.H"
#include "acousticFormulas.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(symmetry, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, symmetry, dictionary);
}
}


Foam::solidBoundaryConditions::symmetry::symmetry
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    solidBoundaryCondition(dual, patchi, dict)
{}


Foam::scalar Foam::solidBoundaryConditions::symmetry::contactState
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
    // The plane's own normal (the reference one): the deformed normal may
    // tilt, and its normal reaction would then push along the plane
    acousticFormulas::mixedState(tL, v, 0, Zero, N, w.Zp, w.Zs, tC, vC);
    return tC & vC;
}


void Foam::solidBoundaryConditions::symmetry::describe(Ostream& os) const
{
    os  << "symmetry plane";
}


// ************************************************************************* //
