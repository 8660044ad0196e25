/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    Test-dualMesh

Description
    Checks the median dual of the case's mesh against its invariants:
      - closure  sum_j C_ij + sum_g C_g = 0 at every point;
      - the control volumes sum to the mesh volume (tets: V/4 per vertex);
      - the boundary points' offsets from their dual cells' centroids
        (tets and parallelepipeds, where the vertex parts' centroids are
        known in closed form);
      - C_ij = -C_ji through the point-edge connectivity;
      - the Green-Gauss gradient of a linear field (exact on tets and
        parallelepipeds, with the boundary weights of dualMesh::patchSubFaces;
        -linearExact asserts it, and that dualMesh::linearExact() is true;
        on prisms only interior points are exact).
    With -dump, writes per-point volumes and per-edge vectors with global
    (serial) point labels, so a parallel run can be compared with a serial
    one (tests/dualMesh/compareDumps).  Exits non-zero if a check fails.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "cellModel.H"
#include "labelIOList.H"
#include "OFstream.H"
#include "IOmanip.H"
#include "dualMesh.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

label nFailed = 0;

void check(const bool ok, const word& name, const scalar value, const scalar tol)
{
    Info<< "    " << (ok ? "PASS " : "FAIL ") << name << ": " << value
        << " (tolerance " << tol << ")" << endl;
    if (!ok)
    {
        ++nFailed;
    }
}

} // End anonymous namespace


// Largest |sum of a point's area vectors| over their magnitudes' sum: this
// processor's part of every edge's vector (oriented start to end) and every
// physical patch's sub-face areas, summed over processors at shared points
scalar closureError
(
    const dualMesh& dual,
    const vectorField& edgeC,
    const List<vectorField>& subFaceA
)
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    vectorField residual(dual.nPoints(), Zero);
    scalarField scale(dual.nPoints(), 0.0);
    forAll(es, e)
    {
        residual[es[e]] += edgeC[e];
        residual[ee[e]] -= edgeC[e];
        scale[es[e]] += mag(edgeC[e]);
        scale[ee[e]] += mag(edgeC[e]);
    }
    forAll(subFaceA, patchi)
    {
        const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
        forAll(sf.point, k)
        {
            residual[sf.point[k]] += subFaceA[patchi][k];
            scale[sf.point[k]] += mag(subFaceA[patchi][k]);
        }
    }
    dual.syncPointResidual(residual);
    dual.syncPointResidual(scale);

    scalar maxRel = 0;
    forAll(residual, i)
    {
        maxRel = max(maxRel, mag(residual[i])/scale[i]);
    }
    return returnReduce(maxRel, maxOp<scalar>());
}


