/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "dualMesh.H"
#include "unitConversion.H"
#include <Eigen/Eigenvalues>
#include "Time.H"
#include "polyMesh.H"
#include "coupledPolyPatch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dualMesh, 0);
}


// * * * * * * * * * * * * * Local Helper Functions  * * * * * * * * * * * * //

namespace
{

// Area vector of the median-dual sub-face of vertex a in a face, the
// quadrilateral (a, mid(a,next), face centre, mid(prev,a)), oriented with
// the face (right-hand rule on the face's point order)
inline Foam::vector subFaceArea
(
    const Foam::point& a,
    const Foam::point& mNext,
    const Foam::point& fc,
    const Foam::point& mPrev
)
{
    return 0.5*(((mNext - a) ^ (fc - a)) + ((fc - a) ^ (mPrev - a)));
}

// Area vector of the dual triangle (edge midpoint, face centre, cell
// centre) of the edge from a face point to the next one, oriented from that
// point to the next when the face points out of the cell
inline Foam::vector dualTriangleArea
(
    const Foam::point& mNext,
    const Foam::point& fc,
    const Foam::point& cc
)
{
    return 0.5*((cc - mNext) ^ (fc - mNext));
}

// Signed volume of the pyramid with apex cc over that sub-face, positive
// when the face is oriented away from cc: the two tetrahedra (a, mNext,
// fc, cc) and (a, fc, mPrev, cc).  With moment, also their first moment
// about a (each one's volume times its centroid less a)
inline Foam::scalar subFacePyramidVolume
(
    const Foam::point& a,
    const Foam::point& mNext,
    const Foam::point& fc,
    const Foam::point& mPrev,
    const Foam::point& cc,
    Foam::vector* moment = nullptr
)
{
    const Foam::vector ra(a - cc);
    const Foam::scalar six1 = ra & ((mNext - cc) ^ (fc - cc));
    const Foam::scalar six2 = ra & ((fc - cc) ^ (mPrev - cc));
    if (moment)
    {
        *moment =
            (1.0/24.0)
           *(
                six1*((mNext - a) + (fc - a) + (cc - a))
              + six2*((fc - a) + (mPrev - a) + (cc - a))
            );
    }
    return (six1 + six2)/6.0;
}

// The mesh edge a-b among the edges of point a (what primitiveMesh's
// faceEdges would hold, without its list per face)
inline Foam::label edgeOf
(
    const Foam::edgeList& edges,
    const Foam::labelList& edgesOfA,
    const Foam::label a,
    const Foam::label b
)
{
    for (const Foam::label e : edgesOfA)
    {
        if (edges[e].otherVertex(a) == b)
        {
            return e;
        }
    }
    return -1;
}

// A strict order of two distinct points that every processor agrees on,
// to give shared edges one orientation while summing across processors
inline bool lexLess(const Foam::point& p, const Foam::point& q)
{
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    return p.z() < q.z();
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dualMesh::checkCells(const scalarField& V) const
{
    // An inverted cell would enter the dual with negative sub-volumes (the
    // run then creates energy) and a flat one divides by zero: stop with
    // the first such cell.  Flat means below 1e-12 of the mean volume.
    const scalar meanV =
        returnReduce(sum(mag(V)), sumOp<scalar>())
       /max(returnReduce(V.size(), sumOp<label>()), label(1));
    label bad = -1;
    forAll(V, celli)
    {
        if (!(V[celli] > 1e-12*meanV))
        {
            bad = celli;
            break;
        }
    }
    if (returnReduce(bad < 0, andOp<bool>()))
    {
        return;
    }
    if (bad >= 0)
    {
        point centre(Zero);
        const labelList& cPoints = mesh_.cellPoints()[bad];
        for (const label pointi : cPoints)
        {
            centre += mesh_.points()[pointi];
        }
        centre /= max(cPoints.size(), label(1));
        FatalErrorInFunction
            << "Cell " << bad << " of the mesh "
            << mesh_.time().path()/mesh_.facesInstance()/mesh_.meshDir()
            << (Pstream::parRun() ? " (this processor's numbering)" : "")
            << " at " << centre << " has volume " << V[bad]
            << (V[bad] < -1e-12*meanV ? " (inverted)" : " (flat)")
            << "; mean cell volume " << meanV << nl
            << "    Fix the mesh (checkMesh lists its faults)."
            << exit(FatalError);
    }
    // (Other processors go on to the next collective operation, where the
    // reporting processor's abort ends them)
}


void Foam::dualMesh::calcCellContributions
(
    const pointField& cellCentres,
    vectorField& edgeC,
    const labelUList& momentIndex,
    vectorField& moment
)
{
    const pointField& X = mesh_.points();
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const edgeList& edges = mesh_.edges();
    const labelListList& pointEdges = mesh_.pointEdges();

    // Every face is visited once; it contributes to its owner cell (face
    // oriented outwards) and, if internal, to its neighbour (inwards).
    // Edge fp of a face joins f[fp] -> f[fp+1] (primitiveMesh convention).
    forAll(faces, facei)
    {
        const face& f = faces[facei];
        vector fc, fA;
        faceGeometry(f, X, fc, fA);
        const label nSides = (facei < mesh_.nInternalFaces()) ? 2 : 1;

        for (label side = 0; side < nSides; ++side)
        {
            const label celli = (side == 0) ? own[facei] : nei[facei];
            const scalar sgn = (side == 0) ? 1.0 : -1.0;
            const point& cc = cellCentres[celli];

            forAll(f, fp)
            {
                const label a = f[fp];
                const label b = f.nextLabel(fp);
                const label z = f.prevLabel(fp);
                const point mNext(0.5*(X[a] + X[b]));
                const point mPrev(0.5*(X[z] + X[a]));

                // Dual triangle (midpoint, face centre, cell centre) of edge
                // a-b in this cell; with the face oriented out of the cell
                // this orientation points from a to b
                const vector S(sgn*dualTriangleArea(mNext, fc, cc));
                const label e = edgeOf(edges, pointEdges[a], a, b);
                if (edgeStart_[e] == a)
                {
                    edgeC[e] += S;
                }
                else
                {
                    edgeC[e] -= S;
                }

                vector m;
                volume_[a] +=
                    sgn
                   *subFacePyramidVolume
                    (
                        X[a], mNext, fc, mPrev, cc,
                        momentIndex[a] >= 0 ? &m : nullptr
                    );
                if (momentIndex[a] >= 0)
                {
                    moment[momentIndex[a]] += sgn*m;
                }
            }
        }
    }
}


void Foam::dualMesh::calcBoundarySubFaces()
{
    const pointField& X = mesh_.points();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    patchSubFaces_.setSize(patches.size());

    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        patchSubFaces& psf = patchSubFaces_[patchi];

        if (pp.coupled())
        {
            continue;
        }

        label n = 0;
        forAll(pp, i)
        {
            n += pp[i].size();
        }
        psf.point.setSize(n);
        psf.prev.setSize(n);
        psf.next.setSize(n);
        psf.area.setSize(n);
        psf.nbrWeight.setSize(n);

        n = 0;
        forAll(pp, i)
        {
            const face& f = pp[i];
            vector fc, fA;
            faceGeometry(f, X, fc, fA);

            forAll(f, fp)
            {
                const label a = f[fp];
                const label b = f.nextLabel(fp);
                const label z = f.prevLabel(fp);

                psf.point[n] = a;
                psf.prev[n] = z;
                psf.next[n] = b;
                psf.nbrWeight[n] = (f.size() == 3) ? 0.125 : 0.0;
                psf.area[n] =
                    subFaceArea
                    (
                        X[a], 0.5*(X[a] + X[b]), fc, 0.5*(X[z] + X[a])
                    );
                ++n;
            }
        }
    }
}


void Foam::dualMesh::synchronise(vectorField& edgeC)
{
    if (Pstream::parRun())
    {
        const pointField& X = mesh_.points();

        syncTools::syncPointList(mesh_, volume_, plusEqOp<scalar>(), 0.0);
        scalarField nHolders(volume_.size(), 1.0);
        syncTools::syncPointList
        (
            mesh_, nHolders, plusEqOp<scalar>(), 0.0
        );
        forAll(nHolders, i)
        {
            multiplicity_[i] = uint8_t(nHolders[i] + 0.5);
        }

        // Shared edges may be oriented differently on each processor:
        // sum them in a common (lexicographic) orientation
        forAll(edgeC, e)
        {
            if (!lexLess(X[edgeStart_[e]], X[edgeEnd_[e]]))
            {
                edgeC[e] = -edgeC[e];
            }
        }
        syncTools::syncEdgeList
        (
            mesh_, edgeC, plusEqOp<vector>(), vector(Zero)
        );
        forAll(edgeC, e)
        {
            if (!lexLess(X[edgeStart_[e]], X[edgeEnd_[e]]))
            {
                edgeC[e] = -edgeC[e];
            }
        }
    }

    // The normals are made in place and the list handed over: a second
    // edge-sized vector list would sit on the construction's memory peak
    edgeMagSf_.setSize(edgeC.size());
    forAll(edgeC, e)
    {
        const scalar magC = mag(edgeC[e]);
        edgeC[e] /= max(magC, VSMALL);
        edgeMagSf_[e] = magC;
    }
    if (Pstream::parRun())
    {
        // Each processor holding a shared edge keeps its share
        edgeMagSf_ *= edgeWeights();
    }
    edgeNormal_.transfer(edgeC);
}


void Foam::dualMesh::calcPointEdges()
{
    const label nPts = volume_.size();

    pointEdgeStart_.setSize(nPts + 1);
    pointEdgeStart_ = 0;
    forAll(edgeStart_, e)
    {
        ++pointEdgeStart_[edgeStart_[e] + 1];
        ++pointEdgeStart_[edgeEnd_[e] + 1];
    }
    for (label i = 0; i < nPts; ++i)
    {
        pointEdgeStart_[i + 1] += pointEdgeStart_[i];
    }

    pointEdges_.setSize(pointEdgeStart_[nPts]);
    labelList fill(SubList<label>(pointEdgeStart_, nPts));
    forAll(edgeStart_, e)
    {
        pointEdges_[fill[edgeStart_[e]]++] = e;
        pointEdges_[fill[edgeEnd_[e]]++] = e;
    }
}


void Foam::dualMesh::calcBoundaryNormals()
{
    // Patch by patch (the same physical patches on every processor, before
    // the processor patches), each of the point's planes of the patch
    // (patchPointPlanes: both where one patch folds round an edge) with the
    // part along the normals already taken removed; a normal within about
    // 17 degrees of those (a curved patch continuing another) adds nothing
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    FixedList<vector, 3> none;
    none = Zero;
    List<FixedList<vector, 3>> normals(nPoints(), none);
    labelList nNormals(nPoints(), 0);
    forAll(patches, patchi)
    {
        if (patches[patchi].coupled())
        {
            continue;
        }
        List<FixedList<vector, 3>> planes;
        labelList nPlanes;
        patchPointPlanes(patchi, planes, nPlanes);
        forAll(planes, i)
        {
            for (label p = 0; p < nPlanes[i] && nNormals[i] < 3; ++p)
            {
                const vector& Np = planes[i][p];
                vector r(Np);
                for (label k = 0; k < nNormals[i]; ++k)
                {
                    r -= (normals[i][k] & Np)*normals[i][k];
                }
                const scalar magR = mag(r);
                if (magR > 0.3)
                {
                    normals[i][nNormals[i]++] = r/magR;
                }
            }
        }
    }

    DynamicList<label> points;
    DynamicList<FixedList<vector, 3>> pointNormals;
    boundaryIndex_.setSize(nPoints());
    boundaryIndex_ = -1;
    forAll(nNormals, i)
    {
        if (nNormals[i])
        {
            boundaryIndex_[i] = points.size();
            points.append(i);
            pointNormals.append(normals[i]);
        }
    }
    boundaryPoints_.transfer(points);
    boundaryNormals_.transfer(pointNormals);
}


const Foam::scalar Foam::dualMesh::featureAngle = 30;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dualMesh::dualMesh(const polyMesh& mesh)
:
    mesh_(mesh),
    edgeStart_(mesh.nEdges()),
    edgeEnd_(mesh.nEdges()),
    edgeNormal_(),
    edgeMagSf_(),
    volume_(mesh.nPoints(), 0.0),
    multiplicity_(mesh.nPoints(), uint8_t(1)),
    patchSubFaces_(),
    pointEdgeStart_(),
    pointEdges_(),
    boundaryPoints_(),
    boundaryNormals_(),
    boundaryIndex_(),
    boundaryCentroidOffset_(),
    linearExact_(calcLinearExact()),
    faceEdges_(),
    deformable_(false)
{
    const edgeList& edges = mesh.edges();
    const pointField& X = mesh.points();

    forAll(edges, e)
    {
        edgeStart_[e] = edges[e].start();
        edgeEnd_[e] = edges[e].end();
    }

    {
        // Build-time data: cell centres and volumes, and the full area
        // vectors of the edges (the fluxes keep their normals and this
        // processor's share of their magnitudes)
        pointField cellCentres;
        scalarField cellVolumes;
        calcCellCentres(X, nullptr, nullptr, cellCentres, cellVolumes);
        checkCells(cellVolumes);
        cellVolumes.clear();

        // The first moments of the dual cells of the points on physical
        // patches (on any processor), kept for those points only
        boolList onPatch(mesh.nPoints(), false);
        const polyBoundaryMesh& patches = mesh.boundaryMesh();
        for
        (
            label facei = mesh.nInternalFaces();
            facei < mesh.nFaces();
            ++facei
        )
        {
            if (!patches[patches.whichPatch(facei)].coupled())
            {
                for (const label i : mesh.faces()[facei])
                {
                    onPatch[i] = true;
                }
            }
        }
        if (Pstream::parRun())
        {
            syncTools::syncPointList(mesh, onPatch, orEqOp<bool>(), false);
        }
        labelList momentIndex(mesh.nPoints(), -1);
        label nMoments = 0;
        forAll(onPatch, i)
        {
            if (onPatch[i])
            {
                momentIndex[i] = nMoments++;
            }
        }
        onPatch.clear();
        vectorField moment(nMoments, Zero);

        vectorField edgeC(mesh.nEdges(), Zero);
        calcCellContributions(cellCentres, edgeC, momentIndex, moment);
        cellCentres.clear();
        calcBoundarySubFaces();
        synchronise(edgeC);
        if (Pstream::parRun())
        {
            vectorField all(mesh.nPoints(), Zero);
            forAll(momentIndex, i)
            {
                if (momentIndex[i] >= 0)
                {
                    all[i] = moment[momentIndex[i]];
                }
            }
            syncTools::syncPointList
            (
                mesh, all, plusEqOp<vector>(), vector(Zero)
            );
            forAll(momentIndex, i)
            {
                if (momentIndex[i] >= 0)
                {
                    moment[momentIndex[i]] = all[i];
                }
            }
        }
        calcPointEdges();
        calcBoundaryNormals();
        boundaryCentroidOffset_.setSize(boundaryPoints_.size());
        forAll(boundaryPoints_, b)
        {
            const label i = boundaryPoints_[b];
            const label k = momentIndex[i];
            boundaryCentroidOffset_[b] =
                k >= 0 ? vector(-moment[k]/volume_[i]) : vector(Zero);
        }
    }

    forAll(volume_, i)
    {
        if (volume_[i] <= 0)
        {
            FatalErrorInFunction
                << "Control volume of point " << i << " at "
                << X[i] << " is " << volume_[i] << " (not positive)."
                << nl << "    The mesh "
                << mesh.time().path()/mesh.facesInstance()/mesh.meshDir()
                << " has inverted or badly distorted cells: run checkMesh."
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::dualMesh::lengths() const
{
    const pointField& X = mesh_.points();
    tmp<scalarField> tl(new scalarField(nPoints(), GREAT));
    scalarField& l = tl.ref();
    forAll(edgeStart_, e)
    {
        const label i = edgeStart_[e], j = edgeEnd_[e];
        const scalar le = mag(X[j] - X[i]);
        l[i] = min(l[i], le);
        l[j] = min(l[j], le);
    }
    if (Pstream::parRun())
    {
        syncTools::syncPointList(mesh_, l, minEqOp<scalar>(), GREAT);
    }
    return tl;
}


bool Foam::dualMesh::patchFlat
(
    const label patchi,
    const scalar maxAngle
) const
{
    const vectorField& A = patchSubFaces_[patchi].area;
    const vector mean(patchArea(patchi));
    if (mag(mean) < VSMALL)
    {
        return false;
    }
    const vector n(mean/mag(mean));
    scalar minCos = 1;
    forAll(A, s)
    {
        minCos = min(minCos, (A[s] & n)/max(mag(A[s]), VSMALL));
    }
    reduce(minCos, minOp<scalar>());
    return minCos >= std::cos(degToRad(maxAngle));
}


Foam::vector Foam::dualMesh::patchArea(const label patchi) const
{
    return returnReduce(sum(patchSubFaces_[patchi].area), sumOp<vector>());
}


Foam::scalar Foam::dualMesh::patchSpan(const label patchi) const
{
    const vector A(patchArea(patchi));
    const scalar magA = mag(A);
    if (magA < VSMALL)
    {
        return 0;
    }
    const scalarField Xn(mesh_.points() & (A/magA));
    const scalar extent = gMax(Xn) - gMin(Xn);
    const scalar V = sumPoints(volumes());
    return V > VSMALL ? magA*extent/V : 0;
}


Foam::scalar Foam::dualMesh::minLength() const
{
    return gMin(lengths());
}


Foam::boolList Foam::dualMesh::patchFeaturePoints
(
    const label patchi,
    const vectorField& meanN
) const
{
    // The smallest cosine between a sub-face and its point's mean normal,
    // over processors
    const patchSubFaces& sf = patchSubFaces_[patchi];
    scalarField minCos(nPoints(), 1.0);
    forAll(sf.point, s)
    {
        const label i = sf.point[s];
        const scalar a = mag(sf.area[s]);
        if (a > VSMALL)
        {
            minCos[i] = min(minCos[i], (sf.area[s] & meanN[i])/a);
        }
    }
    syncTools::syncPointList(mesh_, minCos, minEqOp<scalar>(), 1.0);

    const scalar cosFeature = Foam::cos(degToRad(featureAngle));
    boolList feature(nPoints());
    forAll(minCos, i)
    {
        feature[i] = (minCos[i] < cosFeature);
    }
    return feature;
}


void Foam::dualMesh::patchPointPlanes
(
    const label patchi,
    List<FixedList<vector, 3>>& planes,
    labelList& nPlanes
) const
{
    const vectorField meanN(patchPointNormals(patchi));
    const boolList feature(patchFeaturePoints(patchi, meanN));
    const patchSubFaces& sf = patchSubFaces_[patchi];

    // Per point: the sub-faces' area-weighted normal tensor (summed over
    // processors, so that every processor finds the same planes)
    symmTensorField T(nPoints(), Zero);
    forAll(sf.point, s)
    {
        const scalar a = mag(sf.area[s]);
        if (a > VSMALL)
        {
            T[sf.point[s]] += sqr(sf.area[s])/a;
        }
    }
    syncTools::syncPointList
    (
        mesh_, T, plusEqOp<symmTensor>(), symmTensor::zero
    );

    FixedList<vector, 3> none;
    none = Zero;
    planes.setSize(nPoints());
    planes = none;
    nPlanes.setSize(nPoints());
    nPlanes = 0;

    // A feature point's principal directions; degenerate: the two leading
    // ones share their principal value (to 1e-6 of the largest), and are
    // only the basis (p1, p2) of their plane in which the fourth moments of
    // the sub-face normals are summed next
    boolList degenerate(nPoints(), false);
    forAll(T, i)
    {
        if (tr(T[i]) <= 0)
        {
            continue;
        }
        if (!feature[i] && magSqr(meanN[i]) > 0.25)
        {
            planes[i][0] = meanN[i];
            nPlanes[i] = 1;
            continue;
        }
        // A feature point: the directions the sub-faces' normals span
        // (eigenvalues of T at least a twentieth of the largest: two faces
        // meeting at any angle from featureAngle on, with areas up to
        // 20:1 apart)
        const symmTensor& t = T[i];
        Eigen::Matrix3d m;
        m << t.xx(), t.xy(), t.xz(),
             t.xy(), t.yy(), t.yz(),
             t.xz(), t.yz(), t.zz();
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
        const scalar lMax = eig.eigenvalues()(2);
        for (int k = 2; k >= 0; --k)
        {
            if (eig.eigenvalues()(k) >= 0.05*lMax)
            {
                const Eigen::Vector3d e(eig.eigenvectors().col(k));
                planes[i][nPlanes[i]++] = vector(e(0), e(1), e(2));
            }
        }
        if
        (
            nPlanes[i] >= 2
         && eig.eigenvalues()(2) - eig.eigenvalues()(1) <= 1e-6*lMax
        )
        {
            degenerate[i] = true;
        }
    }

    // The fourth moments sum_s |A_s| (n_s.u)^4 for u = cos(a) p1 + sin(a)
    // p2 in terms of M_jk = sum_s |A_s| (n_s.p1)^j (n_s.p2)^k, j + k = 4
    // (summed over processors like T)
    List<scalarField> M(5, scalarField(nPoints(), 0.0));
    forAll(sf.point, s)
    {
        const label i = sf.point[s];
        const scalar a = mag(sf.area[s]);
        if (!degenerate[i] || a <= VSMALL)
        {
            continue;
        }
        const vector n(sf.area[s]/a);
        const scalar c = n & planes[i][0], d = n & planes[i][1];
        M[0][i] += a*c*c*c*c;
        M[1][i] += a*c*c*c*d;
        M[2][i] += a*c*c*d*d;
        M[3][i] += a*c*d*d*d;
        M[4][i] += a*d*d*d*d;
    }
    for (scalarField& Mk : M)
    {
        syncTools::syncPointList(mesh_, Mk, plusEqOp<scalar>(), scalar(0));
    }
    forAll(degenerate, i)
    {
        if (!degenerate[i])
        {
            continue;
        }
        auto moment = [&](const scalar a)
        {
            const scalar c = Foam::cos(a), d = Foam::sin(a);
            return M[0][i]*c*c*c*c + 4*M[1][i]*c*c*c*d
                + 6*M[2][i]*c*c*d*d + 4*M[3][i]*c*d*d*d + M[4][i]*d*d*d*d;
        };
        // The largest over [0, pi) on a grid of a quarter degree, then
        // refined by golden sections within a grid step
        const label nGrid = 720;
        scalar best = 0, fBest = -GREAT;
        for (label g = 0; g < nGrid; ++g)
        {
            const scalar a = g*constant::mathematical::pi/nGrid;
            const scalar f = moment(a);
            if (f > fBest)
            {
                fBest = f;
                best = a;
            }
        }
        const scalar r = 0.5*(Foam::sqrt(5.0) - 1);
        scalar lo = best - constant::mathematical::pi/nGrid;
        scalar hi = best + constant::mathematical::pi/nGrid;
        for (label iter = 0; iter < 60; ++iter)
        {
            const scalar a1 = hi - r*(hi - lo), a2 = lo + r*(hi - lo);
            if (moment(a1) < moment(a2))
            {
                lo = a1;
            }
            else
            {
                hi = a2;
            }
        }
        const scalar a = 0.5*(lo + hi);
        const vector p1(planes[i][0]), p2(planes[i][1]);
        planes[i][0] = Foam::cos(a)*p1 + Foam::sin(a)*p2;
        planes[i][1] = -Foam::sin(a)*p1 + Foam::cos(a)*p2;
    }

    // Every plane facing out of the body: the Riemann boundary slopes
    // take the waves the face sends in along it (greenGauss.C)
    forAll(planes, i)
    {
        for (label k = 0; k < nPlanes[i]; ++k)
        {
            if ((planes[i][k] & meanN[i]) < 0)
            {
                planes[i][k] = -planes[i][k];
            }
        }
    }
}


Foam::tmp<Foam::vectorField>
Foam::dualMesh::patchPointNormals(const label patchi) const
{
    tmp<vectorField> tN(new vectorField(nPoints(), Zero));
    vectorField& N = tN.ref();
    const patchSubFaces& sf = patchSubFaces_[patchi];
    forAll(sf.point, s)
    {
        N[sf.point[s]] += sf.area[s];
    }
    syncTools::syncPointList(mesh_, N, plusEqOp<vector>(), vector::zero);
    for (vector& n : N)
    {
        n /= max(mag(n), VSMALL);
    }
    return tN;
}


bool Foam::dualMesh::calcLinearExact() const
{
    const faceList& faces = mesh_.faces();
    const pointField& X = mesh_.points();

    // A cell of four faces is a tetrahedron; a cell of six four-sided
    // faces that are all parallelograms (a - b + c - d = 0 to round-off)
    // is a parallelepiped
    auto parallelogram = [&](const face& f)
    {
        return
            f.size() == 4
         && mag(X[f[0]] - X[f[1]] + X[f[2]] - X[f[3]])
         <= 1e-8*(mag(X[f[2]] - X[f[0]]) + mag(X[f[3]] - X[f[1]]));
    };
    // Counted face by face from the owner and neighbour lists: the cells'
    // face lists (primitiveMesh::cells(), about 50 bytes per cell) would be
    // built for this alone and held at the construction's memory peak
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    labelList nCellFaces(mesh_.nCells(), 0);
    boolList parallelogramsOnly(mesh_.nCells(), true);
    forAll(faces, facei)
    {
        const bool p = parallelogram(faces[facei]);
        ++nCellFaces[own[facei]];
        parallelogramsOnly[own[facei]] &= p;
        if (facei < nei.size())
        {
            ++nCellFaces[nei[facei]];
            parallelogramsOnly[nei[facei]] &= p;
        }
    }

    bool exact = true;
    forAll(nCellFaces, celli)
    {
        if
        (
            nCellFaces[celli] != 4
         && !(nCellFaces[celli] == 6 && parallelogramsOnly[celli])
        )
        {
            exact = false;
            break;
        }
    }
    reduce(exact, andOp<bool>());
    return exact;
}


void Foam::dualMesh::enableDeformedAreas()
{
    const faceList& faces = mesh_.faces();
    label n = 0;
    for (const face& f : faces)
    {
        n += f.size();
    }
    faceEdges_.setSize(n);

    // The edge of every face side, found among the edges of its first
    // point (the dual's own point-edge lists: OpenFOAM's edge addressing
    // is not kept)
    n = 0;
    forAll(faces, facei)
    {
        const face& f = faces[facei];
        if (f.size() < 3)
        {
            FatalErrorInFunction
                << "Face " << facei << " of mesh " << mesh_.name()
                << " has " << f.size() << " points: the internal faces were"
                << " released before the deformed dual was set up"
                << " (an internal error of the solver)" << exit(FatalError);
        }
        forAll(f, fp)
        {
            const label a = f[fp];
            const label b = f.nextLabel(fp);
            label found = -1;
            for (label k = pointEdgeStart_[a]; k < pointEdgeStart_[a + 1]; ++k)
            {
                const label e = pointEdges_[k];
                if (otherPoint(e, a) == b)
                {
                    found = e;
                    break;
                }
            }
            if (found < 0)
            {
                FatalErrorInFunction
                    << "Face " << facei << " side " << a << "-" << b
                    << " is not a mesh edge" << exit(FatalError);
            }
            faceEdges_[n++] = (edgeStart_[found] == a) ? found : -found - 1;
        }
    }
    deformable_ = true;
}


void Foam::dualMesh::deformedAreas
(
    const pointField& x,
    vectorField& edgeC,
    List<vectorField>& subFaceA
) const
{
    if (!deformedAreasEnabled())
    {
        FatalErrorInFunction
            << "Deformed dual areas asked for on mesh " << mesh_.name()
            << " without enableDeformedAreas() (an internal error of the"
            << " solver)" << exit(FatalError);
    }

    // The construction of the reference dual (calcCellContributions,
    // calcBoundarySubFaces) on the current positions: the dual cells stay
    // closed polyhedra, sum_j c_ij + sum_g a_g = 0 at every point
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    calcFaceGeometry(x, deformedFaceCentres_, deformedFaceAreas_);
    calcCellCentres
    (
        x, &deformedFaceCentres_, &deformedFaceAreas_,
        deformedCellCentres_, deformedCellVolumes_
    );
    const vectorField& fcs = deformedFaceCentres_;
    const pointField& ccs = deformedCellCentres_;

    edgeC.setSize(nEdges());
    edgeC = Zero;
    label n = 0;
    forAll(faces, facei)
    {
        const face& f = faces[facei];
        const point& fc = fcs[facei];
        const point& cOwn = ccs[own[facei]];
        forAll(f, fp)
        {
            const point mNext(0.5*(x[f[fp]] + x[f.nextLabel(fp)]));
            // The owner's dual triangle, oriented from f[fp] to the next
            // point, minus the neighbour's (the face points into it)
            vector S(dualTriangleArea(mNext, fc, cOwn));
            if (facei < nInternal)
            {
                S -= dualTriangleArea(mNext, fc, ccs[nei[facei]]);
            }
            const label se = faceEdges_[n++];
            if (se >= 0)
            {
                edgeC[se] += S;
            }
            else
            {
                edgeC[-se - 1] -= S;
            }
        }
    }

    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    subFaceA.setSize(patches.size());
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        vectorField& a = subFaceA[patchi];
        a.setSize(patchSubFaces_[patchi].size());
        if (a.empty())
        {
            continue;
        }
        label s = 0;
        forAll(pp, i)
        {
            const face& f = pp[i];
            const point& fc = fcs[pp.start() + i];
            forAll(f, fp)
            {
                const point& xa = x[f[fp]];
                a[s++] = subFaceArea
                (
                    xa,
                    0.5*(xa + x[f.nextLabel(fp)]),
                    fc,
                    0.5*(x[f.prevLabel(fp)] + xa)
                );
            }
        }
    }
}


bool Foam::dualMesh::triangleBoundary() const
{
    bool found = false;
    for (const patchSubFaces& sf : patchSubFaces_)
    {
        for (const scalar w : sf.nbrWeight)
        {
            found = found || w > 0;
        }
    }
    return returnReduce(found, orOp<bool>());
}


Foam::tmp<Foam::scalarField> Foam::dualMesh::edgeWeights() const
{
    tmp<scalarField> tw(new scalarField(nEdges(), 1.0));
    if (Pstream::parRun())
    {
        scalarField& w = tw.ref();
        syncTools::syncEdgeList(mesh_, w, plusEqOp<scalar>(), 0.0);
        w = 1.0/w;
    }
    return tw;
}


Foam::scalar Foam::dualMesh::sumPoints(const UList<scalar>& f) const
{
    scalar s = 0;
    forAll(f, i)
    {
        s += pointWeight(i)*f[i];
    }
    reduce(s, sumOp<scalar>());
    return s;
}


// ************************************************************************* //
