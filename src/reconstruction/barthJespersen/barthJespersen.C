/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "barthJespersen.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace limiters
{
    defineTypeNameAndDebug(barthJespersen, 0);
    addToRunTimeSelectionTable(limiter, barthJespersen, dictionary);
}
}


void Foam::limiters::barthJespersen::limit
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G
) const
{
    // The point loop finds the extrema itself (serial)
    limitPoints<false>(dual, q, G, qMin_, qMax_);
}


void Foam::limiters::barthJespersen::limit
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G,
    List<fluxState>& qMin,
    List<fluxState>& qMax
) const
{
    limitPoints<true>(dual, q, G, qMin, qMax);
}


template<bool GivenBounds>
void Foam::limiters::barthJespersen::limitPoints
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G,
    List<fluxState>& qMin,
    List<fluxState>& qMax
) const
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const labelList& pointEdgeStart = dual.pointEdgeStart();
    const labelList& pointEdges = dual.pointEdges();
    const pointField& X = dual.mesh().points();
    const label nPts = q.size();
    const bool serial = !Pstream::parRun();

    if (!GivenBounds && !serial)
    {
        // Extrema over the processor's edges, completed below
        qMin = q;
        qMax = q;
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            fluxStateMinEqOp()(qMin[i], q[j]);
            fluxStateMaxEqOp()(qMax[i], q[j]);
            fluxStateMinEqOp()(qMin[j], q[i]);
            fluxStateMaxEqOp()(qMax[j], q[i]);
        }
    }
    // In serial without given extrema the point loop finds them itself
    const bool ownBounds = !GivenBounds && serial;

    if (!serial)
    {
        fluxState big; big = GREAT;
        fluxState small; small = -GREAT;
        syncTools::syncPointList
        (
            dual.mesh(), qMin, fluxStateMinEqOp(), big
        );
        syncTools::syncPointList
        (
            dual.mesh(), qMax, fluxStateMaxEqOp(), small
        );
        phi_.setSize(nPts);
    }

    // Body-wide magnitudes: velocity components share one, stress
    // components (P and Sigma_J) another.  Increments below 'noise' (a tiny
    // fraction of the magnitude of the quantity) are not limited: for
    // components that are zero up to round-off (transverse velocity of a 1D
    // wave, say) the ratio would be noise over noise and the limited scheme
    // would amplify round-off.
    scalar vScale = 0, PScale = 0;
    forAll(q, i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            vScale = max(vScale, mag(q[i][c]));
        }
        for (direction c = 3; c < nFluxComponents; ++c)
        {
            PScale = max(PScale, mag(q[i][c]));
        }
    }
    reduce(vScale, maxOp<scalar>());
    reduce(PScale, maxOp<scalar>());
    fluxState noise;
    for (direction c = 0; c < nFluxComponents; ++c)
    {
        noise[c] = relativeNoise_*(c < 3 ? vScale : PScale) + VSMALL;
    }

    // Point by point: the largest and smallest unlimited increments
    // G_i (X_j - X_i)/2 over the point's edges, then Phi = the room to the
    // extrema over them (at most 1)
    for (label i = 0; i < nPts; ++i)
    {
        fluxStateGradient& g = G[i];
        const point& Xi = X[i];
        const fluxState& qi = q[i];
        fluxState dHi, dLo, lo(qi), hi(qi);
        dHi = 0.0;
        dLo = 0.0;
        for (label k = pointEdgeStart[i]; k < pointEdgeStart[i + 1]; ++k)
        {
            const label e = pointEdges[k];
            const label j = es[e] + ee[e] - i;
            const vector halfdX(0.5*(X[j] - Xi));
            fluxState d;
            gradientIncrements(g, halfdX, d);
            #pragma GCC unroll 1
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                dHi[c] = max(dHi[c], d[c]);
                dLo[c] = min(dLo[c], d[c]);
            }
            if (ownBounds)
            {
                const fluxState& qj = q[j];
                #pragma GCC unroll 1
                for (direction c = 0; c < nFluxComponents; ++c)
                {
                    lo[c] = min(lo[c], qj[c]);
                    hi[c] = max(hi[c], qj[c]);
                }
            }
        }
        if (!ownBounds)
        {
            lo = qMin[i];
            hi = qMax[i];
        }

        fluxState phi;
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            scalar p = 1;
            if (dHi[c] > noise[c])
            {
                p = min(p, (hi[c] - qi[c])/dHi[c]);
            }
            if (dLo[c] < -noise[c])
            {
                p = min(p, (lo[c] - qi[c])/dLo[c]);
            }
            phi[c] = p;
        }
        if (serial)
        {
            scaleGradient(g, phi);
        }
        else
        {
            phi_[i] = phi;
        }
    }

    if (!serial)
    {
        // A shared point's Phi is the smallest over all its edges
        fluxState one; one = 1.0;
        syncTools::syncPointList
        (
            dual.mesh(), phi_, fluxStateMinEqOp(), one
        );
        forAll(G, i)
        {
            scaleGradient(G[i], phi_[i]);
        }
    }
}


// ************************************************************************* //
