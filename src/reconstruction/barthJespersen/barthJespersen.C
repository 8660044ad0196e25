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


namespace
{

// Limit one end: lower phi so that fi + phi d stays within [fmin, fmax],
// d the unlimited increment towards the edge midpoint.  Increments below
// 'noise' (a tiny fraction of the body-wide magnitude of the quantity) are
// not limited: for components that are zero up to round-off (transverse
// velocity of a 1D wave, say) the ratio would be noise over noise and the
// limited scheme would amplify round-off.  The division is done only when
// it lowers phi.
inline void bjLimit
(
    const Foam::scalar d,
    const Foam::scalar fi,
    const Foam::scalar fmin,
    const Foam::scalar fmax,
    const Foam::scalar noise,
    Foam::scalar& phi
)
{
    if (d > noise)
    {
        const Foam::scalar room = fmax - fi;
        if (phi*d > room)
        {
            phi = room/d;
        }
    }
    else if (d < -noise)
    {
        const Foam::scalar room = fmin - fi;
        if (phi*d < room)
        {
            phi = room/d;
        }
    }
}

} // End anonymous namespace


void Foam::limiters::barthJespersen::limit
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    const UList<fluxStateGradient>& G,
    List<fluxState>& phi
) const
{
    // Neighbourhood extrema (the point itself included)
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    qMin_ = q;
    qMax_ = q;
    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        fluxStateMinEqOp()(qMin_[i], q[j]);
        fluxStateMaxEqOp()(qMax_[i], q[j]);
        fluxStateMinEqOp()(qMin_[j], q[i]);
        fluxStateMaxEqOp()(qMax_[j], q[i]);
    }
    limit(dual, q, G, qMin_, qMax_, phi);
}


void Foam::limiters::barthJespersen::limit
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    const UList<fluxStateGradient>& G,
    List<fluxState>& qMin,
    List<fluxState>& qMax,
    List<fluxState>& phi
) const
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const pointField& X = dual.mesh().points();
    const label nPts = q.size();

    if (Pstream::parRun())
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
    }

    // Body-wide magnitudes: velocity components share one, stress
    // components (P and Sigma_J) another
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

    for (label i = 0; i < nPts; ++i)
    {
        phi[i] = 1.0;
    }

    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        const vector halfdX(0.5*(X[j] - X[i]));
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            bjLimit
            (
                G[i][c] & halfdX, q[i][c], qMin[i][c], qMax[i][c],
                noise[c], phi[i][c]
            );
            bjLimit
            (
                -(G[j][c] & halfdX), q[j][c], qMin[j][c], qMax[j][c],
                noise[c], phi[j][c]
            );
        }
    }
    if (Pstream::parRun())
    {
        fluxState one; one = 1.0;
        syncTools::syncPointList
        (
            dual.mesh(), phi, fluxStateMinEqOp(), one
        );
    }
}


// ************************************************************************* //
