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
    limitPoints(dual, q, G, nullptr);
}


void Foam::limiters::barthJespersen::limitPoints
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G,
    const UList<bool>* only
) const
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const labelList& pointEdgeStart = dual.pointEdgeStart();
    const labelList& pointEdges = dual.pointEdges();
    const pointField& X = dual.mesh().points();
    const label nPts = q.size();
    const bool parallel = Pstream::parRun();

    // The extrema of q over point i and its edge neighbours on this
    // processor
    auto localBounds = [&](const label i, fluxState& lo, fluxState& hi)
    {
        lo = q[i];
        hi = q[i];
        for (label k = pointEdgeStart[i]; k < pointEdgeStart[i + 1]; ++k)
        {
            const label e = pointEdges[k];
            const fluxState& qj = q[es[e] + ee[e] - i];
            fluxStateMinEqOp()(lo, qj);
            fluxStateMaxEqOp()(hi, qj);
        }
    };

    // Points on processor boundaries have neighbours on other processors:
    // complete their extrema first (only these points are exchanged)
    const labelList* shared = nullptr;
    if (parallel)
    {
        shared = &dual.mesh().globalData().coupledPatch().meshPoints();
        if (sharedIndex_.size() != nPts)
        {
            sharedIndex_.setSize(nPts);
            sharedIndex_ = -1;
            forAll(*shared, s)
            {
                sharedIndex_[(*shared)[s]] = s;
            }
        }
        const label nShared = shared->size();
        sharedMin_.setSize(nShared);
        sharedMax_.setSize(nShared);
        sharedPhi_.setSize(nShared);
        forAll(*shared, s)
        {
            localBounds((*shared)[s], sharedMin_[s], sharedMax_[s]);
        }
        fluxState big; big = GREAT;
        fluxState small; small = -GREAT;
        syncTools::syncPointList
        (
            dual.mesh(), *shared, sharedMin_, fluxStateMinEqOp(), big
        );
        syncTools::syncPointList
        (
            dual.mesh(), *shared, sharedMax_, fluxStateMaxEqOp(), small
        );
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
        const label s = parallel ? sharedIndex_[i] : -1;
        if (only && !(*only)[i])
        {
            if (s >= 0)
            {
                sharedPhi_[s] = 1.0;
            }
            continue;
        }
        fluxStateGradient& g = G[i];
        const point& Xi = X[i];
        const fluxState& qi = q[i];
        fluxIncrement dHi, dLo;
        fluxState lo(qi), hi(qi);
        dHi = gradientScalar(0);
        dLo = gradientScalar(0);
        for (label k = pointEdgeStart[i]; k < pointEdgeStart[i + 1]; ++k)
        {
            const label e = pointEdges[k];
            const label j = es[e] + ee[e] - i;
            const vector halfdX(0.5*(X[j] - Xi));
            fluxIncrement d;
            gradientIncrements(g, halfdX, d);
            #pragma GCC unroll 1
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                dHi[c] = max(dHi[c], d[c]);
                dLo[c] = min(dLo[c], d[c]);
            }
            if (s < 0)
            {
                // (the extrema from the neighbour values on the way)
                fluxStateMinEqOp()(lo, q[j]);
                fluxStateMaxEqOp()(hi, q[j]);
            }
        }
        if (s >= 0)
        {
            lo = sharedMin_[s];
            hi = sharedMax_[s];
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
        if (s < 0)
        {
            scaleGradient(g, phi);
        }
        else
        {
            sharedPhi_[s] = phi;
        }
    }

    if (parallel)
    {
        // A shared point's Phi is the smallest over all its edges, on
        // every processor
        fluxState one; one = 1.0;
        syncTools::syncPointList
        (
            dual.mesh(), *shared, sharedPhi_, fluxStateMinEqOp(), one
        );
        forAll(*shared, s)
        {
            scaleGradient(G[(*shared)[s]], sharedPhi_[s]);
        }
    }
}


// ************************************************************************* //
