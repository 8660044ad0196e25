/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "multirateRungeKutta2.H"
#include "acousticFormulas.H"
#include "greenGauss.H"
#include "Time.H"
#include "tvdRungeKutta2.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::multirateRungeKutta2::multirateRungeKutta2
(
    const Time& runTime,
    const PtrList<solidBody>& bodies,
    PtrList<contactPair>& contacts,
    const label nLevels
)
:
    nLevels_(nLevels),
    levels_(bodies.size()),
    contacts_(contacts),
    pairBodyA_(contacts.size(), -1),
    pairBodyB_(contacts.size(), -1),
    pairLevel_(contacts.size(), 0),
    pairMinLevel_(contacts.size(), 0),
    finest_(0),
    assignedDt_(-1),
    boundaryFirst_(false),
    lastUpdates_(0),
    pointsPerLevel_(nLevels, 0),
    pointsPerLevelSum_(nLevels, 0.0)
{
    const dictionary& controlDict = runTime.controlDict();
    auto unsupported = [&](const string& what)
    {
        FatalIOErrorInFunction(controlDict)
            << "multirateLevels " << nLevels_ << " (multirate time stepping)"
            << " does not support " << what.c_str() << "." << nl
            << "    Change that, or use multirateLevels 1 (one global step)."
            << exit(FatalIOError);
    };
    // Each pair's bodies
    forAll(contacts, p)
    {
        forAll(bodies, bi)
        {
            if (&contacts[p].bodyA() == &bodies[bi]) pairBodyA_[p] = bi;
            if (&contacts[p].bodyB() == &bodies[bi]) pairBodyB_[p] = bi;
        }
        Info<< "Multirate stepping: contact pair " << contacts[p].name()
            << ": the points of both patches step together, on the finest"
            << " level of any of them" << nl;
    }

    forAll(bodies, bi)
    {
        const solidBody& b = bodies[bi];
        const bodyScheme& s = b.scheme();
        const string body("body " + b.name() + "'s ");
        if (s.secondOrder() && b.limiter_->limitsGradients())
        {
            unsupported
            (
                body + "limiter " + s.limiter() + " (a point limiter; use"
                " a per-edge one: vanAlbada, superbee, monotonizedCentral,"
                " or none)"
            );
        }
        if (s.secondOrder() && s.riemannBoundarySlope())
        {
            boundaryFirst_ = true;
        }
        if (s.deformedPressure())
        {
            unsupported(body + "deformedPressure yes");
        }
        if (s.onsetStabilisation())
        {
            // (solidBody::addInteriorFluxes: the zone's edges and Riemann
            // slopes belong to one step)
            Info<< "Body " << b.name() << ": with multirate stepping"
                << " onsetStabilisation is not applied (the onset zone's"
                << " upwind F flux and Riemann slopes need one global step)"
                << nl;
        }
        if (s.energyStable())
        {
            Info<< "Body " << b.name() << ": with multirate stepping"
                << " energyStable blends each level's edges within the"
                << " step's dissipation";
            if (b.material_->plastic())
            {
                Info<< " (the step's energy balance is left out: the return"
                    << " maps are committed level by level)";
            }
            Info<< nl;
        }

        const label n = b.lm_.size();
        bodyLevels* Lp = new bodyLevels;
        levels_.set(bi, Lp);
        bodyLevels& L = *Lp;
        L.dtPoint.setSize(n);
        L.level.setSize(n);
        L.points.setSize(nLevels_);
        L.edges.setSize(nLevels_);
        L.finerEdges.setSize(nLevels_);
        L.gradient1.setSize(nLevels_);
        L.coarser.setSize(nLevels_);
        L.edgePoints.setSize(nLevels_);
        L.sharedOnLevel.setSize(nLevels_);
        L.sharedGradient1.setSize(nLevels_);
        L.levelWeight.setSize(nLevels_, 0.0);
        L.onLevel.setSize(nLevels_);
        L.inGradient1.setSize(nLevels_);
        for (label l = 0; l < nLevels_; ++l)
        {
            L.onLevel[l].setSize(n, false);
            L.inGradient1[l].setSize(n, false);
        }
        L.gradientEdges.setSize(nLevels_);
        L.listed.setSize(n, false);
        L.qStart.setSize(n);
        L.qPredicted.setSize(n);
        // Each point's boundary sub-faces
        const dualMesh& dual = b.dual_;
        if (Pstream::parRun())
        {
            // (collective: made here, used in the steps)
            dual.sharedSums();
            DynamicList<label> shared;
            for (label i = 0; i < n; ++i)
            {
                if (dual.pointWeight(i) < 1)
                {
                    shared.append(i);
                }
            }
            L.sharedPoints.transfer(shared);
        }
        pointSubFaceRows(dual, L.pointSubFaceStart, L.subFacePatch, L.subFace);
        L.stagePower.setSize(nLevels_, 0.0);
        L.Am.setSize(n, Zero);
        L.AF.setSize(n, Zero);
        L.AJ.setSize(n, 0.0);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::multirateRungeKutta2::initialLevels
(
    bodyLevels& L,
    const scalar dt
) const
{
    const label K = nLevels_ - 1;
    labelList& level = L.level;

    // The smallest level whose step is within the point's own (a relative
    // tolerance for the point that set dt itself)
    forAll(level, i)
    {
        scalar h = dt;
        label l = 0;
        while (l < K && h > (1 + 1e-9)*L.dtPoint[i])
        {
            h *= 0.5;
            ++l;
        }
        level[i] = l;
    }
}


void Foam::multirateRungeKutta2::smoothLevels
(
    const solidBody& b,
    bodyLevels& L
) const
{
    const dualMesh& dual = b.dual_;
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    labelList& level = L.level;

    // A point shared by processors on one level (the finer), where its
    // copies' own steps differ in rounding.  True if that changed one
    const labelList& shared = L.sharedPoints;
    labelList sharedLevel;
    auto syncShared = [&]()
    {
        if (!Pstream::parRun())
        {
            return false;
        }
        sharedLevel = labelUIndList(level, shared)();
        dual.sharedSums().combine
        (
            shared, sharedLevel,
            [](label& x, const label y) { x = max(x, y); }
        );
        bool changed = false;
        forAll(shared, k)
        {
            if (level[shared[k]] != sharedLevel[k])
            {
                level[shared[k]] = sharedLevel[k];
                changed = true;
            }
        }
        return changed;
    };
    syncShared();

    // Neighbours at most one level apart (finer wins), both plane-strain
    // copies on one level (on every processor: each pass ends with the
    // shared points' exchange)
    const planeStrainTie& tie = b.planeStrain_();
    for (bool changed = true; changed; )
    {
        changed = false;
        forAll(es, e)
        {
            label& li = level[es[e]];
            label& lj = level[ee[e]];
            if (li < lj - 1)
            {
                li = lj - 1;
                changed = true;
            }
            else if (lj < li - 1)
            {
                lj = li - 1;
                changed = true;
            }
        }
        forAll(tie.copiesA(), k)
        {
            label& la = level[tie.copiesA()[k]];
            label& lb = level[tie.copiesB()[k]];
            if (la != lb)
            {
                la = lb = max(la, lb);
                changed = true;
            }
        }
        changed = syncShared() || changed;
        if (Pstream::parRun())
        {
            reduce(changed, orOp<bool>());
        }
    }
}


void Foam::multirateRungeKutta2::assignLevels
(
    const PtrList<solidBody>& bodies,
    const scalar dt
)
{
    forAll(bodies, bi)
    {
        initialLevels(levels_[bi], dt);
        smoothLevels(bodies[bi], levels_[bi]);
    }

    // Contact pairs: all points of both patches on one level, the finest
    // of any of them (and at least the one the step's gap limit took,
    // deltaT), so that the pair's two sides step together and its Riemann
    // problems, closing allowances and impulses belong to one step of
    // that level; their neighbours then grade away from it.  Raising a
    // pair's points can raise their neighbours, and with them points of
    // the pair again: repeat until no point moves (levels only rise)
    for (bool changed = contacts_.size(); changed; )
    {
        changed = false;
        forAll(contacts_, p)
        {
            const contactPair& c = contacts_[p];
            labelList& levelA = levels_[pairBodyA_[p]].level;
            labelList& levelB = levels_[pairBodyB_[p]].level;
            label lp = pairMinLevel_[p];
            for (const label i : c.pointsA()) lp = max(lp, levelA[i]);
            for (const label i : c.pointsB()) lp = max(lp, levelB[i]);
            reduce(lp, maxOp<label>());
            pairLevel_[p] = lp;
            for (const label i : c.pointsA())
            {
                if (levelA[i] != lp)
                {
                    levelA[i] = lp;
                    changed = true;
                }
            }
            for (const label i : c.pointsB())
            {
                if (levelB[i] != lp)
                {
                    levelB[i] = lp;
                    changed = true;
                }
            }
        }
        reduce(changed, orOp<bool>());
        if (changed)
        {
            forAll(bodies, bi)
            {
                smoothLevels(bodies[bi], levels_[bi]);
            }
        }
    }
}


void Foam::multirateRungeKutta2::levelLists
(
    const solidBody& b,
    bodyLevels& L
)
{
    const dualMesh& dual = b.dual_;
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const labelList& level = L.level;
    const labelList& shared = L.sharedPoints;

    for (label l = 0; l < nLevels_; ++l)
    {
        L.points[l].clear();
        L.edges[l].clear();
        L.finerEdges[l].clear();
        for (const label i : L.gradient1[l]) L.inGradient1[l][i] = false;
        L.gradient1[l].clear();
        L.coarser[l].clear();
        L.onLevel[l] = false;
        L.gradientEdges[l].clear();
    }
    L.finest = 0;
    L.levelWeight = 0;
    forAll(level, i)
    {
        L.points[level[i]].append(i);
        L.onLevel[level[i]][i] = true;
        L.levelWeight[level[i]] += dual.pointWeight(i);
        L.finest = max(L.finest, level[i]);
    }
    forAll(pointsPerLevelSum_, l)
    {
        pointsPerLevelSum_[l] += L.levelWeight[l];
    }
    // (every processor recurses to the finest level of any: the stages
    // exchange with each other)
    if (Pstream::parRun())
    {
        reduce(L.finest, maxOp<label>());
    }
    forAll(es, e)
    {
        const label li = level[es[e]], lj = level[ee[e]];
        const label fine = max(li, lj), coarse = min(li, lj);
        L.edges[fine].append(e);
        if (fine > coarse)
        {
            L.finerEdges[coarse].append(e);
        }
    }

    // Gradients: stage 1 of level l at t, which every finer level shares,
    // needs them at its points and at the finer ends of its finer edges
    // (stage 2 at its own points only).  Coarser neighbours: the points of level
    // l - 1 at the coarse ends of the level's edges.  (listed marks each
    // point once; cleared after)
    boolList& mark = L.listed;
    for (label l = 0; l < nLevels_; ++l)
    {
        for (const label i : L.points[l])
        {
            L.gradient1[l].append(i);
            mark[i] = true;
        }
        for (const label e : L.finerEdges[l])
        {
            const label j = (level[es[e]] > l) ? es[e] : ee[e];
            if (!mark[j])
            {
                mark[j] = true;
                L.gradient1[l].append(j);
            }
        }
        completeShared(b, L, mark, L.gradient1[l]);
        for (const label e : L.edges[l])
        {
            const label i = es[e], j = ee[e];
            if (level[i] < l && !mark[i])
            {
                mark[i] = true;
                L.coarser[l].append(i);
            }
            if (level[j] < l && !mark[j])
            {
                mark[j] = true;
                L.coarser[l].append(j);
            }
        }
        completeShared(b, L, mark, L.coarser[l]);
        L.sharedOnLevel[l].clear();
        L.sharedGradient1[l].clear();
        for (const label i : shared)
        {
            if (level[i] == l)
            {
                L.sharedOnLevel[l].append(i);
            }
            if (mark[i] && level[i] >= l)
            {
                L.sharedGradient1[l].append(i);
            }
        }
        for (const label i : L.gradient1[l])
        {
            mark[i] = false;
            L.inGradient1[l][i] = true;
            // (the gradients' edge lists below rely on it)
            if (level[i] != l && level[i] != l + 1)
            {
                FatalErrorInFunction
                    << "Point " << i << " on level " << level[i]
                    << " is in the gradient list of level " << l
                    << ": neighbours more than one level apart"
                    << abort(FatalError);
            }
        }
        for (const label i : L.coarser[l]) mark[i] = false;
        L.edgePoints[l] = L.points[l];
        L.edgePoints[l].append(L.coarser[l]);
    }

    // The gradients' edges.  A point is listed for the first stage of its
    // own level and of the next coarser one (a finer end) only, and
    // neighbours differ by at most one level: an edge's candidates are
    // the levels from one below its coarser end to its finer end.  (The
    // second stage's points are among the first's: one list serves both)
    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        const label li = level[i], lj = level[j];
        const label fine = max(li, lj);
        for (label l = max(min(li, lj) - 1, label(0)); l <= fine; ++l)
        {
            if (L.inGradient1[l][i] || L.inGradient1[l][j])
            {
                L.gradientEdges[l].append(e);
            }
        }
    }
}


void Foam::multirateRungeKutta2::interpolateCoarser
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const scalar t,
    const scalar tc,
    const scalar hc
) const
{
    const scalar theta = (t - tc)/hc;
    for (const label j : L.coarser[l])
    {
        const fluxState& q0 = L.qStart[j];
        const fluxState& q1 = L.qPredicted[j];
        fluxState& q = b.q_[j];
        for (direction c = 0; c < nFluxComponents; ++c)
        {
            q[c] = q0[c] + theta*(q1[c] - q0[c]);
        }
    }
}


