/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "solidBody.H"
#include "Time.H"
#include "pointFieldIO.H"
#include "uniformStateIO.H"
#include "timeDirectory.H"
#include "checkedInput.H"
#include "emptyPolyPatch.H"
#include "syncTools.H"
#include "tensorCross.H"
#include "acousticFormulas.H"
#include "interiorHugoniot.H"
#include "hugoniot.H"
#include "greenGauss.H"
#include "shockFlattening.H"
#include "vector2D.H"
#include "unitConversion.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "ListListOps.H"

#include <malloc.h>
#include <cstring>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::solidBody::readScheme()
{
    checkKeywords
    (
        dict_,
        {"material", "scheme", "initialVelocity", "bodyForce",
         "planeStrain", "boundaryConditions", "probes"}
    );

    // Each switch given in the scheme dictionary or chosen from the
    // material (bodyScheme.H)
    scheme_.reset
    (
        new bodyScheme
        (
            dict_, material_(), dual_.linearExact(), dual_.triangleBoundary()
        )
    );
    if (scheme_->energyStable())
    {
        energyStability_.reset(new energyStability(dual_, scheme_->JLaw()));
    }
    if (scheme_->secondOrder())
    {
        limiter_ = limiter::New(scheme_->limiter(), scheme_->dict());
    }
}


void Foam::solidBody::checkDecomposition() const
{
    // processor*/ directories left from another mesh would run silently on
    // that mesh: compare the decomposed cell count with the undecomposed
    // mesh's (from the 'note' of its owner file header)
    if (!Pstream::parRun())
    {
        return;
    }
    label nCells = -1;
    const fileName owner
    (
        runTime_.globalPath()/runTime_.constant()
       /(name_ == polyMesh::defaultRegion ? word::null : name_)
       /polyMesh::meshSubDir/"owner"
    );
    if (Pstream::master() && isFile(owner))
    {
        IFstream is(owner);
        string line;
        for (label n = 0; n < 30 && is.good(); ++n)
        {
            is.getLine(line);
            const auto pos = line.find("nCells:");
            if (pos != string::npos)
            {
                IStringStream ss(line.substr(pos + 7));
                ss >> nCells;
                break;
            }
        }
    }
    Pstream::scatter(nCells);
    const label nDecomposed = returnReduce(mesh_.nCells(), sumOp<label>());
    if (nCells >= 0 && nCells != nDecomposed)
    {
        FatalErrorInFunction
            << "Body " << name_ << ": the decomposed mesh in processor*/ has "
            << nDecomposed << " cells, the mesh in " << owner.path()
            << " has " << nCells << ": the processor directories are stale."
            << nl << "    Decompose again: decomposePar -force"
            << (name_ == polyMesh::defaultRegion ? "" : " -allRegions")
            << exit(FatalError);
    }
}


void Foam::solidBody::createBoundaryConditions()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const dictionary& bcDict = dict_.subDict("boundaryConditions");

    wordList physical;
    forAll(patches, patchi)
    {
        if (!patches[patchi].coupled())
        {
            physical.append(patches[patchi].name());
        }
    }

    for (const entry& e : bcDict)
    {
        if (!e.isDict() && patches.findPatchID(e.keyword()) >= 0)
        {
            FatalIOErrorInFunction(bcDict)
                << "The boundary condition of patch '" << e.keyword()
                << "' of body '" << name_ << "' must be a dictionary: "
                << e.keyword() << " { type "
                << (e.stream().size() ? e.stream()[0] : token(word("traction")))
                << "; }" << nl << "Types: "
                << flatOutput(solidBoundaryCondition::
                   dictionaryConstructorTablePtr_->sortedToc())
                << exit(FatalIOError);
        }
        if (patches.findPatchID(e.keyword()) < 0)
        {
            FatalIOErrorInFunction(bcDict)
                << "Boundary condition for '" << e.keyword()
                << "', which is not a patch of body '" << name_ << "'" << nl
                << "Patches: " << flatOutput(physical)
                << exit(FatalIOError);
        }
    }

    dictionary emptyDict;
    emptyDict.add("type", "symmetry");

    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (pp.coupled())
        {
            continue;
        }

        if (isA<emptyPolyPatch>(pp) && !bcDict.found(pp.name()))
        {
            bcs_.append
            (
                solidBoundaryCondition::New(dual_, patchi, emptyDict)
            );
        }
        else if (bcDict.isDict(pp.name()))
        {
            bcs_.append
            (
                solidBoundaryCondition::New
                (
                    dual_, patchi, bcDict.subDict(pp.name())
                )
            );
        }
        else
        {
            FatalIOErrorInFunction(bcDict)
                << "No boundary condition for patch '" << pp.name()
                << "' of body '" << name_ << "'" << nl
                << "Every patch needs one: "
                << flatOutput(solidBoundaryCondition::
                   dictionaryConstructorTablePtr_->sortedToc())
                << exit(FatalIOError);
        }
    }
}


void Foam::solidBody::readState()
{
    const label nPts = mesh_.nPoints();
    const bool restart = restart_;

    // A restart reads every field it needs (or stops naming the file).  A
    // fresh run reads the fields the user put in the start directory and
    // takes the initial conditions of solidProperties for the others
    lm_.setSize(nPts);
    u_.setSize(nPts, Zero);
    F_.setSize(nPts, tensor::I);
    if (!readPointFieldIfPresent(mesh_, "lm", lm_, restart))
    {
        lm_ = material_->rho()*initialVelocity_;
    }
    readPointFieldIfPresent(mesh_, "u", u_, restart);
    readPointFieldIfPresent(mesh_, "F", F_, restart);

    if (scheme_->HLaw())
    {
        H_.setSize(nPts);
        if (!readPointFieldIfPresent(mesh_, "H", H_, restart))
        {
            forAll(H_, i)
            {
                H_[i] = cofactor(F_[i]);
            }
        }
    }
    else
    {
        Hc_.setSize(nPts);
    }

    if (scheme_->JLaw())
    {
        J_.setSize(nPts);
        if (!readPointFieldIfPresent(mesh_, "J", J_, restart))
        {
            forAll(J_, i)
            {
                J_[i] = det(F_[i]);
            }
        }
    }
    else
    {
        Jc_.setSize(nPts);
    }

    if (restart)
    {
        material_->readState(mesh_);
    }
}


