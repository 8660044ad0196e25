/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "frictionless.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(frictionless, 0);
    addToRunTimeSelectionTable(frictionLaw, frictionless, dictionary);
}
}


Foam::vector Foam::frictionLaws::frictionless::tangentialTraction
(
    const vector& ttStick,
    const scalar tn,
    bool& stick
) const
{
    stick = false;
    return Zero;
}


// ************************************************************************* //
