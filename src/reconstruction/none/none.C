/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "none.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(limiter, none, dictionary);
}
}


// ************************************************************************* //
