/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "symmetryConstraint.H"
#include "dualMesh.H"
#include "ListOps.H"

Foam::symmetryConstraint::symmetryConstraint
(
    const dualMesh& dual,
    const PtrList<solidBoundaryCondition>& bcs
)
{
    // Projector per point, I - sum e e over the orthonormalised normals of
    // its constraining patches.  Normals are summed over processors: a
    // point on a processor boundary must be constrained alike on every
    // processor holding it
    const label nPoints = dual.mesh().nPoints();
    List<tensor> P(nPoints, I);
    boolList constrained(nPoints, false);
    List<DynamicList<tensor>> Q(nPoints);
    for (const solidBoundaryCondition& bc : bcs)
    {
        if (!bc.constrainsNormal())
        {
            continue;
        }
        // (a patch that folds round an edge, such as the one symmetry
        // patch on all four sides of a bar, gives its points there both
        // planes: with the mean normal alone the bar's edge points could
        // slide along the diagonal, and on tets under finite-strain
        // compression they did, crushing the struck face: doc/results.md,
        // "Finite-strain bars on tets")
        List<FixedList<vector, 3>> planes;
        labelList nPlanes;
        dual.patchPointPlanes(bc.patchi(), planes, nPlanes);
        forAll(planes, i)
        {
            for (label k = 0; k < nPlanes[i]; ++k)
            {
                constrained[i] = true;
                vector e(P[i] & planes[i][k]);
                if (mag(e) > 1e-6)
                {
                    e /= mag(e);
                    P[i] -= e*e;
                    Q[i].append(I - 2*(e*e));
                }
            }
        }
    }

    points_ = findIndices(constrained, true);
    projections_ = UIndirectList<tensor>(P, points_)();
    reflections_.setSize(points_.size());
    forAll(points_, k)
    {
        reflections_[k] = Q[points_[k]];
    }
}


// ************************************************************************* //
