/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    Test-limiter

Description
    Limiters on the case's (tet) mesh:
      - vanAlbada, superbee and monotonizedCentral: their increments,
        written without branches (branchFree.H), equal the textbook forms
        bit for bit on pairs of every sign and magnitude, zeros included;
      - barthJespersen, vanAlbada, monotonizedCentral and superbee
        reconstruct a linear field
        exactly to the edge midpoints (Barth-Jespersen: Phi = 1);
      - barthJespersen, random field: the limited midpoint values
        f_i + 1/2 Phi G dX stay within the neighbourhood extrema
        [fmin_i, fmax_i] (no new extrema) and Phi is in [0, 1];
      - vanAlbada and superbee, random field: both midpoint states of every
        edge lie between f_i and f_j, and superbee's increments are never
        smaller than van Albada's (it is the upper edge of the TVD region),
        and larger on a good part of the edges; monotonizedCentral's lie
        between the two (and its states between f_i and f_j);
      - simpleWaveSuperbee: superbee's midpoint states on every edge
        across one simple wave (every component the same profile along a
        direction), van Albada's on a good part of the edges where a second
        wave crosses it, and no other states;
      - vanAlbada on a field with a smooth maximum (a paraboloid): only
        edges near the maximum are limited, by less than the
        Barth-Jespersen limiter;
      - shockFlattening: across a closing jump of J from 1 to 1/2 (a strong
        shock) every point of a crossing edge takes the coefficient 1 and
        every other point 0; the same jump opening, and a gentle
        compression (J changing by less than onsetRatio along any edge),
        0 everywhere; a steeper compression the ramp's value of its
        steepest closing edge; flatten moves the midpoint states by the
        coefficient towards the points' own.
    Exits non-zero if a check fails.

    With -dump <file>: the Barth-Jespersen limited gradients of a field that
    is random but a function of the point positions only (so that serial
    and decomposed runs limit the same field), one line per point
    "X Y Z g_0 .. g_38" into <file> (with -parallel <file>.<processor>),
    for the serial/parallel comparison (tests/reconstruction/run parallel).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "Random.H"
