/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "solidBoundaryCondition.H"
#include "acousticFormulas.H"
#include "checkedInput.H"
#include "UIndirectList.H"
#include "materialModel.H"
#include "syncTools.H"

namespace Foam
{
    defineTypeNameAndDebug(solidBoundaryCondition, 0);
    defineRunTimeSelectionTable(solidBoundaryCondition, dictionary);
}



Foam::solidBoundaryCondition::solidBoundaryCondition
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    dual_(dual),
    patchi_(patchi),
    dict_(dict)
{
    const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi_);
    const polyMesh& mesh = dual_.mesh();

    const vectorField meanN(dual_.patchPointNormals(patchi_));
    const boolList feature(dual_.patchFeaturePoints(patchi_, meanN));
    auto normal = [&](const label i, const vector& N) -> vector
    {
        return feature[i] ? N : meanN[i];
    };

    // The distinct (point, normal) pairs, found through the pairs already
    // met at each point (a handful)
    List<DynamicList<label>> ofPoint(mesh.nPoints());
    DynamicList<label> points(sf.size());
    DynamicList<vector> normals(sf.size());
    auto stateIndex = [&](const label i, const vector& n) -> label
    {
        for (const label k : ofPoint[i])
        {
            if (normals[k] == n)
            {
                return k;
            }
        }
        ofPoint[i].append(points.size());
        points.append(i);
        normals.append(n);
        return points.size() - 1;
    };

    subFaceState_.setSize(sf.size());
    subFacePrevState_.setSize(sf.size(), -1);
    subFaceNextState_.setSize(sf.size(), -1);
    forAll(sf.point, s)
    {
        const vector N(sf.area[s]/mag(sf.area[s]));
        subFaceState_[s] = stateIndex(sf.point[s], normal(sf.point[s], N));
        if (sf.nbrWeight[s] > 0)
        {
            const label p = sf.prev[s], n = sf.next[s];
            subFacePrevState_[s] = stateIndex(p, normal(p, N));
            subFaceNextState_[s] = stateIndex(n, normal(n, N));
        }
    }
    statePoint_.transfer(points);
    stateNormal_.transfer(normals);
    stateMagA_.setSize(statePoint_.size(), 0.0);
    forAll(sf.point, s)
    {
        stateMagA_[subFaceState_[s]] += mag(sf.area[s]);
    }
    stateT_.setSize(statePoint_.size());
    stateV_.setSize(statePoint_.size());
    stateP_.setSize(statePoint_.size());
}


