/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "interiorRiemannSolver.H"
#include "FlatOutput.H"

namespace Foam
{
    defineTypeNameAndDebug(interiorRiemannSolver, 0);
    defineRunTimeSelectionTable(interiorRiemannSolver, material);
}


Foam::autoPtr<Foam::interiorRiemannSolver> Foam::interiorRiemannSolver::New
(
    const dictionary& schemeDict,
    const word& type,
    const materialModel& material
)
{
    auto cstrIter = materialConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(schemeDict)
            << "Unknown riemannSolver '" << type << "' in the scheme" << nl
            << "Valid solvers: auto (the material's: hugoniot for a material"
            << " with a Hugoniot, else acoustic) or "
            << flatOutput(materialConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }
    return autoPtr<interiorRiemannSolver>(cstrIter()(material));
}


// ************************************************************************* //
