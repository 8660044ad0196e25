/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "greenGauss.H"
#include "stageResidual.H"

namespace
{

// One edge's Green-Gauss terms: both ends gain (q_j - q_i) C/2, the
// difference form of (q_i + q_j) C/2, equal to it because each dual cell is
// closed (its edge and boundary areas sum to zero).  Its terms are of the
// size of the gradient times the cell, not of the values'.  (Gi and Gj
// never alias)
inline void __attribute__((always_inline)) addEdgeGradient
(
    const Foam::scalar* __restrict__ qi,
    const Foam::scalar* __restrict__ qj,
    const Foam::vector& C,
    Foam::gradientScalar* __restrict__ Gi,
    Foam::gradientScalar* __restrict__ Gj
)
{
    using namespace Foam;
    const gradientScalar Cx = C.x(), Cy = C.y(), Cz = C.z();
    const direction n = nFluxComponents;
    for (direction c = 0; c < n; ++c)
    {
        const gradientScalar f = qj[c] - qi[c];
        const gradientScalar fx = f*Cx, fy = f*Cy, fz = f*Cz;
        Gi[c] += fx;
        Gi[n + c] += fy;
        Gi[2*n + c] += fz;
        Gj[c] += fx;
        Gj[n + c] += fy;
        Gj[2*n + c] += fz;
    }
}

// Sub-face s of a physical patch in the difference form (f_g - f_i) C_g,
// f_g = f_i + w (f_prev + f_next - 2 f_i) (dualMesh.H)
inline void addSubFaceGradient
(
    const Foam::dualMesh::patchSubFaces& sf,
    const Foam::label s,
    const Foam::UList<Foam::fluxState>& q,
    Foam::fluxStateGradient& Gi
)
{
    using namespace Foam;
    const scalar w = sf.nbrWeight[s];
    const fluxState& qi = q[sf.point[s]];
    const fluxState& qp = q[sf.prev[s]];
    const fluxState& qn = q[sf.next[s]];
    for (direction c = 0; c < nFluxComponents; ++c)
    {
        addGradient(Gi, c, (w*(qp[c] + qn[c] - 2*qi[c]))*sf.area[s]);
    }
}

// The boundary's a_B of one boundary point along its patch normals (the
// point's boundary normals bn), from one of its sub-faces s with the
// stage's Riemann state (tB, vB) there (greenGauss.H)
inline void addBoundaryJump
(
    const Foam::dualMesh::patchSubFaces& sf,
    const Foam::label s,
    const Foam::UList<Foam::fluxState>& q,
    const Foam::vector& tB,
    const Foam::vector& vB,
    const Foam::scalar Zp,
    const Foam::scalar Zs,
    const Foam::FixedList<Foam::vector, 3>& bn,
    Foam::FixedList<Foam::vector, 3>& aB
)
{
    using namespace Foam;
    const label i = sf.point[s];
    const scalar w = sf.nbrWeight[s];
    const fluxState& qi = q[i];
    const fluxState& qp = q[sf.prev[s]];
    const fluxState& qn = q[sf.next[s]];
    fluxState qg;
    for (direction c = 0; c < 12; ++c)
    {
        qg[c] = qi[c] + w*(qp[c] + qn[c] - 2*qi[c]);
    }

    // The sub-face's normal among the point's patch normals
    const vector& A = sf.area[s];
    label k = 0;
    for (label m = 1; m < 3; ++m)
    {
        if (mag(bn[m] & A) > mag(bn[k] & A))
        {
            k = m;
        }
    }
    const vector& N = bn[k];

    // Jumps to the Riemann state of the sub-face
    const vector dt
    (
        tB
      - vector
        (
            qg[3]*N.x() + qg[4]*N.y() + qg[5]*N.z(),
            qg[6]*N.x() + qg[7]*N.y() + qg[8]*N.z(),
            qg[9]*N.x() + qg[10]*N.y() + qg[11]*N.z()
        )
    );
    const vector dv(vB - vector(qg[0], qg[1], qg[2]));
    const scalar dvN = dv & N;
    aB[k] += (dt + Zp*dvN*N + Zs*(dv - dvN*N))*(A & N);
}


// The slopes of the incoming waves of one boundary point from its a_B
// (greenGauss.H): along N, with t = P N and Z = Zp N N + Zs (I - N N), the
// waves leaving through the face carry t - Z v, the ones the face sends in
// t + Z v; the second's derivative aIn = d_N t + Z d_N v becomes the
// boundary's a_B = sum_g (dt + Z dv) C_g.N, and the change (a_B - aIn)/2
// goes to d_N t and Z^-1 (a_B - aIn)/2 to d_N v, which leaves the outgoing
// d_N t - Z d_N v as it was.  Gi: the Green-Gauss sums (not yet divided by
// the volume; linear in them and in a_B, so that processors' partial sums
// add up to the map of the whole)
inline void applyIncomingSlopes
(
    const Foam::FixedList<Foam::vector, 3>& bn,
    const Foam::FixedList<Foam::vector, 3>& aB,
    const Foam::scalar Zp,
    const Foam::scalar Zs,
    Foam::fluxStateGradient& Gi
)
{
    using namespace Foam;
    for (label k = 0; k < 3; ++k)
    {
        const vector& N = bn[k];
        if (magSqr(N) < 0.5)
        {
            break;
        }

        // Derivatives along N of v and of t = P N
        const vector dv
        (
            gradientOf(Gi, 0) & N,
            gradientOf(Gi, 1) & N,
            gradientOf(Gi, 2) & N
        );
        vector dt(Zero);
        for (direction a = 0; a < 3; ++a)
        {
            for (direction c = 0; c < 3; ++c)
            {
                dt[a] += (gradientOf(Gi, 3 + 3*a + c) & N)*N[c];
            }
        }
        const scalar dvN = dv & N;
        const vector aIn(dt + Zp*dvN*N + Zs*(dv - dvN*N));
        const vector half(0.5*(aB[k] - aIn));

        // d_N t += half (as P += half N along N), d_N v += Z^-1 half
        // (no tangential waves without a shear impedance)
        const scalar halfN = half & N;
        const vector halfT(half - halfN*N);
        const vector dvIncrement
        (
            (halfN/Zp)*N + (Zs > VSMALL ? halfT/Zs : vector::zero)
        );
        const vector dtIncrement(Zs > VSMALL ? half : halfN*N);
        for (direction a = 0; a < 3; ++a)
        {
            addGradient(Gi, a, dvIncrement[a]*N);
            for (direction c = 0; c < 3; ++c)
            {
                addGradient(Gi, 3 + 3*a + c, (dtIncrement[a]*N[c])*N);
            }
        }
    }
}


// The Green-Gauss sums of the boundary points with the slope of the
// incoming waves along each patch normal N from the boundary
void boundarySlopes
(
    const Foam::dualMesh& dual,
    const Foam::UList<Foam::fluxState>& q,
    const Foam::stageResidual& R,
    const Foam::scalar Zp,
    const Foam::scalar Zs,
    Foam::List<Foam::fluxStateGradient>& G,
    const Foam::UList<bool>* mask
)
{
    using namespace Foam;
    const polyBoundaryMesh& patches = dual.mesh().boundaryMesh();
    const labelList& bp = dual.boundaryPoints();
    const List<FixedList<vector, 3>>& bn = dual.boundaryNormals();
    const labelList& index = dual.boundaryIndex();

    // The boundary's a_B per boundary point and normal
    FixedList<vector, 3> none;
    none = Zero;
    List<FixedList<vector, 3>> aB(bp.size(), none);
    forAll(patches, patchi)
    {
        if (!R.boundarySet[patchi])
        {
            continue;
        }
        const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
        const List<vector>& tB = R.boundaryTraction[patchi];
        const List<vector>& vB = R.boundaryVelocity[patchi];
        forAll(sf.point, s)
        {
            const label i = sf.point[s];
            if (mask && !(*mask)[i])
            {
                continue;
            }
            const label b = index[i];
            addBoundaryJump(sf, s, q, tB[s], vB[s], Zp, Zs, bn[b], aB[b]);
        }
    }

    // (every boundary point, also on a processor without its sub-faces:
    // the map is linear in the partial sums, so the processors' parts add
    // up to the map of the whole)
    forAll(bp, b)
    {
        if (mask && !(*mask)[bp[b]])
        {
            continue;
        }
        applyIncomingSlopes(bn[b], aB[b], Zp, Zs, G[bp[b]]);
    }
}

} // End anonymous namespace


