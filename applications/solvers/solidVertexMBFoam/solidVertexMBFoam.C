/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    solidVertexMBFoam

Description
    Explicit multi-body solver for large-strain solid contact dynamics on the
    median dual of each body's mesh.  Bodies are the regions listed under
    'solid' in constant/regionProperties, or the single mesh in
    constant/polyMesh when there is no such file.

    This version reads the bodies and builds their dual meshes.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "regionProperties.H"
#include "dualMesh.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit vertex-centred solver for large-strain solid contact"
        " dynamics"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    wordList bodies(1, polyMesh::defaultRegion);
    if (isFile(runTime.constant()/"regionProperties"))
    {
        bodies = regionProperties(runTime)["solid"];
    }

    forAll(bodies, bodyi)
    {
        Info<< "Body " << bodies[bodyi] << nl;
        polyMesh mesh
        (
            IOobject
            (
                bodies[bodyi],
                runTime.timeName(),
                runTime,
                IOobject::MUST_READ
            )
        );
        const dualMesh dual(mesh);

        Info<< "    points " << returnReduce(mesh.nPoints(), sumOp<label>())
            << ", cells " << returnReduce(mesh.nCells(), sumOp<label>())
            << ", edges " << returnReduce(dual.nEdges(), sumOp<label>())
            << nl
            << "    volume " << dual.sumPoints(dual.volumes())
            << ", control volumes " << gMin(dual.volumes()) << " .. "
            << gMax(dual.volumes()) << nl
            << "    shortest edge " << dual.minLength() << nl << endl;
    }

    Info<< "End\n" << endl;
    return 0;
}

// ************************************************************************* //
