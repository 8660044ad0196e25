/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "contactRiemannSolver.H"

namespace Foam
{
    defineTypeNameAndDebug(contactRiemannSolver, 0);
    defineRunTimeSelectionTable(contactRiemannSolver, dictionary);
}


Foam::autoPtr<Foam::contactRiemannSolver> Foam::contactRiemannSolver::New
(
    const dictionary& dict,
    const word& type
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown riemannSolver '" << type << "'" << nl
            << "Valid Riemann solvers: auto (chosen per pair from the"
            << " materials and the impact Mach number) or "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    return autoPtr<contactRiemannSolver>(cstrIter()(dict));
}


// ************************************************************************* //
