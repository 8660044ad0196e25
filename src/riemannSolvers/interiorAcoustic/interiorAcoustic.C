/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "interiorAcoustic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace interiorRiemannSolvers
{
    defineTypeNameAndDebug(acoustic, 0);
    addToRunTimeSelectionTable(interiorRiemannSolver, acoustic, material);
}
}


// ************************************************************************* //