Foam::autoPtr<Foam::solidBoundaryCondition> Foam::solidBoundaryCondition::New
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
{
    const word bcType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(bcType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown boundary condition type '" << bcType
            << "' for patch '" << dual.mesh().boundaryMesh()[patchi].name()
            << "'" << nl << "Valid types: "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    autoPtr<solidBoundaryCondition> bc(cstrIter()(dual, patchi, dict));
    checkKeywords(dict, bc->keywords());
    return bc;
}


Foam::scalar Foam::solidBoundaryCondition::solveState
(
    const label k,
    const UList<vector>& u,
    const UList<fluxState>& q,
    const UList<tensor>& H,
    const waveData& body,
    const scalar t,
    const stageStep& step,
    const deformedDual* deformed,
    const bool extrapolated
) const
{
    const label i = statePoint_[k];
    const vector& N = stateNormal_[k];
    vector n(H[i] & N);
    const vector hN(n);
    vector tL(fluxStress(q[i]) & N);
    const vector v(fluxVelocity(q[i]));
    // The deformed area per unit reference area of the state's sub-faces
    // in place of H N (the interior's pressure acts on the deformed dual
    // too: solidBody::addInteriorFluxes)
    const vector a
    (
        deformed ? vector(stateDeformedA_[k]/stateDeformedMagA_[k]) : vector(Zero)
    );
    if (deformed)
    {
        deformed->toDeformedArea(i, a, tL, n);
    }
    // The Riemann problem's input: the point's own state or the state
    // extrapolated from its cell's centroid to the point
    // (boundaryExtrapolation), with the same area map
    vector tB(tL), vB(v);
    if (extrapolated)
    {
        const stateIncrement& dq =
            (*step.increment)[dual_.boundaryIndex()[i]];
        fluxState qB(q[i]);
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            qB[c] += dq[c];
        }
        tB = fluxStress(qB) & N;
        vB = fluxVelocity(qB);
        if (deformed)
        {
            vector hNB(hN);
            deformed->toDeformedArea(i, a, tB, hNB);
        }
    }
    const scalar Lambda = mag(n);
    n /= Lambda;
    // The face's Lagrangian impedances, as the interior faces' (doc/
    // method.md, section 4): a sub-face compressed along its normal
    // (Lambda = |H N| > 1) carries its waves Lambda times faster in
    // reference coordinates.  With the reference impedances the upwind
    // part of the boundary velocity, (t - tbar)/Z, damped its traction
    // Lambda times too fast, beyond the stable step's estimate: the Taylor
    // bar's impact face (Lambda 15 at the axis) let the numerical
    // dissipation fall from cfl 0.65-0.75 on (doc/results.md, "Compressed
    // boundary faces")
    const scalar s = acousticFormulas::compressedFaceFactor(Lambda);
    // (a Hugoniot material's Zp at the point's compression)
    const scalar Zp =
        body.J
      ? body.material->rho()*body.material->tangentWaveSpeed((*body.J)[i])
      : body.Zp;
    const waveData w
    {
        s*Zp, s*body.Zs, body.shockMass*Lambda, nullptr, nullptr
    };
    const point& X = dual_.mesh().points()[i];
    stateP_[k] = contactState
    (
        n, N, X + u[i], X + step.u0[i], vB, tB,
        w, t, step, stateT_[k], stateV_[k]
    );

    // Numerical dissipation per unit area, measured with the point's own
    // state: the condition's work less the power the residuals take from
    // the body, v.t^C + t.v^C - t.v.  Not negative for the point's own
    // state, whose Riemann solution upwinds its jump (doc/method.md,
    // section 4)
    return
        stateP_[k] - (v & stateT_[k]) - (tL & stateV_[k]) + (tL & v);
}


Foam::scalar Foam::solidBoundaryCondition::addSubFaceFlux
(
    const label s,
    UList<vector>& Rp,
    UList<tensor>& RF,
    UList<vector>& tB,
    UList<vector>& vB
) const
{
    const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi_);
    const label i = sf.point[s];
    const scalar magA = mag(sf.area[s]);
    const label k = subFaceState_[s];

    vector tC(stateT_[k]);
    vector vC(stateV_[k]);

    // The power is the same quadrature of the pointwise power t.v, not
    // the product of the averaged t and v: a fixed frictionless wall or
    // a symmetry plane then does no work, as in the continuum (the
    // product of averages is not zero at a contact perimeter, where an
    // open neighbour approaching the wall meets a closed point's
    // pressure, and would hide numerical dissipation as external work)
    scalar pC = stateP_[k];
    const scalar w = sf.nbrWeight[s];
    if (w > 0)
    {
        const label kP = subFacePrevState_[s], kN = subFaceNextState_[s];
        tC = (1 - 2*w)*tC + w*(stateT_[kP] + stateT_[kN]);
        vC = (1 - 2*w)*vC + w*(stateV_[kP] + stateV_[kN]);
        pC = (1 - 2*w)*pC + w*(stateP_[kP] + stateP_[kN]);
    }

    Rp[i] += magA*tC;
    RF[i] += vC*sf.area[s];
    if (tB.size())
    {
        tB[s] = tC;
        vB[s] = vC;
    }
    return magA*pC;
}


void Foam::solidBoundaryCondition::subFaceRows
(
    const labelUList& rowOf,
    const label nRows,
    labelList& start,
    labelList& items
) const
{
    const labelList& sfPoint = dual_.subFaces(patchi_).point;
    start.setSize(nRows + 1);
    start = 0;
    for (const label i : sfPoint)
    {
        ++start[rowOf[i] + 1];
    }
    for (label r = 0; r < nRows; ++r)
    {
        start[r + 1] += start[r];
    }
    items.setSize(sfPoint.size());
    labelList next(SubList<label>(start, nRows));
    forAll(sfPoint, s)
    {
        items[next[rowOf[sfPoint[s]]]++] = s;
    }
}