void Foam::multirateRungeKutta2::completeShared
(
    const solidBody& b,
    const bodyLevels& L,
    boolList& mark,
    DynamicList<label>& list
) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    const labelList& shared = L.sharedPoints;
    boolList listed(shared.size());
    forAll(shared, k)
    {
        listed[k] = mark[shared[k]];
    }
    b.dual_.sharedSums().combine
    (
        shared, listed, [](bool& x, const bool y) { x = x || y; }
    );
    forAll(shared, k)
    {
        const label i = shared[k];
        if (listed[k] && !mark[i])
        {
            mark[i] = true;
            list.append(i);
        }
    }
}


void Foam::multirateRungeKutta2::syncResiduals
(
    solidBody& b,
    bodyLevels& L,
    const DynamicList<label>& shared
) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    // Momentum, F and J in one exchange
    typedef FixedList<scalar, 13> residualShare;
    stageResidual& R = b.residual_;
    const bool RJ = R.J.size();
    DynamicList<residualShare>& r = L.residualShares;
    r.setSize(shared.size());
    forAll(shared, k)
    {
        const label i = shared[k];
        residualShare& rk = r[k];
        for (direction c = 0; c < 3; ++c) rk[c] = R.momentum[i][c];
        for (direction c = 0; c < 9; ++c) rk[3 + c] = R.F[i][c];
        rk[12] = RJ ? R.J[i] : 0;
    }
    b.dual_.sharedSums().sum(shared, r);
    forAll(shared, k)
    {
        const label i = shared[k];
        const residualShare& rk = r[k];
        for (direction c = 0; c < 3; ++c) R.momentum[i][c] = rk[c];
        for (direction c = 0; c < 9; ++c) R.F[i][c] = rk[3 + c];
        if (RJ) R.J[i] = rk[12];
    }
}