// One pass over the edges: the Green-Gauss sums
void Foam::greenGaussGradient
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G,
    const stageResidual* R,
    const scalar Zp,
    const scalar Zs,
    const UList<bool>* mask
)
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const vectorField& Ne = dual.edgeNormals();
    const scalarField& Ae = dual.edgeMagSf();
    const scalarField& V = dual.volumes();
    const polyBoundaryMesh& patches = dual.mesh().boundaryMesh();

    fluxStateGradient zero;
    zero = 0.0;
    G = zero;

    const label nEdges = es.size();
    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        if (e + edgePrefetchDistance < nEdges)
        {
            const label jAhead = ee[e + edgePrefetchDistance];
            prefetchObject(q[jAhead]);
            prefetchObject<1>(G[jAhead]);
        }
        // (i != j: the two gradients never alias)
        addEdgeGradient
        (
            q[i].cdata(), q[j].cdata(), 0.5*Ae[e]*Ne[e],
            G[i].data(), G[j].data()
        );
    }

    // Physical patches (coupled patches have no sub-faces), in the same
    // difference form: (f_g - f_i) C_g
    forAll(patches, patchi)
    {
        const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
        forAll(sf.point, s)
        {
            const label i = sf.point[s];
            addSubFaceGradient(sf, s, q, G[i]);
        }
    }

    // Boundary points with the stage's boundary states: along each patch
    // normal, the slope of the wave the boundary sends in from the jump to
    // the Riemann state, the others from the interior (all linear in G and
    // the jumps: before the processor sums)
    if (R)
    {
        boundarySlopes(dual, q, *R, Zp, Zs, G, mask);
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
        for (gradientScalar& g : G[i])
        {
            g *= invV;
        }
    }
}


