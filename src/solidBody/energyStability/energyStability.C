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
    openPoints_(),
    openAreaSum_(),
    edgeAreaMag_(dual.mesh().nPoints(), 0.0f),
    JLaw_(JLaw),
    boundaryPoints_(),
    asideMomentum_(),
    asideF_(),
    requiredDissipation_(0)
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const vectorField& Ne = dual.edgeNormals();
    const scalarField& Ae = dual.edgeMagSf();
    List<vector> edgeAreaSum(dual.mesh().nPoints(), Zero);
    forAll(es, e)
    {
        edgeAreaSum[es[e]] += Ae[e]*Ne[e];
        edgeAreaSum[ee[e]] -= Ae[e]*Ne[e];
        edgeAreaMag_[es[e]] += Ae[e];
        edgeAreaMag_[ee[e]] += Ae[e];
    }

    // A closed cell's edge areas sum to zero: only the points whose cell
    // the physical or a processor boundary closes keep theirs (elsewhere
    // the sum is rounding, far below the production's rounding scale)
    DynamicList<label> open;
    DynamicList<vector> openSum;
    forAll(edgeAreaSum, i)
    {
        if (mag(edgeAreaSum[i]) > 1e-10*edgeAreaMag_[i])
        {
            open.append(i);
            openSum.append(edgeAreaSum[i]);
        }
    }
    openPoints_.transfer(open);
    openAreaSum_.transfer(openSum);

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
    const UList<fluxState>& q
) const
{
    vector2D prod(Zero);
    forAll(R.momentum, i)
    {
        const vector v(fluxVelocity(q[i]));
        const tensor P(fluxStress(q[i]));
        prod.x() += (v & R.momentum[i]) + (P && R.F[i]);
        prod.y() += mag(v)*mag(P)*edgeAreaMag_[i];
    }
    forAll(openPoints_, k)
    {
        const label i = openPoints_[k];
        prod.x() -= fluxVelocity(q[i]) & (fluxStress(q[i]) & openAreaSum_[k]);
    }
    forAll(boundaryPoints_, b)
    {
        const label i = boundaryPoints_[b];
        const vector v(fluxVelocity(q[i]));
        const tensor P(fluxStress(q[i]));
        prod.x() -= (v & asideMomentum_[b]) + (P && asideF_[b]);
        // (what is taken out counts in the rounding: at rest against a
        // wall, unstressed, only the wall's fluxes are not zero)
        prod.y() +=
            mag(v)*mag(asideMomentum_[b]) + mag(P)*mag(asideF_[b]);
    }
    if (JLaw_)
    {
        forAll(R.J, i)
        {
            prod.x() += fluxSigmaJ(q[i])*R.J[i];
        }
    }
    return prod;
}


// ************************************************************************* //