void Foam::multirateRungeKutta2::resetResiduals
(
    solidBody& b,
    const bodyLevels& L,
    const label l
) const
{
    stageResidual& R = b.residual_;
    const bool J = R.J.size();
    auto reset = [&](const label i)
    {
        R.momentum[i] = Zero;
        R.F[i] = Zero;
        if (J)
        {
            R.J[i] = 0;
        }
    };
    for (const label i : L.points[l]) reset(i);
    for (const label i : L.coarser[l]) reset(i);
    R.power = 0;
    R.surfacePoints.clear();
    R.surfaceVelocities.clear();
}


void Foam::multirateRungeKutta2::gradients
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const bool second,
    const DynamicList<label>& shared
) const
{
    const DynamicList<label>& points =
        second ? L.points[l] : L.gradient1[l];
    if (!b.scheme_->secondOrder())
    {
        return;
    }
    if (points.size())
    {
        // Riemann boundary slopes: the level's own points, from this
        // stage's boundary states (the boundary and contact fluxes come
        // first, boundaryFirst_).  The finer points of the first stage's
        // list have none at its time (theirs come in their own stages):
        // their slopes, which only the predictor's finer-edge fluxes use,
        // are the interior ones
        const bool riemann = b.scheme_->riemannBoundarySlope();
        greenGaussGradient
        (
            b.dual_, b.q_, b.G_, points,
            L.gradientEdges[l],
            second ? L.onLevel[l] : L.inGradient1[l],
            L.pointSubFaceStart, L.subFacePatch, L.subFace,
            riemann ? &b.residual_ : nullptr,
            b.material_->Zp(),
            acousticFormulas::interiorShearImpedance
            (
                b.material_->Zp(), b.material_->Zs()
            ),
            &L.onLevel[l]
        );
    }
    if (Pstream::parRun())
    {
        // Each processor's share over its own edges and sub-faces, already
        // divided by the (whole) volume: the shares add up
        DynamicList<fluxStateGradient>& g = L.gradientShares;
        g.setSize(shared.size());
        forAll(shared, k)
        {
            g[k] = b.G_[shared[k]];
        }
        b.dual_.sharedSums().sum(shared, g);
        forAll(shared, k)
        {
            b.G_[shared[k]] = g[k];
        }
    }
}


