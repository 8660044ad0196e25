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
    for (const solidBoundaryCondition& bc : bcs)
    {
        if (!bc.constrainsNormal())
        {
            continue;
        }
        const vectorField N(dual.patchPointNormals(bc.patchi()));
        forAll(N, i)
        {
            if (magSqr(N[i]) > 0)
            {
                constrained[i] = true;
                vector e(P[i] & N[i]);
                if (mag(e) > 1e-6)
                {
                    e /= mag(e);
                    P[i] -= e*e;
                }
            }
        }
    }

    points_ = findIndices(constrained, true);
    projections_ = UIndirectList<tensor>(P, points_)();
}


// ************************************************************************* //