int main(int argc, char *argv[])
{
    argList::addNote("Check the median dual mesh against its invariants");
    argList::addOption("tol", "scalar", "relative tolerance (default 1e-12)");
    argList::addBoolOption
    (
        "linearExact",
        "require the Green-Gauss gradient to be exact for a linear field"
    );
    argList::addOption
    (
        "dump",
        "file",
        "write volumes and edge vectors with serial point labels to file"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const scalar tol = args.getOrDefault<scalar>("tol", 1e-12);

    // (not const: section 5 asks it for the deformed dual)
    dualMesh dual(mesh);

    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    // Full area vectors C_e (summed over processors) and the processor's
    // share w_e of each
    const scalarField w(dual.edgeWeights());
    const vectorField C(dual.edgeNormals()*dual.edgeMagSf()/w);
    const scalarField& vol = dual.volumes();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const label nPts = mesh.nPoints();

    Info<< "Dual mesh: " << returnReduce(mesh.nCells(), sumOp<label>())
        << " cells, " << returnReduce(dual.nEdges(), sumOp<label>())
        << " edges (processor copies counted), min length "
        << dual.minLength() << nl << endl;

    // 1. Closure ------------------------------------------------------------
    {
        List<vectorField> subFaceA(patches.size());
        forAll(patches, patchi)
        {
            subFaceA[patchi] = dual.subFaces(patchi).area;
        }
        const scalar maxRel = closureError(dual, w*C, subFaceA);
        check(maxRel < tol, "closure |sum C|/sum|C|", maxRel, tol);
    }

    // 2. Volumes --------------------------------------------------------------
    {
        const scalar dualV = dual.sumPoints(vol);
        const scalar meshV = gSum(mesh.cellVolumes());
        const scalar rel = mag(dualV - meshV)/meshV;
        check(rel < tol, "volume sum vs mesh volume", rel, tol);

        // Tetrahedra: each vertex gets exactly a quarter of every cell
        const cellModel& tet = cellModel::ref(cellModel::TET);
        const cellShapeList& shapes = mesh.cellShapes();
        bool allTets = true;
        forAll(shapes, celli)
        {
            allTets = allTets && (shapes[celli].model() == tet);
        }
        reduce(allTets, andOp<bool>());

        if (allTets)
        {
            scalarField quarter(nPts, 0.0);
            forAll(shapes, celli)
            {
                for (const label pointi : shapes[celli])
                {
                    quarter[pointi] += 0.25*mesh.cellVolumes()[celli];
                }
            }
            dual.syncPointResidual(quarter);
            scalar maxRel = 0;
            forAll(vol, i)
            {
                maxRel = max(maxRel, mag(vol[i] - quarter[i])/quarter[i]);
            }
            reduce(maxRel, maxOp<scalar>());
            check(maxRel < tol, "tet vertex volume = sum V/4", maxRel, tol);
        }
    }

    // 2b. Boundary points' cell centroids ------------------------------------
    // A vertex's part of a tetrahedron is the region where its barycentric
    // coordinate is the largest: its volume is V/4 and its centroid
    // X_v + 23/36 (X_c - X_v) (the mean of the largest of four uniform
    // barycentric coordinates is 25/48); of a parallelepiped, the octant:
    // V/8 and X_v + 1/2 (X_c - X_v)
    {
        const cellShapeList& shapes = mesh.cellShapes();
        const cellModel& tet = cellModel::ref(cellModel::TET);
        const cellModel& hex = cellModel::ref(cellModel::HEX);
        bool exact = dual.linearExact();
        forAll(shapes, celli)
        {
            exact =
                exact
             && (shapes[celli].model() == tet || shapes[celli].model() == hex);
        }
        reduce(exact, andOp<bool>());
        if (exact)
        {
            const pointField& X = mesh.points();
            vectorField moment(nPts, Zero);
            scalarField volume(nPts, 0.0);
            forAll(shapes, celli)
            {
                const bool isTet = (shapes[celli].model() == tet);
                const scalar share = isTet ? 0.25 : 0.125;
                const scalar k = isTet ? 23.0/36.0 : 0.5;
                const point& Xc = mesh.cellCentres()[celli];
                for (const label i : shapes[celli])
                {
                    const scalar Vi = share*mesh.cellVolumes()[celli];
                    moment[i] += Vi*k*(Xc - X[i]);
                    volume[i] += Vi;
                }
            }
            dual.syncPointResidual(moment);
            dual.syncPointResidual(volume);
            const scalarField len(dual.lengths());
            const labelList& bp = dual.boundaryPoints();
            const List<vector>& offset = dual.boundaryCentroidOffsets();
            scalar maxRel = 0;
            scalar meanRatio = 0;
            forAll(bp, b)
            {
                const label i = bp[b];
                const vector expected(-moment[i]/volume[i]);
                maxRel = max(maxRel, mag(offset[b] - expected)/len[i]);
                meanRatio += mag(offset[b])/len[i];
            }
            reduce(maxRel, maxOp<scalar>());
            check
            (
                maxRel < tol, "boundary centroid offsets (tets, parallelepipeds)",
                maxRel, tol
            );
            Info<< "    boundary points' mean |X - c|/shortest edge: "
                << returnReduce(meanRatio, sumOp<scalar>())
                  /max(returnReduce(bp.size(), sumOp<label>()), 1) << nl;
        }
    }

    // 3. Antisymmetry through the point-edge connectivity -------------------
    {
        const labelList& start = dual.pointEdgeStart();
        const labelList& pe = dual.pointEdges();
        scalar maxRel = 0;
        labelList count(dual.nEdges(), 0);
        for (label i = 0; i < nPts; ++i)
        {
            for (label k = start[i]; k < start[i+1]; ++k)
            {
                const label e = pe[k];
                const label j = dual.otherPoint(e, i);
                ++count[e];
                maxRel = max
                (
                    maxRel,
                    mag(dual.C(e, i) + dual.C(e, j))/(w[e]*mag(C[e]))
                );
                if (i != es[e] && i != ee[e])
                {
                    maxRel = GREAT;
                }
            }
        }
        forAll(count, e)
        {
            if (count[e] != 2)
            {
                maxRel = GREAT;
            }
        }
        reduce(maxRel, maxOp<scalar>());
        check(maxRel < tol, "C_ij + C_ji (point-edge lists)", maxRel, tol);
    }

    // 4. Green-Gauss gradient of a linear field ----------------------------
    {
        const vector b(2, -3, 0.5);
        const pointField& X = mesh.points();
        scalarField f(nPts);
        forAll(f, i)
        {
            f[i] = 1 + (b & X[i]);
        }

        vectorField G(nPts, Zero);
        forAll(es, e)
        {
            const vector flux(0.5*w[e]*(f[es[e]] + f[ee[e]])*C[e]);
            G[es[e]] += flux;
            G[ee[e]] -= flux;
        }
        boolList onBoundary(nPts, false);
        forAll(patches, patchi)
        {
            const dualMesh::patchSubFaces& sf = dual.subFaces(patchi);
            forAll(sf.point, k)
            {
                const scalar fi = f[sf.point[k]];
                const scalar fb =
                    fi + sf.nbrWeight[k]*(f[sf.prev[k]] + f[sf.next[k]] - 2*fi);
                G[sf.point[k]] += fb*sf.area[k];
                onBoundary[sf.point[k]] = true;
            }
        }
        dual.syncPointResidual(G);
        syncTools::syncPointList(mesh, onBoundary, orEqOp<bool>(), false);

        scalar errInternal = 0, errBoundary = 0;
        forAll(G, i)
        {
            const scalar err = mag(G[i]/vol[i] - b)/mag(b);
            if (onBoundary[i])
            {
                errBoundary = max(errBoundary, err);
            }
            else
            {
                errInternal = max(errInternal, err);
            }
        }
        reduce(errInternal, maxOp<scalar>());
        reduce(errBoundary, maxOp<scalar>());

        const scalar gtol = 1e3*tol;
        if (args.found("linearExact"))
        {
            check(errInternal < gtol, "linear gradient, interior", errInternal, gtol);
            check(errBoundary < gtol, "linear gradient, boundary", errBoundary, gtol);
        }
        else
        {
            Info<< "    info linear gradient error: interior " << errInternal
                << ", boundary " << errBoundary << endl;
        }

        // The mesh's own answer (every cell a tetrahedron or a
        // parallelepiped), on which the automatic scheme relies, agrees
        check
        (
            dual.linearExact() == args.found("linearExact"),
            "dualMesh::linearExact() as the mesh type says",
            dual.linearExact(), 0.5
        );
    }

    // 5. The deformed dual (dualMesh::deformedAreas) ------------------------
    //    On the reference positions it is the reference dual; under a
    //    linear map x = A X its area vectors are cof(A) times the
    //    reference ones; under any deformation its cells stay closed
    {
        dual.enableDeformedAreas();
        const pointField& X = mesh.points();
        const boundBox bb(X, true);
        const scalar L = bb.mag();

        vectorField c0, c;
        List<vectorField> a0, a;
        dual.deformedAreas(X, c0, a0);

        // This processor's part of each edge's reference vector, and the
        // largest relative difference of two sets of area vectors
        auto maxDiff = [&]
        (
            const vectorField& c1, const List<vectorField>& a1,
            const vectorField& c2, const List<vectorField>& a2
        )
        {
            scalar err = 0, scale = 0;
            forAll(c1, e)
            {
                err = max(err, mag(c1[e] - c2[e]));
                scale = max(scale, mag(c2[e]));
            }
            forAll(a1, patchi)
            {
                forAll(a1[patchi], k)
                {
                    err = max(err, mag(a1[patchi][k] - a2[patchi][k]));
                    scale = max(scale, mag(a2[patchi][k]));
                }
            }
            reduce(err, maxOp<scalar>());
            reduce(scale, maxOp<scalar>());
            return err/scale;
        };

        if (!Pstream::parRun())
        {
            List<vectorField> aRef(patches.size());
            forAll(patches, patchi)
            {
                aRef[patchi] = dual.subFaces(patchi).area;
            }
            const scalar err = maxDiff(c0, a0, C, aRef);
            check(err < tol, "deformed dual on X = reference dual", err, tol);
        }

        // A linear map (stretch, shear and rotation, det A = 1.05)
        const tensor A
        (
            1.2, 0.3, -0.1,
            0.05, 0.9, 0.2,
            0.1, -0.25, 1.1
        );
        pointField x(A & X);
        dual.deformedAreas(x, c, a);
        const tensor cofA(cof(A));
        vectorField cA(cofA & c0);
        List<vectorField> aA(a0.size());
        forAll(a0, patchi)
        {
            aA[patchi] = cofA & a0[patchi];
        }
        const scalar errLinear = maxDiff(c, a, cA, aA);
        // (Exact where every face is flat: a warped face's centroid, the
        // area-weighted one of its triangles, does not follow a linear map)
        bool flat = true;
        forAll(mesh.faces(), facei)
        {
            const face& f = mesh.faces()[facei];
            const vector n(mesh.faceAreas()[facei]);
            const scalar magN = mag(n);
            for (const label pi : f)
            {
                flat =
                    flat
                 && mag((X[pi] - mesh.faceCentres()[facei]) & n)
                  < 1e-12*magN*std::sqrt(magN);
            }
        }
        reduce(flat, andOp<bool>());
        if (flat)
        {
            check
            (
                errLinear < 10*tol, "deformed dual under x = A X: cof(A) C",
                errLinear, 10*tol
            );
        }
        else
        {
            Info<< "    info deformed dual under x = A X (warped faces): "
                << errLinear << " from cof(A) C" << endl;
        }

        // A non-linear deformation: the deformed cells stay closed
        forAll(X, i)
        {
            const vector d((X[i] - bb.min())/L);
            x[i] =
                X[i]
              + 0.1*L*vector
                (
                    std::sin(3*d.y()) + d.z()*d.z(),
                    std::cos(2*d.x())*d.z(),
                    std::sin(4*d.x() + d.y())
                );
        }
        dual.deformedAreas(x, c, a);
        const scalar maxRel = closureError(dual, c, a);
        check
        (
            maxRel < tol, "deformed dual closure |sum c|/sum|c|", maxRel, tol
        );
    }

    // 6. Sums over the copies of shared points (sharedPointSums) ----------
    if (Pstream::parRun())
    {
        Info<< "sums over shared points (sharedPointSums):" << nl;
        const sharedPointSums& sums = dual.sharedSums();
        const pointField& X = mesh.points();
        typedef FixedList<scalar, 4> sample;

        // Every copy gives (1, X): the sum is the number of copies times
        // that, on the shared points, and the rest is left alone
        labelList all(identity(nPts));
        List<sample> v(nPts);
        auto fill = [&]()
        {
            forAll(v, i)
            {
                v[i] = sample({1, X[i].x(), X[i].y(), X[i].z()});
            }
        };
        fill();
        sums.sum(all, v);
        scalar err = 0;
        label nShared = 0;
        forAll(v, i)
        {
            const scalar m = 1/dual.pointWeight(i);
            nShared += sums.shared(i);
            err = max(err, mag(v[i][0] - m));
            for (direction c = 0; c < 3; ++c)
            {
                err = max(err, mag(v[i][c + 1] - m*X[i][c])/(1 + mag(X[i][c])));
            }
            // (shared exactly where the dual counts several copies)
            err = max(err, scalar(sums.shared(i) != (m > 1)));
        }
        reduce(err, maxOp<scalar>());
        reduce(nShared, sumOp<label>());
        check
        (
            err < 1e-14 && nShared > 0,
            "every copy: sum of (1, X) = copies (1, X)", err, 1e-14
        );

        // The copies hold the same bits: their largest and smallest agree
        List<sample> hi(v), lo(v);
        sums.combine
        (
            all, hi,
            [](sample& x, const sample& y)
            {
                for (direction c = 0; c < 4; ++c) x[c] = max(x[c], y[c]);
            }
        );
        sums.combine
        (
            all, lo,
            [](sample& x, const sample& y)
            {
                for (direction c = 0; c < 4; ++c) x[c] = min(x[c], y[c]);
            }
        );
        scalar spread = 0;
        forAll(v, i)
        {
            for (direction c = 0; c < 4; ++c)
            {
                spread = max(spread, hi[i][c] - lo[i][c]);
            }
        }
        reduce(spread, maxOp<scalar>());
        check(spread == 0, "copies of a sum equal to the bit", spread, 0);

        // Some points listed (the same on every copy: by position), values
        // that round differently in other orders: the listed shared points
        // get OpenFOAM's sum to rounding, the others keep their values
        const boundBox box(X, true);
        DynamicList<label> listed;
        forAll(X, i)
        {
            if (X[i].x() + 2*X[i].y() - X[i].z() < box.centre().x())
            {
                listed.append(i);
            }
        }
        List<sample> part(listed.size());
        List<scalarList> reference(4, scalarList(nPts, 0.0));
        forAll(listed, k)
        {
            const point& x = X[listed[k]];
            part[k] = sample({0.1, std::sin(x.x()), 1/(3 + x.y()), x.z()/7});
            for (direction c = 0; c < 4; ++c)
            {
                reference[c][listed[k]] = part[k][c];
            }
        }
        sums.sum(listed, part);
        for (scalarList& r : reference)
        {
            syncTools::syncPointList(mesh, r, plusEqOp<scalar>(), 0.0);
        }
        scalar partErr = 0;
        forAll(listed, k)
        {
            for (direction c = 0; c < 4; ++c)
            {
                partErr =
                    max(partErr, mag(part[k][c] - reference[c][listed[k]]));
            }
        }
        reduce(partErr, maxOp<scalar>());
        check
        (
            partErr < 1e-14, "listed points: the sum of syncPointList",
            partErr, 1e-14
        );
    }

    // 7. Dump with serial point labels ---------------------------------------
    if (args.found("dump"))
    {
        labelList global(identity(nPts));
        if (Pstream::parRun())
        {
            global = labelIOList
            (
                IOobject
                (
                    "pointProcAddressing",
                    mesh.facesInstance(),
                    polyMesh::meshSubDir,
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE,
                    false
                )
            );
        }

        fileName dumpName(args.get<fileName>("dump"));
        if (Pstream::parRun())
        {
            dumpName += "." + Foam::name(Pstream::myProcNo());
        }
        OFstream os(dumpName);
        os.precision(17);
        forAll(vol, i)
        {
            os  << "p " << global[i] << ' ' << vol[i] << ' '
                << dual.pointWeight(i) << nl;
        }
        forAll(es, e)
        {
            // Orient from the lower to the higher serial label
            const label gs = global[es[e]];
            const label ge = global[ee[e]];
            const vector c((gs < ge) ? C[e] : -C[e]);
            os  << "e " << min(gs, ge) << ' ' << max(gs, ge) << ' '
                << c.x() << ' ' << c.y() << ' ' << c.z() << ' ' << w[e] << nl;
        }
    }

    reduce(nFailed, sumOp<label>());
    Info<< nl << (nFailed ? "FAILED " : "All checks passed ")
        << "(" << nFailed << " failed)" << nl << "End" << nl << endl;

    // (OpenFOAM v1912 ends a run with status 0 when the argList is
    // destroyed after main returns, whatever main returned: leave here)
    Pstream::exit(nFailed ? 1 : 0);
    return 0;
}


// ************************************************************************* //
