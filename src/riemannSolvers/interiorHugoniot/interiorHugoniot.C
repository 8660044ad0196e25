/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "interiorHugoniot.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace interiorRiemannSolvers
{
    defineTypeNameAndDebug(hugoniot, 0);
    addToRunTimeSelectionTable(interiorRiemannSolver, hugoniot, material);
}
}


// ************************************************************************* //