Foam::scalar Foam::multirateRungeKutta2::power
(
    const solidBody& b,
    const bodyLevels& L,
    const label l
) const
{
    scalar P = b.residual_.power;
    if (magSqr(b.bodyForce_) > 0)
    {
        const scalarField& V = b.dual_.volumes();
        const scalar rho = b.material_->rho();
        for (const label i : L.points[l])
        {
            P +=
                b.dual_.pointWeight(i)*V[i]*rho
               *(b.bodyForce_ & fluxVelocity(b.q_[i]));
        }
    }
    // (in parallel this processor's share: summed at the end of the step)
    return P;
}


void Foam::multirateRungeKutta2::ownEdgeFluxes
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const scalar halfh
) const
{
    // First in the stage (with boundaryFirst_, the boundary and contact
    // residuals are set aside meanwhile): the residuals of the level's
    // points and coarser neighbours then hold only these fluxes
    // (energyStable's blend of them, with their weight h/2 in the step's
    // energy)
    b.levelStageWeight_ = halfh;
    b.addInteriorFluxes(&L.edges[l], &L.edgePoints[l]);
    const stageResidual& R = b.residual_;
    const bool RJ = R.J.size();
    for (const label j : L.coarser[l])
    {
        L.Am[j] += halfh*R.momentum[j];
        L.AF[j] += halfh*R.F[j];
        if (RJ) L.AJ[j] += halfh*R.J[j];
    }
}


