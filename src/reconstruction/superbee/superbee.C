/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "superbee.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(superbee, 0);
    addToRunTimeSelectionTable(limiter, superbee, dictionary);
}
}


// ************************************************************************* //
