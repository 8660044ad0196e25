/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "unlimited.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(unlimited, 0);
    addToRunTimeSelectionTable(limiter, unlimited, dictionary);
}
}


void Foam::limiters::unlimited::limit
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    const UList<fluxStateGradient>& G,
    List<fluxState>& phi
) const
{
    for (fluxState& p : phi)
    {
        p = 1.0;
    }
}


// ************************************************************************* //
