/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "vanAlbada.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(vanAlbada, 0);
    addToRunTimeSelectionTable(limiter, vanAlbada, dictionary);
}
}


// ************************************************************************* //
