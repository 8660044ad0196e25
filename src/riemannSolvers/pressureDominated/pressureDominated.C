/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "pressureDominated.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactRiemannSolvers
{
    defineTypeNameAndDebug(pressureDominated, 0);
    addToRunTimeSelectionTable(contactRiemannSolver, pressureDominated, dictionary);
}
}

// ************************************************************************* //
