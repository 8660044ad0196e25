/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "shockFlattening.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::shockFlattening::pointCoefficients
(
    const dualMesh& dual,
    const UList<point>& X,
    const UList<vector>& u,
    const UList<scalar>& J,
    const UList<fluxState>& q,
    List<scalar>& chi
)
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    chi.setSize(q.size());
    chi = 0;
    const scalar rampRate = 1/(fullRatio - onsetRatio);
    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        const vector dv(fluxVelocity(q[j]) - fluxVelocity(q[i]));
        const vector dx(X[j] + u[j] - X[i] - u[i]);
        if ((dv & dx) >= 0)
        {
            continue;
        }
        const scalar r = 1 - min(J[i], J[j])/max(J[i], J[j]);
        const scalar c = min(scalar(1), max(scalar(0), (r - onsetRatio)*rampRate));
        chi[i] = max(chi[i], c);
        chi[j] = max(chi[j], c);
    }
}


// ************************************************************************* //