void Foam::greenGaussGradient
(
    const dualMesh& dual,
    const UList<fluxState>& q,
    List<fluxStateGradient>& G,
    const labelUList& points,
    const labelUList& edges,
    const UList<bool>& listed,
    const labelUList& pointSubFaceStart,
    const labelUList& subFacePatch,
    const labelUList& subFace,
    const stageResidual* R,
    const scalar Zp,
    const scalar Zs,
    const UList<bool>* riemannPoints
)
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const vectorField& Ne = dual.edgeNormals();
    const scalarField& Ae = dual.edgeMagSf();
    const scalarField& V = dual.volumes();

    for (const label i : points)
    {
        for (gradientScalar& g : G[i])
        {
            g = 0;
        }
    }

    // The full pass's edge loop over the listed edges: each end that is
    // listed gains (q_j - q_i) C/2 (an edge between two listed points is
    // formed once for both).  An end that is not listed sums into a
    // scratch gradient, which keeps the component loop free of branches;
    // an edge with no listed end is skipped
    fluxStateGradient scratch;
    scratch = 0.0;
    const label nEdges = edges.size();
    for (label k = 0; k < nEdges; ++k)
    {
        const label e = edges[k];
        const label i = es[e], j = ee[e];
        if (!listed[i] && !listed[j])
        {
            continue;
        }
        if (k + edgePrefetchDistance < nEdges)
        {
            const label jAhead = ee[edges[k + edgePrefetchDistance]];
            prefetchObject(q[jAhead]);
            prefetchObject<1>(G[jAhead]);
        }
        // (i != j and one end at least listed: the two never alias)
        addEdgeGradient
        (
            q[i].cdata(), q[j].cdata(), 0.5*Ae[e]*Ne[e],
            listed[i] ? G[i].data() : scratch.data(),
            listed[j] ? G[j].data() : scratch.data()
        );
    }

    for (const label i : points)
    {
        for (label m = pointSubFaceStart[i]; m < pointSubFaceStart[i + 1]; ++m)
        {
            const dualMesh::patchSubFaces& sf = dual.subFaces(subFacePatch[m]);
            const label s = subFace[m];
            addSubFaceGradient(sf, s, q, G[i]);
        }
    }

    // Boundary points with the stage's boundary states of their own
    // sub-faces (the full pass's boundarySlopes, point by point; every
    // listed boundary point, also on a processor without its sub-faces)
    if (R)
    {
        const List<FixedList<vector, 3>>& bn = dual.boundaryNormals();
        const labelList& index = dual.boundaryIndex();
        for (const label i : points)
        {
            const label b = index[i];
            if (b < 0 || (riemannPoints && !(*riemannPoints)[i]))
            {
                continue;
            }
            FixedList<vector, 3> aB;
            aB = Zero;
            for
            (
                label m = pointSubFaceStart[i];
                m < pointSubFaceStart[i + 1];
                ++m
            )
            {
                const label patchi = subFacePatch[m];
                if (!R->boundarySet[patchi])
                {
                    continue;
                }
                const label s = subFace[m];
                addBoundaryJump
                (
                    dual.subFaces(patchi), s, q,
                    R->boundaryTraction[patchi][s],
                    R->boundaryVelocity[patchi][s],
                    Zp, Zs, bn[b], aB
                );
            }
            applyIncomingSlopes(bn[b], aB, Zp, Zs, G[i]);
        }
    }

    for (const label i : points)
    {
        const scalar invV = 1.0/V[i];
        for (gradientScalar& g : G[i])
        {
            g *= invV;
        }
    }
}


void Foam::pointSubFaceRows
(
    const dualMesh& dual,
    labelList& pointSubFaceStart,
    labelList& subFacePatch,
    labelList& subFace
)
{
    const label n = dual.volumes().size();
    const label nPatches = dual.mesh().boundaryMesh().size();
    pointSubFaceStart.setSize(n + 1);
    pointSubFaceStart = 0;
    for (label patchi = 0; patchi < nPatches; ++patchi)
    {
        for (const label i : dual.subFaces(patchi).point)
        {
            ++pointSubFaceStart[i + 1];
        }
    }
    for (label i = 0; i < n; ++i)
    {
        pointSubFaceStart[i + 1] += pointSubFaceStart[i];
    }
    subFacePatch.setSize(pointSubFaceStart[n]);
    subFace.setSize(pointSubFaceStart[n]);
    labelList next(SubList<label>(pointSubFaceStart, n));
    for (label patchi = 0; patchi < nPatches; ++patchi)
    {
        const labelList& point = dual.subFaces(patchi).point;
        forAll(point, s)
        {
            const label m = next[point[s]]++;
            subFacePatch[m] = patchi;
            subFace[m] = s;
        }
    }
}


// ************************************************************************* //
