/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "contact.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(contact, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, contact, dictionary);
}
}

// ************************************************************************* //
