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

// * * * * * * * * * * * * * Local Helper Functions  * * * * * * * * * * * * //

namespace
{

using namespace Foam;

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
        side.N[side.sfLocal[s]] += sf.area[s];
    }
    side.N /= mag(side.N);

    side.length.setSize(side.points.size());
    forAll(side.points, i)
    {
        side.length[i] = body.dual().lengths()[side.points[i]];
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
    side.force.setSize(side.points.size(), Zero);
    side.closed.setSize(side.points.size(), false);
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
    const List<pointData> a(gatherData(A_));
    const List<pointData> b(gatherData(B_));
    const label offsetA = localOffset(A_.points.size());

    scalar worst = 0;
    point where(Zero);
    forAll(A_.points, i)
    {
        const pointData& da = a[offsetA + i];
        const pointData& db = b[A_.partner[i]];
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


void Foam::contactPair::matchSides()
{
    const pointField& XA = A_.body->mesh().points();
    const pointField& XB = B_.body->mesh().points();

    const pointField globalA(allGather(pointField(XA, A_.points)));
    const pointField globalB(allGather(pointField(XB, B_.points)));
    const vectorField globalNA(allGather(A_.N));

    // Partner: the point of the other side at the same tangential position
    // (relative to A's normal), i.e. across the gap
    auto match = [&]
    (
        const pointField& from,
        const vectorField& fromN,
        const scalarField& len,
        const pointField& to,
        labelList& partner,
        const word& fromBody
    )
    {
        partner.setSize(from.size());
        forAll(from, i)
        {
            scalar best = GREAT;
            label ibest = -1;
            forAll(to, j)
            {
                const vector d(to[j] - from[i]);
                const vector n(gapDirection(fromN[i]));
                const scalar dt = mag(d - (d & n)*n);
                if (dt < best)
                {
                    best = dt;
                    ibest = j;
                }
            }
            if (ibest < 0 || best > 1e-6*len[i])
            {
                FatalIOErrorInFunction(dict_)
                    << "Contact pair '" << name_ << "': the patches do not"
                    << " match. The point of body " << fromBody << " at "
                    << from[i] << " has no partner on the other patch"
                    << " (nearest tangential distance " << best << ")."
                    << nl << "Matching (conforming) contact meshes are"
                    << " needed: mesh both patches with the same surface"
                    << " mesh."
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
    };

    // All copies of each partner point (a point shared by processors
    // appears once per processor in the gathered lists)
    auto copies = [&](const labelList& partner, const pointField& to)
    {
        labelListList result(partner.size());
        forAll(partner, i)
        {
            const point& p = to[partner[i]];
            forAll(to, j)
            {
                if (to[j] == p)
                {
                    result[i].append(j);
                }
            }
        }
        return result;
    };

    // A's points look along their own normal; B's along the normal of the
    // nearest A point (A's normal defines the contact direction)
    match
    (
        pointField(XA, A_.points), A_.N, A_.length, globalB, A_.partner,
        A_.body->name()
    );

    vectorField NB(B_.points.size());
    forAll(B_.points, i)
    {
        label ibest = 0;
        scalar best = GREAT;
        forAll(globalA, j)
        {
            const scalar d = magSqr(globalA[j] - XB[B_.points[i]]);
            if (d < best)
            {
                best = d;
                ibest = j;
            }
        }
        NB[i] = globalNA[ibest];
    }
    match
    (
        pointField(XB, B_.points), NB, B_.length, globalA, B_.partner,
        B_.body->name()
    );
    B_.partners = copies(B_.partner, globalA);
}


Foam::List<Foam::contactPair::pointData> Foam::contactPair::gatherData
(
    const contactSide& side
) const
{
    const solidBody& body = *side.body;
    const List<point>& x = body.x();
    const List<vector>& v = body.v();
    const List<tensor>& P = body.P();
    const List<tensor>& H = body.Hc();

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
        const vector t(P[p] & N);
        const vector hN(H[p] & N);
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
        local[i] = pointData{x[p], v[p], t, n, Lambda, side.length[i]};
    }
    return allGather(local);
}


void Foam::contactPair::pairState
(
    const bool closed,
    const pointData& a,
    const pointData& b,
    vector& tC,
    vector& vCA,
    vector& vCB
) const
{
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

    if (!closed)
    {
        separate();
        return;
    }

    // Traction of B measured with A's normal: t^R = -P^B N^B
    const vector tB(-tBown);

    contactRiemannSolver::side L
    {
        tA & n, vA & n, mA.rho(), mA.cp(), a.Lambda,
        mA.hugoniot() ? mA.hugoniotS() : 0
    };
    contactRiemannSolver::side R
    {
        tB & n, vB & n, mB.rho(), mB.cp(), b.Lambda,
        mB.hugoniot() ? mB.hugoniotS() : 0
    };
    scalar vnC, tnC;
    riemann_->normalState(L, R, vnC, tnC);

    if (tnC >= 0)
    {
        separate();
        return;
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
        const vector vtStick((ZA*vAt + ZB*vBt + tBt - tAt)/(ZA + ZB));
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
    vCA = vnC*n + vtA;
    vCB = vnC*n + vtB;
}


Foam::scalar Foam::contactPair::addSideFluxes
(
    contactSide& side,
    const bool tractions
)
{
    solidBody& body = *side.body;
    const dualMesh::patchSubFaces& sf = body.dual().subFaces(side.patchi);
    List<vector>& Rp = body.residual().momentum;
    List<tensor>& RF = body.residual().F;

    side.force = Zero;
    scalar power = 0;
    forAll(sf.point, s)
    {
        const label i = side.sfLocal[s];
        const label ip = side.sfPrev[s];
        const label in = side.sfNext[s];
        const scalar w = sf.nbrWeight[s];
        const vector tC((1 - 2*w)*side.tC[i] + w*(side.tC[ip] + side.tC[in]));
        const vector vC((1 - 2*w)*side.vC[i] + w*(side.vC[ip] + side.vC[in]));
        const scalar magA = mag(sf.area[s]);

        // Quadrature of the pointwise power, as for boundary conditions
        // (solidBoundaryCondition::addFluxes): frictionless matched contact
        // then exchanges energy between the bodies without creating any
        const scalar pC =
            (1 - 2*w)*(side.tC[i] & side.vC[i])
          + w*((side.tC[ip] & side.vC[ip]) + (side.tC[in] & side.vC[in]));

        side.force[i] += magA*tC;
        RF[sf.point[s]] += vC*sf.area[s];
        power += magA*pC;
    }
    if (tractions)
    {
        forAll(side.points, i)
        {
            Rp[side.points[i]] += side.force[i];
        }
    }
    return power;
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
    riemann_(contactRiemannSolver::New(dict)),
    friction_(frictionLaw::New(dict, "contact pair '" + name + "'")),
    matchDirection_(getFiniteOrDefault<vector>(dict, "matchDirection", Zero)),
    maxPenetration_(0)
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
        {"bodyA", "patchA", "bodyB", "patchB", "riemannSolver", "matchDirection"}
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
    setSide(A_, bodyA, dict.get<word>("patchA"));
    setSide(B_, bodyB, dict.get<word>("patchB"));

    checkFacing();
    matchSides();
    const bool restart = timeDirectory::isRestart(time());
    if (!restart)
    {
        checkOverlap();
    }

    // A restart carries the history of the earlier runs on
    if (restart)
    {
        const autoPtr<IOdictionary> state
        (
            readUniformState(stateName(), time())
        );
        maxPenetration_ = readUniformEntry<scalar>(*state, "maxPenetration");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactPair::write() const
{
    dictionary state;
    state.add("maxPenetration", maxPenetration_);
    writeUniformState(stateName(), time(), state);
}


void Foam::contactPair::addFluxes()
{
    dataA_ = gatherData(A_);
    dataB_ = gatherData(B_);

    const label offsetA = localOffset(A_.points.size());
    const label offsetB = localOffset(B_.points.size());

    // Pairs closed at the start of the step move with their Riemann
    // velocities, also when tension releases them: the traction-free
    // velocities then open the gap (for the acoustic solver tension is
    // exactly that condition), whereas the nodal velocities, driven by the
    // rest of the control volume, can carry the released points through
    // each other (B2: contact corners pulled past the plane by the side
    // surface rolling over).  Open pairs move with their nodal velocities.
    vector vOther;
    forAll(A_.points, i)
    {
        const pointData& a = dataA_[offsetA + i];
        const pointData& b = dataB_[A_.partner[i]];
        pairState(A_.closed[i], a, b, A_.tC[i], A_.vC[i], vOther);
        if (A_.closed[i])
        {
            A_.body->residual().prescribeSurfaceVelocity
            (
                A_.points[i], A_.vC[i]
            );
            const scalar pen = -pairGap(a, b);
            maxPenetration_ = max(maxPenetration_, pen/a.length);
        }
    }
    forAll(B_.points, i)
    {
        const pointData& b = dataB_[offsetB + i];
        const pointData& a = dataA_[B_.partner[i]];
        vector tC;
        pairState(B_.closed[i], a, b, tC, vOther, B_.vC[i]);
        if (B_.closed[i])
        {
            B_.body->residual().prescribeSurfaceVelocity
            (
                B_.points[i], B_.vC[i]
            );
        }
        B_.tC[i] = -tC;
    }
    reduce(maxPenetration_, maxOp<scalar>());

    // A: its own integrated tractions.  B: minus the forces of its
    // partners on A (summed over the processor copies of a partner, shared
    // by B's processor copies of the point through the point weights)
    A_.body->residual().power += addSideFluxes(A_, true);
    B_.body->residual().power += addSideFluxes(B_, false);

    const vectorField forceA(allGather(A_.force));
    List<vector>& RpB = B_.body->residual().momentum;
    const scalarField& wB = B_.body->dual().pointWeights();
    forAll(B_.points, i)
    {
        vector F(Zero);
        for (const label k : B_.partners[i])
        {
            F -= forceA[k];
        }
        RpB[B_.points[i]] += wB[B_.points[i]]*F;
    }
}


void Foam::contactPair::startStep()
{
    const List<pointData> a(gatherData(A_));
    const List<pointData> b(gatherData(B_));
    const label offsetA = localOffset(A_.points.size());

    // A's points against their partners; B's take their partner's flag
    scalarField closedA(A_.points.size(), 0.0);
    forAll(A_.points, i)
    {
        const pointData& da = a[offsetA + i];
        const pointData& db = b[A_.partner[i]];
        const scalar gap = pairGap(da, db);
        A_.closed[i] = (gap <= gapTolerance*da.length);
        closedA[i] = A_.closed[i];
    }
    const scalarField globalClosedA(allGather(closedA));
    forAll(B_.points, i)
    {
        B_.closed[i] = (globalClosedA[B_.partner[i]] > 0.5);
    }
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


Foam::scalar Foam::contactPair::deltaTLimit(const scalar dtFloor) const
{
    const List<pointData> a(gatherData(A_));
    const List<pointData> b(gatherData(B_));
    const label offsetA = localOffset(A_.points.size());

    scalar dt = GREAT;
    forAll(A_.points, i)
    {
        const pointData& da = a[offsetA + i];
        const pointData& db = b[A_.partner[i]];
        const vector n(gapDirection(pairNormal(da, db)));
        const scalar gap = (db.x - da.x) & n;
        const scalar closing = (da.v - db.v) & n;
        if
        (
            gap > gapTolerance*da.length && closing > 0
         && gap > closing*dtFloor
        )
        {
            dt = min(dt, gap/closing);
        }
    }
    reduce(dt, minOp<scalar>());
    return dt;
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
    os  << ", friction ";
    friction_->describe(os);
    os  << nl;
}


// ************************************************************************* //
