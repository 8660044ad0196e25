/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "contactPair.H"
#include "acousticFormulas.H"
#include "ListListOps.H"
#include "uniformStateIO.H"
#include "checkedInput.H"
#include "timeDirectory.H"
#include "AMIPatchToPatchInterpolation.H"
#include "EdgeMap.H"
#include "clockTime.H"
#include "clockValue.H"
#include "globalIndex.H"
#include "indexedOctree.H"
#include "treeDataPoint.H"
#include "syncTools.H"

// * * * * * * * * * * * * * Local Helper Functions  * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The impact Mach number beyond which pairs of shear-free bodies on tets
// stop (A3 on 64 structured tets: Mach 2.5 runs, 3 stops at cfl 0.3 and
// 1.2; doc/results.md, "Why the struck faces of tets go uneven")
constexpr scalar shearFreeTetsMach = 2.75;

// Normal of a point pair, from A to B: the bisector of A's normal and minus
// B's.  Either normal alone makes the pair's Riemann problem lopsided where
// the surfaces curve (edges and corners of a contact area), and mirrored
// bodies then stop deforming as mirror images
inline vector pairNormal
(
    const contactPair::pointData& a,
    const contactPair::pointData& b
)
{
    const vector n(a.n - b.n);
    const scalar magN = mag(n);
    return magN > SMALL ? n/magN : a.n;
}

// Stand-in partner of a point without one (outside the other surface): its
// own state facing back, so that the pair normal is the point's own normal;
// such a point is always open (traction-free)
inline contactPair::pointData mirrored(const contactPair::pointData& a)
{
    contactPair::pointData b(a);
    b.n = -a.n;
    b.t = -a.t;
    return b;
}

// Lexicographic order of points (to merge processor copies of a point)
struct lexicographicLess
{
    const UList<point>& X;

    bool operator()(const label a, const label b) const
    {
        const point& p = X[a];
        const point& q = X[b];
        if (p.x() != q.x()) return p.x() < q.x();
        if (p.y() != q.y()) return p.y() < q.y();
        return p.z() < q.z();
    }
};

// Processor copies of gathered points (the same position): each point's
// unique point, numbered in lexicographic order of the positions, and each
// unique point's copies in increasing order
void mergeCopies
(
    const UList<point>& X,
    labelList& copyUnique,
    labelListList& uniqueCopies
)
{
    labelList order(identity(X.size()));
    std::sort(order.begin(), order.end(), lexicographicLess{X});
    copyUnique.setSize(X.size());
    label nUnique = 0;
    forAll(order, k)
    {
        if (k > 0 && X[order[k]] != X[order[k - 1]])
        {
            ++nUnique;
        }
        copyUnique[order[k]] = nUnique;
    }
    nUnique = X.empty() ? 0 : nUnique + 1;
    uniqueCopies.setSize(nUnique);
    for (labelList& copies : uniqueCopies)
    {
        copies.clear();
    }
    forAll(X, k)
    {
        uniqueCopies[copyUnique[k]].append(k);
    }
}


// Points binned by their position in the plane normal to a direction, in
// square cells of a given width (only occupied cells are stored)
class tangentialGrid
{
    vector t1_, t2_;
    scalar width_;
    HashTable<DynamicList<label>, labelPair, Hash<labelPair>> cells_;

    labelPair cell(const point& p) const
    {
        // (clamped to the label range: cells beyond share a cell, which
        // only adds candidates)
        auto index = [this](const scalar x)
        {
            return label(std::floor(min(max(x/width_, -1e9), 1e9)));
        };
        return labelPair(index(p & t1_), index(p & t2_));
    }

public:

    tangentialGrid
    (
        const UList<point>& P,
        const vector& direction,
        const scalar width
    )
    :
        width_(width > 0 ? width : GREAT)
    {
        // Any two unit vectors normal to the direction and to each other
        const vector e(normalised(direction));
        const vector a
        (
            mag(e.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)
        );
        t1_ = normalised(a - (a & e)*e);
        t2_ = e ^ t1_;
        forAll(P, j)
        {
            cells_(cell(P[j])).append(j);
        }
    }

    //- The points in the cell of p and its eight neighbours, in
    //  increasing order
    labelList near(const point& p) const
    {
        const labelPair c(cell(p));
        DynamicList<label> result;
        for (label i = -1; i <= 1; ++i)
        {
            for (label j = -1; j <= 1; ++j)
            {
                const auto iter =
                    cells_.cfind(labelPair(c.first() + i, c.second() + j));
                if (iter.found())
                {
                    result.append(*iter);
                }
            }
        }
        std::sort(result.begin(), result.end());
        return labelList(std::move(result));
    }
};


// Adds the wall time of its scope to a total
struct scopeTimer
{
    scalar& total;
    const clockValue start;

    explicit scopeTimer(scalar& t)
    :
        total(t),
        start(true)
    {}

    ~scopeTimer()
    {
        total += double(start.elapsed());
    }
};