void Foam::multirateRungeKutta2::startStage
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const bool second,
    const scalar t,
    const scalar h,
    const scalar tc,
    const scalar hc
) const
{
    const DynamicList<label>& P = L.points[l];
    const scalar ts = second ? t + h : t;

    if (second)
    {
        // From the predicted state (the finer levels' steps interpolated
        // it)
        for (const label i : P)
        {
            b.q_[i] = L.qPredicted[i];
        }
    }
    interpolateCoarser(b, L, l, ts, tc, hc);
    if (!second)
    {
        b.storeState(P);
        for (const label i : P)
        {
            L.qStart[i] = b.q_[i];
        }
    }
    resetResiduals(b, L, l);
    if (boundaryFirst_)
    {
        b.addBoundaryFluxes(ts, h, second, &P);
        return;
    }
    interiorStage(b, L, l, second, h);
    b.addBoundaryFluxes(ts, h, second, &P);
    if (second)
    {
        addFinerIntegral(b, L, l, h);
    }
}


void Foam::multirateRungeKutta2::interiorStage
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const bool second,
    const scalar h
) const
{
    const DynamicList<label>& P = L.points[l];
    const scalar halfh = 0.5*h;
    if (second)
    {
        gradients(b, L, l, true, L.sharedOnLevel[l]);
        ownEdgeFluxes(b, L, l, halfh);
        return;
    }

    stageResidual& R = b.residual_;
    const bool RJ = R.J.size();
    gradients(b, L, l, false, L.sharedGradient1[l]);
    ownEdgeFluxes(b, L, l, halfh);

    // The finer edges' fluxes at t: in the predictor, and out of the final
    // update again (the finer level integrates them over the step)
    for (const label i : P)
    {
        L.Am[i] = R.momentum[i];
        L.AF[i] = R.F[i];
        L.AJ[i] = RJ ? R.J[i] : 0;
    }
    b.addInteriorFluxes(&L.finerEdges[l]);
    for (const label i : P)
    {
        L.Am[i] = -halfh*(R.momentum[i] - L.Am[i]);
        L.AF[i] = -halfh*(R.F[i] - L.AF[i]);
        L.AJ[i] = RJ ? -halfh*(R.J[i] - L.AJ[i]) : 0;
    }
}


