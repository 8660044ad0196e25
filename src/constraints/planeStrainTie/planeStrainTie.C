/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "planeStrainTie.H"
#include "dualMesh.H"
#include "FlatOutput.H"

Foam::planeStrainTie::planeStrainTie
(
    const dualMesh& dual,
    const PtrList<solidBoundaryCondition>& bcs,
    const dictionary& bodyDict,
    const word& bodyName
)
:
    depth_(0)
{
    const polyMesh& mesh = dual.mesh();
    wordList patchNames;
    if (!bodyDict.readIfPresent("planeStrain", patchNames))
    {
        return;
    }

    // Normals of the points on the planes (zero elsewhere)
    vectorField N(mesh.nPoints(), Zero);
    for (const word& patchName : patchNames)
    {
        const label patchi = mesh.boundaryMesh().findPatchID(patchName);
        const solidBoundaryCondition* bcPtr = nullptr;
        for (const solidBoundaryCondition& bc : bcs)
        {
            if (bc.patchi() == patchi) bcPtr = &bc;
        }
        if (!bcPtr || !bcPtr->constrainsNormal())
        {
            FatalIOErrorInFunction(bodyDict)
                << "planeStrain: '" << patchName << "' is not a symmetry"
                << " (or empty) patch of body '" << bodyName << "'" << nl
                << "It lists the patches holding the two planes of the"
                << " one-layer mesh, e.g. planeStrain (frontBack);"
                << exit(FatalIOError);
        }
        N += dual.patchPointNormals(patchi);
    }

    const pointField& X = mesh.points();
    const labelList& start = dual.edgeStart();
    const labelList& end = dual.edgeEnd();

    labelList partner(mesh.nPoints(), -1);
    label nBad = 0;
    forAll(start, e)
    {
        const label i = start[e], j = end[e];
        if (magSqr(N[i]) == 0 || magSqr(N[j]) == 0)
        {
            continue;
        }
        const vector d(X[j] - X[i]);
        const vector n(N[i]/mag(N[i]));
        if (mag(d ^ n) < 1e-6*mag(d))
        {
            if (partner[i] != -1 || partner[j] != -1) ++nBad;
            partner[i] = j;
            partner[j] = i;
        }
    }
    forAll(partner, i)
    {
        if (partner[i] == -1) ++nBad;
    }
    if (returnReduce(nBad, sumOp<label>()))
    {
        FatalIOErrorInFunction(bodyDict)
            << "planeStrain: the mesh of body '" << bodyName << "' is not one"
            << " layer between the planes of " << flatOutput(patchNames)
            << ": "
            << returnReduce(nBad, sumOp<label>()) << " points lack a single"
            << " partner across the layer" << nl
            << "Mesh a plane-strain body as one extruded layer (gmsh"
            << " Extrude ... Layers{1})"
            << exit(FatalIOError);
    }

    forAll(partner, i)
    {
        if (i < partner[i])
        {
            A_.append(i);
            B_.append(partner[i]);
        }
    }
    forAll(A_, k)
    {
        depth_ = max(depth_, mag(X[B_[k]] - X[A_[k]]));
    }
    reduce(depth_, maxOp<scalar>());
}


// ************************************************************************* //
