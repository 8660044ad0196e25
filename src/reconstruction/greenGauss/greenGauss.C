/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "greenGauss.H"

namespace
{

// One pass over the edges: the Green-Gauss sums and, when Bounds, the
// neighbourhood extrema (the limiter's pass over the same data)
template<bool Bounds>
void gradientAndBounds
(
    const Foam::dualMesh& dual,
    const Foam::UList<Foam::fluxState>& q,
    Foam::List<Foam::fluxStateGradient>& G,
    Foam::List<Foam::fluxState>& qMin,
    Foam::List<Foam::fluxState>& qMax
)
{
    using namespace Foam;

    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const vectorField& Ne = dual.edgeNormals();
    const scalarField& Ae = dual.edgeMagSf();
    const scalarField& V = dual.volumes();
    const polyBoundaryMesh& patches = dual.mesh().boundaryMesh();

    fluxStateGradient zero;
    zero = vector::zero;
    G = zero;
    if (Bounds)
    {
        qMin = q;
        qMax = q;
    }

    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        const vector C(0.5*Ae[e]*Ne[e]);
        const fluxState& qi = q[i];
        const fluxState& qj = q[j];
        fluxStateGradient& Gi = G[i];
        fluxStateGradient& Gj = G[j];
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            const vector flux((qi[c] + qj[c])*C);
            Gi[c] += flux;
            Gj[c] -= flux;
        }
        if (Bounds)
        {
            fluxStateMinEqOp()(qMin[i], qj);
            fluxStateMaxEqOp()(qMax[i], qj);
            fluxStateMinEqOp()(qMin[j], qi);
            fluxStateMaxEqOp()(qMax[j], qi);
        }
    }

    // Physical patches (coupled patches have no sub-faces)
    forAll(patches, patchi)
    {
        const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
        forAll(sf.point, s)
        {
            const label i = sf.point[s];
            const scalar w = sf.nbrWeight[s];
            const fluxState& qi = q[i];
            const fluxState& qp = q[sf.prev[s]];
            const fluxState& qn = q[sf.next[s]];
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                G[i][c] +=
                    (qi[c] + w*(qp[c] + qn[c] - 2*qi[c]))*sf.area[s];
            }
        }
    }

    if (Pstream::parRun())
    {
        syncTools::syncPointList
        (
            dual.mesh(), G, componentPlusEqOp<fluxStateGradient>(), zero
        );
    }

    forAll(G, i)
    {
        const scalar invV = 1.0/V[i];
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            G[i][c] *= invV;
        }
    }
}

} // End anonymous namespace


void Foam::greenGaussGradient
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G
)
{
    List<fluxState> unused;
    gradientAndBounds<false>(dual, q, G, unused, unused);
}


void Foam::greenGaussGradient
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G,
    List<fluxState>& qMin,
    List<fluxState>& qMax
)
{
    gradientAndBounds<true>(dual, q, G, qMin, qMax);
}


// ************************************************************************* //
