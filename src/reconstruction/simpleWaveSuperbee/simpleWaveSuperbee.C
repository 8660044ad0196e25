/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "simpleWaveSuperbee.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(simpleWaveSuperbee, 0);
    addToRunTimeSelectionTable(limiter, simpleWaveSuperbee, dictionary);
}
}


// ************************************************************************* //
