/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "multirateRungeKutta2.H"
#include "greenGauss.H"
#include "Time.H"
#include "tvdRungeKutta2.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::multirateRungeKutta2::multirateRungeKutta2
(
    const Time& runTime,
    const PtrList<solidBody>& bodies,
    const PtrList<contactPair>& contacts,
    const label nLevels
)
:
    nLevels_(nLevels),
    levels_(bodies.size()),
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
    if (contacts.size())
    {
        unsupported
        (
            "contact pairs (constant/contactProperties): their gap limit"
            " and impulses belong to one shared step"
        );
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
            unsupported(body + "boundarySlope riemann (use interior)");
        }
        if (s.deformedPressure())
        {
            unsupported(body + "deformedPressure yes");
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
        for (boolList& on : L.onLevel)
        {
            on.setSize(n, false);
        }
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
        const label nPatches = dual.mesh().boundaryMesh().size();
        L.pointSubFaceStart.setSize(n + 1, 0);
        for (label patchi = 0; patchi < nPatches; ++patchi)
        {
            for (const label i : dual.subFaces(patchi).point)
            {
                ++L.pointSubFaceStart[i + 1];
            }
        }
        for (label i = 0; i < n; ++i)
        {
            L.pointSubFaceStart[i + 1] += L.pointSubFaceStart[i];
        }
        L.subFacePatch.setSize(L.pointSubFaceStart[n]);
        L.subFace.setSize(L.pointSubFaceStart[n]);
        labelList next(SubList<label>(L.pointSubFaceStart, n));
        for (label patchi = 0; patchi < nPatches; ++patchi)
        {
            const labelList& point = dual.subFaces(patchi).point;
            forAll(point, s)
            {
                const label m = next[point[s]]++;
                L.subFacePatch[m] = patchi;
                L.subFace[m] = s;
            }
        }
        L.Am.setSize(n, Zero);
        L.AF.setSize(n, Zero);
        L.AJ.setSize(n, 0.0);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::multirateRungeKutta2::setLevels
(
    const solidBody& b,
    bodyLevels& L,
    const scalar dt
)
{
    const label K = nLevels_ - 1;
    const dualMesh& dual = b.dual_;
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
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

    for (label l = 0; l < nLevels_; ++l)
    {
        L.points[l].clear();
        L.edges[l].clear();
        L.finerEdges[l].clear();
        L.gradient1[l].clear();
        L.coarser[l].clear();
        L.onLevel[l] = false;
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
        for (const label i : L.gradient1[l]) mark[i] = false;
        for (const label i : L.coarser[l]) mark[i] = false;
        L.edgePoints[l] = L.points[l];
        L.edgePoints[l].append(L.coarser[l]);
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
    const DynamicList<label>& points,
    const DynamicList<label>& shared
) const
{
    if (!b.scheme_->secondOrder())
    {
        return;
    }
    if (points.size())
    {
        greenGaussGradient
        (
            b.dual_, b.q_, b.G_, points,
            L.pointSubFaceStart, L.subFacePatch, L.subFace
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
    // First in the stage: the residuals of the level's points and coarser
    // neighbours then hold only these fluxes (energyStable's blend of them,
    // with their weight h/2 in the step's energy)
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


bool Foam::multirateRungeKutta2::advance
(
    solidBody& b,
    bodyLevels& L,
    const label l,
    const scalar t,
    const scalar h,
    const scalar tc,
    const scalar hc
)
{
    const DynamicList<label>& P = L.points[l];
    const UList<bool>& on = L.onLevel[l];
    stageResidual& R = b.residual_;
    const bool RJ = R.J.size();
    const scalar halfh = 0.5*h;

    // Stage 1 at t
    interpolateCoarser(b, L, l, t, tc, hc);
    b.storeState(P);
    for (const label i : P)
    {
        L.qStart[i] = b.q_[i];
    }
    resetResiduals(b, L, l);
    gradients(b, L, L.gradient1[l], L.sharedGradient1[l]);

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
    b.addBoundaryFluxes(t, h, false, &P);
    syncResiduals(b, L, L.sharedOnLevel[l]);
    const scalar P1 = power(b, L, l);
    b.rkStage(h, 0, &P);
    b.applyConstraints(&on);
    if (!b.updateConstitutive(&P))
    {
        return false;
    }
    for (const label i : P)
    {
        L.qPredicted[i] = b.q_[i];
    }
    lastUpdates_ += L.levelWeight[l];

    // The finer levels: two steps each
    if (L.finest > l)
    {
        if
        (
            !advance(b, L, l + 1, t, halfh, t, h)
         || !advance(b, L, l + 1, t + halfh, halfh, t, h)
        )
        {
            return false;
        }
    }

    // Stage 2 at t + h, from the predicted state (the finer levels'
    // steps interpolated it)
    for (const label i : P)
    {
        b.q_[i] = L.qPredicted[i];
    }
    interpolateCoarser(b, L, l, t + h, tc, hc);
    resetResiduals(b, L, l);
    gradients(b, L, P, L.sharedOnLevel[l]);
    ownEdgeFluxes(b, L, l, halfh);
    b.addBoundaryFluxes(t + h, h, true, &P);
    // U^n+1 = U^n + h/2 (R1 + R2) over the level's edges, plus the finer
    // edges' integral: the stage-2 form 1/2 (U^n + U* + h R) with R2
    // completed by 2/h A
    const scalar twoByH = 2/h;
    for (const label i : P)
    {
        R.momentum[i] += twoByH*L.Am[i];
        R.F[i] += twoByH*L.AF[i];
        if (RJ) R.J[i] += twoByH*L.AJ[i];
    }
    syncResiduals(b, L, L.sharedOnLevel[l]);
    const scalar P2 = power(b, L, l);
    b.rkStage(h, 0.5, &P);
    b.applyConstraints(&on);
    if (!b.updateConstitutive(&P))
    {
        return false;
    }
    b.endStep(&P);
    b.Wext_ += halfh*(P1 + P2);
    lastUpdates_ += L.levelWeight[l];

    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::multirateRungeKutta2::deltaT
(
    const PtrList<solidBody>& bodies,
    const scalar cfl
)
{
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
    return dtMin*scalar(label(1) << (nLevels_ - 1));
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

    forAll(bodies, bi)
    {
        solidBody& b = bodies[bi];
        bodyLevels& L = levels_[bi];
        setLevels(b, L, dt);
        save(b, L);
        if (b.lm0_.size() != b.lm_.size())
        {
            // (the step-start copies are made by the first storeState)
            b.storeState();
        }
        L.E = balance && check[bi] ? b.kineticEnergy() + b.strainEnergy() : 0;
        b.levelEnergyBudget_ = 0;
        const bool advanced = advance(b, L, 0, t, dt, t, dt);
        if (advanced && Pstream::parRun())
        {
            // The level stages' external work and plastic dissipation were
            // this processor's shares
            b.Wext_ = L.Wext + returnReduce(b.Wext_ - L.Wext, sumOp<scalar>());
            b.Dplastic_ =
                L.Dplastic
              + returnReduce(b.Dplastic_ - L.Dplastic, sumOp<scalar>());
        }
        if (!advanced)
        {
            // (where it failed, before going back)
            const point where(b.invalidPoint_);
            const scalar value = b.invalidValue_;
            const word quantity(b.invalidQuantity_);
            for (label k = 0; k <= bi; ++k)
            {
                restore(bodies[k], levels_[k]);
            }
            b.invalidPoint_ = where;
            b.invalidValue_ = value;
            b.invalidQuantity_ = quantity;
            return bi;
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