void Foam::solidBoundaryCondition::makePatchPointRows() const
{
    const polyMesh& mesh = dual_.mesh();
    const labelList& sfPoint = dual_.subFaces(patchi_).point;

    // The patch's points; in parallel also those this processor holds
    // without any of their patch faces (its cells touch them by an edge or
    // a corner only): their copies must move as the others
    labelList rowOf(mesh.nPoints(), -1);
    DynamicList<label> pts(sfPoint.size());
    auto add = [&](const label i)
    {
        if (rowOf[i] < 0)
        {
            rowOf[i] = pts.size();
            pts.append(i);
        }
    };
    for (const label i : sfPoint)
    {
        add(i);
    }
    if (Pstream::parRun())
    {
        boolList onPatch(mesh.nPoints(), false);
        UIndirectList<bool>(onPatch, sfPoint) = true;
        syncTools::syncPointList(mesh, onPatch, orEqOp<bool>(), false);
        forAll(onPatch, i)
        {
            if (onPatch[i])
            {
                add(i);
            }
        }
    }
    subFaceRows(rowOf, pts.size(), patchPointSubFaceStart_, patchPointSubFaces_);
    patchPoints_.transfer(pts);
}


Foam::scalar Foam::solidBoundaryCondition::addFluxes
(
    const UList<vector>& u,
    const UList<fluxState>& q,
    const UList<tensor>& H,
    const waveData& body,
    const scalar t,
    const stageStep& step,
    UList<vector>& Rp,
    UList<tensor>& RF,
    UList<vector>& tB,
    UList<vector>& vB,
    const deformedDual* deformed,
    const labelUList* points
) const
{
    const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi_);
    scalar power = 0;

    if (points)
    {
        // The sub-faces of some points only (multirate stepping): each
        // state solved once, when a sub-face first needs it
        if (pointSubFaceStart_.empty())
        {
            // (rows by mesh point)
            subFaceRows
            (
                identity(dual_.mesh().nPoints()), dual_.mesh().nPoints(),
                pointSubFaceStart_, pointSubFaces_
            );
            stateStage_.setSize(statePoint_.size(), -1);
        }
        ++stage_;
        auto need = [&](const label k)
        {
            if (stateStage_[k] != stage_)
            {
                stateStage_[k] = stage_;
                // (extrapolated states one by one: kept where they
                // dissipate)
                if
                (
                    !step.increment || !extrapolates()
                 || solveState(k, u, q, H, body, t, step, nullptr, true) < 0
                )
                {
                    solveState(k, u, q, H, body, t, step, nullptr, false);
                }
            }
        };
        for (const label i : *points)
        {
            for (label m = pointSubFaceStart_[i]; m < pointSubFaceStart_[i + 1]; ++m)
            {
                const label s = pointSubFaces_[m];
                need(subFaceState_[s]);
                if (subFacePrevState_[s] >= 0)
                {
                    need(subFacePrevState_[s]);
                    need(subFaceNextState_[s]);
                }
                power += addSubFaceFlux(s, Rp, RF, tB, vB);
            }
        }
        return power;
    }

    if (deformed)
    {
        stateDeformedA_.setSize(statePoint_.size());
        stateDeformedA_ = Zero;
        forAll(sf.point, s)
        {
            stateDeformedA_[subFaceState_[s]] += deformed->subFaceArea[s];
        }
        stateDeformedMagA_ = stateMagA_;
        if (Pstream::parRun())
        {
            syncDeformedAreas();
        }
    }

    // The one-sided Riemann state of every distinct (point, normal) pair
    scalar pointDissipation = 0;
    forAll(statePoint_, k)
    {
        pointDissipation +=
            stateMagA_[k]
           *solveState(k, u, q, H, body, t, step, deformed, false);
    }
    if (step.increment && extrapolates())
    {
        // Boundary extrapolation: the states from the points' extrapolated
        // states, blended back towards the points' own by the one factor
        // that keeps the patch's numerical dissipation from falling below
        // zero.  The fluxes are linear in the states: the blend's
        // dissipation is the same blend of the two.  (State by state, half
        // of a smooth surface's states would fall back: the extrapolated
        // traction is near zero and the own one's product with the
        // velocity's increment takes either sign)
        stateT0_ = stateT_;
        stateV0_ = stateV_;
        stateP0_ = stateP_;
        scalar dissipation = 0;
        // (and the rounding scale of the sums: a patch whose dissipation
        // is zero to rounding, as at rest or in uniform motion, is left
        // alone, or processors that sum in another order would blend
        // differently)
        scalar scale = 0;
        forAll(statePoint_, k)
        {
            dissipation +=
                stateMagA_[k]
               *solveState(k, u, q, H, body, t, step, deformed, true);
            const label i = statePoint_[k];
            scale +=
                stateMagA_[k]
               *(
                    mag(fluxVelocity(q[i]))*mag(fluxStress(q[i]))
                  + mag(stateT_[k])*mag(stateV_[k])
                );
        }
        reduce(pointDissipation, sumOp<scalar>());
        reduce(dissipation, sumOp<scalar>());
        reduce(scale, sumOp<scalar>());
        if (dissipation < -1e-12*scale)
        {
            const scalar theta =
                max(pointDissipation, scalar(0))
               /(max(pointDissipation, scalar(0)) - dissipation);
            forAll(statePoint_, k)
            {
                stateT_[k] = theta*stateT_[k] + (1 - theta)*stateT0_[k];
                stateV_[k] = theta*stateV_[k] + (1 - theta)*stateV0_[k];
                stateP_[k] = theta*stateP_[k] + (1 - theta)*stateP0_[k];
            }
        }
    }
    forAll(sf.point, s)
    {
        power += addSubFaceFlux(s, Rp, RF, tB, vB);
    }

    return power;
}


