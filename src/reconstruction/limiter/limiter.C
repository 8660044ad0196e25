/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "limiter.H"

namespace Foam
{
    defineTypeNameAndDebug(limiter, 0);
    defineRunTimeSelectionTable(limiter, dictionary);
}


Foam::autoPtr<Foam::limiter> Foam::limiter::New
(
    const word& type,
    const dictionary& dict
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown limiter '" << type << "' (keyword 'limiter')" << nl
            << "Valid limiters: auto (chosen from the material) or "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    return autoPtr<limiter>(cstrIter()(dict));
}


// ************************************************************************* //