void Foam::multirateRungeKutta2::interiorAfterBoundary
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const bool second,
    const scalar h
) const
{
    // The gradients take the boundary states of this stage (Riemann
    // boundary slopes); the boundary and contact residuals wait aside
    // while the interior fluxes (and the energy blend of them) go in
    const DynamicList<label>& P = L.points[l];
    stageResidual& R = b.residual_;
    const bool RJ = R.J.size();
    L.asideM.setSize(P.size());
    L.asideF.setSize(P.size());
    L.asideJ.setSize(RJ ? P.size() : 0);
    forAll(P, k)
    {
        const label i = P[k];
        L.asideM[k] = R.momentum[i];
        L.asideF[k] = R.F[i];
        R.momentum[i] = Zero;
        R.F[i] = Zero;
        if (RJ)
        {
            L.asideJ[k] = R.J[i];
            R.J[i] = 0;
        }
    }

    interiorStage(b, L, l, second, h);

    forAll(P, k)
    {
        const label i = P[k];
        R.momentum[i] += L.asideM[k];
        R.F[i] += L.asideF[k];
        if (RJ)
        {
            R.J[i] += L.asideJ[k];
        }
    }
    if (second)
    {
        addFinerIntegral(b, L, l, h);
    }
}


void Foam::multirateRungeKutta2::addFinerIntegral
(
    solidBody& b,
    const bodyLevels& L,
    const label l,
    const scalar h
) const
{
    // U^n+1 = U^n + h/2 (R1 + R2) over the level's edges, plus the finer
    // edges' integral: the stage-2 form 1/2 (U^n + U* + h R) with R2
    // completed by 2/h A
    stageResidual& R = b.residual_;
    const bool RJ = R.J.size();
    const scalar twoByH = 2/h;
    for (const label i : L.points[l])
    {
        R.momentum[i] += twoByH*L.Am[i];
        R.F[i] += twoByH*L.AF[i];
        if (RJ) R.J[i] += twoByH*L.AJ[i];
    }
}


bool Foam::multirateRungeKutta2::finishStage
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const bool second,
    const scalar h,
    scalar& P1
)
{
    const DynamicList<label>& P = L.points[l];
    syncResiduals(b, L, L.sharedOnLevel[l]);
    const scalar Ps = power(b, L, l);
    b.rkStage(h, second ? 0.5 : 0, &P);
    b.applyConstraints(&L.onLevel[l]);
    if (!b.updateConstitutive(&P))
    {
        return false;
    }
    if (second)
    {
        b.endStep(&P);
        b.Wext_ += 0.5*h*(P1 + Ps);
    }
    else
    {
        for (const label i : P)
        {
            L.qPredicted[i] = b.q_[i];
        }
        P1 = Ps;
    }
    lastUpdates_ += L.levelWeight[l];
    return true;
}


