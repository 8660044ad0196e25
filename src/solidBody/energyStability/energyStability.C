/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "energyStability.H"
#include "dualMesh.H"
#include "bitSet.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::energyStability::energyStability(const dualMesh& dual, const bool JLaw)
:
    edgeAreaSum_(dual.mesh().nPoints(), Zero),
    edgeAreaMag_(dual.mesh().nPoints(), Zero),
    JLaw_(JLaw),
    boundaryPoints_(),
    asideMomentum_(),
    asideF_()
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const vectorField& Ne = dual.edgeNormals();
    const scalarField& Ae = dual.edgeMagSf();
    forAll(es, e)
    {
        edgeAreaSum_[es[e]] += Ae[e]*Ne[e];
        edgeAreaSum_[ee[e]] -= Ae[e]*Ne[e];
        edgeAreaMag_[es[e]] += Ae[e];
        edgeAreaMag_[ee[e]] += Ae[e];
    }

    // Boundary conditions and contact pairs add to the points of the
    // sub-faces of the physical patches only
    bitSet onBoundary(dual.mesh().nPoints());
    const polyBoundaryMesh& patches = dual.mesh().boundaryMesh();
    forAll(patches, patchi)
    {
        if (!patches[patchi].coupled())
        {
            for (const label i : dual.subFaces(patchi).point)
            {
                onBoundary.set(i);
            }
        }
    }
    boundaryPoints_ = onBoundary.sortedToc();
    asideMomentum_.setSize(boundaryPoints_.size());
    asideF_.setSize(boundaryPoints_.size());
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::energyStability::setAside(const stageResidual& R)
{
    forAll(boundaryPoints_, b)
    {
        asideMomentum_[b] = R.momentum[boundaryPoints_[b]];
        asideF_[b] = R.F[boundaryPoints_[b]];
    }
}


Foam::vector2D Foam::energyStability::production
(
    const stageResidual& R,
    const UList<vector>& v,
    const UList<tensor>& P,
    const UList<scalar>& SigmaJ
) const
{
    vector2D prod(Zero);
    forAll(R.momentum, i)
    {
        prod.x() +=
            (v[i] & R.momentum[i]) + (P[i] && R.F[i])
          - (v[i] & (P[i] & edgeAreaSum_[i]));
        prod.y() += mag(v[i])*mag(P[i])*edgeAreaMag_[i];
    }
    forAll(boundaryPoints_, b)
    {
        const label i = boundaryPoints_[b];
        prod.x() -= (v[i] & asideMomentum_[b]) + (P[i] && asideF_[b]);
        // (what is taken out counts in the rounding: at rest against a
        // wall, unstressed, only the wall's fluxes are not zero)
        prod.y() +=
            mag(v[i])*mag(asideMomentum_[b]) + mag(P[i])*mag(asideF_[b]);
    }
    if (JLaw_)
    {
        forAll(R.J, i)
        {
            prod.x() += SigmaJ[i]*R.J[i];
        }
    }
    return prod;
}


// ************************************************************************* //
