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
    const dictionary& dict
)
{
    const word type(dict.getOrDefault<word>("riemannSolver", "acoustic"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown riemannSolver '" << type << "'" << nl
            << "Valid Riemann solvers: "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    return autoPtr<contactRiemannSolver>(cstrIter()(dict));
}


// ************************************************************************* //