void Foam::solidBody::readBookkeeping()
{
    if (restart_)
    {
        const autoPtr<IOdictionary> state
        (
            readUniformState("bodyState", mesh_)
        );
        E0_ = readUniformEntry<scalar>(*state, "initialEnergy");
        Wext_ = readUniformEntry<scalar>(*state, "externalWork");
        Dplastic_ = readUniformEntry<scalar>(*state, "plasticDissipation");
        nEnergyLimited_ =
            readUniformEntry<label>(*state, "energyLimitedStages");
        minEnergyTheta_ =
            readUniformEntry<scalar>(*state, "minEnergyBlending");
        nRelaxedSteps_ = state->getOrDefault<label>("relaxedSteps", 0);
        minRelaxation_ = state->getOrDefault<scalar>("minRelaxation", 1);
        nDissipatingRetries_ =
            state->getOrDefault<label>("dissipatingRetries", 0);
        readOnsetStarts(*state);
        readHeldClosed(*state);
    }
    else
    {
        E0_ = kineticEnergy() + strainEnergy();
        if (!std::isfinite(E0_) || E0_ > maxInputMagnitude)
        {
            FatalIOErrorInFunction(dict_)
                << "Body " << name_ << ": the initial energy " << E0_
                << " is not representable (initialVelocity "
                << initialVelocity_ << ", density " << material_->rho()
                << "): check the units of the inputs"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidBody::solidBody(const Time& runTime, const word& region)
:
    runTime_(runTime),
    name_(region),
    restart_(timeDirectory::isRestart(runTime)),
    mesh_
    (
        IOobject
        (
            region,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    ),
    dual_(mesh_),
    dict_
    (
        IOobject
        (
            "solidProperties",
            runTime.constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    material_(),
    limiter_(),
    riemann_(),
    nEnergyLimited_(0),
    minEnergyTheta_(1),
    levelEnergyBudget_(0),
    levelStageWeight_(0),
    stepEnergy0_(0),
    nRelaxedSteps_(0),
    minRelaxation_(1),
    nDissipatingRetries_(0),
    kineticEnergy_(0),
    strainEnergy_(0),
    kineticEnergyKnown_(false),
    strainEnergyKnown_(false),
    bcs_(),
    bodyForce_(getFiniteOrDefault<vector>(dict_, "bodyForce", Zero)),
    initialVelocity_
    (
        getFiniteOrDefault<vector>(dict_, "initialVelocity", Zero)
    ),
    Wext_(0),
    Wext0_(0),
    E0_(0),
    Dplastic_(0),
    dDplastic_(),
    invalidPoint_(Zero),
    invalidValue_(0),
    invalidQuantity_()
{
    heldLimit_ = false;
    impactSpeed_ = -1;
    lastDeltaT_ = 0;
    recentDeltaT_ = 0;
    strikeIndex_ = -1;
    releaseCentralF_ = false;

    // The dual mesh holds all the solver needs: free OpenFOAM's
    // demand-driven geometry and addressing, and the point lists of the
    // internal faces (kept where the pressure acts on the deformed dual)
    material_ = materialModel::New(dict_.subDict("material"), mesh_.nPoints());
    readScheme();
    mesh_.clearGeom();
    mesh_.clearAddressing();
    if (scheme_->deformedPressure())
    {
        dual_.enableDeformedAreas();
        xDeformed_.setSize(mesh_.nPoints());
        pressureCoeff_.setSize(mesh_.nPoints());
    }
    releaseUnusedMesh();
    malloc_trim(0);
    checkDecomposition();

    riemann_ = interiorRiemannSolver::New
    (
        scheme_->dict(), scheme_->riemannSolver(), material_()
    );
    createBoundaryConditions();
    symmetry_.reset(new symmetryConstraint(dual_, bcs_));
    if (scheme_->secondOrder() && scheme_->boundaryExtrapolation())
    {
        // A point on a mirror plane stands for its cell completed by the
        // mirror image, whose centroid lies on the plane: no offset along
        // the plane's normal (a one-layer plane-strain mesh is then the
        // confined 3D bar's middle layer)
        boundaryOffset_ = dual_.boundaryCentroidOffsets();
        const labelList& sp = symmetry_->points();
        forAll(sp, k)
        {
            const label b = dual_.boundaryIndex()[sp[k]];
            if (b >= 0)
            {
                boundaryOffset_[b] =
                    symmetry_->projections()[k] & boundaryOffset_[b];
            }
        }
    }
    planeStrain_.reset(new planeStrainTie(dual_, bcs_, dict_, name_));
    contactRotation_.reset(new contactRotation(dual_, bcs_));
    stableStep_.reset
    (
        new stableTimeStep(dual_, material_(), bcs_, scheme_->JLaw())
    );
    readState();
    if (material_->plastic())
    {
        dDplastic_.setSize(mesh_.nPoints());
    }

    const label nPts = mesh_.nPoints();
    q_.setSize(nPts);
    residual_.setSize(nPts, scheme_->JLaw());
    residual_.setBoundarySize
    (
        dual_,
        scheme_->riemannBoundarySlope() || scheme_->onsetStabilisation()
    );
    if (scheme_->secondOrder())
    {
        G_.setSize(nPts);
    }
    stageTime_ = runTime_.value();
    if (!updateConstitutive())
    {
        FatalErrorInFunction
            << "Body " << name_ << ": the "
            << (restart_ ? "restart" : "initial")
            << " state at t = " << runTime_.timeName() << " is invalid: "
            << invalidQuantity_ << " = " << invalidValue_
            << " at the point at " << invalidPoint_ << exit(FatalError);
    }
    readBookkeeping();
    // (what contact reads of the body before the first stage)
    updateDeformedDual();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::solidBody::nGlobalPoints() const
{
    return label(dual_.sumPoints(scalarField(mesh_.nPoints(), 1.0)) + 0.5);
}


namespace
{

// A patch whose Riemann traction is a contact load: a contact pair's or a
// rigid wall's (the onset zone's points, onsetStabilisation)
bool contactLoaded(const Foam::solidBoundaryCondition& bc)
{
    return bc.type() == "contact" || bc.type() == "rigidWall";
}

} // End anonymous namespace


const Foam::scalar Foam::solidBody::planarImpactAngle = 10;

// (A1 at 128 cells on tets, cfl 1.5: 2 transits left a 2.6 % overshoot,
// 3-6 transits 1.5-1.8 %; on hexahedra 2 transits 4.9 %, 4-10 transits
// 3.4-3.6 %: doc/results.md, "Contact onset where the F flux is central")
const Foam::scalar Foam::solidBody::onsetTransits = 4;
const Foam::scalar Foam::solidBody::plasticOnsetTransits = 8;

// (the copper bar of tests/solidBody/plasticWaves at 100 m/s: van Albada on
// the edges of every point that has not yielded put the precursor 2.0 %
// below the yield point, from half the yield stress 2.1 %, from 0.9 of it
// (with the edges between yielded and unyielded points) 1.6 %, with
// monotonized central on the rest, which still stops the precursor front's
// ringing; the plastic torus then loses 9.40 % of E0 instead of 9.56 %
// (8.85 % unlimited): doc/results.md, "Elastic precursors of plastic
// waves")
const Foam::scalar Foam::solidBody::nearYieldShare = 0.9;

// (the central F flux's separating faces, tension after the release: A1 on
// 64 tets 6.3 -> 2.6 %, a bar on a wall 10.4 -> 4.8 %; the same from one
// transit to sixteen, but longer zones cost the elastic torus more energy;
// 0.04 transits, one stage, left 4.4 and 7.5 %: doc/results.md, "Contact
// release where the F flux is central")
const Foam::scalar Foam::solidBody::releaseTransits = 1;


Foam::scalar Foam::solidBody::wallImpactMach(const bool planarOnly) const
{
    scalar speed = 0;
    for (const solidBoundaryCondition& bc : bcs_)
    {
        const scalar s = bc.closingSpeed(initialVelocity_);
        if
        (
            s > 0
         && (!planarOnly || dual_.patchFlat(bc.patchi(), planarImpactAngle))
        )
        {
            speed = max(speed, s);
        }
    }
    return speed/material_->cp();
}


bool Foam::solidBody::driven() const
{
    bool driven = magSqr(bodyForce_) > 0;
    for (const solidBoundaryCondition& bc : bcs_)
    {
        driven = driven || bc.drives();
    }
    return driven;
}


const Foam::scalar Foam::solidBody::planeWaveSpanTolerance = 0.1;


bool Foam::solidBody::planeWaveImpact
(
    const label patchi,
    const bool uniaxial
) const
{
    return
        dual_.patchFlat(patchi, planarImpactAngle)
     && mag(dual_.patchSpan(patchi) - 1) <= planeWaveSpanTolerance
     && (!uniaxial || laterallyConfined(patchi));
}


bool Foam::solidBody::laterallyConfined(const label patchi) const
{
    const vector A(dual_.patchArea(patchi));
    const vector n(A/max(mag(A), VSMALL));
    const scalar parallel = Foam::cos(degToRad(planarImpactAngle));
    for (const solidBoundaryCondition& bc : bcs_)
    {
        const label p = bc.patchi();
        // (a symmetry plane holds its points on their plane)
        if (p == patchi || bc.constrainsNormal())
        {
            continue;
        }
        const vector Ap(dual_.patchArea(p));
        const bool parallelFace =
            dual_.patchFlat(p, planarImpactAngle)
         && mag(Ap & n) >= parallel*mag(Ap);
        if (!parallelFace)
        {
            return false;
        }
    }
    return true;
}


bool Foam::solidBody::planeWaveBoundaryImpact(const bool uniaxial) const
{
    // (a velocity or traction step on a bar's end face sends the same
    // plane front as a wall: without the upwind F flux the face overshoots
    // by 19 and 15 %, doc/results.md, "Plane-wave impacts")
    for (const solidBoundaryCondition& bc : bcs_)
    {
        if
        (
            (bc.closingSpeed(initialVelocity_) > 0 || bc.drives())
         && planeWaveImpact(bc.patchi(), uniaxial)
        )
        {
            return true;
        }
    }
    return false;
}


void Foam::solidBody::chooseFromScene
(
    const scalar planarMach,
    const scalar impactMach,
    const bool planeWave,
    const bool uniaxial,
    const bool multirate
)
{
    bool contactPatches = false;
    for (const solidBoundaryCondition& bc : bcs_)
    {
        contactPatches = contactPatches || contactLoaded(bc);
    }
    scheme_->chooseFromScene
    (
        planarMach, impactMach, planeWave, uniaxial, contactPatches,
        multirate
    );
    if (scheme_->secondOrder() && limiter_->type() != scheme_->limiter())
    {
        limiter_ = limiter::New(scheme_->limiter(), scheme_->dict());
    }
    if (scheme_->onsetZoneLimited())
    {
        onsetLimiter_.reset(new limiters::barthJespersen(scheme_->dict()));
    }
    if
    (
        material_->plastic() && scheme_->secondOrder()
     && scheme_->elasticLimiter() != scheme_->limiter()
    )
    {
        elasticLimiter_ =
            limiter::New(scheme_->elasticLimiter(), scheme_->dict());
        yieldLimiter_ = limiter::New("vanAlbada", scheme_->dict());
        updateElasticPoints();
    }
    // With the central F flux the points closed on a wall or contact face
    // (or driven) have a mode of their own, which sets their step
    // (stableTimeStep.H)
    stableStep_->useCentralFFlux(!scheme_->FStabilisation());
    heldLimit_ = false;
    for (const solidBoundaryCondition& bc : bcs_)
    {
        heldLimit_ = heldLimit_ || bc.holdsVelocity();
    }
    heldLimit_ = heldLimit_ && !scheme_->FStabilisation();
    // The upwind F flux's release zone: a released point's opening edges
    // take the central F flux for the release's transit (updateOnsetZone,
    // addInteriorFluxes)
    releaseCentralF_ = contactPatches && scheme_->FStabilisation();
    if (releaseCentralF_)
    {
        Info<< "    release: the central F flux on the opening edges of the "
            << "points released within " << releaseTransits << " transit of "
            << "their shortest edge" << nl;
    }
    // (the boundary states are kept for the Riemann boundary slopes, for
    // the onset zone's loaded points and for the closed points' step)
    residual_.setBoundarySize
    (
        dual_,
        scheme_->riemannBoundarySlope() || scheme_->onsetStabilisation()
     || heldLimit_
    );
}


template<class Select>
void Foam::solidBody::markLoaded
(
    const Select& select,
    UList<bool>& loaded
) const
{
    for (const solidBoundaryCondition& bc : bcs_)
    {
        const label patchi = bc.patchi();
        if (!select(bc) || !residual_.boundarySet[patchi])
        {
            continue;
        }
        const labelList& sp = dual_.subFaces(patchi).point;
        const List<vector>& tB = residual_.boundaryTraction[patchi];
        forAll(tB, s)
        {
            if (magSqr(tB[s]) > 0)
            {
                loaded[sp[s]] = true;
            }
        }
    }
}


template<class Type>
Foam::List<Type> Foam::solidBody::gatherLists(const UList<Type>& mine)
{
    List<List<Type>> lists(Pstream::nProcs());
    lists[Pstream::myProcNo()] = mine;
    Pstream::gatherList(lists);
    Pstream::scatterList(lists);
    return ListListOps::combine<List<Type>>(lists, accessOp<List<Type>>());
}


Foam::labelList Foam::solidBody::boundaryPointsAt
(
    const UList<point>& positions
) const
{
    // Each boundary point at one of the positions (within a millionth of
    // its shortest edge's scale: decomposePar and reconstructPar may round
    // the coordinates) takes its index
    const labelList& bp = dual_.boundaryPoints();
    const pointField& X = mesh_.points();
    const boundBox box(X, false);
    const scalar tol = 1e-9*box.mag() + VSMALL;
    labelList at(bp.size(), -1);
    if (positions.empty())
    {
        return at;
    }
    forAll(bp, b)
    {
        const point& x = X[bp[b]];
        forAll(positions, k)
        {
            if (magSqr(positions[k] - x) < sqr(tol))
            {
                at[b] = k;
                break;
            }
        }
    }
    return at;
}


void Foam::solidBody::writeStartTimes
(
    dictionary& state,
    const word& kind,
    const scalarList& starts,
    const UList<bool>& keep
) const
{
    // The points by their reference positions, gathered from every
    // processor: the list does not depend on the decomposition, and
    // reconstructPar's copy of any processor's state holds all of it
    const labelList& bp = dual_.boundaryPoints();
    const pointField& X = mesh_.points();
    DynamicList<point> myPositions;
    DynamicList<scalar> myStarts;
    forAll(starts, b)
    {
        if (keep[b])
        {
            myPositions.append(X[bp[b]]);
            myStarts.append(starts[b]);
        }
    }
    // (full precision: the start times decide when an onset ends)
    const unsigned int precision = IOstream::defaultPrecision(17);
    state.add(word(kind + "Positions"), gatherLists<point>(myPositions));
    state.add(word(kind + "Starts"), gatherLists<scalar>(myStarts));
    IOstream::defaultPrecision(precision);
}


void Foam::solidBody::writeOnsetStarts(dictionary& state) const
{
    List<bool> keep(onsetStart_.size());
    forAll(onsetStart_, b)
    {
        keep[b] = onsetStart_[b] < VGREAT;
    }
    writeStartTimes(state, "onset", onsetStart_, keep);

    // The points still in their release (all that have one, when no stage
    // has set the durations since a restart)
    const scalar t = runTime_.value();
    const scalar share = releaseShare();
    const bool durations = onsetDuration_.size() == releaseStart_.size();
    keep.setSize(releaseStart_.size());
    forAll(releaseStart_, b)
    {
        keep[b] =
            durations
          ? t - releaseStart_[b] < share*onsetDuration_[b]
          : releaseStart_[b] > -VGREAT;
    }
    writeStartTimes(state, "release", releaseStart_, keep);
}


void Foam::solidBody::writeHeldClosed(dictionary& state) const
{
    // The closed held points by their reference positions, as the onset
    // starts: the restarted run's first step takes the same step
    updateHeldClosed();
    const labelList& bp = dual_.boundaryPoints();
    const pointField& X = mesh_.points();
    DynamicList<point> myPositions;
    forAll(bp, b)
    {
        if (heldClosed_[bp[b]])
        {
            myPositions.append(X[bp[b]]);
        }
    }
    const unsigned int precision = IOstream::defaultPrecision(17);
    state.add("closedPositions", gatherLists<point>(myPositions));
    IOstream::defaultPrecision(precision);
}


void Foam::solidBody::readHeldClosed(const dictionary& state)
{
    const labelList at
    (
        boundaryPointsAt
        (
            state.getOrDefault<pointField>("closedPositions", pointField())
        )
    );
    const labelList& bp = dual_.boundaryPoints();
    heldClosed_.setSize(mesh_.nPoints());
    heldClosed_ = false;
    forAll(bp, b)
    {
        heldClosed_[bp[b]] = (at[b] >= 0);
    }
}


void Foam::solidBody::updateHeldClosed() const
{
    // The points closed in the last stage on patches that hold the
    // velocity (a traction on one of their sub-faces), and those that will
    // close within the coming step (a wall's gap closing within twice the
    // last step, which may grow).  Before the first stage (no patch set):
    // on a restart the written flags (readHeldClosed), at the start the
    // points touching (the step that starts the contact is theirs)
    bool anySet = false;
    for (const solidBoundaryCondition& bc : bcs_)
    {
        anySet = anySet || residual_.boundarySet[bc.patchi()];
    }
    anySet = returnReduce(anySet, orOp<bool>());
    if (heldClosed_.size() != mesh_.nPoints())
    {
        heldClosed_.setSize(mesh_.nPoints());
        heldClosed_ = false;
    }
    if (!anySet && restart_)
    {
        return;
    }
    heldClosed_ = false;
    markLoaded
    (
        [](const solidBoundaryCondition& bc) { return bc.holdsVelocity(); },
        heldClosed_
    );
    const scalar dt = anySet ? 2*runTime_.deltaTValue() : 0;
    for (const solidBoundaryCondition& bc : bcs_)
    {
        bc.markClosing(u_, q_, runTime_.value(), dt, heldClosed_);
    }
    if (Pstream::parRun())
    {
        syncTools::syncPointList(mesh_, heldClosed_, orEqOp<bool>(), false);
    }
}


void Foam::solidBody::readStartTimes
(
    const dictionary& state,
    const word& kind,
    scalarList& starts,
    const scalar none
)
{
    const word positionsKey(kind + "Positions");
    const word startsKey(kind + "Starts");
    const pointField positions
    (
        state.getOrDefault<pointField>(positionsKey, pointField())
    );
    const scalarField times
    (
        state.getOrDefault<scalarField>(startsKey, scalarField())
    );
    if (times.size() != positions.size())
    {
        FatalIOErrorInFunction(state)
            << "Body " << name_ << ": " << positions.size()
            << " " << positionsKey << " but " << times.size() << " "
            << startsKey << " in " << state.name() << nl
            << "    The restart file is damaged:"
            << " restart from an earlier complete time." << exit(FatalIOError);
    }
    if (positions.empty())
    {
        return;
    }

    // Each boundary point at one of the positions takes its start time
    const labelList at(boundaryPointsAt(positions));
    starts.setSize(at.size(), none);
    forAll(at, b)
    {
        if (at[b] >= 0)
        {
            starts[b] = times[at[b]];
        }
    }
}


void Foam::solidBody::readOnsetStarts(const dictionary& state)
{
    readStartTimes(state, "onset", onsetStart_, VGREAT);
    readStartTimes(state, "release", releaseStart_, -VGREAT);
}


Foam::scalar Foam::solidBody::bodyOnsetTransits() const
{
    return material_->plastic() ? plasticOnsetTransits : onsetTransits;
}


Foam::scalar Foam::solidBody::releaseShare() const
{
    return releaseTransits/bodyOnsetTransits();
}


bool Foam::solidBody::updateOnsetZone()
{
    const label nPts = mesh_.nPoints();
    const labelList& es = dual_.edgeStart();
    const labelList& ee = dual_.edgeEnd();
    const labelList& bp = dual_.boundaryPoints();
    const scalar t = stageTime_;

    if (onsetStart_.size() != bp.size())
    {
        onsetStart_.setSize(bp.size(), VGREAT);
    }
    if (releaseStart_.size() != bp.size())
    {
        releaseStart_.setSize(bp.size(), -VGREAT);
    }
    if (onsetDuration_.size() != bp.size())
    {
        // Each point's onset lasts onsetTransits times the p-wave's
        // transit of its shortest edge (in the reference configuration,
        // so that a restart finds the same durations): the time its
        // one-sided cells take to settle after the front has formed.  A
        // plastic body's face settles later, behind the slower plastic
        // wave: ended after four transits, a copper bar's face on
        // hexahedra, still short of its plateau, sprang back by 2.0-3.1 %;
        // after eight, 0.3 % (doc/results.md, "Contact onset where the F
        // flux is central")
        const scalarField h(dual_.lengths());
        onsetDuration_.setSize(bp.size());
        forAll(bp, b)
        {
            onsetDuration_[b] = h[bp[b]];
        }
        const scalar transits = bodyOnsetTransits()/material_->cp();
        for (scalar& d : onsetDuration_)
        {
            d *= transits;
        }
    }
    if (onsetZoneEdge_.size() != es.size())
    {
        onsetZonePoint_.setSize(nPts);
        onsetScratch_.setSize(nPts);
        onsetZoneEdge_.setSize(es.size());
    }

    // The points this stage's contact and wall Riemann states load
    List<bool>& loaded = onsetScratch_;
    loaded = false;
    markLoaded(contactLoaded, loaded);
    if (Pstream::parRun())
    {
        syncTools::syncPointList(mesh_, loaded, orEqOp<bool>(), false);
    }

    // The zone's core: loaded for less than the onset's duration, or
    // released for less than the release's (after the onsets, nearly every
    // stage: an empty zone, whose stage is the central F flux's and needs
    // no pass over the edges).  At a release the traction a point held
    // drops to zero, the same jump as at onset the other way: with the
    // central F flux the point's F springs past its new state and its face
    // carries tension after it comes free
    List<bool>& core = onsetZonePoint_;
    core = false;
    bool anyCore = false;
    const scalar share = releaseShare();
    forAll(bp, b)
    {
        const label i = bp[b];
        if (!loaded[i])
        {
            if (onsetStart_[b] < VGREAT)
            {
                releaseStart_[b] = t;
            }
            onsetStart_[b] = VGREAT;
            core[i] = (t - releaseStart_[b] < share*onsetDuration_[b]);
            anyCore = anyCore || core[i];
            continue;
        }
        onsetStart_[b] = min(onsetStart_[b], t);
        core[i] = (t - onsetStart_[b] < onsetDuration_[b]);
        anyCore = anyCore || core[i];
    }
    // The upwind F flux's bodies (releaseCentralF_): their zone is the
    // released points alone, their F flux being upwind everywhere else
    // (addInteriorFluxes drops its traction-jump term on the zone's
    // opening edges).  The loaded flags are synchronised and so are the
    // start times, so processors agree on the points without an exchange
    if (scheme_->FStabilisation())
    {
        bool anyReleased = false;
        forAll(bp, b)
        {
            const label i = bp[b];
            core[i] = core[i] && !loaded[i];
            anyReleased = anyReleased || core[i];
        }
        if (anyReleased)
        {
            forAll(es, e)
            {
                onsetZoneEdge_[e] = core[es[e]] || core[ee[e]];
            }
        }
        return anyReleased;
    }
    if (!returnReduce(anyCore, orOp<bool>()))
    {
        return false;
    }

    // Around the onset's points one layer of neighbours (a struck point's
    // own edges alone left a 3.9 % overshoot on A1, one layer 1.2 %:
    // doc/results.md, "Plane-wave impacts"); a release's points alone
    // (with the layer the tension is the same and the elastic torus loses
    // 10.9 % of E0 instead of 10.2 %: doc/results.md, "Contact release
    // where the F flux is central"); then the edges that touch the zone
    List<bool>& onsetCore = onsetScratch_;
    forAll(onsetCore, i)
    {
        onsetCore[i] = loaded[i] && core[i];
    }
    List<bool>& zone = onsetZonePoint_;
    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        if (onsetCore[i] || onsetCore[j])
        {
            zone[i] = true;
            zone[j] = true;
        }
    }
    if (Pstream::parRun())
    {
        syncTools::syncPointList(mesh_, zone, orEqOp<bool>(), false);
    }
    forAll(es, e)
    {
        onsetZoneEdge_[e] = onsetZonePoint_[es[e]] || onsetZonePoint_[ee[e]];
    }
    return true;
}


Foam::word Foam::solidBody::boundaryConditionType(const label patchi) const
{
    for (const solidBoundaryCondition& bc : bcs_)
    {
        if (bc.patchi() == patchi)
        {
            return bc.type();
        }
    }
    return word::null;
}


void Foam::solidBody::storeState()
{
    lm0_ = lm_;
    u0_ = u_;
    F0_ = F_;
    if (scheme_->HLaw()) H0_ = H_;
    if (scheme_->JLaw()) J0_ = J_;
    Wext0_ = Wext_;
    if (checksStepEnergy())
    {
        stepEnergy0_ = kineticEnergy() + strainEnergy();
    }
}


void Foam::solidBody::storeState(const labelUList& points)
{
    const bool HLaw = scheme_->HLaw();
    const bool JLaw = scheme_->JLaw();
    for (const label i : points)
    {
        lm0_[i] = lm_[i];
        u0_[i] = u_[i];
        F0_[i] = F_[i];
        if (HLaw) H0_[i] = H_[i];
        if (JLaw) J0_[i] = J_[i];
    }
}


void Foam::solidBody::restoreState()
{
    stateChanged();
    lm_ = lm0_;
    u_ = u0_;
    F_ = F0_;
    if (scheme_->HLaw()) H_ = H0_;
    if (scheme_->JLaw()) J_ = J0_;
    Wext_ = Wext0_;
    updateConstitutive();
}


bool Foam::solidBody::updateConstitutive(const labelUList* points)
{
    stateChanged();
    const scalar invRho = 1.0/material_->rho();
    const label n = lm_.size();

    forEachPoint(n, points, [&](const label i)
    __attribute__((always_inline))
    {
        setFluxVelocity(q_[i], invRho*lm_[i]);
    });
    if (!scheme_->HLaw())
    {
        forEachPoint(n, points, [&](const label i)
        __attribute__((always_inline))
        {
            Hc_[i] = cofactor(F_[i]);
        });
    }
    if (!scheme_->JLaw())
    {
        forEachPoint(n, points, [&](const label i)
        __attribute__((always_inline))
        {
            Jc_[i] = det(F_[i]);
        });
    }

    // An inverted or collapsed volume (or NaN) must not reach the material
    // (pow of a negative J or det F); the time loop reports it
    const List<scalar>& J = Jc();
    const List<tensor>& H = Hc();
    // (With floating-point traps off, an overflow shows here as a
    // non-finite J, det F or momentum: the run stops with where and when)
    label bad = -1;
    label kind = 0;
    const auto check = [&](const label i)
    {
        const scalar detF = (H[i] && F_[i])/3.0;
        const scalar lm2 = magSqr(lm_[i]);
        if
        (
            !(J[i] > 0) || !(detF > 0)
         || !std::isfinite(J[i]) || !std::isfinite(detF)
         || !std::isfinite(lm2)
        )
        {
            bad = i;
            if (!(J[i] > 0) || !std::isfinite(J[i]))
            {
                kind = 0;
                invalidValue_ = J[i];
            }
            else if (!(detF > 0) || !std::isfinite(detF))
            {
                kind = 1;
                invalidValue_ = detF;
            }
            else
            {
                kind = 2;
                invalidValue_ = invRho*std::sqrt(lm2);
            }
            return false;
        }
        return true;
    };
    if (points)
    {
        for (const label i : *points)
        {
            if (!check(i)) break;
        }
    }
    else
    {
        for (label i = 0; i < n; ++i)
        {
            if (!check(i)) break;
        }
    }
    if (returnReduce(bad < 0, andOp<bool>()))
    {
        material_->stress(F_, H, J, q_, points);
        return true;
    }

    // Report the first bad point of the lowest processor that has one
    label proc = (bad >= 0) ? Pstream::myProcNo() : Pstream::nProcs();
    reduce(proc, minOp<label>());
    invalidPoint_ = Zero;
    scalar value = 0;
    if (proc == Pstream::myProcNo())
    {
        invalidPoint_ = mesh_.points()[bad];
        value = invalidValue_;
    }
    else
    {
        kind = 0;
    }
    reduce(invalidPoint_, sumOp<vector>());
    invalidValue_ = returnReduce(value, sumOp<scalar>());
    // (kind: 0 J, 1 det F, 2 momentum; J is det F without the J law)
    const label k = returnReduce(kind, sumOp<label>());
    invalidQuantity_ =
        (k == 2) ? "|v|" : (k == 1 || !scheme_->JLaw()) ? "det F" : "J";
    return false;
}


void Foam::solidBody::startStage()
{
    residual_.reset();
    updateDeformedDual();
}


void Foam::solidBody::updateDeformedDual()
{
    // The deformed dual and the points' pressure coefficients for this
    // stage's fluxes (doc/method.md, "Pressure on the deformed dual")
    if (scheme_->deformedPressure())
    {
        const pointField& X = mesh_.points();
        forAll(X, i)
        {
            xDeformed_[i] = X[i] + u_[i];
        }
        dual_.deformedAreas(xDeformed_, deformedEdgeC_, deformedSubFaceA_);
        const List<tensor>& H = Hc();
        forAll(q_, i)
        {
            pressureCoeff_[i] = (fluxStress(q_[i]) && H[i])/(H[i] && H[i]);
        }
    }
}


namespace
{

// Shock stabilisation: an edge whose points close at this fraction of the
// wave speed or more, with a closing jump left by the reconstruction, gets
// the full normal part of the upwind F flux.  The impact Mach number
// below which the acoustic contact solver is exact enough (doc/method.md,
// section 3): the non-linearity of the wave speed that makes shocks, and
// their post-shock noise, starts there (doc/results.md, "Shocks in
// non-linear elastic bodies")
const Foam::scalar shockSensorMach = 0.01;

// vorticityDamping: the rotational tangential jumps' extra impedance, in
// units of the normal wave's.  The A3 pair on 64 structured tets: with 1
// it stopped at Mach 3 (t = 0.085, with the pressure on H N), with 2 and 3
// it ran; on the deformed dual with positionalF, 3 holds Mach 1-2.5 within
// 0.5 % (doc/results.md, "Why the struck faces of tets go uneven")
const Foam::scalar vorticityDampingFactor = 3;

// The square of the relative size below which a jump between two points'
// states is round-off: (1e-12)^2 of their squared magnitudes
const Foam::scalar roundOffJump2 = 1e-24;

// The closing speed, as a fraction of the points' velocity jump, over which
// a closing edge's lower impedance bound is blended in
const Foam::scalar compressiveBlend = 1e-3;

// The traction of a run-time selected interior Riemann solver (one virtual
// call per edge)
struct solverTraction
{
    const Foam::interiorRiemannSolver& solver;

    //- Whether compressive edges take their jumps' own impedances (below)
    static constexpr bool compressiveJumps = false;

    Foam::vector operator()
    (
        const Foam::vector& tL, const Foam::vector& tR,
        const Foam::vector& vL, const Foam::vector& vR,
        const Foam::vector& n, const Foam::scalar Lambda,
        const Foam::scalar Zstate
    ) const
    {
        return solver.traction(tL, tR, vL, vR, n, Lambda, Zstate);
    }

    //- (not used: compressiveJumps is false)
    Foam::vector operator()
    (
        const Foam::vector& tL, const Foam::vector& tR,
        const Foam::vector& vL, const Foam::vector& vR,
        const Foam::vector& n, const Foam::scalar Lambda,
        const Foam::scalar, const Foam::scalar,
        const Foam::scalar, const Foam::scalar,
        const Foam::scalar
    ) const
    {
        return solver.traction(tL, tR, vL, vR, n, Lambda, 0);
    }
};

// The acoustic stick traction with constant impedances (times the face's
// compression factor), inlined
struct stickTraction
{
    const Foam::scalar Zp, Zs;

    static constexpr bool compressiveJumps = true;

    Foam::vector operator()
    (
        const Foam::vector& tL, const Foam::vector& tR,
        const Foam::vector& vL, const Foam::vector& vR,
        const Foam::vector& n, const Foam::scalar Lambda,
        const Foam::scalar
    ) const
    {
        return Foam::acousticFormulas::interiorStickTraction
        (
            tL, tR, vL, vR, n, Lambda, Zp, Zs
        );
    }

    //- The same with each part's impedance the points' own jump's within
    //  [lower, 1] times the wave's (acousticFormulas::jumpTractionFactor),
    //  from the parts of their traction and velocity jumps: normal (dtn,
    //  dvn) and the magnitudes of the tangential ones (dtt, dvt).  (With
    //  lower = 1 the wave's, to the bit)
    Foam::vector operator()
    (
        const Foam::vector& tL, const Foam::vector& tR,
        const Foam::vector& vL, const Foam::vector& vR,
        const Foam::vector& n, const Foam::scalar Lambda,
        const Foam::scalar dtn, const Foam::scalar dvn,
        const Foam::scalar dtt, const Foam::scalar dvt,
        const Foam::scalar lower
    ) const
    {
        namespace AF = Foam::acousticFormulas;
        const Foam::scalar s = AF::compressedFaceFactor(Lambda);
        return AF::stickTraction
        (
            tL, tR, vL, vR, n,
            s*Zp*AF::jumpTractionFactor(dtn, dvn, s*Zp, lower),
            s*Zs*AF::jumpTractionFactor(dtt, dvt, s*Zs, lower)
        );
    }
};

} // End anonymous namespace


void Foam::solidBody::addInteriorFluxes
(
    const labelUList* edges,
    const labelUList* edgePoints
)
{
    scalar Zp = 0, Zs = 0;
    if (riemann_->constantImpedances(Zp, Zs))
    {
        addInteriorFluxes(stickTraction{Zp, Zs}, edges, edgePoints);
    }
    else
    {
        addInteriorFluxes(solverTraction{riemann_()}, edges, edgePoints);
    }
}


template<class Traction>
void Foam::solidBody::addInteriorFluxes
(
    const Traction& traction,
    const labelUList* edges,
    const labelUList* edgePoints
)
{
    const labelList& es = dual_.edgeStart();
    const labelList& ee = dual_.edgeEnd();
    const vectorField& Ne = dual_.edgeNormals();
    const scalarField& Ae = dual_.edgeMagSf();
    const pointField& X = mesh_.points();
    const List<tensor>& H = Hc();

    // The velocity's upwind part in the F flux (the Riemann velocity's
    // traction-jump term, doc/method.md section 4).  Through J' = H : D it
    // damps the jump of the normal traction, and with it the jump of
    // Sigma_J, with the coefficient of the J stabilisation itself
    // (|H C|^2/(2 Z |C|), Z = Zp max(1, |H N|)): with it the J stabilisation is already there,
    // and adding it again damps a checkerboard of J at twice the rate the
    // stable step allows
    // Contact onset (onsetStabilisation): the upwind F flux and the
    // Riemann boundary slopes on the onset zone only (not with multirate
    // stepping, whose levels take their edges in turns)
    const bool onsetZone =
        scheme_->onsetStabilisation() && !scheme_->FStabilisation() && !edges
     && updateOnsetZone();
    const bool* __restrict__ zoneEdge =
        onsetZone ? onsetZoneEdge_.cdata() : nullptr;
    // The upwind F flux's release zone: the released points' edges
    const bool releaseZone = releaseCentralF_ && !edges && updateOnsetZone();
    const bool* __restrict__ releaseEdge =
        releaseZone ? onsetZoneEdge_.cdata() : nullptr;
    const bool upwindF = scheme_->FStabilisation() || onsetZone;
    const bool JStabilisation = scheme_->JLaw() && !scheme_->FStabilisation();
    const scalar Sfactor = 0.5/material_->Zp();
    // Shock stabilisation: the normal part of the term, in full on the
    // edges no shock is closing, and on the ones a shock closes weighted
    // by the sensor (there it takes over its share of the J
    // stabilisation).  (The term on the shock's edges alone, as the
    // sensor's name suggests, left the standing pattern behind neo-Hookean
    // shocks at 0.21-0.51 % of the shocked stress instead of 0.05-0.28 %:
    // doc/results.md, "Shocks in non-linear elastic bodies")
    const bool shockF =
        !scheme_->FStabilisation() && scheme_->shockStabilisation();
    const scalar shockSensorSpeed = shockSensorMach*material_->cp();
    const scalar vStabP = upwindF || shockF ? 0.5/material_->Zp() : 0;
    const scalar vStabS =
        upwindF && material_->Zs() > VSMALL ? 0.5/material_->Zs() : 0;
    const scalar ZpBody = material_->Zp();
    const scalar shockMass = upwindF || shockF ? material_->shockMass() : 0;
    const bool shearFree = material_->shearFree();
    // vorticityDamping (bodyScheme): the rotational part of the points'
    // tangential velocity jumps damped with vorticityDampingFactor times
    // the normal wave's impedance on top of the interior solver's
    // tangential impedance (with the gradients: second order, one global
    // step)
    const bool vorticityDamping =
        shearFree && scheme_->vorticityDamping() && scheme_->secondOrder()
     && !edges;
    // A Hugoniot material's normal impedance at an edge: at least that of
    // the chord of its pressure between the points' volume ratios, which
    // grows with compression (interiorRiemannSolvers::hugoniot::
    // normalImpedance); other materials' wave speeds do not depend on
    // the state here
    const materialModel& material = material_();
    const bool stateImpedance = material.hugoniot();
    const List<scalar>& Jstate = Jc();
    // With the upwind F flux, the edges whose points close (a compressive
    // front) take their jumps' own impedances, in the traction and in the
    // F flux (acousticFormulas::jumpTractionFactor): an oblique
    // front then leaves a struck face's one-sided cells on the front's
    // characteristic.  Opening edges (relief fronts) keep the wave's: a
    // sharper relief front leaves more tension at a face that separates
    // (doc/results.md, "Onset and release on other bar meshes").  Not
    // with a limiter that steepens beyond the front's own jump (superbee):
    // the compressive bump it leaves ahead of a release is an artefact,
    // which the jump's own impedance would damp less
    const bool compressiveJumps =
        upwindF && Traction::compressiveJumps && !shearFree
     && !(scheme_->secondOrder() && limiter_->overSteepens());
    // The pressure on the deformed dual: the central part of the traction,
    // pi H N A, acts on the deformed area vector instead
    const vector* __restrict__ deformedC =
        scheme_->deformedPressure() ? deformedEdgeC_.cdata() : nullptr;
    const scalar* __restrict__ pressureCoeff = pressureCoeff_.cdata();

    if (scheme_->secondOrder() && !edges)
    {
        greenGaussGradient
        (
            dual_, q_, G_,
            scheme_->riemannBoundarySlope() || onsetZone
          ? &residual_ : nullptr,
            material_->Zp(),
            acousticFormulas::interiorShearImpedance
            (
                material_->Zp(), material_->Zs()
            ),
            onsetZone && !scheme_->riemannBoundarySlope()
          ? &onsetZonePoint_ : nullptr
        );
        limiter_->limit(dual_, q_, G_);
        // Unlimited, the Riemann boundary slopes at a struck face swing
        // from step to step (a plastic bar on a wall, hexahedra: 12.4 %
        // onset overshoot with the zone, 9.8 % without it); Barth-
        // Jespersen on the zone's points alone, for the zone's few
        // stages, takes it to 2.2 % (0.3 % with the
        // plastic zone's eight transits) (doc/results.md, "Contact onset
        // where the F flux is central")
        if (onsetZone && onsetLimiter_)
        {
            onsetLimiter_->limitPoints(dual_, q_, G_, &onsetZonePoint_);
        }
    }

    // One edge's upwind fluxes from its two midpoint states: the traction
    // and the velocity times the area (tC, vCA), and the J flux dS
    // (Inlined into each loop: as a call, each edge waited for the
    // previous one's square root and division)
    auto edgeFlux =
    [&]
    (
        const label e,
        const vector& vL, const vector& vR,
        const tensor& PL, const tensor& PR,
        const scalar SJL, const scalar SJR,
        vector& tC, vector& vCA, scalar& dS
    ) __attribute__((always_inline))
    {
        const label i = es[e], j = ee[e];
        const vector& N = Ne[e];
        const scalar A = Ae[e];
        const bool upwindE = upwindF && (!zoneEdge || zoneEdge[e]);
        const scalar Zstate =
            stateImpedance
          ? material.rho()*material.chordWaveSpeed(Jstate[i], Jstate[j])
          : ZpBody;

        // Spatial normal from the average area map
        const vector hN(0.5*((H[i] & N) + (H[j] & N)));
        const scalar hN2 = hN & hN;
        const scalar invMagHN = 1.0/std::sqrt(hN2);
        const vector n(invMagHN*hN);
        const scalar magHN = hN2*invMagHN;

        // The upwind traction (the body's interior Riemann solver) and the
        // velocity of the F flux.  In a shear-free body no wave carries a
        // tangential velocity jump, so there is nothing to reconstruct:
        // both take the points' own tangential velocities (the normal ones
        // stay reconstructed).  The solver's tangential impedance
        // (acousticFormulas::interiorShearImpedance) then damps the
        // points' jump, at first order, by Z/2 |[v_t]|^2 >= 0 per edge, and
        // the F flux takes their average, which is exact at the midpoint
        // for a linear field.  (With the reconstructed tangential
        // velocities a transverse mode grew from round-off at the contact
        // face of strong Hugoniot impacts: doc/results.md, "Shear-free
        // bodies")
        const vector tL(PL & N), tR(PR & N);
        vector vAverage(0.5*(vL + vR));

        // The points' own jumps (the F flux's weight and impedances), and
        // their normal and tangential parts
        vector dtP(Zero);
        scalar dtPn = 0, dvPn = 0, dtPt = 0, dvPt = 0;
        // (the lower bound of the jumps' own impedances, in units of the
        // wave's: one keeps the wave's)
        scalar lower = 1;
        if (upwindE)
        {
            const vector ti(fluxStress(q_[i]) & N), tj(fluxStress(q_[j]) & N);
            const vector vi(fluxVelocity(q_[i])), vj(fluxVelocity(q_[j]));
            dtP = tj - ti;
            vector dvP(vj - vi);
            // A jump at the round-off of the points' states (two points
            // in the same state) has no impedance of its own: it is none.
            // (Read as one, its impedance was the ratio of two round-offs:
            // turned to another axis, the bar on a wall's face parted from
            // the run along x by 1.7e-4 in one step; doc/results.md,
            // "Orientation")
            const scalar Z2 = ZpBody*ZpBody;
            if
            (
                magSqr(dtP) + Z2*magSqr(dvP)
             <= roundOffJump2
               *(magSqr(ti) + magSqr(tj) + Z2*(magSqr(vi) + magSqr(vj)))
            )
            {
                dtP = Zero;
                dvP = Zero;
            }
            dtPn = dtP & n;
            dvPn = dvP & n;
            if (vStabS > 0)
            {
                dtPt = mag(dtP - dtPn*n);
                dvPt = mag(dvP - dvPn*n);
            }
            // A closing edge's bound (compressiveJumps) is blended in over
            // closing speeds up to compressiveBlend of the points' whole
            // velocity jump: a switch at dvPn = 0 changed the bound of the
            // tangential part too, whose jump need not vanish there, and
            // the sign of a round-off closing speed then chose between
            // them (serial and 2-rank runs parted by 5.6e-4 of the contact
            // stress from contact onset on, against 3e-8 now;
            // doc/results.md, "Orientation")
            if (compressiveJumps && dvPn < 0)
            {
                const scalar band2 = sqr(compressiveBlend)*magSqr(dvP);
                const scalar closing =
                    dvPn*dvPn >= band2
                  ? 1 : -dvPn/std::sqrt(band2);
                lower =
                    1
                  - (1 - acousticFormulas::compressiveJumpLowerBound)
                   *closing;
            }
        }

        if (shearFree)
        {
            const vector vi(fluxVelocity(q_[i]));
            const vector vj(fluxVelocity(q_[j]));
            tC = A*traction
            (
                tL, tR,
                vi + ((vL - vi) & n)*n, vj + ((vR - vj) & n)*n,
                n, magHN, Zstate
            );
            const vector vP(0.5*(vi + vj));
            vAverage = vP + ((vAverage - vP) & n)*n;

            // The part of the points' velocity jump that their mean
            // velocity gradient's symmetric part does not explain is
            // rotational: zero across a plane wave whatever the edge's
            // direction, the whole jump in a shear flow or a spin.  Its
            // share w of the tangential jump takes the extra damping
            // (Z/2 w |[v_t]|^2 >= 0 per unit area: D never falls from it)
            if (vorticityDamping)
            {
                const fluxStateGradient& Gi = G_[i];
                const fluxStateGradient& Gj = G_[j];
                const vector d(X[j] - X[i]);
                tensor L;
                for (direction c = 0; c < 3; ++c)
                {
                    const vector g
                    (
                        0.5*(gradientOf(Gi, c) + gradientOf(Gj, c))
                    );
                    L(c, 0) = g.x();
                    L(c, 1) = g.y();
                    L(c, 2) = g.z();
                }
                const vector dv(vj - vi);
                const vector r(dv - 0.5*((L & d) + (d & L)));
                const vector dvt(dv - (dv & n)*n);
                const vector rt(r - (r & n)*n);
                const scalar dvt2 = magSqr(dvt);
                if (dvt2 > VSMALL)
                {
                    const scalar w = min(1.0, magSqr(rt)/dvt2);
                    tC +=
                        (
                            A*0.5*vorticityDampingFactor*w
                           *acousticFormulas::compressedFaceFactor(magHN)
                           *ZpBody
                        )*dvt;
                }
            }

            // On the deformed dual a uniform pressure is in equilibrium at
            // every point: its closed cells' area vectors sum to zero,
            // where the points' H N do not (the discrete divergence of the
            // cofactors is not zero where H varies)
            if (deformedC)
            {
                tC +=
                    (0.5*(pressureCoeff[i] + pressureCoeff[j]))
                   *(deformedC[e] - A*hN);
            }
        }
        else if (compressiveJumps && upwindE)
        {
            tC = A*traction
            (
                tL, tR, vL, vR, n, magHN, dtPn, dvPn, dtPt, dvPt, lower
            );
        }
        else
        {
            tC = A*traction(tL, tR, vL, vR, n, magHN, Zstate);
        }

        // The upwind (Riemann) velocity: average plus the traction jump
        // over twice the impedances, weighted by how much of the points'
        // own jump the reconstruction left: one at a front the limiter
        // has cut back to first order, of the order of the mesh size where
        // the solution is smooth (there the full term damped bending on
        // coarse meshes many times more than the momentum's upwinding:
        // doc/method.md, section 8)
        vector dt(tR - tL);
        scalar w = upwindE ? 1 : 0;
        if (shockF && !upwindE)
        {
            // The sensor: a jump the reconstruction left closing, at a
            // closing speed of the points above shockSensorMach of the
            // wave speed (a shock closes its edges at a good part of the
            // particle velocity jump and the limiter leaves its jump in
            // place; smooth waves and bending within elastic limits close
            // far slower, with reconstructed jumps of either sign)
            const scalar closing =
                (fluxVelocity(q_[i]) - fluxVelocity(q_[j])) & n;
            w =
                closing > 0 && ((vL - vR) & n) > 0
              ? min(1.0, closing/shockSensorSpeed) : 0;
        }
        // The face's impedances grow with its compression as in the
        // traction (acousticFormulas::compressedFaceFactor): the F flux's
        // upwind velocity and the J stabilisation are the same Riemann
        // solution's
        // (1/max(1, |H N|) from the inverse already taken: no division)
        const scalar invS = min(1.0, invMagHN);
        // With a Hugoniot material the normal impedance is the shock one
        // in compression, as in the traction: F and momentum then follow
        // one Riemann solution.  (With the acoustic impedance here the
        // Mach 1 bar A3 reached -98 instead of -75.)
        scalar vStabN =
            shockMass > 0
          ? 0.5/interiorRiemannSolvers::hugoniot::normalImpedance
            (
                ZpBody, shockMass, vL, vR, n, magHN, Zstate
            )
          : invS*vStabP;
        scalar vStabT = invS*vStabS;
        if (w > 0)
        {
            if (!upwindE)
            {
                dtP = (fluxStress(q_[j]) - fluxStress(q_[i])) & N;
            }
            const scalar jump1 = mag(dtP);
            w *= jump1 > VSMALL ? min(1.0, 2*mag(dt)/jump1) : 1.0;
            dt *= w;
            if (upwindE)
            {
                // Each part of the term divides the traction jump by the
                // impedance of the points' own jump, |[t]|/|[v]|, where
                // that exceeds the wave's: a wave carries [t] = Z [v] and
                // keeps Godunov's term, a shock faster than the wave gets
                // its own (Rankine-Hugoniot) impedance, and a slow mode
                // (bending, the compression of a nearly incompressible
                // body), whose traction jumps are far larger than Z [v],
                // is not damped as if it were a wave: Godunov's low-Mach
                // excess (the ring at level 0.5 lost 87 % of E0 with the
                // wave's impedance, 61 % with the jump's; the nearly
                // incompressible bars stopped with J < 0 at their contact
                // face; doc/results.md, "The upwind F flux in slow modes")
                // (on a closing edge the jump's own impedance also below
                // the wave's, down to half of it: compressiveJumps above)
                vStabN *= acousticFormulas::jumpUpwindFactor
                (
                    dtPn, dvPn, 0.5/vStabN, lower
                );
                if (vStabT > 0)
                {
                    vStabT *= acousticFormulas::jumpUpwindFactor
                    (
                        dtPt, dvPt, 0.5/vStabT, lower
                    );
                }
            }
        }
        // A released point's opening edges: no term.  Behind a face that
        // has just come free the rest of the arriving relief front
        // reflects, and the term, which damps the traction jump of the
        // opening edges as a wave's, holds that reflection's tension in
        // the face point's half cell (the central F flux on these edges for
        // the release's transit: A1 on 32 tets 3.1 -> 2.6 %, a bar leaving
        // a wall on 50 tets 3.2 -> 2.5 %; everywhere, it cost the bars' L1
        // errors and the onset: doc/results.md, "Contact release with the
        // upwind F flux")
        if (releaseEdge && releaseEdge[e] && dvPn > 0)
        {
            vStabN = 0;
            vStabT = 0;
        }
        // (off the onset zone: no term; the shock stabilisation keeps its
        // normal part, unweighted where its sensor is zero)
        if (!upwindE)
        {
            vStabT = 0;
            if (!shockF)
            {
                vStabN = 0;
            }
        }
        const scalar dtn = dt & n;
        vCA =
            A
           *(vAverage + (vStabN*dtn)*n + vStabT*(dt - dtn*n));
        dS = JStabilisation ? (1 - w)*Sfactor*A*invS*hN2*(SJR - SJL) : 0;
    };

    // Add one edge's fluxes to the residuals
    List<vector>& Rp = residual_.momentum;
    List<tensor>& RF = residual_.F;
    List<scalar>& RJ = residual_.J;
    auto addFlux =
    [&]
    (
        const label e,
        const vector& tC, const vector& vCA, const scalar dS
    ) __attribute__((always_inline))
    {
        const label i = es[e], j = ee[e];
        const tensor vN(vCA*Ne[e]);
        Rp[i] += tC;
        Rp[j] -= tC;
        RF[i] += vN;
        RF[j] -= vN;
        if (JStabilisation)
        {
            RJ[i] += dS;
            RJ[j] -= dS;
        }
    };

    // The edge's second-order fluxes (from its reconstructed midpoint
    // states) and its first-order ones (from its points' states).  A
    // plastic body's edges with a point that has not yielded may take a
    // limiter of their own (bodyScheme elasticLimiter)
    const char* __restrict__ elasticPoint =
        elasticLimiter_ ? elasticPoint_.cdata() : nullptr;
    // The edges a strong shock closes: first-order states, in part or in
    // full (shockFlattening.H).  (Over every edge also at a multirate
    // level's stage: a point's coefficient reads its neighbours' states,
    // which the other levels keep as they were)
    const scalar* __restrict__ flattening = nullptr;
    if (scheme_->secondOrder() && scheme_->shockFlattening())
    {
        shockFlattening::pointCoefficients
        (
            dual_, X, u_, Jstate, q_, flattening_
        );
        if (Pstream::parRun())
        {
            syncTools::syncPointList
            (
                mesh_, flattening_, maxEqOp<scalar>(), scalar(0)
            );
        }
        flattening = flattening_.cdata();
    }
    fluxState qL, qR;
    auto secondOrderFlux =
    [&]
    (
        const label e, vector& tC, vector& vCA, scalar& dS
    ) __attribute__((always_inline))
    {
        const label i = es[e], j = ee[e];
        const vector halfdX(0.5*(X[j] - X[i]));
        const limiter* edgeLimiter = limiter_.get();
        if (elasticPoint)
        {
            // (an edge between a yielded point and one that has not
            // yielded crosses the yield point's kink however steep the
            // front)
            const char si = elasticPoint[i], sj = elasticPoint[j];
            if (si == 2 || sj == 2 || (si == 0) != (sj == 0))
            {
                edgeLimiter = yieldLimiter_.get();
            }
            else if (si == 1)
            {
                edgeLimiter = elasticLimiter_.get();
            }
        }
        edgeLimiter->midpointStates
        (
            q_[i], q_[j], G_[i], G_[j], halfdX, qL, qR
        );
        if (flattening)
        {
            const scalar chi = max(flattening[i], flattening[j]);
            if (chi > 0)
            {
                shockFlattening::flatten(chi, q_[i], q_[j], qL, qR);
            }
        }
        edgeFlux
        (
            e,
            fluxVelocity(qL), fluxVelocity(qR),
            fluxStress(qL), fluxStress(qR),
            fluxSigmaJ(qL), fluxSigmaJ(qR),
            tC, vCA, dS
        );
    };
    auto firstOrderFlux =
    [&]
    (
        const label e, vector& tC, vector& vCA, scalar& dS
    ) __attribute__((always_inline))
    {
        const label i = es[e], j = ee[e];
        const fluxState& qi = q_[i];
        const fluxState& qj = q_[j];
        edgeFlux
        (
            e,
            fluxVelocity(qi), fluxVelocity(qj),
            fluxStress(qi), fluxStress(qj),
            fluxSigmaJ(qi), fluxSigmaJ(qj),
            tC, vCA, dS
        );
    };

    // The energy an edge's fluxes produce (energyStability.H)
    auto production =
    [&]
    (
        const label e,
        const vector& tC, const vector& vCA, const scalar dS
    ) __attribute__((always_inline))
    {
        const label i = es[e], j = ee[e];
        const fluxState& qi = q_[i];
        const fluxState& qj = q_[j];
        return energyStability::edgeProduction
        (
            tC, vCA, dS,
            fluxVelocity(qi), fluxStress(qi), fluxSigmaJ(qi),
            fluxVelocity(qj), fluxStress(qj), fluxSigmaJ(qj),
            Ne[e], Ae[e]
        );
    };

    // Interior fluxes: one pass over the edges (energy stability first
    // keeps the boundary and contact residuals added before)
    const bool energyStable =
        energyStability_.valid() && scheme_->secondOrder() && !edges;
    if (energyStable)
    {
        energyStability_->setAside(residual_);
    }
    vector tC, vCA;
    scalar dS;
    // Multirate stepping: one level's edges (out of line: the inlined
    // flux code it repeats would otherwise push the inliner past its
    // budget in the passes below, which then called the limiter's and
    // the traction's functions per edge: -40 % on the throughput mesh)
    auto levelFluxes = [&]() __attribute__((noinline))
    {
        // Multirate stepping: one level's edges, their energy production
        // summed as they go (with its rounding scale)
        const bool blend =
            edgePoints && energyStability_.valid() && scheme_->secondOrder();
        scalar S2 = 0, scale = 0;
        if (blend)
        {
            levelPowerScale_.setSize(q_.size());
            for (const label i : *edgePoints)
            {
                const fluxState& qi = q_[i];
                levelPowerScale_[i] =
                    mag(fluxVelocity(qi))*mag(fluxStress(qi));
            }
        }
        const scalar* __restrict__ powerScale = levelPowerScale_.cdata();
        const labelUList& levelEdges = *edges;
        const label nLevelEdges = levelEdges.size();
        for (label k = 0; k < nLevelEdges; ++k)
        {
            const label e = levelEdges[k];
            // (as in the full pass below: the far end's data asked for
            // ahead)
            if (k + edgePrefetchDistance < nLevelEdges)
            {
                const label jAhead = ee[levelEdges[k + edgePrefetchDistance]];
                if (scheme_->secondOrder())
                {
                    prefetchObject(G_[jAhead]);
                }
                prefetchObject(q_[jAhead]);
                prefetchObject(H[jAhead]);
                prefetchObject<1>(residual_.F[jAhead]);
                prefetchObject<1>(residual_.momentum[jAhead]);
            }
            if (scheme_->secondOrder())
            {
                secondOrderFlux(e, tC, vCA, dS);
            }
            else
            {
                firstOrderFlux(e, tC, vCA, dS);
            }
            addFlux(e, tC, vCA, dS);
            if (blend)
            {
                S2 += production(e, tC, vCA, dS);
                scale += Ae[e]*(powerScale[es[e]] + powerScale[ee[e]]);
            }
        }
        // energyStable across the levels: this stage's edges enter the
        // step's energy with weight w (h/2 in the stage's Heun average);
        // what the earlier stages of the step dissipated (the budget, <=
        // 0) may be spent, beyond it the edges' fluxes are blended towards
        // first order (the blend of energyStability.H): the step's
        // production over all levels then stays <= 0, as one global step's
        if (blend)
        {
            // (every processor blends alike: its edges' shares of the
            // level's production, in one exchange)
            vector2D sums(S2, scale);
            reduce(sums, sumOp<vector2D>());
            S2 = sums.x();
            scale = sums.y();
        }
        const scalar w = levelStageWeight_;
        if (!blend || !(levelEnergyBudget_ + w*S2 > 1e-12*w*scale))
        {
            if (blend)
            {
                levelEnergyBudget_ += w*S2;
            }
            return;
        }

        // The residuals of edgePoints hold only these edges' fluxes
        // (multirateRungeKutta2 adds the others after)
        scalar S1 = 0;
        for (const label e : *edges)
        {
            firstOrderFlux(e, tC, vCA, dS);
            S1 += production(e, tC, vCA, dS);
        }
        reduce(S1, sumOp<scalar>());
        S1 = min(S1, 0.0);
        const scalar allowed = -levelEnergyBudget_/w;
        const scalar theta =
            S1 < allowed ? min(1.0, (allowed - S1)/(S2 - S1)) : 0;
        levelEnergyBudget_ = min(0.0, levelEnergyBudget_ + w*(theta*S2 + (1 - theta)*S1));
        const bool JRes = residual_.J.size();
        for (const label i : *edgePoints)
        {
            residual_.momentum[i] *= theta;
            residual_.F[i] *= theta;
            if (JRes)
            {
                residual_.J[i] *= theta;
            }
        }
        for (const label e : *edges)
        {
            firstOrderFlux(e, tC, vCA, dS);
            addFlux(e, (1 - theta)*tC, (1 - theta)*vCA, (1 - theta)*dS);
        }
        ++nEnergyLimited_;
        minEnergyTheta_ = min(minEnergyTheta_, theta);
        return;
    };
    if (edges)
    {
        levelFluxes();
        return;
    }
    else if (scheme_->secondOrder())
    {
        const label nEdges = es.size();
        forAll(es, e)
        {
            // (the far end's data, the slowest loads of an edge, asked
            // for ahead: fluxState.H)
            if (e + edgePrefetchDistance < nEdges)
            {
                const label jAhead = ee[e + edgePrefetchDistance];
                prefetchObject(G_[jAhead]);
                prefetchObject(q_[jAhead]);
                prefetchObject(H[jAhead]);
                prefetchObject<1>(residual_.F[jAhead]);
                prefetchObject<1>(residual_.momentum[jAhead]);
            }
            secondOrderFlux(e, tC, vCA, dS);
            addFlux(e, tC, vCA, dS);
        }
    }
    else
    {
        forAll(es, e)
        {
            firstOrderFlux(e, tC, vCA, dS);
            addFlux(e, tC, vCA, dS);
        }
    }

    // Energy stability (energyStability.H): blend towards the first-order
    // interior fluxes where the second-order ones produce energy
    if (energyStable)
    {
        const scalar theta = energyStability_->apply
        (
            residual_, q_,
            [&]()
            {
                scalar S0 = 0;
                forAll(es, e)
                {
                    firstOrderFlux(e, tC, vCA, dS);
                    S0 += production(e, tC, vCA, dS);
                }
                return S0;
            },
            [&](const scalar w)
            {
                forAll(es, e)
                {
                    firstOrderFlux(e, tC, vCA, dS);
                    addFlux(e, w*tC, w*vCA, w*dS);
                }
            }
        );
        if (theta >= 0)
        {
            ++nEnergyLimited_;
            minEnergyTheta_ = min(minEnergyTheta_, theta);
        }
    }
}


void Foam::solidBody::addBoundaryFluxes
(
    const scalar t,
    const scalar h,
    const bool second,
    const labelUList* points
)
{
    // (u0_: the start of the step, stored by storeState)
    const UList<stateIncrement>* increment = nullptr;
    if (scheme_->secondOrder() && scheme_->boundaryExtrapolation())
    {
        updateBoundaryIncrements();
        increment = &boundaryIncrement_;
    }
    const solidBoundaryCondition::stageStep step{u0_, h, second, increment};
    stageTime_ = t;
    const List<tensor>& H = Hc();
    const materialModel& m = material_();
    const solidBoundaryCondition::waveData body
    {
        m.Zp(), m.Zs(), m.shockMass(), m.hugoniot() ? &Jc() : nullptr, &m
    };
    for (const solidBoundaryCondition& bc : bcs_)
    {
        const label patchi = bc.patchi();
        residual_.power += bc.addFluxes
        (
            u_, q_, H, body, t, step, residual_.momentum, residual_.F,
            residual_.boundaryTraction[patchi],
            residual_.boundaryVelocity[patchi],
            deformedDual(patchi).get(),
            points
        );
        bc.prescribeDisplacements(u_, q_, t, step, residual_, points);
        residual_.boundarySet[patchi] = true;
    }

}


void Foam::solidBody::updateBoundaryIncrements()
{
    // Omega_i G_i = sum_j 1/2 (f_j - f_i) C_ij: with interior slopes the
    // boundary sub-faces take the point's own value and add nothing.  All
    // boundary points every time, also in multirate stepping, where a
    // level's sub-faces use their neighbours' states too
    const labelList& bp = dual_.boundaryPoints();
    const List<vector>& delta = boundaryOffset_;
    const labelList& pes = dual_.pointEdgeStart();
    const labelList& pe = dual_.pointEdges();
    const scalarField& V = dual_.volumes();
    boundaryIncrement_.setSize(bp.size());
    forAll(bp, b)
    {
        const label i = bp[b];
        const scalar* __restrict__ qi = q_[i].cdata();
        stateIncrement& dq = boundaryIncrement_[b];
        dq = scalar(0);
        const scalar s = 0.5/V[i];
        for (label k = pes[i]; k < pes[i + 1]; ++k)
        {
            const label e = pe[k];
            const scalar w = s*(dual_.C(e, i) & delta[b]);
            const scalar* __restrict__ qj =
                q_[dual_.otherPoint(e, i)].cdata();
            for (direction c = 0; c < nFluxComponents; ++c)
            {
                dq[c] += w*(qj[c] - qi[c]);
            }
        }
    }

    // Each processor summed its own edges: add the shares of shared points
    // (every processor lists the points on a patch of any of them)
    if (Pstream::parRun())
    {
        dual_.sharedSums().sum(bp, boundaryIncrement_);
    }
}


void Foam::solidBody::finishResiduals()
{
    residual_.synchronise(dual_);

    // Body force power
    if (magSqr(bodyForce_) > 0)
    {
        const scalarField& V = dual_.volumes();
        const scalar rho = material_->rho();
        forAll(q_, i)
        {
            residual_.power +=
                dual_.pointWeight(i)*V[i]*rho
               *(bodyForce_ & fluxVelocity(q_[i]));
        }
    }
    reduce(residual_.power, sumOp<scalar>());
}


void Foam::solidBody::rkStage
(
    const scalar dt,
    const scalar a,
    const labelUList* points
)
{
    stateChanged();
    const scalarField& V = dual_.volumes();
    const vector rhoB(material_->rho()*bodyForce_);
    const List<tensor>& H = Hc();
    const scalar b = 1 - a;

    // Points in closed contact: displacement from the contact velocity
    List<vector> uSurface(residual_.surfacePoints.size());
    forAll(residual_.surfacePoints, k)
    {
        const label i = residual_.surfacePoints[k];
        uSurface[k] = a*u0_[i] + b*(u_[i] + dt*residual_.surfaceVelocities[k]);
    }

    const bool HLaw = scheme_->HLaw();
    const bool JLaw = scheme_->JLaw();
    forEachPoint(lm_.size(), points, [&](const label i)
    __attribute__((always_inline))
    {
        const scalar invV = 1.0/V[i];
        const tensor Drate(invV*residual_.F[i]);

        // Rates of H and J use the stage's F and H (before the update)
        if (HLaw)
        {
            H_[i] = a*H0_[i] + b*(H_[i] + dt*tensorCross(F_[i], Drate));
        }
        if (JLaw)
        {
            J_[i] =
                a*J0_[i] + b*(J_[i] + dt*((H[i] && Drate) + invV*residual_.J[i]));
        }

        lm_[i] = a*lm0_[i] + b*(lm_[i] + dt*(invV*residual_.momentum[i] + rhoB));
        u_[i] = a*u0_[i] + b*(u_[i] + dt*fluxVelocity(q_[i]));
        F_[i] = a*F0_[i] + b*(F_[i] + dt*Drate);
    });

    forAll(residual_.surfacePoints, k)
    {
        u_[residual_.surfacePoints[k]] = uSurface[k];
    }

    // (multirate stepping integrates the external work itself)
    if (!points)
    {
        Wext_ = a*Wext0_ + b*(Wext_ + dt*residual_.power);
    }
}


namespace
{

// U = U0 + gamma (U - U0)
template<class Type>
void relaxIncrement
(
    const Foam::scalar gamma,
    const Foam::UList<Type>& U0,
    Foam::UList<Type>& U
)
{
    forAll(U, i)
    {
        U[i] = U0[i] + gamma*(U[i] - U0[i]);
    }
}

} // End anonymous namespace


bool Foam::solidBody::checksStepEnergy() const
{
    return scheme_->energyStable();
}


Foam::scalar Foam::solidBody::stepEnergyExcess(const scalar gamma) const
{
    // The energy of the state, and for plastic bodies the dissipation the
    // step's return map would commit (D = E0 + W_ext - E - D_plastic)
    scalar E = 0;
    if (gamma == 1)
    {
        E = kineticEnergy() + strainEnergy();
        if (material_->plastic())
        {
            scalarField dD(F_.size());
            material_->dissipationOfLastStress(dD);
            dD *= dual_.volumes();
            E += dual_.sumPoints(dD);
        }
    }
    else
    {
        // The state U^n + gamma (U - U^n), in blocks of points (no lists
        // of the size of the mesh)
        const scalarField& V = dual_.volumes();
        const scalar halfInvRho = 0.5/material_->rho();
        const bool HLaw = scheme_->HLaw();
        const bool JLaw = scheme_->JLaw();
        const label blockSize = 256;
        List<tensor> Fb(blockSize), Hb(blockSize);
        List<scalar> Jb(blockSize), Wb(blockSize), Db(blockSize);
        const label n = lm_.size();
        for (label start = 0; start < n; start += blockSize)
        {
            const label m = min(blockSize, n - start);
            for (label k = 0; k < m; ++k)
            {
                const label i = start + k;
                Fb[k] = F0_[i] + gamma*(F_[i] - F0_[i]);
                Hb[k] =
                    HLaw ? H0_[i] + gamma*(H_[i] - H0_[i]) : cofactor(Fb[k]);
                Jb[k] = JLaw ? J0_[i] + gamma*(J_[i] - J0_[i]) : det(Fb[k]);
            }
            SubList<scalar> W(Wb, m), dD(Db, m);
            material_->trialEnergy
            (
                start,
                SubList<tensor>(Fb, m), SubList<tensor>(Hb, m),
                SubList<scalar>(Jb, m), W, dD
            );
            for (label k = 0; k < m; ++k)
            {
                const label i = start + k;
                const vector lm(lm0_[i] + gamma*(lm_[i] - lm0_[i]));
                E +=
                    dual_.pointWeight(i)*V[i]
                   *(W[k] + dD[k] + halfInvRho*magSqr(lm));
            }
        }
        reduce(E, sumOp<scalar>());
    }
    return E - stepEnergy0_ - gamma*(Wext_ - Wext0_);
}


void Foam::solidBody::relaxStep(const scalar gamma)
{
    stateChanged();
    relaxIncrement(gamma, lm0_, lm_);
    relaxIncrement(gamma, u0_, u_);
    relaxIncrement(gamma, F0_, F_);
    if (scheme_->HLaw()) relaxIncrement(gamma, H0_, H_);
    if (scheme_->JLaw()) relaxIncrement(gamma, J0_, J_);
    Wext_ = Wext0_ + gamma*(Wext_ - Wext0_);
    ++nRelaxedSteps_;
    minRelaxation_ = min(minRelaxation_, gamma);
}


void Foam::solidBody::applyConstraints(const UList<bool>* active)
{
    stateChanged();
    // positionalF (bodyScheme): F follows the positions, set after them
    // below, so nothing turns it here (one global step; a multirate level
    // stage would leave the others' points as they are)
    const bool FFromPositions = scheme_->positionalF() && !active;
    // A closed contact point's normal stays on the deformed surface
    // (contactRotation.H); before the symmetry planes, which then take out
    // any turn about their own axes (bodyScheme: not for small-strain
    // materials, whose energy a rotation changes)
    if (scheme_->contactRotation() && !FFromPositions)
    {
        contactRotation_->apply
        (
            u_, F_, scheme_->HLaw() ? &H_ : nullptr, active
        );
    }
    symmetry_->apply(lm_, u_, active);
    // A point on a symmetry plane stands for its control volume completed
    // by the mirror image, which does not rotate about the plane's axes
    // (symmetryConstraint.H)
    if (!FFromPositions)
    {
        symmetry_->removePlaneRotation(F_, active);
        if (scheme_->HLaw())
        {
            symmetry_->removePlaneRotation(H_, active);
        }
    }
    planeStrain_->apply(dual_.volumes(), lm_, u_, active);
    if (FFromPositions)
    {
        deformationFromPositions();
    }
}


void Foam::solidBody::deformationFromPositions()
{
    // F = I + Grad u by Green-Gauss on the reference dual, in the
    // difference form of the flux states' gradients (exact for linear
    // fields: the boundary sub-faces with their neighbours' weights)
    const labelList& es = dual_.edgeStart();
    const labelList& ee = dual_.edgeEnd();
    const vectorField& Ne = dual_.edgeNormals();
    const scalarField& Ae = dual_.edgeMagSf();
    const scalarField& V = dual_.volumes();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    List<tensor>& G = positionalGradient_;
    G.setSize(u_.size());
    G = Zero;
    forAll(es, e)
    {
        const label i = es[e], j = ee[e];
        const tensor f((u_[j] - u_[i])*(0.5*Ae[e]*Ne[e]));
        G[i] += f;
        G[j] += f;
    }
    forAll(patches, patchi)
    {
        const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi);
        forAll(sf.point, s)
        {
            const label i = sf.point[s];
            G[i] +=
                (sf.nbrWeight[s]*(u_[sf.prev[s]] + u_[sf.next[s]] - 2*u_[i]))
               *sf.area[s];
        }
    }
    if (Pstream::parRun())
    {
        syncTools::syncPointList
        (
            mesh_, G, plusEqOp<tensor>(), tensor(Zero)
        );
    }
    forAll(G, i)
    {
        F_[i] = tensor::I + G[i]/V[i];
        if (scheme_->HLaw())
        {
            H_[i] = cofactor(F_[i]);
        }
    }
}


void Foam::solidBody::updateElasticPoints(const labelUList* points)
{
    if (!elasticLimiter_)
    {
        return;
    }
    const scalarList& epsP = material_->epsP();
    // (the von Mises equivalent of the Kirchhoff stress tau = P F^T, whose
    // deviator is the one the return map bounds)
    const scalar nearYield2 =
        sqr(nearYieldShare*material_->initialYieldStress());
    auto state = [&](const label i)
    {
        if (epsP[i] > 0)
        {
            return char(0);
        }
        const tensor tauDev(dev(fluxStress(q_[i]) & F_[i].T()));
        return char(1.5*(tauDev && tauDev) >= nearYield2 ? 2 : 1);
    };
    if (elasticPoint_.size() != epsP.size())
    {
        elasticPoint_.setSize(epsP.size());
        points = nullptr;
    }
    if (points)
    {
        for (const label i : *points)
        {
            elasticPoint_[i] = state(i);
        }
    }
    else
    {
        forAll(epsP, i)
        {
            elasticPoint_[i] = state(i);
        }
    }
}


void Foam::solidBody::endStep(const labelUList* points)
{
    if (material_->plastic())
    {
        stateChanged();
        material_->updateState(F_, Jc(), dDplastic_, points);
        updateElasticPoints(points);
        if (points)
        {
            // (multirate stepping: one level's points, a point shared by
            // processors counted once; in parallel this processor's share,
            // summed over the processors at the end of the step)
            scalar dD = 0;
            for (const label i : *points)
            {
                dD += dual_.pointWeight(i)*dDplastic_[i]*dual_.volumes()[i];
            }
            Dplastic_ += dD;
            return;
        }
        forAll(dDplastic_, i)
        {
            dDplastic_[i] *= dual_.volumes()[i];
        }
        Dplastic_ += dual_.sumPoints(dDplastic_);
        // The stress of the accepted state is unchanged: it was evaluated
        // with the returned state that updateState() just committed
    }
}


const Foam::label Foam::solidBody::approachSteps = 3;


Foam::boundBox Foam::solidBody::velocityRange() const
{
    boundBox range;
    forAll(q_, i)
    {
        range.add(fluxVelocity(q_[i]));
    }
    range.reduce();
    return range;
}


Foam::scalar Foam::solidBody::approachWindow() const
{
    const label index = runTime_.timeIndex();
    if (index == runTime_.startTimeIndex())
    {
        return GREAT;
    }
    if (index != strikeIndex_)
    {
        const scalar dt = runTime_.deltaTValue();
        recentDeltaT_ = max(dt, lastDeltaT_);
        lastDeltaT_ = dt;
        strikeIndex_ = index;
    }
    return approachSteps*recentDeltaT_;
}


Foam::scalar Foam::solidBody::ownStrikeSpeed(const boundBox& v) const
{
    if (!v.valid())
    {
        return 0;
    }
    const scalar window = approachWindow();
    scalar s = mag(v.span());
    const scalar t = runTime_.value();
    for (const solidBoundaryCondition& bc : bcs_)
    {
        s = max(s, bc.strikeSpeed(v, u_, q_, t, window));
        // (a prescribed traction's compressive jump: the velocity jump of
        // the shock it drives, from the material's Hugoniot)
        const scalar jump = bc.drivingTractionJump(q_, t);
        if (jump > 0)
        {
            s = max
            (
                s,
               -contactRiemannSolvers::hugoniot::rigidShockJump
                (
                    -jump, material_->Zp(), material_->shockMass()
                )
            );
        }
    }
    return s;
}


Foam::scalar Foam::solidBody::impactSpeed() const
{
    return impactSpeed_ < 0 ? ownStrikeSpeed(velocityRange()) : impactSpeed_;
}


Foam::scalar Foam::solidBody::localStableDeltaT
(
    UList<scalar>* pointDeltaT
) const
{
    const scalar vMax = material_->hugoniot() ? impactSpeed() : 0;
    if (heldLimit_)
    {
        updateHeldClosed();
    }
    return stableStep_->deltaT
    (
        F_, Hc(), Jc(), vMax, pointDeltaT,
        heldLimit_ ? &heldClosed_ : nullptr
    );
}


Foam::scalar Foam::solidBody::stableDeltaT() const
{
    return returnReduce(localStableDeltaT(), minOp<scalar>());
}


Foam::scalar Foam::solidBody::stableDeltaT(point& X) const
{
    const scalar dtLocal = localStableDeltaT();
    const scalar dt = returnReduce(dtLocal, minOp<scalar>());
    const label i = stableStep_->limitingPoint();
    label proc =
        (dtLocal == dt && i >= 0) ? Pstream::myProcNo() : Pstream::nProcs();
    reduce(proc, minOp<label>());
    X = (proc == Pstream::myProcNo()) ? mesh_.points()[i] : Zero;
    reduce(X, sumOp<vector>());
    return dt;
}


Foam::scalar Foam::solidBody::kineticEnergy() const
{
    if (!kineticEnergyKnown_)
    {
        const scalarField& V = dual_.volumes();
        scalarField e(lm_.size());
        const scalar half = 0.5/material_->rho();
        forAll(lm_, i)
        {
            e[i] = half*V[i]*magSqr(lm_[i]);
        }
        kineticEnergy_ = dual_.sumPoints(e);
        kineticEnergyKnown_ = true;
    }
    return kineticEnergy_;
}


Foam::scalar Foam::solidBody::strainEnergy() const
{
    if (!strainEnergyKnown_)
    {
        scalarField W(F_.size());
        // Every change of F_ is followed by a stress evaluation
        // (updateConstitutive): a model that kept its energy gives it
        if (!material_->energyOfLastStress(W))
        {
            material_->energy(F_, Hc(), Jc(), W);
        }
        W *= dual_.volumes();
        strainEnergy_ = dual_.sumPoints(W);
        strainEnergyKnown_ = true;
    }
    return strainEnergy_;
}


Foam::vector Foam::solidBody::linearMomentum() const
{
    const scalarField& V = dual_.volumes();
    vector sum(Zero);
    forAll(lm_, i)
    {
        sum += dual_.pointWeight(i)*V[i]*lm_[i];
    }
    reduce(sum, sumOp<vector>());
    return sum;
}


Foam::label Foam::solidBody::findPoint(const point& X) const
{
    const pointField& pts = mesh_.points();
    label nearest = -1;
    scalar d2 = GREAT;
    forAll(pts, i)
    {
        const scalar d = magSqr(pts[i] - X);
        if (d < d2)
        {
            d2 = d;
            nearest = i;
        }
    }
    const scalar globalD2 = returnReduce(d2, minOp<scalar>());
    label owner = (d2 == globalD2) ? Pstream::myProcNo() : Pstream::nProcs();
    reduce(owner, minOp<label>());
    return (owner == Pstream::myProcNo()) ? nearest : -1;
}


Foam::symmTensor Foam::solidBody::cauchyStress(const label i) const
{
    // Push-forward with det F (= H:F/3), consistent with the F it uses;
    // with the J law J may differ slightly from det F
    return symm(fluxStress(q_[i]) & F_[i].T())/((Hc()[i] && F_[i])/3.0);
}


void Foam::solidBody::releaseUnusedMesh()
{
    // Nothing reads the internal faces once the dual is built: the
    // boundary conditions, contact, point fields (pointMesh) and processor
    // exchanges (globalMeshData's coupled patch) read the boundary faces,
    // which stay, and the face count and owners stay too (a patch's
    // faceCells are its part of the owners).  On tetrahedral meshes this
    // frees about a sixth of the run's memory (three labels and an
    // allocation per face, some eleven faces per point), and the
    // neighbours, which only the internal faces have, some 40 bytes per
    // point more.  The mesh is never written (its files are not touched).
    // The deformed dual (deformedPressure) reads them every stage
    if (!dual_.deformedAreasEnabled())
    {
        faceList& faces = const_cast<faceList&>(mesh_.faces());
        for (label f = 0; f < mesh_.nInternalFaces(); ++f)
        {
            faces[f].clear();
        }
        const_cast<labelList&>(mesh_.faceNeighbour()).clear();
    }

    // Nor does it read zones (gmsh's physical groups become zones: a label
    // per cell of every body)
    const_cast<pointZoneMesh&>(mesh_.pointZones()).clear();
    const_cast<faceZoneMesh&>(mesh_.faceZones()).clear();
    const_cast<cellZoneMesh&>(mesh_.cellZones()).clear();
}


void Foam::solidBody::checkReleasedFaces() const
{
    // Topology OpenFOAM would rebuild from the faces is wrong once the
    // internal faces are released: stop rather than use it
    if
    (
        !dual_.deformedAreasEnabled()
     && (
        mesh_.hasEdges() || mesh_.hasPointEdges() || mesh_.hasFaceEdges()
     || mesh_.hasCellPoints() || mesh_.hasPointFaces() || mesh_.hasCellEdges()
     || mesh_.hasPointPoints() || mesh_.hasCellShapes()
     || mesh_.hasFaceCentres() || mesh_.hasCellCentres()
        )
    )
    {
        FatalErrorInFunction
            << "Body " << name_ << ": OpenFOAM's mesh topology or geometry"
            << " was rebuilt after the internal faces were released (an"
            << " internal error of the solver)" << exit(FatalError);
    }
}


void Foam::solidBody::write()
{
    checkReleasedFaces();

    // A plastic point's stress is that of the state its return map started
    // from, and endStep() commits the returned state without evaluating it
    // again (it equals the committed state's to the return map's series
    // truncation, about 1e-10).  A restart can only evaluate the committed
    // state, so this run does the same at each write, and a run restarted
    // from the write continues exactly as this one does
    if (material_->plastic())
    {
        updateConstitutive();
        updateElasticPoints();
    }

    // The state's lists are lent to the fields for the write (no copies:
    // the write would otherwise set the run's peak memory), v, sigma and p
    // computed into theirs, in the room of the residuals (which are not in
    // use between steps)
    writePointFieldLending(mesh_, "lm", lm_, dimDensity*dimVelocity);
    writePointFieldLending(mesh_, "u", u_, dimLength);
    writePointFieldLending(mesh_, "F", F_, dimless);
    if (scheme_->HLaw()) writePointFieldLending(mesh_, "H", H_, dimless);
    if (scheme_->JLaw()) writePointFieldLending(mesh_, "J", J_, dimless);
    const label nPts = residual_.releasePointLists();
    writePointFieldOf<vector>
    (
        mesh_, "v", dimVelocity,
        [this](const label i) { return fluxVelocity(q_[i]); }
    );
    writePointFieldOf<symmTensor>
    (
        mesh_, "sigma", dimPressure,
        [this](const label i) { return cauchyStress(i); }
    );
    writePointFieldOf<scalar>
    (
        mesh_, "p", dimPressure,
        [this](const label i) { return -tr(cauchyStress(i))/3.0; }
    );
    {
        // Each point's stable step (cfl = 1) in the written state: the run
        // steps with cfl times their minimum (unless a closing contact gap
        // asks for less), so the field shows what sets the step
        scalarField pointDeltaT(nPts);
        localStableDeltaT(&pointDeltaT);
        writePointFieldLending(mesh_, "stableDeltaT", pointDeltaT, dimTime);
    }
    residual_.setSize(nPts, scheme_->JLaw());
    material_->writeState(mesh_);

    // Energy bookkeeping for restarts
    dictionary state;
    state.add("initialEnergy", E0_);
    state.add("externalWork", Wext_);
    state.add("plasticDissipation", Dplastic_);
    state.add("energyLimitedStages", nEnergyLimited_);
    state.add("minEnergyBlending", minEnergyTheta_);
    state.add("relaxedSteps", nRelaxedSteps_);
    state.add("minRelaxation", minRelaxation_);
    state.add("dissipatingRetries", nDissipatingRetries_);
    if (scheme_->onsetStabilisation() || releaseCentralF_)
    {
        writeOnsetStarts(state);
    }
    if (heldLimit_)
    {
        writeHeldClosed(state);
    }
    writeUniformState("bodyState", mesh_, state);
}


void Foam::solidBody::describe(Ostream& os) const
{
    os  << "Body " << name_ << ": " << nGlobalPoints() << " points, "
        << returnReduce(mesh_.nCells(), sumOp<label>()) << " cells" << nl
        << "    material   ";
    material_->describe(os);
    os  << nl << "    solves     p, F"
        << (scheme_->HLaw() ? ", H" : "") << (scheme_->JLaw() ? ", J" : "")
        << (scheme_->HLaw() ? "" : "; H = cof F")
        << (scheme_->JLaw() ? "" : "; J = det F")
        << nl << "    scheme     ";
    if (scheme_->secondOrder())
    {
        os  << "second order, limiter " << limiter_->type().c_str()
            << (
                   scheme_->riemannBoundarySlope()
                 ? ", boundary slopes from Riemann" : ""
               );
    }
    else
    {
        os  << "first order (Godunov)";
    }
    os  << (scheme_->FStabilisation() ? ", upwind F flux" : "")
        << (energyStability_.valid() ? ", energy stable" : "")
        << ", Riemann solver ";
    riemann_->describe(os);
    os  << nl;
    scheme_->describe(os, "        ");
    if (material_->hugoniot())
    {
        // The stable step's anticipation of a shock (stableTimeStep.H), so
        // that a small step before any contact is not a surprise
        const scalar vImpact = impactSpeed();
        scalar Jstar;
        const scalar factor =
            stableTimeStep::anticipatedWaveFactor
            (
                material_(), vImpact, &Jstar
            );
        os  << "    step       held for the wave speed of the state an "
            << "impact at " << vImpact << " (the fastest closing on its "
            << "walls, its pairs or within it) would shock it to: "
            << factor << " c_p (J = " << Jstar << ")" << nl;
    }
    if (returnReduce(planeStrain_->size(), sumOp<label>()))
    {
        os  << "    plane strain: both copies of "
            << returnReduce(planeStrain_->size(), sumOp<label>())
            << " in-plane points move alike" << nl;
    }
    for (const solidBoundaryCondition& bc : bcs_)
    {
        os  << "    patch " << bc.patchName() << ": ";
        bc.describe(os);
        os  << nl;
    }
}


// ************************************************************************* //