Foam::label Foam::multirateRungeKutta2::advance
(
    PtrList<solidBody>& bodies,
    const label l,
    const scalar t,
    const scalar h,
    const scalar tc,
    const scalar hc
)
{
    // Every body's level-l points stage by stage together, so that the
    // contact pairs on this level see both of their sides at the stage's
    // time (a body's own operations are those of a body stepped alone)
    auto stage = [&](const bool second)
    {
        forAll(bodies, bi)
        {
            if (levels_[bi].finest >= l)
            {
                startStage(bodies[bi], levels_[bi], l, second, t, h, tc, hc);
            }
        }
        forAll(contacts_, p)
        {
            if (pairLevel_[p] == l)
            {
                contacts_[p].addFluxes();
            }
        }
        forAll(bodies, bi)
        {
            if (levels_[bi].finest < l)
            {
                continue;
            }
            if (boundaryFirst_)
            {
                interiorAfterBoundary(bodies[bi], levels_[bi], l, second, h);
            }
            bodyLevels& L = levels_[bi];
            if (!finishStage(bodies[bi], L, l, second, h, L.stagePower[l]))
            {
                return bi;
            }
        }
        return label(-1);
    };

    forAll(contacts_, p)
    {
        if (pairLevel_[p] == l)
        {
            contacts_[p].startStep(h);
        }
    }

    // Stage 1 at t, the finer levels' two steps each, stage 2 at t + h
    label failed = stage(false);
    if (failed < 0 && finest_ > l)
    {
        const scalar halfh = 0.5*h;
        failed = advance(bodies, l + 1, t, halfh, t, h);
        if (failed < 0)
        {
            failed = advance(bodies, l + 1, t + halfh, halfh, t, h);
        }
    }
    if (failed < 0)
    {
        failed = stage(true);
    }
    return failed;
}


Foam::scalar Foam::multirateRungeKutta2::deltaT
(
    const PtrList<solidBody>& bodies,
    const scalar cfl
)
{
    // (a Hugoniot body's step anticipates the fastest impact it can meet)
    contactPair::anticipateImpacts(bodies, contacts_);
    scalar dtMin = GREAT;
    forAll(bodies, bi)
    {
        bodyLevels& L = levels_[bi];
        bodies[bi].localStableDeltaT(&L.dtPoint);
        for (scalar& dti : L.dtPoint)
        {
            dti *= cfl;
            dtMin = min(dtMin, dti);
        }
    }
    reduce(dtMin, minOp<scalar>());
    scalar dt = dtMin*scalar(label(1) << (nLevels_ - 1));

    // Contact pairs: a closing gap closes at the end of a step of the
    // pair's level, as with one global step (tvdRungeKutta2::stableDeltaT:
    // gaps closing within a quarter of that step are not waited for).
    // The pair keeps at least this level in the step (assignLevels), which
    // may be shorter (write times) and so have coarser points
    if (contacts_.size())
    {
        pairMinLevel_ = 0;
        assignLevels(bodies, dt);
        assignedDt_ = dt;
        scalar dtGap = GREAT;
        forAll(contacts_, p)
        {
            const label lp = pairLevel_[p];
            const scalar scale = scalar(label(1) << lp);
            const scalar hp = dt/scale;
            dtGap = min(dtGap, scale*contacts_[p].deltaTLimit(0.25*hp));
            pairMinLevel_[p] = lp;
        }
        if (dtGap < dt)
        {
            // (the step's levels are then those of the shorter step)
            dt = dtGap;
            assignedDt_ = -1;
        }
    }
    return dt;
}


