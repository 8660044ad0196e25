/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "monotonizedCentral.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(monotonizedCentral, 0);
    addToRunTimeSelectionTable(limiter, monotonizedCentral, dictionary);
}
}


// ************************************************************************* //