void Foam::solidBoundaryCondition::describe(Ostream& os) const
{
    os  << dict_.get<word>("type");
}


void Foam::solidBoundaryCondition::syncDeformedAreas() const
{
    // A point on a processor cut has sub-faces on both sides: its states'
    // deformed area per unit reference area is the ratio of the sums over
    // all of them, the same on every copy (each processor's own share gave
    // each copy another normal and area ratio: a bar on tets at a wall,
    // split across its struck face, parted from the serial run by 4e-3).
    // The states of a point are matched across processors by the nearest
    // of the point's orthonormalised patch normals
    const polyMesh& mesh = dual_.mesh();
    const labelList& bIndex = dual_.boundaryIndex();
    const List<FixedList<vector, 3>>& bNormals = dual_.boundaryNormals();
    // (slot m's deformed area in row m of a tensor, its reference area in
    // component m of a vector: lists syncTools sums as they are)
    List<tensor> aSums(mesh.nPoints(), Zero);
    List<vector> magSums(mesh.nPoints(), Zero);
    labelList slot(statePoint_.size(), 0);
    forAll(statePoint_, k)
    {
        const label i = statePoint_[k];
        const label b = bIndex[i];
        if (b >= 0)
        {
            scalar best = -1;
            for (label m = 0; m < 3; ++m)
            {
                const scalar c = mag(bNormals[b][m] & stateNormal_[k]);
                if (c > best)
                {
                    best = c;
                    slot[k] = m;
                }
            }
        }
        const label m = slot[k];
        tensor& a = aSums[i];
        a(m, 0) += stateDeformedA_[k].x();
        a(m, 1) += stateDeformedA_[k].y();
        a(m, 2) += stateDeformedA_[k].z();
        magSums[i][m] += stateMagA_[k];
    }
    syncTools::syncPointList(mesh, aSums, plusEqOp<tensor>(), tensor(Zero));
    syncTools::syncPointList(mesh, magSums, plusEqOp<vector>(), vector(Zero));
    forAll(statePoint_, k)
    {
        const label i = statePoint_[k];
        const label m = slot[k];
        stateDeformedA_[k] =
            vector(aSums[i](m, 0), aSums[i](m, 1), aSums[i](m, 2));
        stateDeformedMagA_[k] = magSums[i][m];
    }
}


// ************************************************************************* //