Foam::label Foam::multirateRungeKutta2::step
(
    PtrList<solidBody>& bodies,
    const scalar t,
    const scalar dt,
    scalar& fraction
)
{
    lastUpdates_ = 0;
    pointsPerLevelSum_ = 0;
    fraction = 1;

    // The step's energy balance of tvdRungeKutta2 on the whole step (the
    // increments of every level scaled alike), for elastic bodies that
    // check it: a plastic body's return maps are committed level by level,
    // which a shortened increment would not follow
    bool balance = true;
    boolList check(bodies.size(), false);
    forAll(bodies, bi)
    {
        check[bi] = bodies[bi].checksStepEnergy();
        balance = balance && !bodies[bi].material_->plastic();
    }

    // Keep each body's state at t: a failure sends every body back to it
    auto save = [](solidBody& b, bodyLevels& L)
    {
        L.lm = b.lm_;
        L.u = b.u_;
        L.F = b.F_;
        if (b.scheme_->HLaw()) L.H = b.H_;
        if (b.scheme_->JLaw()) L.J = b.J_;
        L.Wext = b.Wext_;
        L.Dplastic = b.Dplastic_;
        b.material_->saveState();
    };
    // The step's start as the start of tvdRungeKutta2's step (its energy
    // balance and relaxStep read them)
    auto startOfStep = [](solidBody& b, bodyLevels& L, const scalar E)
    {
        b.lm0_ = L.lm;
        b.u0_ = L.u;
        b.F0_ = L.F;
        if (b.scheme_->HLaw()) b.H0_ = L.H;
        if (b.scheme_->JLaw()) b.J0_ = L.J;
        b.Wext0_ = L.Wext;
        b.stepEnergy0_ = E;
    };
    // (restoreState() goes back to the step-start copies)
    auto restore = [&startOfStep](solidBody& b, bodyLevels& L)
    {
        startOfStep(b, L, 0);
        b.Dplastic_ = L.Dplastic;
        b.material_->restoreSavedState();
        b.restoreState();
    };

    // (deltaT assigned them already for this step when it had to, for the
    // pairs' gap limit: the same levels)
    if (dt != assignedDt_)
    {
        assignLevels(bodies, dt);
    }
    assignedDt_ = -1;
    finest_ = 0;
    forAll(bodies, bi)
    {
        solidBody& b = bodies[bi];
        bodyLevels& L = levels_[bi];
        levelLists(b, L);
        finest_ = max(finest_, L.finest);
        save(b, L);
        if (b.lm0_.size() != b.lm_.size())
        {
            // (the step-start copies are made by the first storeState)
            b.storeState();
        }
        L.E = balance && check[bi] ? b.kineticEnergy() + b.strainEnergy() : 0;
        b.levelEnergyBudget_ = 0;
    }

    const label failed = advance(bodies, 0, t, dt, t, dt);
    if (failed >= 0)
    {
        // (where it failed, before going back)
        solidBody& b = bodies[failed];
        const point where(b.invalidPoint_);
        const scalar value = b.invalidValue_;
        const word quantity(b.invalidQuantity_);
        forAll(bodies, bi)
        {
            restore(bodies[bi], levels_[bi]);
        }
        b.invalidPoint_ = where;
        b.invalidValue_ = value;
        b.invalidQuantity_ = quantity;
        return failed;
    }
    if (Pstream::parRun())
    {
        // The level stages' external work and plastic dissipation were
        // this processor's shares
        forAll(bodies, bi)
        {
            solidBody& b = bodies[bi];
            const bodyLevels& L = levels_[bi];
            b.Wext_ = L.Wext + returnReduce(b.Wext_ - L.Wext, sumOp<scalar>());
            b.Dplastic_ =
                L.Dplastic
              + returnReduce(b.Dplastic_ - L.Dplastic, sumOp<scalar>());
        }
    }

    // The step's work and levels over all processors (a shared point
    // counted once)
    if (Pstream::parRun())
    {
        reduce(lastUpdates_, sumOp<scalar>());
        Pstream::listCombineGather(pointsPerLevelSum_, plusEqOp<scalar>());
        Pstream::listCombineScatter(pointsPerLevelSum_);
    }
    forAll(pointsPerLevel_, l)
    {
        pointsPerLevel_[l] = label(pointsPerLevelSum_[l] + 0.5);
    }

    if (balance && findIndex(check, true) >= 0)
    {
        forAll(bodies, bi)
        {
            if (check[bi])
            {
                startOfStep(bodies[bi], levels_[bi], levels_[bi].E);
            }
        }
        scalarList excess;
        const scalar gamma =
            tvdRungeKutta2::stepRelaxation(bodies, check, excess);
        if (gamma < 1)
        {
            fraction = gamma;
            forAll(bodies, bi)
            {
                // (bodies that do not check it keep the step-start copies
                // of their last level steps: give them the step's start)
                startOfStep(bodies[bi], levels_[bi], 0);
                bodies[bi].relaxStep(gamma);
                if (!bodies[bi].updateConstitutive())
                {
                    return bi;
                }
            }
        }
    }
    return -1;
}


// ************************************************************************* //
