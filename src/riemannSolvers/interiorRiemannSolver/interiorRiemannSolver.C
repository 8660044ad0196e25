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
    const materialModel& material
)
{
    const word type
    (
        schemeDict.getOrDefault<word>
        (
            "riemannSolver", material.hugoniot() ? "hugoniot" : "acoustic"
        )
    );
    auto cstrIter = materialConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(schemeDict)
            << "Unknown riemannSolver '" << type << "' in the scheme" << nl
            << "Valid solvers: "
            << flatOutput(materialConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }
    return autoPtr<interiorRiemannSolver>(cstrIter()(material));
}


// ************************************************************************* //
