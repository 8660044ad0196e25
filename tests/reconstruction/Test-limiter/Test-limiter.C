/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    Test-limiter

Description
    Barth-Jespersen limiter on the case's (tet) mesh:
      - a linear field is reconstructed exactly to the edge midpoints and
        not limited (Phi = 1);
      - for a random field the limited midpoint values f_i + 1/2 Phi G dX
        stay within the neighbourhood extrema [fmin_i, fmax_i] (no new
        extrema) and Phi is in [0, 1].
    Exits non-zero if a check fails.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "Random.H"
#include "greenGauss.H"
#include "limiter.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const dualMesh dual(mesh);
    const pointField& X = mesh.points();
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const label nPts = mesh.nPoints();
    label nFailed = 0;

    autoPtr<limiter> bj(limiter::New("barthJespersen", dictionary()));
    List<fluxState> q(nPts), phi(nPts);
    List<fluxStateGradient> G(nPts);

    // Linear field
    {
        fluxState a;
        List<vector> b(nFluxComponents);
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            a[c] = 1 + c;
            b[c] = vector(0.3*c - 1, 2 - 0.1*c, 0.5);
        }
        forAll(q, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                q[i][c] = a[c] + (b[c] & X[i]);
            }
        }
        greenGaussGradient(dual, q, G);
        bj->limit(dual, q, G, phi);

        scalar minPhi = 1, maxErr = 0;
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            const vector halfdX(0.5*(X[j] - X[i]));
            const point mid(0.5*(X[i] + X[j]));
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                minPhi = min(minPhi, min(phi[i][c], phi[j][c]));
                const scalar exact = a[c] + (b[c] & mid);
                const scalar fL = q[i][c] + phi[i][c]*(G[i][c] & halfdX);
                const scalar fR = q[j][c] - phi[j][c]*(G[j][c] & halfdX);
                maxErr = max(maxErr, max(mag(fL - exact), mag(fR - exact)));
            }
        }
        const bool ok = (minPhi > 1 - 1e-10) && (maxErr < 1e-10);
        Info<< (ok ? "PASS" : "FAIL") << " linear field: smallest Phi "
            << minPhi << ", largest midpoint error " << maxErr << endl;
        nFailed += !ok;
    }

    // Random field: no new extrema
    {
        Random rnd(7);
        forAll(q, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                q[i][c] = rnd.sample01<scalar>();
            }
        }
        greenGaussGradient(dual, q, G);
        bj->limit(dual, q, G, phi);

        List<fluxState> qMin(q), qMax(q);
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                qMin[i][c] = min(qMin[i][c], q[j][c]);
                qMax[i][c] = max(qMax[i][c], q[j][c]);
                qMin[j][c] = min(qMin[j][c], q[i][c]);
                qMax[j][c] = max(qMax[j][c], q[i][c]);
            }
        }
        scalar overshoot = 0, phiMin = 1, phiMax = 0, limited = 0, total = 0;
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            const vector halfdX(0.5*(X[j] - X[i]));
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                const scalar fL = q[i][c] + phi[i][c]*(G[i][c] & halfdX);
                const scalar fR = q[j][c] - phi[j][c]*(G[j][c] & halfdX);
                overshoot = max(overshoot, fL - qMax[i][c]);
                overshoot = max(overshoot, qMin[i][c] - fL);
                overshoot = max(overshoot, fR - qMax[j][c]);
                overshoot = max(overshoot, qMin[j][c] - fR);
            }
        }
        forAll(phi, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                phiMin = min(phiMin, phi[i][c]);
                phiMax = max(phiMax, phi[i][c]);
                limited += (phi[i][c] < 1);
                total += 1;
            }
        }
        const bool ok = overshoot < 1e-12 && phiMin >= 0 && phiMax <= 1;
        Info<< (ok ? "PASS" : "FAIL") << " random field: largest overshoot "
            << overshoot << ", Phi in [" << phiMin << ", " << phiMax
            << "], " << 100*limited/total << " % of values limited" << endl;
        nFailed += !ok;
    }

    Info<< nl << (nFailed ? "FAILED" : "All checks passed") << endl;
    return nFailed ? 1 : 0;
}


// ************************************************************************* //
