/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "stick.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(stick, 0);
    addToRunTimeSelectionTable(frictionLaw, stick, dictionary);
}
}


Foam::vector Foam::frictionLaws::stick::tangentialTraction
(
    const vector& ttStick,
    const scalar tn,
    bool& stick
) const
{
    stick = true;
    return ttStick;
}


// ************************************************************************* //
