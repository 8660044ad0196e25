/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "coulomb.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionLaws
{
    defineTypeNameAndDebug(coulomb, 0);
    addToRunTimeSelectionTable(frictionLaw, coulomb, dictionary);
}
}


Foam::frictionLaws::coulomb::coulomb(const dictionary& dict)
:
    k_(dict.get<scalar>("friction"))
{}


Foam::vector Foam::frictionLaws::coulomb::tangentialTraction
(
    const vector& ttStick,
    const scalar tn,
    bool& stick
) const
{
    const scalar limit = -k_*tn;
    stick = (mag(ttStick) <= limit);
    return stick ? ttStick : (limit/mag(ttStick))*ttStick;
}


// ************************************************************************* //
