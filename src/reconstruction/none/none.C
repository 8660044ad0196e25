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


void Foam::limiters::none::limit
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
