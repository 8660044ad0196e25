/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Description
    Face and cell geometry for the dual's construction, computed as
    OpenFOAM's primitiveMesh computes them (the same operations in the same
    order), so that the mesh-wide face and cell geometry lists primitiveMesh
    would keep are not needed.  This file is built without fused
    multiply-adds, as OpenFOAM's own library is, so that it gives the same
    bits whatever instruction set the rest of the library is built for.

\*---------------------------------------------------------------------------*/

#pragma GCC optimize ("fp-contract=off")

#include "dualMesh.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::dualMesh::faceGeometry
(
    const Foam::face& f,
    const Foam::pointField& p,
    Foam::vector& fc,
    Foam::vector& fA
)
{
    // primitiveMesh::makeFaceCentresAndAreas for one face
    const Foam::label nPoints = f.size();
    if (nPoints == 3)
    {
        fc = (1.0/3.0)*(p[f[0]] + p[f[1]] + p[f[2]]);
        fA = 0.5*((p[f[1]] - p[f[0]])^(p[f[2]] - p[f[0]]));
        return;
    }

    Foam::vector sumN(Foam::Zero);
    Foam::scalar sumA = 0;
    Foam::vector sumAc(Foam::Zero);

    Foam::vector fCentre(p[f[0]]);
    for (Foam::label pi = 1; pi < nPoints; ++pi)
    {
        fCentre += p[f[pi]];
    }
    fCentre /= nPoints;

    for (Foam::label pi = 0; pi < nPoints; ++pi)
    {
        const Foam::label nextPi(pi == nPoints-1 ? 0 : pi+1);
        const Foam::vector nextPoint(p[f[nextPi]]);
        const Foam::vector thisPoint(p[f[pi]]);

        const Foam::vector c(thisPoint + nextPoint + fCentre);
        const Foam::vector n((nextPoint - thisPoint)^(fCentre - thisPoint));
        const Foam::scalar a = Foam::mag(n);
        sumN += n;
        sumA += a;
        sumAc += a*c;
    }

    if (sumA < Foam::ROOTVSMALL)
    {
        fc = fCentre;
        fA = Foam::Zero;
    }
    else
    {
        fc = (1.0/3.0)*sumAc/sumA;
        fA = 0.5*sumN;
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dualMesh::calcFaceGeometry
(
    const pointField& p,
    vectorField& faceCentres,
    vectorField& faceAreas
) const
{
    const faceList& faces = mesh_.faces();
    faceCentres.setSize(faces.size());
    faceAreas.setSize(faces.size());
    forAll(faces, facei)
    {
        faceGeometry(faces[facei], p, faceCentres[facei], faceAreas[facei]);
    }
}


void Foam::dualMesh::calcCellCentres
(
    const pointField& p,
    const vectorField* faceCentres,
    const vectorField* faceAreas,
    pointField& cellCentres,
    scalarField& cellVolumes
) const
{
    // primitiveMesh::makeCellCentresAndVols: an estimate from the face
    // centres, then the volume-weighted centroid of the face pyramids
    // about it.  The face geometry is computed on the fly unless given
    // (the reference dual's construction keeps no face-sized lists: they
    // would raise the run's peak memory, which is reached while the mesh
    // still holds OpenFOAM's own addressing)
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    auto geometry = [&](const label facei, vector& fc, vector& fA)
    {
        if (faceCentres)
        {
            fc = (*faceCentres)[facei];
            fA = (*faceAreas)[facei];
        }
        else
        {
            faceGeometry(faces[facei], p, fc, fA);
        }
    };

    cellCentres.setSize(mesh_.nCells());
    cellVolumes.setSize(mesh_.nCells());
    cellCentres = Zero;
    cellVolumes = 0;

    pointField cEst(mesh_.nCells(), Zero);
    labelList nCellFaces(mesh_.nCells(), 0);
    vector fc, fA;
    forAll(own, facei)
    {
        geometry(facei, fc, fA);
        cEst[own[facei]] += fc;
        ++nCellFaces[own[facei]];
    }
    forAll(nei, facei)
    {
        geometry(facei, fc, fA);
        cEst[nei[facei]] += fc;
        ++nCellFaces[nei[facei]];
    }
    forAll(cEst, celli)
    {
        cEst[celli] /= nCellFaces[celli];
    }

    forAll(own, facei)
    {
        geometry(facei, fc, fA);
        const scalar pyr3Vol = fA & (fc - cEst[own[facei]]);
        const vector pc((3.0/4.0)*fc + (1.0/4.0)*cEst[own[facei]]);
        cellCentres[own[facei]] += pyr3Vol*pc;
        cellVolumes[own[facei]] += pyr3Vol;
    }
    forAll(nei, facei)
    {
        geometry(facei, fc, fA);
        const scalar pyr3Vol = fA & (cEst[nei[facei]] - fc);
        const vector pc((3.0/4.0)*fc + (1.0/4.0)*cEst[nei[facei]]);
        cellCentres[nei[facei]] += pyr3Vol*pc;
        cellVolumes[nei[facei]] += pyr3Vol;
    }

    forAll(cellCentres, celli)
    {
        if (mag(cellVolumes[celli]) > VSMALL)
        {
            cellCentres[celli] /= cellVolumes[celli];
        }
        else
        {
            cellCentres[celli] = cEst[celli];
        }
    }
    cellVolumes *= (1.0/3.0);
}


// ************************************************************************* //