#include "greenGauss.H"
#include "limiter.H"
#include "vanAlbada.H"
#include "superbee.H"
#include "monotonizedCentral.H"
#include "shockFlattening.H"
#include "OFstream.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addOption("dump", "file", "write the limited gradients");
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const dualMesh dual(mesh);

    if (args.found("dump"))
    {
        autoPtr<limiter> bj(limiter::New("barthJespersen", dictionary()));
        const pointField& X = mesh.points();
        List<fluxState> q(X.size());
        List<fluxStateGradient> G(X.size());
        forAll(q, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                // A hash of the position (values in [0, 1))
                const scalar h =
                    Foam::sin
                    (
                        12.9898*X[i].x() + 78.233*X[i].y()
                      + 37.719*X[i].z() + 1.7*c
                    )*43758.5453;
                q[i][c] = h - std::floor(h);
            }
        }
        greenGaussGradient(dual, q, G);
        bj->limit(dual, q, G);

        fileName file(args.get<fileName>("dump"));
        if (Pstream::parRun())
        {
            file += "." + Foam::name(Pstream::myProcNo());
        }
        OFstream os(file);
        os.precision(17);
        forAll(G, i)
        {
            os  << X[i].x() << ' ' << X[i].y() << ' ' << X[i].z();
            for (const scalar g : G[i])
            {
                os  << ' ' << g;
            }
            os  << nl;
        }
        Info<< "Wrote the limited gradients of " << X.size()
            << " points to " << file << endl;
        return 0;
    }

    const pointField& X = mesh.points();
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const label nPts = mesh.nPoints();
    label nFailed = 0;

    // The gradients are stored in single precision (fluxState.H): the
    // reconstructed increments carry a few float epsilons of their size
    const scalar floatTol = 64*std::numeric_limits<float>::epsilon();

    // The edge limiters' increments, written without branches so that
    // their loops vectorise (branchFree.H), against their textbook forms:
    // equal bit for bit (up to the sign of a zero) on pairs (a, b) of every
    // sign, zeros of both signs, equal and opposite values, tiny and large
    // magnitudes
    {
        auto textbookVA = [](const scalar a, const scalar b) -> scalar
        {
            return a*b > 0 ? a*b*(a + b)/(a*a + b*b) : 0;
        };
        auto textbookSB = [](const scalar a, const scalar b) -> scalar
        {
            if (!(a*b > 0)) return 0;
            const scalar s =
                max(min(2*mag(a), mag(b)), min(mag(a), 2*mag(b)));
            return b > 0 ? s : -s;
        };
        auto textbookMC = [](const scalar a, const scalar b) -> scalar
        {
            if (!(a*b > 0)) return 0;
            const scalar s = min(2*min(mag(a), mag(b)), 0.5*mag(a + b));
            return b > 0 ? s : -s;
        };
        DynamicList<scalar> values
        ({
            0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 0.5, 3.0, -0.25, 1e-300, -1e-300,
            1e-150, 1e30, -1e30, 7.3e-12, -4.1e8
        });
        Random rnd(7);
        for (label k = 0; k < 400; ++k)
        {
            const scalar m = std::pow(10.0, rnd.position<scalar>(-20, 20));
            values.append(m*(rnd.sample01<scalar>() - 0.5));
        }
        label nPairs = 0, nDiffer = 0;
        for (const scalar a : values)
        {
            for (const scalar b : values)
            {
                const scalar got[3] =
                {
                    limiters::vanAlbadaIncrement(a, b),
                    limiters::superbee::limited(a, b),
                    limiters::monotonizedCentral::limited(a, b)
                };
                const scalar want[3] =
                {
                    textbookVA(a, b), textbookSB(a, b), textbookMC(a, b)
                };
                for (label l = 0; l < 3; ++l)
                {
                    // (== takes -0 and +0 as equal)
                    if (!(got[l] == want[l]) && nDiffer < 20)
                    {
                        Info<< "  limiter " << l << " a " << a << " b " << b
                            << ": " << got[l] << " against " << want[l]
                            << endl;
                    }
                    nDiffer += !(got[l] == want[l]);
                }
                ++nPairs;
            }
        }
        const bool ok = nDiffer == 0;
        Info<< (ok ? "PASS" : "FAIL") << " vanAlbada, superbee and "
            << "monotonizedCentral increments without branches equal their "
            << "textbook forms on " << nPairs << " pairs: " << nDiffer
            << " differ" << endl;
        nFailed += !ok;
    }

    autoPtr<limiter> bj(limiter::New("barthJespersen", dictionary()));
    List<fluxState> q(nPts), phi(nPts);
    List<fluxStateGradient> G(nPts);

    // Phi of a point limiter, recovered from the limited gradients Gl and
    // the unlimited ones Gu (limit() scales each component gradient by its
    // Phi in place); returns the largest departure of Gl from Phi Gu
    auto recoverPhi =
    [&phi]
    (
        const List<fluxStateGradient>& Gl,
        const List<fluxStateGradient>& Gu
    )
    {
        scalar misfit = 0;
        forAll(Gu, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                const vector gu(gradientOf(Gu[i], c));
                const vector gl(gradientOf(Gl[i], c));
                const scalar g2 = magSqr(gu);
                phi[i][c] = g2 > 0 ? (gl & gu)/g2 : 1.0;
                misfit = max
                (
                    misfit,
                    mag(gl - phi[i][c]*gu)/(mag(gu) + VSMALL)
                );
            }
        }
        return misfit;
    };

    // Uniform random values in [0, 1] for every point and component
    auto randomField = [&q](const label seed)
    {
        Random rnd(seed);
        forAll(q, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                q[i][c] = rnd.sample01<scalar>();
            }
        }
    };

    // Linear field: exact midpoint states with both limiters
    for
    (
        const word type
      : {
            "barthJespersen", "vanAlbada", "monotonizedCentral", "superbee",
            "simpleWaveSuperbee"
        }
    )
    {
        autoPtr<limiter> lim(limiter::New(type, dictionary()));
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
        lim->limit(dual, q, G);

        scalar maxErr = 0, maxJump = 0;
        fluxState qL, qR;
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            const point mid(0.5*(X[i] + X[j]));
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                maxJump = max(maxJump, mag(q[j][c] - q[i][c]));
            }
            lim->midpointStates
            (
                q[i], q[j], G[i], G[j], 0.5*(X[j] - X[i]), qL, qR
            );
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                const scalar exact = a[c] + (b[c] & mid);
                maxErr =
                    max(maxErr, max(mag(qL[c] - exact), mag(qR[c] - exact)));
            }
        }
        const bool ok = maxErr < floatTol*maxJump;
        Info<< (ok ? "PASS" : "FAIL") << " " << type
            << ", linear field: largest midpoint error " << maxErr
            << " (tolerance " << floatTol*maxJump << ")" << endl;
        nFailed += !ok;
    }

    // Random field: no new extrema
    {
        randomField(7);
        greenGaussGradient(dual, q, G);
        const List<fluxStateGradient> Gu(G);
        bj->limit(dual, q, G);
        const scalar misfit = recoverPhi(G, Gu);

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
                const scalar fL = q[i][c] + (gradientOf(G[i], c) & halfdX);
                const scalar fR = q[j][c] - (gradientOf(G[j], c) & halfdX);
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
        const bool ok =
            overshoot < floatTol && phiMin >= -floatTol
         && phiMax <= 1 + floatTol
         && misfit < floatTol && limited > 0.1*total;
        Info<< (ok ? "PASS" : "FAIL") << " random field: largest overshoot "
            << overshoot << ", Phi in [" << phiMin << ", " << phiMax
            << "], " << 100*limited/total << " % of values limited, "
            << "limited gradient = Phi x gradient to " << misfit << endl;
        nFailed += !ok;

    }

    // van Albada and superbee, random field: midpoint states between the
    // end values; superbee's increments at least van Albada's
    autoPtr<limiter> va(limiter::New("vanAlbada", dictionary()));
    autoPtr<limiter> sb(limiter::New("superbee", dictionary()));
    autoPtr<limiter> mc(limiter::New("monotonizedCentral", dictionary()));
    {
        randomField(11);
        greenGaussGradient(dual, q, G);
        va->limit(dual, q, G);
        sb->limit(dual, q, G);

        scalar outsideVA = 0, outsideSB = 0, belowVA = 0;
        scalar firstOrder = 0, steeper = 0, total = 0;
        scalar outsideMC = 0, mcOutsideVASB = 0;
        fluxState qL, qR, qLs, qRs, qLm, qRm;
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            const vector halfdX(0.5*(X[j] - X[i]));
            va->midpointStates
            (
                q[i], q[j], G[i], G[j], halfdX, qL, qR
            );
            sb->midpointStates
            (
                q[i], q[j], G[i], G[j], halfdX, qLs, qRs
            );
            mc->midpointStates
            (
                q[i], q[j], G[i], G[j], halfdX, qLm, qRm
            );
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                const scalar lo = min(q[i][c], q[j][c]);
                const scalar hi = max(q[i][c], q[j][c]);
                outsideVA = max(outsideVA, max(qL[c] - hi, lo - qL[c]));
                outsideVA = max(outsideVA, max(qR[c] - hi, lo - qR[c]));
                outsideSB = max(outsideSB, max(qLs[c] - hi, lo - qLs[c]));
                outsideSB = max(outsideSB, max(qRs[c] - hi, lo - qRs[c]));
                // (increments towards the other end: |qL - f_i|)
                const scalar dVA = mag(qL[c] - q[i][c]);
                const scalar dSB = mag(qLs[c] - q[i][c]);
                belowVA = max(belowVA, dVA - dSB);
                outsideMC = max(outsideMC, max(qLm[c] - hi, lo - qLm[c]));
                outsideMC = max(outsideMC, max(qRm[c] - hi, lo - qRm[c]));
                const scalar dMC = mag(qLm[c] - q[i][c]);
                mcOutsideVASB =
                    max(mcOutsideVASB, max(dVA - dMC, dMC - dSB));
                steeper += (dSB > dVA*(1 + 1e-12));
                firstOrder += (qL[c] == q[i][c]) + (qR[c] == q[j][c]);
                total += 2;
            }
        }
        bool ok = outsideVA < 1e-12;
        Info<< (ok ? "PASS" : "FAIL") << " vanAlbada, random field: largest "
            << "midpoint state outside [f_i, f_j] " << outsideVA << ", "
            << 100*firstOrder/total << " % of edge states first order"
            << endl;
        nFailed += !ok;
        ok = outsideSB < 1e-12 && belowVA < 1e-12 && steeper > 0.1*total;
        Info<< (ok ? "PASS" : "FAIL") << " superbee, random field: largest "
            << "midpoint state outside [f_i, f_j] " << outsideSB
            << ", largest increment below van Albada's " << belowVA << ", "
            << 200*steeper/total << " % of edge increments larger" << endl;
        nFailed += !ok;
        ok = outsideMC < 1e-12 && mcOutsideVASB < 1e-12;
        Info<< (ok ? "PASS" : "FAIL") << " monotonizedCentral, random field:"
            << " largest midpoint state outside [f_i, f_j] " << outsideMC
            << ", largest increment outside [van Albada's, superbee's] "
            << mcOutsideVASB << endl;
        nFailed += !ok;
    }

    // Smooth maximum (paraboloid f = -|X - X0|^2 about the box centre):
    // van Albada keeps second order, i.e. its midpoint states are about as
    // accurate as the unlimited ones and far better than the point values
    // (first order).  Edges along a level set (f_j - f_i ~ 0) may fall to
    // first order, but there the lost increment is itself ~ 0.
    // Barth-Jespersen, printed for comparison, clips only at the maximum.
    {
        const point X0(0.5*(max(X) + min(X)));
        forAll(q, i)
        {
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                q[i][c] = -magSqr(X[i] - X0);
            }
        }
        greenGaussGradient(dual, q, G);
        List<fluxStateGradient> Gb(G);
        bj->limit(dual, q, Gb);

        scalar errVA = 0, errBJ = 0, errNone = 0, errFirst = 0;
        fluxState qL, qR, qLb, qRb;
        forAll(es, e)
        {
            const label i = es[e], j = ee[e];
            const vector halfdX(0.5*(X[j] - X[i]));
            const scalar exact = -magSqr(0.5*(X[i] + X[j]) - X0);
            va->midpointStates  // per edge: unlimited gradients
            (
                q[i], q[j], G[i], G[j], halfdX, qL, qR
            );
            bj->midpointStates  // limited gradients
            (
                q[i], q[j], Gb[i], Gb[j], halfdX, qLb, qRb
            );
            errVA += mag(qL[0] - exact) + mag(qR[0] - exact);
            errBJ += mag(qLb[0] - exact) + mag(qRb[0] - exact);
            errNone +=
                mag(q[i][0] + (gradientOf(G[i], 0) & halfdX) - exact)
              + mag(q[j][0] - (gradientOf(G[j], 0) & halfdX) - exact);
            errFirst += mag(q[i][0] - exact) + mag(q[j][0] - exact);
        }
        const scalar n = 2*es.size();
        const bool ok = errVA < 1.5*errNone && errVA < 0.25*errFirst;
        Info<< (ok ? "PASS" : "FAIL") << " smooth maximum, mean midpoint "
            << "error: vanAlbada " << errVA/n << " (bounds: 1.5 x unlimited "
            << errNone/n << ", 0.25 x first order " << errFirst/n
            << "); Barth-Jespersen " << errBJ/n << endl;
        nFailed += !ok;
    }

    // simpleWaveSuperbee: across one simple wave (every component the same
    // profile along k1 times its own amplitude) every edge takes superbee's
    // states; where a second wave along k2 crosses it (other amplitudes),
    // a good part of the edges take van Albada's, and no edge anything else
    {
        autoPtr<limiter> sw(limiter::New("simpleWaveSuperbee", dictionary()));
        const point X0(0.5*(max(X) + min(X)));
        const scalar width = 0.1*mag(max(X) - min(X));
        const vector k1(vector(1, 0.3, 0.2)/mag(vector(1, 0.3, 0.2)));
        const vector k2(vector(-0.2, 1, 0.4)/mag(vector(-0.2, 1, 0.4)));
        Random rnd(7);
        fluxState A, B;
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            A[c] = 0.5 + rnd.sample01<scalar>();
            B[c] = (c % 2 ? 1 : -1)*(0.5 + rnd.sample01<scalar>());
        }
        for (const bool crossing : {false, true})
        {
            forAll(q, i)
            {
                const scalar s1 = ((X[i] - X0) & k1)/width;
                const scalar s2 = ((X[i] - X0) & k2)/width;
                for (direction c = 0; c < nFluxComponents; ++c)
                {
                    q[i][c] =
                        A[c]*Foam::tanh(s1)
                      + (crossing ? B[c]*Foam::tanh(s2) : 0);
                }
            }
            greenGaussGradient(dual, q, G);

            // Edges (sides) whose states are superbee's, van Albada's and
            // not superbee's, or neither's.  Equal up to the rounding of
            // the single-precision gradient increments (1e-4 of the edge's
            // jump; the two limiters' states differ by about |r - 1|/2 of
            // it): the same increment inlined into another limiter's loop
            // may be contracted into other multiply-adds by the compiler,
            // and G.dX cancels (a behaviour-preserving rewrite of
            // simpleWaveSuperbee's test moved 1,729 sides by 5e-10 against
            // a tolerance of 1e-12, one by 1.1e-5 of its jump)
            label likeSB = 0, onlyVA = 0, neither = 0;
            fluxState qL, qR, qLs, qRs, qLv, qRv;
            auto same = [](const fluxState& x, const fluxState& y,
                const fluxState& qa, const fluxState& qb)
            {
                for (direction c = 0; c < nFluxComponents; ++c)
                {
                    const scalar tol =
                        1e-4*mag(qb[c] - qa[c]) + 1e-12*(1 + mag(y[c]));
                    if (mag(x[c] - y[c]) > tol)
                    {
                        return false;
                    }
                }
                return true;
            };
            forAll(es, e)
            {
                const label i = es[e], j = ee[e];
                const vector halfdX(0.5*(X[j] - X[i]));
                sw->midpointStates(q[i], q[j], G[i], G[j], halfdX, qL, qR);
                sb->midpointStates(q[i], q[j], G[i], G[j], halfdX, qLs, qRs);
                va->midpointStates(q[i], q[j], G[i], G[j], halfdX, qLv, qRv);
                for (const bool left : {true, false})
                {
                    const fluxState& x = left ? qL : qR;
                    if (same(x, left ? qLs : qRs, q[i], q[j]))
                    {
                        ++likeSB;
                    }
                    else if (same(x, left ? qLv : qRv, q[i], q[j]))
                    {
                        ++onlyVA;
                    }
                    else
                    {
                        ++neither;
                    }
                }
            }
            const label n = 2*es.size();
            const bool ok =
                neither == 0
             && (crossing ? onlyVA > n/20 : onlyVA == 0);
            Info<< (ok ? "PASS" : "FAIL") << " simpleWaveSuperbee, "
                << (crossing ? "two crossing waves" : "one simple wave")
                << ": edge sides like superbee " << likeSB
                << ", like van Albada only " << onlyVA << ", neither "
                << neither << " (of " << n << ")" << endl;
            nFailed += !ok;
        }
    }

    // The listed form of the gradients (multirate stepping: a level's
    // points over its edge list, each edge formed once for its listed
    // ends) against the full pass, on a random field and a random third of
    // the points: the listed points' gradients equal (the same sums in the
    // same order: bit for bit, up to the compiler's contractions), the
    // others untouched
    {
        randomField(11);
        greenGaussGradient(dual, q, G);
        const List<fluxStateGradient> Gfull(G);

        Random rnd(5);
        boolList listed(nPts, false);
        DynamicList<label> points;
        for (label i = 0; i < nPts; ++i)
        {
            if (rnd.sample01<scalar>() < 1.0/3)
            {
                listed[i] = true;
                points.append(i);
            }
        }
        DynamicList<label> edges;
        forAll(es, e)
        {
            if (listed[es[e]] || listed[ee[e]])
            {
                edges.append(e);
            }
        }
        // Each point's boundary sub-faces (the rows multirateRungeKutta2
        // keeps)
        labelList start, subFacePatch, subFace;
        pointSubFaceRows(dual, start, subFacePatch, subFace);

        // (the edges with a listed end, and all edges: those without one
        // are skipped)
        labelList allEdges(identity(es.size()));
        for (const bool all : {false, true})
        {
            const labelUList& edgeList = all ? allEdges : edges;
            const gradientScalar sentinel = 12345;
            forAll(G, i)
            {
                G[i] = sentinel;
            }
            greenGaussGradient
            (
                dual, q, G, points, edgeList, listed,
                start, subFacePatch, subFace
            );
            scalar worst = 0, scale = 0;
            label nDiffer = 0, nTouched = 0, nBoundary = 0;
            forAll(G, i)
            {
                for (label k = 0; k < fluxStateGradient::size(); ++k)
                {
                    if (listed[i])
                    {
                        worst = max(worst, mag(scalar(G[i][k] - Gfull[i][k])));
                        scale = max(scale, mag(scalar(Gfull[i][k])));
                        nDiffer += (G[i][k] != Gfull[i][k]);
                    }
                    else
                    {
                        nTouched += (G[i][k] != sentinel);
                    }
                }
                nBoundary += listed[i] && start[i + 1] > start[i];
            }
            const bool ok =
                worst <= 4*std::numeric_limits<float>::epsilon()*scale
             && nTouched == 0 && points.size() > nPts/4 && nBoundary > 0;
            Info<< (ok ? "PASS" : "FAIL") << " listed gradients of "
                << points.size() << " of " << nPts << " points (" << nBoundary
                << " on the boundary) over " << edgeList.size() << " of "
                << es.size() << " edges: largest difference from the full "
                << "pass " << worst << " of " << scale << " (" << nDiffer
                << " components not bit for bit), " << nTouched
                << " components of other points changed" << endl;
            nFailed += !ok;
        }
    }

    // Shock flattening (shockFlattening.H)
    {
        const scalar xMin = min(X.component(vector::X));
        const scalar xMax = max(X.component(vector::X));
        const scalar x0 = 0.5*(xMin + xMax);
        const List<vector> u(nPts, Zero);
        List<fluxState> q(nPts);
        List<scalar> J(nPts), chi;

        // A closing (opening) jump at x0: the left side moves into (away
        // from) the right one, J from 1 to 1/2
        for (const scalar sense : {1.0, -1.0})
        {
            forAll(q, i)
            {
                q[i] = scalar(0);
                const bool left = X[i].x() < x0;
                q[i][0] = left ? sense : 0;
                J[i] = left ? 1 : 0.5;
            }
            shockFlattening::pointCoefficients(dual, X, u, J, q, chi);
            List<bool> crossing(nPts, false);
            forAll(es, e)
            {
                if ((X[es[e]].x() < x0) != (X[ee[e]].x() < x0))
                {
                    crossing[es[e]] = crossing[ee[e]] = true;
                }
            }
            label nWrong = 0, nCrossing = 0;
            forAll(chi, i)
            {
                const scalar expected = (sense > 0 && crossing[i]) ? 1 : 0;
                nWrong += (chi[i] != expected);
                nCrossing += crossing[i];
            }
            const bool ok = (nWrong == 0 && nCrossing > 0);
            Info<< (ok ? "PASS" : "FAIL") << " shock flattening across "
                << (sense > 0 ? "a closing" : "an opening") << " jump of J from 1 "
                << "to 1/2: " << nWrong << " of " << nPts << " points off "
                << (sense > 0 ? "1 on a crossing edge, 0 elsewhere" : "0")
                << " (" << nCrossing << " points on crossing edges)" << endl;
            nFailed += !ok;
        }

        // Compressions J = exp(-a (x - xMin)), the velocity closing along
        // x: the largest ratio over an edge, 1 - J_min/J_max, is 'rise'
        // (on the edge of the largest x extent); a point's coefficient is
        // the ramp's value at the largest ratio of its closing edges (the
        // edges across x, dx = 0, do not close)
        for (const scalar rise : {0.02, 0.6})
        {
            scalar dxMax = 0;
            forAll(es, e)
            {
                dxMax = max(dxMax, mag(X[ee[e]].x() - X[es[e]].x()));
            }
            const scalar a = -Foam::log(1 - rise)/dxMax;
            forAll(q, i)
            {
                q[i] = scalar(0);
                q[i][0] = -(X[i].x() - xMin);
                J[i] = Foam::exp(-a*(X[i].x() - xMin));
            }
            shockFlattening::pointCoefficients(dual, X, u, J, q, chi);
            List<scalar> expected(nPts, scalar(0));
            forAll(es, e)
            {
                const label i = es[e], j = ee[e];
                if ((X[j].x() - X[i].x())*(q[j][0] - q[i][0]) >= 0)
                {
                    continue;
                }
                const scalar r = 1 - min(J[i], J[j])/max(J[i], J[j]);
                const scalar c = min
                (
                    scalar(1),
                    max
                    (
                        scalar(0),
                        (r - shockFlattening::onsetRatio)
                       /(shockFlattening::fullRatio
                       - shockFlattening::onsetRatio)
                    )
                );
                expected[i] = max(expected[i], c);
                expected[j] = max(expected[j], c);
            }
            scalar worst = 0, largest = 0;
            forAll(chi, i)
            {
                worst = max(worst, mag(chi[i] - expected[i]));
                largest = max(largest, chi[i]);
            }
            const bool gentle = rise < shockFlattening::onsetRatio;
            const bool ok =
                worst < 1e-14 && (gentle ? largest == 0 : largest > 0);
            Info<< (ok ? "PASS" : "FAIL") << " shock flattening of a "
                << (gentle ? "gentle" : "steep") << " compression: largest "
                << "coefficient " << largest << ", largest difference from "
                << "the ramp of the steepest closing edge " << worst << endl;
            nFailed += !ok;
        }

        // flatten: chi 0 leaves the states, 1 gives the points' own, 1/2
        // the mean
        fluxState qi, qj, qL0, qR0;
        forAll(qi, c)
        {
            qi[c] = c;
            qj[c] = 2*c + 1;
            qL0[c] = 0.5*c + 3;
            qR0[c] = -c;
        }
        bool ok = true;
        for (const scalar c : {0.0, 0.5, 1.0})
        {
            fluxState qL(qL0), qR(qR0);
            shockFlattening::flatten(c, qi, qj, qL, qR);
            forAll(qL, k)
            {
                ok = ok
                 && mag(qL[k] - ((1 - c)*qL0[k] + c*qi[k])) < 1e-14
                 && mag(qR[k] - ((1 - c)*qR0[k] + c*qj[k])) < 1e-14;
            }
        }
        Info<< (ok ? "PASS" : "FAIL") << " shock flattening of the midpoint "
            << "states by 0, 1/2 and 1" << endl;
        nFailed += !ok;
    }

    Info<< nl << (nFailed ? "FAILED" : "All checks passed") << endl;
    // (OpenFOAM v1912 ends a run with status 0 when the argList is
    // destroyed after main returns, whatever main returned: leave here)
    Pstream::exit(nFailed ? 1 : 0);
    return 0;
}


// ************************************************************************* //