template<class T>
List<T> allGather(const List<T>& local)
{
    List<List<T>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    return ListListOps::combine<List<T>>(all, accessOp<List<T>>());
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactPair::setSide
(
    contactSide& side,
    solidBody& body,
    const word& patchName
)
{
    const polyMesh& mesh = body.mesh();
    side.body = &body;
    side.patchi = mesh.boundaryMesh().findPatchID(patchName);

    if (side.patchi < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Contact pair '" << name_ << "': body '" << body.name()
            << "' has no patch '" << patchName << "'" << nl
            << "Patches: " << flatOutput(mesh.boundaryMesh().names())
            << exit(FatalIOError);
    }
    if (body.boundaryConditionType(side.patchi) != "contact")
    {
        FatalIOErrorInFunction(dict_)
            << "Contact pair '" << name_ << "': patch '" << patchName
            << "' of body '" << body.name() << "' has boundary condition "
            << body.boundaryConditionType(side.patchi)
            << "; give it { type contact; } in its solidProperties"
            << exit(FatalIOError);
    }

    const polyPatch& pp = mesh.boundaryMesh()[side.patchi];
    side.points = pp.meshPoints();
    side.offset = localOffset(side.points.size());
    const Map<label>& local = pp.meshPointMap();

    const dualMesh::patchSubFaces& sf = body.dual().subFaces(side.patchi);
    side.N.setSize(side.points.size(), Zero);
    side.sfLocal.setSize(sf.size());
    side.sfPrev.setSize(sf.size());
    side.sfNext.setSize(sf.size());
    forAll(sf.point, s)
    {
        side.sfLocal[s] = local[sf.point[s]];
        side.sfPrev[s] = local[sf.prev[s]];
        side.sfNext[s] = local[sf.next[s]];
    }
    // The area-weighted normal of all the point's sub-faces, summed over
    // the processors that share it: from the local sub-faces alone a point
    // on a processor boundary of a curved patch took another normal than
    // in a serial run (the rings cut across their contact patch: D 19.3 %
    // serial, 21.0-22.2 % on 2 ranks)
    {
        const vectorField NAll(body.dual().patchPointNormals(side.patchi));
        forAll(side.points, i)
        {
            side.N[i] = NAll[side.points[i]];
        }
    }

    const scalarField lengths(body.dual().lengths());
    side.length.setSize(side.points.size());
    forAll(side.points, i)
    {
        side.length[i] = lengths[side.points[i]];
    }
    side.project.setSize(side.points.size(), I);
    const List<tensor>& proj = body.symmetry().projections();
    forAll(body.symmetry().points(), k)
    {
        const auto iter = local.cfind(body.symmetry().points()[k]);
        if (iter.found())
        {
            side.project[*iter] = proj[k];
        }
    }

    side.tC.setSize(side.points.size(), Zero);
    side.vC.setSize(side.points.size(), Zero);
    side.closed.setSize(side.points.size(), false);
    side.gap0.setSize(side.points.size(), GREAT);
    side.touching.setSize(side.points.size(), false);
}


void Foam::contactPair::checkFacing() const
{
    // The patches' total area vectors (reference configuration): contact
    // surfaces face each other, so these point in opposite directions
    auto areaVector = [](const contactSide& side)
    {
        vector S(Zero);
        const dualMesh::patchSubFaces& sf =
            side.body->dual().subFaces(side.patchi);
        for (const vector& a : sf.area)
        {
            S += a;
        }
        return returnReduce(S, sumOp<vector>());
    };
    const vector SA(areaVector(A_)), SB(areaVector(B_));
    const scalar cosine = (SA & SB)/max(mag(SA)*mag(SB), VSMALL);
    if (cosine > 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Contact pair '" << name_ << "': patch "
            << sideName(A_) << " (mean normal " << normalised(SA)
            << ") and patch " << sideName(B_) << " (mean normal "
            << normalised(SB) << ") face the same way." << nl
            << "    Contact surfaces face each other: check patchA and"
            << " patchB." << exit(FatalIOError);
    }
}


void Foam::contactPair::checkOverlap() const
{
    const List<pointData> a(exchangeData(A_));
    const List<pointData> b(exchangeData(B_));

    scalar worst = 0;
    point where(Zero);
    forAll(A_.points, i)
    {
        const pointData& da = a[i];
        pointData db;
        if (!partnerData(A_, i, b, db))
        {
            continue;
        }
        const scalar gap = pairGap(da, db);
        if (gap/da.length < worst)
        {
            worst = gap/da.length;
            where = da.x;
        }
    }
    const scalar globalWorst = returnReduce(worst, minOp<scalar>());
    if (globalWorst < -overlapTolerance)
    {
        if (worst != globalWorst)
        {
            where = point(-GREAT, -GREAT, -GREAT);
        }
        reduce(where, maxOp<point>());
        FatalIOErrorInFunction(dict_)
            << "Contact pair '" << name_ << "': at the start the bodies"
            << " overlap by " << -globalWorst << " of the local edge length"
            << " at " << where << " (patch " << sideName(A_) << ")." << nl
            << "    The tolerance is " << overlapTolerance << ": move the"
            << " bodies apart (a gap of 0 or more) and mesh again."
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::contactPair::pairGap
(
    const pointData& a,
    const pointData& b
) const
{
    return (b.x - a.x) & gapDirection(pairNormal(a, b));
}


Foam::word Foam::contactPair::sideName(const contactSide& side)
{
    return side.body->name() + "/"
        + side.body->mesh().boundaryMesh()[side.patchi].name();
}


Foam::word Foam::contactPair::sharedPatch(const contactPair& other) const
{
    for (const contactSide* s : {&A_, &B_})
    {
        if (other.uses(*s->body, s->patchi))
        {
            return sideName(*s);
        }
    }
    return word::null;
}


bool Foam::contactPair::partnerData
(
    const contactSide& side,
    const label i,
    const List<pointData>& other,
    pointData& partner
) const
{
    const labelList& from = side.stateFrom[i];
    if (from.empty())
    {
        return false;
    }
    if (from.size() == 1)
    {
        // A matched partner (or a cell inside one of the other's)
        partner = other[from[0]];
        return true;
    }
    const scalarList& w = side.stateWeight[i];
    partner = pointData{Zero, Zero, Zero, Zero, 0, 0, 0};
    forAll(from, m)
    {
        const pointData& d = other[from[m]];
        partner.x += w[m]*d.x;
        partner.v += w[m]*d.v;
        partner.t += w[m]*d.t;
        partner.n += w[m]*d.n;
        partner.Lambda += w[m]*d.Lambda;
        partner.length += w[m]*d.length;
        partner.SigmaJ += w[m]*d.SigmaJ;
    }
    partner.n = normalised(partner.n);
    return true;
}


Foam::contactPair::dualSurface Foam::contactPair::buildSurface
(
    const contactSide& side
) const
{
    dualSurface surface;

    // The patch faces of all processors, over the gathered point list
    const polyPatch& pp = side.body->mesh().boundaryMesh()[side.patchi];
    faceList localFaces(pp.localFaces());
    for (face& f : localFaces)
    {
        for (label& p : f)
        {
            p += side.offset;
        }
    }
    const faceList faces(allGather(localFaces));
    const pointField X0
    (
        allGather(pointField(side.body->mesh().points(), side.points))
    );

    // Merge the processor copies of a point (same reference position)
    mergeCopies(X0, surface.copyUnique, surface.uniqueCopies);
    const label nUnique = surface.uniqueCopies.size();

    // Sub-faces: (point, midpoint to next, face centre, midpoint to
    // previous) of every face corner, as the dual mesh's boundary sub-faces
    EdgeMap<label> midpoints(2*faces.size());
    DynamicList<labelList> extra;
    auto midpoint = [&](const label a, const label b)
    {
        const edge e(a, b);
        const auto iter = midpoints.cfind(e);
        if (iter.found())
        {
            return *iter;
        }
        const label m = nUnique + extra.size();
        extra.append(labelList({a, b}));
        midpoints.insert(e, m);
        return m;
    };

    label nSub = 0;
    for (const face& f : faces)
    {
        nSub += f.size();
    }
    surface.faces.setSize(nSub);
    surface.faceOwner.setSize(nSub);
    nSub = 0;
    for (const face& f : faces)
    {
        labelList u(f.size());
        forAll(f, fp)
        {
            u[fp] = surface.copyUnique[f[fp]];
        }
        const label centre = nUnique + extra.size();
        extra.append(u);
        forAll(u, fp)
        {
            const label a = u[fp];
            const label next = u[f.fcIndex(fp)];
            const label prev = u[f.rcIndex(fp)];
            face& sub = surface.faces[nSub];
            sub.setSize(4);
            sub[0] = a;
            sub[1] = midpoint(a, next);
            sub[2] = centre;
            sub[3] = midpoint(prev, a);
            surface.faceOwner[nSub] = a;
            ++nSub;
        }
    }
    surface.extraPoints.transfer(extra);
    return surface;
}


Foam::pointField Foam::contactPair::uniquePoints
(
    const dualSurface& surface,
    const List<pointData>& data
)
{
    pointField P(surface.uniqueCopies.size());
    forAll(surface.uniqueCopies, u)
    {
        P[u] = data[surface.uniqueCopies[u][0]].x;
    }
    return P;
}


Foam::pointField Foam::contactPair::surfacePoints
(
    const dualSurface& surface,
    const pointField& unique
)
{
    const label nUnique = surface.uniqueCopies.size();
    pointField P(nUnique + surface.extraPoints.size());
    SubList<point>(P, nUnique) = unique;
    forAll(surface.extraPoints, k)
    {
        const labelList& from = surface.extraPoints[k];
        point sum(Zero);
        for (const label u : from)
        {
            sum += P[u];
        }
        P[nUnique + k] = sum/from.size();
    }
    return P;
}


bool Foam::contactPair::needsMapping() const
{
    // Displacements since the last mapping of both sides' points (this
    // processor's and its points' remote partners)
    auto displacement = [this]
    (
        const contactSide& side,
        const dualSurface& surface,
        const pointField& mapped
    )
    {
        List<vector> d(side.points.size());
        forAll(side.points, i)
        {
            d[i] =
                side.body->x(side.points[i])
              - mapped[surface.copyUnique[side.offset + i]];
        }
        return exchanged(side, std::move(d));
    };
    const List<vector> dA(displacement(A_, surfaceA_, mappedA_));
    const List<vector> dB(displacement(B_, surfaceB_, mappedB_));

    // A point's slide relative to its partners (their overlap-weighted
    // displacement), tangentially: surfaces that move or spread together
    // (two bars' faces widening as they are compressed) keep their
    // overlaps, and remapping them would only perturb the contact
    bool slid = false;
    for (const contactSide* side : {&A_, &B_})
    {
        const bool isA = (side == &A_);
        const List<vector>& own = isA ? dA : dB;
        const List<vector>& other = isA ? dB : dA;
        forAll(side->points, i)
        {
            vector d(own[i]);
            const labelList& from = side->stateFrom[i];
            const scalarList& w = side->stateWeight[i];
            forAll(from, m)
            {
                d -= w[m]*other[from[m]];
            }
            // (A point without overlaps remaps on any motion: its partners
            // may come into reach as the surfaces approach; the AMI finds
            // no overlap across a gap wide against the faces, and two bars
            // meshed differently then passed through each other unseen)
            const vector& N = side->N[i];
            const vector slide(from.empty() ? d : d - (d & N)*N);
            if (mag(slide) > AMIUpdate_*side->length[i])
            {
                slid = true;
                break;
            }
        }
    }
    return returnReduce(slid, orOp<bool>());
}


void Foam::contactPair::mapByAMI()
{
    mapByAMI
    (
        uniquePoints(surfaceA_, gatherData(A_)),
        uniquePoints(surfaceB_, gatherData(B_))
    );
}


void Foam::contactPair::mapByAMI
(
    const pointField& uniqueA,
    const pointField& uniqueB
)
{
    const clockTime clock;
    const pointField PA(surfacePoints(surfaceA_, uniqueA));
    const pointField PB(surfacePoints(surfaceB_, uniqueB));
    const primitivePatch patchA
    (
        SubList<face>(surfaceA_.faces, surfaceA_.faces.size()), PA
    );
    const primitivePatch patchB
    (
        SubList<face>(surfaceB_.faces, surfaceB_.faces.size()), PB
    );

    // Every processor maps the whole surfaces itself (the AMI in its
    // serial mode: the surfaces are already complete on each)
    const bool parRun = Pstream::parRun();
    Pstream::parRun() = false;
    const AMIPatchToPatchInterpolation ami
    (
        patchA,
        patchB,
        faceAreaIntersect::tmMesh,
        false,                      // the surfaces may overlap in part
        // (the partial method walks on where the surfaces part instead of
        // failing: curved surfaces in contact over part of their area)
        AMIPatchToPatchInterpolation::imPartialFaceAreaWeight,
        -1,                         // no low-weight correction
        false                       // the surfaces face each other
    );
    Pstream::parRun() = parRun;

    // Overlap areas of the unique points' dual cells: from the sub-face
    // overlaps (normalised weight x covered fraction x sub-face area)
    const label nA = surfaceA_.uniqueCopies.size();
    const label nB = surfaceB_.uniqueCopies.size();
    List<Map<scalar>> overlapAB(nA), overlapBA(nB);
    scalarField areaA(nA, 0.0);
    const labelListList& addr = ami.srcAddress();
    const scalarListList& w = ami.srcWeights();
    const scalarField& wSum = ami.srcWeightsSum();
    const scalarList& magSf = ami.srcMagSf();
    forAll(addr, f)
    {
        const label uA = surfaceA_.faceOwner[f];
        areaA[uA] += magSf[f];
        // The weights are normalised by their sum or by the face area
        // (depending on the AMI method); wSum is the covered fraction
        const scalar sumW = sum(w[f]);
        forAll(addr[f], m)
        {
            const label uB = surfaceB_.faceOwner[addr[f][m]];
            const scalar area = w[f][m]/sumW*wSum[f]*magSf[f];
            overlapAB[uA](uB) += area;
            overlapBA[uB](uA) += area;
        }
    }

    // Overlaps below this fraction of a cell are round-off (slivers of
    // coincident meshes) and dropped
    const scalar sliver = 1e-10;
    scalarField coveredA(nA, 0.0);
    forAll(overlapAB, uA)
    {
        for (const label uB : overlapAB[uA].sortedToc())
        {
            if (overlapAB[uA][uB] < sliver*areaA[uA])
            {
                overlapAB[uA].erase(uB);
                overlapBA[uB].erase(uA);
            }
            else
            {
                coveredA[uA] += overlapAB[uA][uB];
            }
        }
    }

    // Partner states: the other side's first copies of the overlapped
    // points, weighted by the overlap areas
    auto fill = [&]
    (
        contactSide& side,
        const dualSurface& own,
        const dualSurface& other,
        const List<Map<scalar>>& overlap
    )
    {
        side.stateFrom.setSize(side.points.size());
        side.stateWeight.setSize(side.points.size());
        forAll(side.points, i)
        {
            const Map<scalar>& row = overlap[own.copyUnique[side.offset + i]];
            const labelList toc(row.sortedToc());
            scalar sum = 0;
            for (const label u : toc)
            {
                sum += row[u];
            }
            labelList& from = side.stateFrom[i];
            scalarList& weight = side.stateWeight[i];
            from.setSize(toc.size());
            weight.setSize(toc.size());
            forAll(toc, m)
            {
                from[m] = other.uniqueCopies[toc[m]][0];
                weight[m] = row[toc[m]]/sum;
            }
        }
    };
    fill(A_, surfaceA_, surfaceB_, overlapAB);
    fill(B_, surfaceB_, surfaceA_, overlapBA);

    // The overlap pairs are A's (point, partner) entries, flattened in the
    // order of the gathered A points; each B point finds its pairs there
    // (those of the first copy of each A point)
    const label nCopiesA = surfaceA_.copyUnique.size();
    labelList pairStart(nCopiesA + 1, 0);
    for (label k = 0; k < nCopiesA; ++k)
    {
        pairStart[k + 1] =
            pairStart[k] + overlapAB[surfaceA_.copyUnique[k]].size();
    }
    auto pairOf = [&](const label uA, const label uB)
    {
        return
            pairStart[surfaceA_.uniqueCopies[uA][0]]
          + overlapAB[uA].sortedToc().find(uB);
    };

    // B's force shares: the force each A point's traction makes, split
    // over the B points its cell overlaps in proportion to the overlap
    // areas, each share with the traction of its own pair (every
    // processor copy of the A point passes on its own part of the force)
    const label offsetB = B_.offset;
    B_.forceFrom.setSize(B_.points.size());
    B_.forceShare.setSize(B_.points.size());
    B_.forcePair.setSize(B_.points.size());
    B_.pairIndex.setSize(B_.points.size());
    forAll(B_.points, i)
    {
        const label uB = surfaceB_.copyUnique[offsetB + i];
        const Map<scalar>& row = overlapBA[uB];
        const labelList toc(row.sortedToc());
        DynamicList<label> from, pair;
        DynamicList<scalar> share;
        labelList& pairs = B_.pairIndex[i];
        pairs.setSize(toc.size());
        forAll(toc, m)
        {
            const label uA = toc[m];
            pairs[m] = pairOf(uA, uB);
            for (const label k : surfaceA_.uniqueCopies[uA])
            {
                from.append(k);
                share.append(row[uA]/coveredA[uA]);
                pair.append(pairs[m]);
            }
        }
        B_.forceFrom[i].transfer(from);
        B_.forceShare[i].transfer(share);
        B_.forcePair[i].transfer(pair);
    }
    A_.pairClosed.setSize(A_.points.size());
    A_.pairGap0.setSize(A_.points.size());
    forAll(A_.points, i)
    {
        A_.pairClosed[i] = boolList(A_.stateFrom[i].size(), false);
        A_.pairGap0[i] = scalarList(A_.stateFrom[i].size(), GREAT);
    }

    buildExchange();
    forceAreaA_ = exchanged(A_, List<scalar>(tractionAreaA_));

    // (slides are measured from these positions)
    mappedA_ = uniqueA;
    mappedB_ = uniqueB;
    ++nMappings_;
    mappingTime_ += clock.elapsedTime();
}



bool Foam::contactPair::matchSides(const bool fatal)
{
    const pointField& XA = A_.body->mesh().points();
    const pointField& XB = B_.body->mesh().points();

    const pointField globalA(allGather(pointField(XA, A_.points)));
    const pointField globalB(allGather(pointField(XB, B_.points)));
    const vectorField globalNA(allGather(A_.N));

    // Candidate partners from a grid over the plane normal to the approach
    // direction (matchDirection, else A's mean normal), cells one smallest
    // edge length wide: a partner within the matching tolerance lies in
    // the point's cell or a neighbouring one when the point looks along
    // that direction (flat patches, matchDirection); a point whose
    // candidates hold none (its own normal tilted on a curved patch) is
    // matched against all points, so the partners are those of a search
    // over all points, found in about linear time
    const vector approach
    (
        magSqr(matchDirection_) > 0
      ? matchDirection_
      : normalised(sum(globalNA))
    );
    const scalar cellSize = returnReduce
    (
        min(min(A_.length), min(B_.length)),
        minOp<scalar>()
    );
    const tangentialGrid gridB(globalB, approach, cellSize);

    // Partner: the point of the other side at the same tangential position
    // (relative to A's normal), i.e. across the gap; the first of equally
    // near points (processor copies)
    auto match = [&]
    (
        const pointField& from,
        const vectorField& fromN,
        const scalarField& len,
        const pointField& to,
        const tangentialGrid& grid,
        labelList& partner,
        const word& fromBody
    )
    {
        partner.setSize(from.size(), -1);
        forAll(from, i)
        {
            const vector n(gapDirection(fromN[i]));
            scalar best = GREAT;
            label ibest = -1;
            auto nearest = [&](const label j)
            {
                const vector d(to[j] - from[i]);
                const scalar dt = mag(d - (d & n)*n);
                if (dt < best || (dt == best && j < ibest))
                {
                    best = dt;
                    ibest = j;
                }
            };
            for (const label j : grid.near(from[i]))
            {
                nearest(j);
            }
            if (ibest < 0 || best > 1e-6*len[i])
            {
                forAll(to, j)
                {
                    nearest(j);
                }
            }
            if ((ibest < 0 || best > 1e-6*len[i]) && !fatal)
            {
                return false;
            }
            if (ibest < 0 || best > 1e-6*len[i])
            {
                FatalIOErrorInFunction(dict_)
                    << "Contact pair '" << name_ << "': the patches do not"
                    << " match. The point of body " << fromBody << " at "
                    << from[i] << " has no partner on the other patch"
                    << " (nearest tangential distance " << best << ")."
                    << nl << "Matching (conforming) contact meshes are"
                    << " needed for 'mapping matching': mesh both patches"
                    << " with the same surface mesh, or use 'mapping AMI'"
                    << " (or auto) for any two surface meshes."
                    << (
                           magSqr(matchDirection_) > 0 ? "" :
                           "\n    Partners are searched along the normals of"
                           " patchA. If the two surface meshes are copies"
                           " of each other shifted along one direction"
                           " (curved faces such as two rings), set"
                           " matchDirection to that direction."
                       )
                    << exit(FatalIOError);
            }
            partner[i] = ibest;
        }
        return true;
    };

    // A's points look along their own normal; B's along the normal of the
    // nearest A point (A's normal defines the contact direction).  Every
    // processor decides on the whole (gathered) lists, so all agree
    labelList partnerA, partnerB;
    if
    (
        !returnReduce
        (
            match
            (
                pointField(XA, A_.points), A_.N, A_.length, globalB, gridB,
                partnerA, A_.body->name()
            ),
            andOp<bool>()
        )
    )
    {
        return false;
    }

    // Processor copies of a point (the same reference position), in
    // increasing order of their gathered index
    labelList copyUniqueA;
    labelListList uniqueCopiesA;
    mergeCopies(globalA, copyUniqueA, uniqueCopiesA);

    // The nearest A point of each B point (an octree search; of copies,
    // the first)
    vectorField NB(B_.points.size());
    if (globalA.size())
    {
        treeBoundBox bb(globalA);
        bb.inflate(1e-4);
        bb.min() -= point::uniform(ROOTVSMALL);
        bb.max() += point::uniform(ROOTVSMALL);
        const indexedOctree<treeDataPoint> tree
        (
            treeDataPoint(globalA), bb, 8, 10, 3.0
        );
        forAll(B_.points, i)
        {
            const point& p = XB[B_.points[i]];
            const pointIndexHit hit
            (
                tree.findNearest
                (
                    p, sqr(mag(p - bb.min()) + mag(bb.span()))
                )
            );
            NB[i] = globalNA[uniqueCopiesA[copyUniqueA[hit.index()]][0]];
        }
    }
    const tangentialGrid gridA(globalA, approach, cellSize);
    if
    (
        !returnReduce
        (
            match
            (
                pointField(XB, B_.points), NB, B_.length, globalA, gridA,
                partnerB, B_.body->name()
            ),
            andOp<bool>()
        )
    )
    {
        return false;
    }

    // One partner each, weight 1: the partner state is exactly the
    // partner's; B takes all of its partner's force (every copy)
    for (contactSide* side : {&A_, &B_})
    {
        const labelList& partner = (side == &A_) ? partnerA : partnerB;
        side->stateFrom.setSize(partner.size());
        side->stateWeight.setSize(partner.size());
        forAll(partner, i)
        {
            side->stateFrom[i] = labelList(1, partner[i]);
            side->stateWeight[i] = scalarList(1, 1.0);
        }
    }
    B_.forceFrom.setSize(partnerB.size());
    B_.forceShare.setSize(partnerB.size());
    forAll(partnerB, i)
    {
        B_.forceFrom[i] = uniqueCopiesA[copyUniqueA[partnerB[i]]];
        B_.forceShare[i] = scalarList(B_.forceFrom[i].size(), 1.0);
    }
    buildExchange();
    return true;
}


Foam::List<Foam::contactPair::pointData> Foam::contactPair::gatherData
(
    const contactSide& side
) const
{
    return allGather(localData(side));
}


Foam::List<Foam::contactPair::pointData> Foam::contactPair::localData
(
    const contactSide& side
) const
{
    const solidBody& body = *side.body;
    const List<fluxState>& q = body.q();
    const List<tensor>& H = body.Hc();

    // A body whose pressure acts on the deformed dual (solidBody, scheme
    // deformedPressure): each point's deformed area per unit reference
    // area from its sub-faces, in place of H N (on this processor's
    // sub-faces)
    const autoPtr<solidBoundaryCondition::deformedDual> deformed
    (
        body.deformedDual(side.patchi)
    );
    List<vector> aDeformed;
    if (deformed)
    {
        const dualMesh::patchSubFaces& sf =
            body.dual().subFaces(side.patchi);
        aDeformed.setSize(side.points.size(), Zero);
        scalarField magA(side.points.size(), 0.0);
        forAll(sf.point, s)
        {
            aDeformed[side.sfLocal[s]] += deformed->subFaceArea[s];
            magA[side.sfLocal[s]] += mag(sf.area[s]);
        }
        // A point on a processor cut: the sums over every processor's
        // sub-faces, so that its copies take one normal and area ratio
        // (solidBoundaryCondition::syncDeformedAreas)
        if (Pstream::parRun())
        {
            const polyMesh& mesh = body.dual().mesh();
            List<vector> aSum(mesh.nPoints(), Zero);
            List<scalar> magSum(mesh.nPoints(), 0.0);
            forAll(side.points, i)
            {
                aSum[side.points[i]] = aDeformed[i];
                magSum[side.points[i]] = magA[i];
            }
            syncTools::syncPointList
            (
                mesh, aSum, plusEqOp<vector>(), vector(Zero)
            );
            syncTools::syncPointList(mesh, magSum, plusEqOp<scalar>(), 0.0);
            forAll(side.points, i)
            {
                aDeformed[i] = aSum[side.points[i]];
                magA[i] = magSum[side.points[i]];
            }
        }
        forAll(aDeformed, i)
        {
            aDeformed[i] /= magA[i];
        }
    }

    List<pointData> local(side.points.size());
    forAll(side.points, i)
    {
        const label p = side.points[i];
        const vector& N = side.N[i];
        // On a symmetry plane the contact normal lies in the plane.  H N
        // can leave it where the out-of-plane shear of F (front/back
        // points of a plane-strain layer) grows large: at the crushed
        // contact corners of B2 it tilted the pair normal 74 degrees out
        // of the plane, the closing motion became tangential slip and the
        // corners passed 3 edge lengths through each other.  Only the
        // normal is projected: projecting the traction or the contact
        // velocity as well breaks the pairing of the momentum and F
        // fluxes (the rings' energy then rose by 0.27 % of E0)
        const tensor& Pr = side.project[i];
        vector t(fluxStress(q[p]) & N);
        vector hN(H[p] & N);
        if (deformed)
        {
            deformed->toDeformedArea(p, aDeformed[i], t, hN);
        }
        const scalar Lambda = mag(hN);
        // A control volume folded over at a corner can turn H N against
        // the surface; its partner's gap would then be measured backwards
        // and read as open while the points pass through each other, so
        // the reference normal stands in for it
        vector n(normalised(Pr & hN));
        if ((n & N) <= 0)
        {
            n = normalised(Pr & N);
        }
        local[i] = pointData
        {
            body.x(p), fluxVelocity(q[p]), t, n, Lambda, side.length[i],
            fluxSigmaJ(q[p])
        };
    }
    return local;
}


template<class T>
Foam::List<T> Foam::contactPair::exchanged
(
    const contactSide& side,
    List<T> values
) const
{
    (&side == &A_ ? toB_ : toA_)->distribute(values);
    return values;
}


Foam::label Foam::contactPair::nPairsA() const
{
    label n = 0;
    for (const labelList& from : A_.stateFrom)
    {
        n += from.size();
    }
    return n;
}


void Foam::contactPair::buildExchange()
{
    // mapDistribute's compact numbering: this processor's values first (at
    // their local indices), then the remote ones referred to, so that in
    // serial the exchanged list is the local one
    auto build = [](const label localSize, List<labelListList*> lists)
    {
        label n = 0;
        for (const labelListList* l : lists)
        {
            n += l->size();
        }
        labelListList rows(n);
        n = 0;
        for (labelListList* l : lists)
        {
            for (labelList& row : *l)
            {
                rows[n++].transfer(row);
            }
        }
        List<Map<label>> compactMap;
        autoPtr<mapDistribute> map
        (
            new mapDistribute(globalIndex(localSize), rows, compactMap)
        );
        n = 0;
        for (labelListList* l : lists)
        {
            for (labelList& row : *l)
            {
                row.transfer(rows[n++]);
            }
        }
        return map;
    };

    toA_ = build(B_.points.size(), {&A_.stateFrom});
    toB_ = build(A_.points.size(), {&B_.stateFrom, &B_.forceFrom});
    if (useAMI_)
    {
        pairsToB_ = build(nPairsA(), {&B_.pairIndex, &B_.forcePair});
    }
}


Foam::scalar Foam::contactPair::closingAllowance
(
    const scalar d0,
    const scalar d
) const
{
    return max(stage_ == 0 ? d0 : d0 + d, scalar(0))/deltaT_;
}


bool Foam::contactPair::pairState
(
    const bool closed,
    const scalar allowance,
    const pointData& a,
    const pointData& b,
    vector& tC,
    vector& vCA,
    vector& vCB,
    scalar& closingPower
) const
{
    closingPower = 0;
    const materialModel& mA = A_.body->material();
    const materialModel& mB = B_.body->material();

    const vector vA(a.v), vB(b.v);
    const vector tA(a.t), tBown(b.t);
    const vector n(pairNormal(a, b)), nBown(b.n);

    // Open gap or (below) tension: both sides traction-free
    auto separate = [&]()
    {
        tC = Zero;
        vCA = acousticFormulas::tractionVelocity(tA, vA, Zero, n, mA.Zp(), mA.Zs());
        vCB = acousticFormulas::tractionVelocity
        (
            tBown, vB, Zero, nBown, mB.Zp(), mB.Zs()
        );
    };

    if (!closed && allowance >= GREAT)
    {
        separate();
        return false;
    }

    // Traction of B measured with A's normal: t^R = -P^B N^B
    const vector tB(-tBown);

    // An open pair's two contact velocities are apart by the allowance
    // (A approaching B): the stick problem with A's velocity shifted by it
    // (exact for both solvers, whose A-side relation depends on
    // v_n^C - v_n^A only)
    const scalar w = closed ? 0 : allowance;
    contactRiemannSolver::side L
    {
        tA & n, (vA & n) - w, mA.rho(), mA.cp(), a.Lambda,
        mA.hugoniot() ? mA.hugoniotS() : 0, a.SigmaJ
    };
    contactRiemannSolver::side R
    {
        tB & n, vB & n, mB.rho(), mB.cp(), b.Lambda,
        mB.hugoniot() ? mB.hugoniotS() : 0, b.SigmaJ
    };
    // A Hugoniot material's wave speed at the point's compression (the
    // shock relation's c + s dv holds from the undeformed state; a
    // compressed face's small jumps travel faster: interiorRiemannSolvers::
    // hugoniot::normalImpedance)
    if (mA.hugoniot())
    {
        L.c = mA.tangentWaveSpeedAtSigmaJ(a.SigmaJ);
    }
    if (mB.hugoniot())
    {
        R.c = mB.tangentWaveSpeedAtSigmaJ(b.SigmaJ);
    }
    scalar vnC, tnC;
    riemann_->normalState(L, R, vnC, tnC);

    if (tnC >= 0)
    {
        separate();
        return closed || ((vA - vB) & n) > w;
    }

    // Tangential (acoustic)
    const vector tAt(tA - (tA & n)*n), tBt(tB - (tB & n)*n);
    const vector vAt(vA - (vA & n)*n), vBt(vB - (vB & n)*n);
    const scalar ZA = mA.Zs(), ZB = mB.Zs();

    vector ttC(Zero), vtA(vAt), vtB(vBt);
    const bool shear = (ZA > VSMALL && ZB > VSMALL);

    // One-sided tangential velocities for a given tangential traction
    auto slipWith = [&](const vector& tt)
    {
        ttC = tt;
        if (ZA > VSMALL) vtA = vAt - (tAt - tt)/ZA;
        if (ZB > VSMALL) vtB = vBt + (tBt - tt)/ZB;
    };

    if (!shear)
    {
        slipWith(Zero);
    }
    else
    {
        // The stick state; the friction law decides whether it holds or
        // the sides slip with the traction it allows
        const vector vtStick
        (
            riemann_->tangentialTractionJump()
          ? (ZA*vAt + ZB*vBt + tBt - tAt)/(ZA + ZB)
          : (ZA*vAt + ZB*vBt)/(ZA + ZB)
        );
        const vector ttStick
        (
            (ZA*ZB/(ZA + ZB))*(tAt/ZA + tBt/ZB + vBt - vAt)
        );
        bool stick = false;
        const vector tt(friction_->tangentialTraction(ttStick, tnC, stick));
        if (stick)
        {
            ttC = tt;
            vtA = vtStick;
            vtB = vtStick;
        }
        else
        {
            slipWith(tt);
        }
    }

    tC = tnC*n + ttC;
    vCA = (vnC + w)*n + vtA;
    vCB = vnC*n + vtB;
    closingPower = tnC*w;
    return true;
}


void Foam::contactPair::addSideFluxes
(
    contactSide& side,
    const bool tractions
)
{
    solidBody& body = *side.body;
    const dualMesh::patchSubFaces& sf = body.dual().subFaces(side.patchi);
    stageResidual& R = body.residual();
    List<vector>& Rp = R.momentum;
    List<tensor>& RF = R.F;
    List<vector>& tB = R.boundaryTraction[side.patchi];
    List<vector>& vB = R.boundaryVelocity[side.patchi];
    const bool keepStates = tB.size();
    R.boundarySet[side.patchi] = true;

    // (A's integrated forces; B's momentum takes A's traction forces)
    List<vector> force(tractions ? side.points.size() : 0, Zero);
    forAll(sf.point, s)
    {
        const label i = side.sfLocal[s];
        const label ip = side.sfPrev[s];
        const label in = side.sfNext[s];
        const scalar w = sf.nbrWeight[s];
        const vector tC((1 - 2*w)*side.tC[i] + w*(side.tC[ip] + side.tC[in]));
        const vector vC((1 - 2*w)*side.vC[i] + w*(side.vC[ip] + side.vC[in]));
        if (tractions)
        {
            force[i] += mag(sf.area[s])*tC;
        }
        RF[sf.point[s]] += vC*sf.area[s];
        if (keepStates)
        {
            tB[s] = tC;
            vB[s] = vC;
        }
    }
    forAll(force, i)
    {
        Rp[side.points[i]] += force[i];
    }
}


Foam::List<Foam::vector> Foam::contactPair::tractionForcesA() const
{
    List<vector> force(A_.points.size());
    forAll(force, i)
    {
        force[i] = tractionAreaA_[i]*A_.tC[i];
    }
    return force;
}


Foam::scalarField Foam::contactPair::tractionAreasA() const
{
    const dualMesh::patchSubFaces& sf =
        A_.body->dual().subFaces(A_.patchi);
    scalarField area(A_.points.size(), Zero);
    forAll(sf.point, s)
    {
        const scalar w = sf.nbrWeight[s];
        const scalar magA = mag(sf.area[s]);
        area[A_.sfLocal[s]] += (1 - 2*w)*magA;
        area[A_.sfPrev[s]] += w*magA;
        area[A_.sfNext[s]] += w*magA;
    }
    return area;
}


Foam::scalar Foam::contactPair::integrateOverA
(
    const UList<scalar>& density
) const
{
    const dualMesh::patchSubFaces& sf =
        A_.body->dual().subFaces(A_.patchi);
    scalar sum = 0;
    forAll(sf.point, s)
    {
        const label i = A_.sfLocal[s];
        const scalar w = sf.nbrWeight[s];
        sum +=
            mag(sf.area[s])
           *(
                (1 - 2*w)*density[i]
              + w*(density[A_.sfPrev[s]] + density[A_.sfNext[s]])
            );
    }
    return sum;
}


void Foam::contactPair::addPairPower
(
    const UList<scalar>& powerA,
    const UList<scalar>& powerB
)
{
    // (Summed over the processors with each body's other powers)
    A_.body->residual().power += integrateOverA(powerA);
    B_.body->residual().power -= integrateOverA(powerB);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactPair::contactPair
(
    const word& name,
    const dictionary& dict,
    PtrList<solidBody>& bodies
)
:
    name_(name),
    dict_(dict),
    riemann_(),
    friction_(frictionLaw::New(dict, "contact pair '" + name + "'")),
    matchDirection_(getFiniteOrDefault<vector>(dict, "matchDirection", Zero)),
    useAMI_(false),
    AMIUpdate_(dict.getOrDefault<scalar>("AMIUpdate", 0.1)),
    nMappings_(0),
    mappingTime_(0),
    wallTime_(0),
    stepsClosed_(0),
    approaching_(false),
    maxPenetration_(0),
    deltaT_(GREAT),
    stage_(0)
{
    if (dict.found("s"))
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': keyword 's' is not used. The"
            << " Hugoniot slope of each side comes from its material:"
            << " hugoniot { s ...; } in the body's solidProperties"
            << exit(FatalIOError);
    }
    wordList allowed
    (
        {
            "bodyA", "patchA", "bodyB", "patchB", "riemannSolver",
            "matchDirection", "mapping", "AMIUpdate"
        }
    );
    allowed.append(friction_->keywords());
    checkKeywords(dict, allowed);
    auto findBody = [&](const word& key) -> solidBody&
    {
        const word bodyName(dict.get<word>(key));
        wordList names;
        for (solidBody& b : bodies)
        {
            if (b.name() == bodyName)
            {
                return b;
            }
            names.append(b.name());
        }
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': keyword '" << key
            << "' names body '" << bodyName << "', which does not exist"
            << nl << "Bodies: " << flatOutput(names) << exit(FatalIOError);
        return bodies[0];
    };

    if (dict.found("matchDirection"))
    {
        if (mag(matchDirection_) < SMALL)
        {
            FatalIOErrorInFunction(dict)
                << "Contact pair '" << name << "': keyword 'matchDirection'"
                << " must be a non-zero vector" << exit(FatalIOError);
        }
        matchDirection_ /= mag(matchDirection_);
    }

    solidBody& bodyA = findBody("bodyA");
    solidBody& bodyB = findBody("bodyB");
    if (&bodyA == &bodyB)
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': bodyA and bodyB are both '"
            << bodyA.name() << "'. A pair joins two different bodies"
            << " (contact of a body with itself is not supported)."
            << exit(FatalIOError);
    }
    // Plane strain: a pair passes forces per unit depth only if both
    // layers are equally thick (a thinner body would take the thicker
    // one's force over less depth: with rings of 1 and 5/7 that depth the
    // contact point drifted 2.3 mm into the thinner ring)
    const scalar depthA = bodyA.planeStrainDepth();
    const scalar depthB = bodyB.planeStrainDepth();
    if (depthA > 0 && depthB > 0 && mag(depthA - depthB) > 1e-6*depthA)
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': bodies '" << bodyA.name()
            << "' and '" << bodyB.name() << "' are plane-strain layers of"
            << " different thickness (" << depthA << " and " << depthB
            << ")" << nl << "Mesh both layers equally thick (in the"
            << " tutorials' .geo files: -setnumber t <thickness>)"
            << exit(FatalIOError);
    }
    chooseRiemannSolver(bodyA, bodyB);
    setSide(A_, bodyA, dict.get<word>("patchA"));
    setSide(B_, bodyB, dict.get<word>("patchB"));
    tractionAreaA_ = tractionAreasA();

    checkFacing();

    const word mapping(dict.getOrDefault<word>("mapping", "auto"));
    if (mapping != "auto" && mapping != "matching" && mapping != "AMI")
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': unknown mapping '" << mapping
            << "'" << nl << "Valid: auto (matching patches point for point,"
            << " others through the AMI), matching, AMI"
            << exit(FatalIOError);
    }
    if (!(AMIUpdate_ > 0 && AMIUpdate_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': AMIUpdate " << AMIUpdate_
            << " is out of range: (0, 1] (a fraction of the edge length)"
            << exit(FatalIOError);
    }
    if (mapping == "AMI" && magSqr(matchDirection_) > 0)
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair '" << name << "': matchDirection pairs points"
            << " of matching patches; it cannot be used with mapping AMI"
            << exit(FatalIOError);
    }
    useAMI_ =
        mapping == "AMI"
     || (mapping == "auto" && !matchSides(mapping == "matching"));
    if (mapping == "matching")
    {
        matchSides(true);
    }
    if (useAMI_)
    {
        surfaceA_ = buildSurface(A_);
        surfaceB_ = buildSurface(B_);
    }

    // A restart carries the history of the earlier runs on
    if (timeDirectory::isRestart(time()))
    {
        const autoPtr<IOdictionary> state
        (
            readUniformState(stateName(), time())
        );
        maxPenetration_ = readUniformEntry<scalar>(*state, "maxPenetration");
        if (useAMI_)
        {
            restartMapping(*state);
        }
    }
    else
    {
        if (useAMI_)
        {
            mapByAMI();
        }
        checkOverlap();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::contactPair::impactMach
(
    const solidBody& b,
    const bool planarOnly
) const
{
    if (A_.body != &b && B_.body != &b)
    {
        return 0;
    }
    // (a planar impact: both contact patches flat)
    if
    (
        planarOnly
     && (
        !A_.body->dual().patchFlat(A_.patchi, solidBody::planarImpactAngle)
     || !B_.body->dual().patchFlat(B_.patchi, solidBody::planarImpactAngle)
        )
    )
    {
        return 0;
    }
    const solidBody& other = (A_.body == &b) ? *B_.body : *A_.body;
    const materialModel& m = b.material();
    const scalar Z = m.Zp();
    const scalar ZOther = other.material().Zp();
    return
        mag(b.initialVelocity() - other.initialVelocity())
       *ZOther/(Z + ZOther)/m.cp();
}


const Foam::label Foam::contactPair::onsetSteps = 10;


Foam::scalar Foam::contactPair::hugoniotShare
(
    const materialModel& m,
    const materialModel& other,
    const scalar w
)
{
    if (!m.hugoniot() || !other.hugoniot() || w <= 0)
    {
        return max(w, 0);
    }
    // rho_m (c_m + s_m u) u = rho_o (c_o + s_o (w - u)) (w - u), that is
    // a u^2 + b u - c = 0 with b > 0 and c >= 0; the left side less the
    // right grows from -c at u = 0 to a positive value at u = w, and its
    // root there is 2 c/(b + sqrt(b^2 + 4 a c)) (no cancellation)
    const scalar rm = m.rho(), cm = m.cp(), sm = m.hugoniotS();
    const scalar ro = other.rho(), co = other.cp(), so = other.hugoniotS();
    const scalar a = rm*sm - ro*so;
    const scalar b = rm*cm + ro*co + 2*ro*so*w;
    const scalar c = ro*(co + so*w)*w;
    const scalar u = 2*c/(b + Foam::sqrt(max(sqr(b) + 4*a*c, 0)));
    return min(max(u, 0), w);
}


void Foam::contactPair::anticipateImpacts
(
    const PtrList<solidBody>& bodies,
    const PtrList<contactPair>& contacts
)
{
    bool hugoniot = false;
    for (const solidBody& b : bodies)
    {
        hugoniot = hugoniot || b.material().hugoniot();
    }
    if (!hugoniot)
    {
        // (only a Hugoniot body's step anticipates an impact)
        return;
    }
    List<boundBox> range(bodies.size());
    forAll(bodies, bi)
    {
        range[bi] = bodies[bi].velocityRange();
        bodies[bi].anticipateImpactSpeed
        (
            bodies[bi].ownStrikeSpeed(range[bi])
        );
    }
    for (const contactPair& c : contacts)
    {
        label a = -1, b = -1;
        forAll(bodies, bi)
        {
            a = (&bodies[bi] == c.A_.body) ? bi : a;
            b = (&bodies[bi] == c.B_.body) ? bi : b;
        }
        const boundBox& ra = range[a];
        const boundBox& rb = range[b];
        if (!ra.valid() || !rb.valid())
        {
            continue;
        }
        // The largest |v_a - v_b| over the two boxes, component by
        // component
        const vector w
        (
            max(ra.max() - rb.min(), rb.max() - ra.min())
        );
        const scalar closing = mag(w);
        const solidBody& A = bodies[a];
        const solidBody& B = bodies[b];
        bool inContact;
        scalar timeToClose;
        c.gapState(inContact, timeToClose);
        c.stepsClosed_ = inContact ? c.stepsClosed_ + 1 : 0;
        // Approaching once a gap closes within the approach window, and
        // then while one closes (solidBoundaryCondition::approachCounts)
        const scalar window = A.approachWindow();
        if
        (
           !solidBoundaryCondition::approachCounts
            (
                c.approaching_,
                inContact || timeToClose <= window,
                timeToClose < GREAT,
                window
            )
        )
        {
            // Open and not closing within the next steps: no impact yet
            // (the steps before it are the bodies' own)
            continue;
        }
        if (c.stepsClosed_ <= onsetSteps)
        {
            A.anticipateImpactSpeed(max(A.impactSpeed(), closing));
            B.anticipateImpactSpeed(max(B.impactSpeed(), closing));
            continue;
        }
        A.anticipateImpactSpeed
        (
            max
            (
                A.impactSpeed(),
                hugoniotShare(A.material(), B.material(), closing)
            )
        );
        B.anticipateImpactSpeed
        (
            max
            (
                B.impactSpeed(),
                hugoniotShare(B.material(), A.material(), closing)
            )
        );
    }
}


bool Foam::contactPair::planeWaveImpact
(
    const solidBody& b,
    const bool uniaxial
) const
{
    if (impactMach(b, true) <= 0)
    {
        return false;
    }
    // Head-on: the bodies close along the patch's normal at least at half
    // their relative speed (a block sliding on a plate does not strike it)
    const contactSide& s = (A_.body == &b) ? A_ : B_;
    const solidBody& other = (A_.body == &b) ? *B_.body : *A_.body;
    const vector dv(b.initialVelocity() - other.initialVelocity());
    const vector A(b.dual().patchArea(s.patchi));
    const scalar closing = (dv & A)/max(mag(A), VSMALL);
    return closing >= 0.5*mag(dv) && b.planeWaveImpact(s.patchi, uniaxial);
}


void Foam::contactPair::chooseRiemannSolver
(
    const solidBody& bodyA,
    const solidBody& bodyB
)
{
    const word given(dict_.getOrDefault<word>("riemannSolver", "auto"));
    word type(given);
    const materialModel& mA = bodyA.material();
    const materialModel& mB = bodyB.material();
    // The impact Mach number M = |[[v]]|/c (doc/method.md, section 3)
    const scalar M =
        mag(bodyA.initialVelocity() - bodyB.initialVelocity())
       /min(mA.cp(), mB.cp());
    if (given != "auto")
    {
        riemannChoice_ = "given";
    }
    else
    {
        // The Hugoniot contact stress of two like bodies is the acoustic
        // one times (1 + s M/2), so below M = 0.01 the acoustic solver is
        // exact to a fraction of a percent; towards 1 the Hugoniot changes
        // shock speed and separation time substantially
        OStringStream reason;
        if (!mA.hugoniot() && !mB.hugoniot())
        {
            type = "acoustic";
            reason << "auto: neither material has a Hugoniot";
        }
        else if (bodyA.driven() || bodyB.driven())
        {
            type = "hugoniot";
            reason << "auto: a Hugoniot material, and a driven body (the"
                << " initial velocities do not bound the impact speed)";
        }
        else if (M >= 0.01)
        {
            type = "hugoniot";
            reason << "auto: a Hugoniot material at impact Mach number "
                << M << " >= 0.01";
        }
        else
        {
            type = "acoustic";
            reason << "auto: impact Mach number " << M << " < 0.01, where"
                << " the acoustic contact stress is within s M/2 of the"
                << " Hugoniot one";
        }
        riemannChoice_ = reason.str();
    }
    riemann_ = contactRiemannSolver::New(dict_, type);

    // Bodies without shear stiffness on tetrahedra: their end faces'
    // points have half cells of depths that differ threefold and nothing
    // pulls the struck points back into line (doc/results.md, "Why the
    // struck faces of tets go uneven").  Said at the start, not only after
    // the failure
    string bodies;
    bool driven = false;
    for (const solidBody* b : {&bodyA, &bodyB})
    {
        if (b->material().shearFree() && b->dual().triangleBoundary())
        {
            bodies += (bodies.empty() ? "" : " and ") + b->name();
            driven = driven || b->driven();
        }
    }
    if (!bodies.empty() && (M >= shearFreeTetsMach || driven))
    {
        WarningInFunction
            << "Contact " << name_ << ": " << bodies.c_str() << " without shear"
            << " stiffness (mu = 0) meshed with tetrahedra, impact Mach"
            << " number " << M << (driven ? " or more (a driven body)" : "")
            << ". Such pairs on tets stop from about 3 times the wave"
            << " speed; mesh them with hexahedra (README, known"
            << " limitations)." << endl;
    }
}


void Foam::contactPair::write() const
{
    dictionary state;
    state.add("maxPenetration", maxPenetration_);
    if (useAMI_)
    {
        // A list entry is turned into tokens here, at the stream precision
        // of the moment: full precision, so that the restart maps the same
        // surfaces to the last bit
        const unsigned int precision = IOstream::defaultPrecision(17);
        state.add("mappedA", mappedA_);
        state.add("mappedB", mappedB_);
        IOstream::defaultPrecision(precision);
        state.add("closedA", uniqueFlags(A_, surfaceA_, A_.closed));
    }
    writeUniformState(stateName(), time(), state);
}


Foam::labelList Foam::contactPair::uniqueFlags
(
    const contactSide& side,
    const dualSurface& surface,
    const boolList& flags
) const
{
    labelList local(side.points.size());
    forAll(side.points, i)
    {
        local[i] = flags[i];
    }
    // (the processor copies of a point carry the same flag)
    const labelList copies(allGather(local));
    labelList unique(surface.uniqueCopies.size(), 0);
    forAll(copies, k)
    {
        label& u = unique[surface.copyUnique[k]];
        u = max(u, copies[k]);
    }
    return unique;
}


void Foam::contactPair::restartMapping(const IOdictionary& state)
{
    // The surfaces of the last mapping: the same overlaps, and slides
    // measured from where they were
    const pointField uniqueA(readUniformEntry<pointField>(state, "mappedA"));
    const pointField uniqueB(readUniformEntry<pointField>(state, "mappedB"));
    const labelList closedA(readUniformEntry<labelList>(state, "closedA"));
    const label nA = surfaceA_.uniqueCopies.size();
    const label nB = surfaceB_.uniqueCopies.size();
    if
    (
        uniqueA.size() != nA || uniqueB.size() != nB
     || closedA.size() != nA
    )
    {
        FatalIOErrorInFunction(state)
            << "Contact pair '" << name_ << "': the restart file holds "
            << uniqueA.size() << " and " << uniqueB.size()
            << " surface points (closed flags: " << closedA.size()
            << "), the patches have " << nA << " and " << nB << nl
            << "    It was written for other meshes: restart from a time"
            << " written with these meshes." << exit(FatalIOError);
    }
    mapByAMI(uniqueA, uniqueB);

    // Which points the pair holds closed (their pairs stay closed while
    // the gap is below holdTolerance)
    forAll(A_.points, i)
    {
        A_.closed[i] = closedA[surfaceA_.copyUnique[A_.offset + i]];
    }
}


void Foam::contactPair::addNonMatchingFluxes()
{
    // One Riemann problem per overlap of an A cell with a B cell, between
    // the two points' own states.  Each side's contact traction and
    // velocity are the overlap-weighted averages of its pairs' solutions:
    // every pair solution satisfies both sides' characteristic relations,
    // so the averages do too (each side's boundary is consistent), and the
    // two surfaces share one interface velocity field
    label nPairs = nPairsA();
    vectorField tPair(nPairs), vBPair(nPairs);
    scalarField touchingPairs(nPairs, 0.0);
    scalarField powerA(A_.points.size(), 0.0);
    scalarField powerB(A_.points.size(), 0.0);
    vector vA, vOther;
    nPairs = 0;
    forAll(A_.points, i)
    {
        const pointData& a = dataA_[i];
        const labelList& from = A_.stateFrom[i];
        const scalarList& w = A_.stateWeight[i];
        A_.touching[i] = false;
        if (from.empty())
        {
            scalar closingPower;
            pairState
            (
                false, GREAT, a, mirrored(a), A_.tC[i], A_.vC[i], vOther,
                closingPower
            );
            powerA[i] = A_.tC[i] & A_.vC[i];
            continue;
        }
        A_.tC[i] = Zero;
        A_.vC[i] = Zero;
        scalar fraction = 0;
        forAll(from, m)
        {
            const pointData& b = dataB_[from[m]];
            const bool closed = A_.pairClosed[i][m];
            const scalar allowance =
                closed ? 0 : closingAllowance(A_.pairGap0[i][m], pairGap(a, b));
            scalar closingPower;
            const bool touching = pairState
            (
                closed, allowance, a, b, tPair[nPairs], vA, vBPair[nPairs],
                closingPower
            );
            touchingPairs[nPairs] = touching;
            fraction += touching*w[m];
            A_.tC[i] += w[m]*tPair[nPairs];
            A_.vC[i] += w[m]*vA;
            powerA[i] += w[m]*((tPair[nPairs] & vA) - closingPower);
            powerB[i] += w[m]*(tPair[nPairs] & vBPair[nPairs]);
            ++nPairs;
        }
        // Closed pairs always touch, so a closed point does too
        A_.touching[i] = (fraction > 0.5);
        if (A_.closed[i])
        {
            // Interpenetration: against the other surface averaged over the
            // cell (a pair's own gap on a curved surface also counts the
            // surface's bow between the two points)
            pointData partner;
            partnerData(A_, i, dataB_, partner);
            maxPenetration_ =
                max(maxPenetration_, -pairGap(a, partner)/a.length);
        }
        if (A_.touching[i])
        {
            A_.body->residual().prescribeSurfaceVelocity
            (
                A_.points[i], A_.vC[i]
            );
        }
    }
    reduce(maxPenetration_, maxOp<scalar>());

    // A's forces: its tractions integrated over its sub-faces
    addSideFluxes(A_, true);
    addPairPower(powerA, powerB);
    const List<vector> tAll(exchangedPairs(tPair));
    const List<vector> vBAll(exchangedPairs(vBPair));
    B_.touching =
        byMajority(B_, B_.pairIndex, exchangedPairs(touchingPairs));

    // B: its pairs' solutions averaged over its cell for its velocity (and
    // the power); for its momentum, minus the forces its own pairs'
    // tractions make on A: A point k's force is a_k t_k, t_k = sum_b w_kb
    // t*_kb, so B point b takes a_k w_kb t*_kb from each of its pairs, and
    // the momentum exchanged is equal and opposite to round-off.  (Taking
    // the share w_kb of A's force a_k t_k instead, the average of all of
    // k's pairs, left the points of a B mesh finer than A's without forces
    // of their own: their face crushed (C3, 4 / 8 cells across: shortest
    // edge 0.26 of its length, interpenetration 0.33 edge lengths))
    const materialModel& mB = B_.body->material();
    vectorField FB(B_.points.size(), Zero);
    forAll(B_.points, i)
    {
        const pointData& b = dataB_[i];
        const labelList& pairs = B_.pairIndex[i];
        const scalarList& w = B_.stateWeight[i];
        B_.tC[i] = Zero;
        if (pairs.empty())
        {
            B_.vC[i] = acousticFormulas::tractionVelocity
            (
                b.t, b.v, Zero, b.n, mB.Zp(), mB.Zs()
            );
        }
        else
        {
            B_.vC[i] = Zero;
            forAll(pairs, m)
            {
                B_.tC[i] -= w[m]*tAll[pairs[m]];
                B_.vC[i] += w[m]*vBAll[pairs[m]];
            }
        }
        const labelList& from = B_.forceFrom[i];
        const scalarList& share = B_.forceShare[i];
        const labelList& pairOfShare = B_.forcePair[i];
        forAll(from, m)
        {
            FB[i] -= (share[m]*forceAreaA_[from[m]])*tAll[pairOfShare[m]];
        }
        if (B_.touching[i])
        {
            B_.body->residual().prescribeSurfaceVelocity
            (
                B_.points[i], B_.vC[i]
            );
        }
    }
    addSideFluxes(B_, false);

    List<vector>& RpB = B_.body->residual().momentum;
    const dualMesh& dualB = B_.body->dual();
    forAll(B_.points, i)
    {
        RpB[B_.points[i]] += dualB.pointWeight(B_.points[i])*FB[i];
    }
}


void Foam::contactPair::addFluxes()
{
    const scopeTimer timer(wallTime_);
    dataA_ = exchangeData(A_);
    dataB_ = exchangeData(B_);
    if (useAMI_)
    {
        addNonMatchingFluxes();
        ++stage_;
        return;
    }

    // Pairs closed at the start of the step, and open ones shutting their
    // gap in this stage, move with their Riemann velocities, also when
    // tension releases them: the traction-free velocities then open the
    // gap (for the acoustic solver tension is exactly that condition),
    // whereas the nodal velocities, driven by the rest of the control
    // volume, can carry the released points through each other (B2:
    // contact corners pulled past the plane by the side surface rolling
    // over).  Other open pairs move with their nodal velocities.
    vector vOther;
    pointData partner;
    scalarField powerA(A_.points.size());
    scalarField powerB(A_.points.size());
    forAll(A_.points, i)
    {
        const pointData& a = dataA_[i];
        scalar allowance = GREAT;
        if (partnerData(A_, i, dataB_, partner))
        {
            allowance = closingAllowance(A_.gap0[i], pairGap(a, partner));
        }
        else
        {
            partner = mirrored(a);
        }
        scalar closingPower;
        A_.touching[i] = pairState
        (
            A_.closed[i], allowance, a, partner, A_.tC[i], A_.vC[i], vOther,
            closingPower
        );
        powerA[i] = (A_.tC[i] & A_.vC[i]) - closingPower;
        powerB[i] = A_.tC[i] & vOther;
        if (A_.touching[i])
        {
            A_.body->residual().prescribeSurfaceVelocity
            (
                A_.points[i], A_.vC[i]
            );
        }
        if (A_.closed[i])
        {
            const scalar pen = -pairGap(a, partner);
            maxPenetration_ = max(maxPenetration_, pen/a.length);
        }
    }
    forAll(B_.points, i)
    {
        const pointData& b = dataB_[i];
        scalar allowance = GREAT;
        if (partnerData(B_, i, dataA_, partner))
        {
            allowance = closingAllowance(B_.gap0[i], pairGap(partner, b));
        }
        else
        {
            partner = mirrored(b);
        }
        vector tC;
        scalar closingPower;
        B_.touching[i] = pairState
        (
            B_.closed[i], allowance, partner, b, tC, vOther, B_.vC[i],
            closingPower
        );
        if (B_.touching[i])
        {
            B_.body->residual().prescribeSurfaceVelocity
            (
                B_.points[i], B_.vC[i]
            );
        }
        B_.tC[i] = -tC;
    }
    reduce(maxPenetration_, maxOp<scalar>());

    // A: its own integrated tractions.  B: minus its shares of the forces
    // of its partners on A (summed over the processor copies of a partner,
    // shared by B's processor copies of the point through the point
    // weights)
    addSideFluxes(A_, true);
    addSideFluxes(B_, false);
    addPairPower(powerA, powerB);
    ++stage_;

    const List<vector> forceA(exchanged(A_, tractionForcesA()));
    List<vector>& RpB = B_.body->residual().momentum;
    const dualMesh& dualB = B_.body->dual();
    forAll(B_.points, i)
    {
        vector F(Zero);
        const labelList& from = B_.forceFrom[i];
        const scalarList& share = B_.forceShare[i];
        forAll(from, m)
        {
            F -= share[m]*forceA[from[m]];
        }
        RpB[B_.points[i]] += dualB.pointWeight(B_.points[i])*F;
    }
}


void Foam::contactPair::startStep(const scalar dt)
{
    const scopeTimer timer(wallTime_);
    deltaT_ = dt;
    stage_ = 0;

    if (useAMI_ && needsMapping())
    {
        mapByAMI();
    }

    const List<pointData> a(exchangeData(A_));
    const List<pointData> b(exchangeData(B_));

    if (useAMI_)
    {
        // Every overlap pair against its own gap; a point is closed (moves
        // with its contact velocity) when the overlap-weighted majority of
        // its pairs is.  The two sides' points do not move in lock-step,
        // so the pairs of a closed point stay closed while their gap is
        // below holdTolerance; tension still releases them at once
        DynamicList<scalar> closedPairs;
        forAll(A_.points, i)
        {
            const pointData& da = a[i];
            const labelList& from = A_.stateFrom[i];
            const scalarList& w = A_.stateWeight[i];
            const scalar tol =
                (A_.closed[i] ? holdTolerance : gapTolerance)*da.length;
            A_.pairClosed[i].setSize(from.size());
            A_.pairGap0[i].setSize(from.size());
            scalar fraction = 0;
            forAll(from, m)
            {
                const scalar gap = pairGap(da, b[from[m]]);
                const bool closed = (gap <= tol);
                A_.pairGap0[i][m] = gap;
                A_.pairClosed[i][m] = closed;
                closedPairs.append(closed);
                fraction += closed*w[m];
            }
            A_.closed[i] = (fraction > 0.5);
        }
        B_.closed =
            byMajority(B_, B_.pairIndex, exchangedPairs(closedPairs));
        markClosed();
        return;
    }

    // A's points against their partner states.  B's points take the
    // verdict of their partners on A (the overlap-weighted majority), so
    // that a B point never receives forces from A as open or moves with A
    // as closed on a verdict of its own: for a matched pair both points
    // then have the same flag
    List<scalar> closedA(A_.points.size(), 0.0);
    pointData partner;
    forAll(A_.points, i)
    {
        const pointData& da = a[i];
        A_.closed[i] = false;
        A_.gap0[i] = GREAT;
        if (partnerData(A_, i, b, partner))
        {
            A_.gap0[i] = pairGap(da, partner);
            A_.closed[i] = (A_.gap0[i] <= gapTolerance*da.length);
        }
        closedA[i] = A_.closed[i];
    }
    B_.closed = byMajority(B_, B_.stateFrom, exchanged(A_, closedA));

    // B's own gaps (its closing allowances)
    forAll(B_.points, i)
    {
        B_.gap0[i] = GREAT;
        if (partnerData(B_, i, a, partner))
        {
            B_.gap0[i] = pairGap(partner, b[i]);
        }
    }
    markClosed();
}


void Foam::contactPair::markClosed()
{
    // The bodies keep the normals of their closed points on their deformed
    // surfaces (contactRotation.H)
    A_.body->contactRotations().setClosed(A_.points, A_.closed);
    B_.body->contactRotations().setClosed(B_.points, B_.closed);
}


Foam::boolList Foam::contactPair::byMajority
(
    const contactSide& side,
    const labelListList& index,
    const UList<scalar>& flags
)
{
    boolList result(side.points.size());
    forAll(side.points, i)
    {
        const labelList& from = index[i];
        const scalarList& w = side.stateWeight[i];
        scalar fraction = 0;
        forAll(from, m)
        {
            fraction += w[m]*flags[from[m]];
        }
        result[i] = (fraction > 0.5);
    }
    return result;
}


Foam::label Foam::contactPair::localOffset(const label localSize)
{
    labelList sizes(Pstream::nProcs(), 0);
    sizes[Pstream::myProcNo()] = localSize;
    Pstream::listCombineGather(sizes, plusEqOp<label>());
    Pstream::listCombineScatter(sizes);
    label offset = 0;
    for (label p = 0; p < Pstream::myProcNo(); ++p)
    {
        offset += sizes[p];
    }
    return offset;
}


template<class GapFn>
void Foam::contactPair::forEachGap
(
    const List<pointData>& a,
    const List<pointData>& b,
    const GapFn& gapFn
) const
{
    auto pairGap = [&](const pointData& da, const pointData& db)
    {
        const vector n(gapDirection(pairNormal(da, db)));
        gapFn(da, (db.x - da.x) & n, (da.v - db.v) & n);
    };
    if (useAMI_)
    {
        // Every overlap pair between its two points' own states
        forAll(A_.points, i)
        {
            for (const label k : A_.stateFrom[i])
            {
                pairGap(a[i], b[k]);
            }
        }
        return;
    }
    // A's points against their matched partners
    pointData partner;
    forAll(A_.points, i)
    {
        if (partnerData(A_, i, b, partner))
        {
            pairGap(a[i], partner);
        }
    }
}


Foam::scalar Foam::contactPair::deltaTLimit(const scalar dtFloor) const
{
    const scopeTimer timer(wallTime_);
    scalar dt = GREAT;
    forEachGap
    (
        exchangeData(A_), exchangeData(B_),
        [&](const pointData& da, const scalar gap, const scalar closing)
        {
            if
            (
                gap > gapTolerance*da.length && closing > 0
             && gap > closing*dtFloor
            )
            {
                dt = min(dt, gap/closing);
            }
        }
    );
    return returnReduce(dt, minOp<scalar>());
}


void Foam::contactPair::gapState(bool& closed, scalar& timeToClose) const
{
    const scopeTimer timer(wallTime_);
    closed = false;
    timeToClose = GREAT;
    forEachGap
    (
        exchangeData(A_), exchangeData(B_),
        [&](const pointData& da, const scalar gap, const scalar closing)
        {
            if (gap <= gapTolerance*da.length)
            {
                closed = true;
            }
            else if (closing > 0)
            {
                timeToClose = min(timeToClose, gap/closing);
            }
        }
    );
    reduce(closed, orOp<bool>());
    reduce(timeToClose, minOp<scalar>());
}


void Foam::contactPair::describe(Ostream& os) const
{
    os  << "Contact " << name_ << ": " << A_.body->name() << "/"
        << A_.body->mesh().boundaryMesh()[A_.patchi].name() << " - "
        << B_.body->name() << "/"
        << B_.body->mesh().boundaryMesh()[B_.patchi].name()
        << ", " << returnReduce(A_.points.size(), sumOp<label>())
        << " point pairs, Riemann solver ";
    riemann_->describe(os);
    if (riemann_->type() == "hugoniot")
    {
        const materialModel& mA = A_.body->material();
        const materialModel& mB = B_.body->material();
        os  << " (s " << (mA.hugoniot() ? mA.hugoniotS() : 0) << " / "
            << (mB.hugoniot() ? mB.hugoniotS() : 0) << ")";
    }
    os  << " (" << riemannChoice_.c_str() << "), friction ";
    friction_->describe(os);
    if (useAMI_)
    {
        os  << ", non-matching (AMI, remapped after slides of " << AMIUpdate_
            << " edge lengths; first mapping " << mappingTime_ << " s)";
    }
    else
    {
        os  << ", matching point for point";
    }
    if (Pstream::parRun())
    {
        // Values each stage moves between processors: the remote partner
        // values received (gathering both surfaces onto every processor
        // would move every other processor's values to each)
        label received =
            toA_->constructSize() - B_.points.size()
          + toB_->constructSize() - A_.points.size();
        label all = A_.points.size() + B_.points.size();
        if (useAMI_)
        {
            received += pairsToB_->constructSize() - nPairsA();
            all += nPairsA();
        }
        reduce(received, sumOp<label>());
        reduce(all, sumOp<label>());
        os  << nl << "    processor exchange: " << received
            << " remote point and pair values per stage (gathering the"
            << " surfaces would move " << (Pstream::nProcs() - 1)*all << ")";
    }
    os  << nl;
}


// ************************************************************************* //
