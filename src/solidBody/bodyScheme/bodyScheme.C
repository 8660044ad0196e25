/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "bodyScheme.H"
#include "materialModel.H"
#include "checkedInput.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * * //

namespace Foam
{
    //- Why a Hugoniot body with the upwind F flux takes shockFlattening,
    //  whether the flux was given or chosen from the scene
    static const char* const shockFlatteningWhy =
        "Hugoniot shocks with the upwind F flux: the edges a strong shock"
        " closes take first-order states, so that the struck face does not"
        " ring";
}

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::bodyScheme::automatic(const word& key) const
{
    if (!dict_.found(key))
    {
        return true;
    }
    const entry& e = dict_.lookupEntry(key, keyType::LITERAL);
    if (e.isStream())
    {
        ITstream& is = e.stream();
        if (is.size() == 1 && is[0].isWord() && is[0].wordToken() == "auto")
        {
            return true;
        }
    }
    return false;
}


void Foam::bodyScheme::note
(
    const word& key,
    const word& value,
    const string& why
)
{
    choices_.append(Tuple2<word, string>(key, value + "  (" + why + ")"));
}


Foam::Switch Foam::bodyScheme::choose
(
    const word& key,
    const bool autoValue,
    const string& why
)
{
    if (automatic(key))
    {
        note(key, autoValue ? "yes" : "no", "auto: " + why);
        return Switch(autoValue);
    }
    const Switch s(dict_.get<Switch>(key));
    note(key, s ? "yes" : "no", "given");
    return s;
}


Foam::word Foam::bodyScheme::given
(
    const word& key,
    const wordList& allowed
) const
{
    const word value(dict_.get<word>(key));
    if (!allowed.empty() && !allowed.found(value))
    {
        FatalIOErrorInFunction(dict_)
            << "scheme/" << key << " '" << value << "' in " << dict_.name()
            << " is not allowed." << nl
            << "    Valid: auto or " << flatOutput(allowed)
            << exit(FatalIOError);
    }
    return value;
}


Foam::word Foam::bodyScheme::choose
(
    const word& key,
    const wordList& allowed,
    const word& autoValue,
    const string& why
)
{
    if (automatic(key))
    {
        note(key, autoValue, "auto: " + why);
        return autoValue;
    }
    const word value(given(key, allowed));
    note(key, value, "given");
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyScheme::bodyScheme
(
    const dictionary& solidProperties,
    const materialModel& m,
    const bool linearExact,
    const bool triangleBoundary
)
:
    dict_(solidProperties, dictionary(fileName("scheme"))),
    shockFromScene_(false),
    FStabFromScene_(false),
    flatteningFromScene_(false),
    FStabUniaxialFromScene_(false),
    onsetFromScene_(false),
    plastic_(false),
    limiterFromScene_(false),
    extrapolationFromScene_(false)
{
    if (solidProperties.isDict("scheme"))
    {
        dict_ = solidProperties.subDict("scheme");
    }
    else if (solidProperties.found("scheme"))
    {
        const word value(solidProperties.get<word>("scheme"));
        if (value != "auto")
        {
            FatalIOErrorInFunction(solidProperties)
                << "scheme '" << value << "' in " << solidProperties.name()
                << " is not allowed." << nl
                << "    Valid: auto (every switch chosen from the material)"
                << " or a dictionary of switches (scheme { limiter"
                << " vanAlbada; }; those not given are chosen)"
                << exit(FatalIOError);
        }
    }
    checkKeywords
    (
        dict_,
        {
            "secondOrder", "limiter", "relativeNoise", "JLaw", "HLaw",
            "energyStable", "riemannSolver", "FStabilisation",
            "onsetStabilisation", "shockStabilisation", "boundarySlope",
            "contactRotation", "deformedPressure", "vorticityDamping",
            "positionalF", "boundaryExtrapolation",
            "elasticLimiter", "shockFlattening"
        }
    );

    // What the material asks for.  Nearly incompressible: kappa/mu >= 50
    // (nu >= 0.49).  Below that the J law bought nothing measurable and
    // cost energy: the nearly incompressible bars at nu 0.45-0.48 lose
    // the same with or without it (D 10.3-10.6 %, no pressure extrema),
    // the elastic torus (nu 0.45, tets) 28.8 % with it against 20.9 %
    // without it, with a pressure as smooth; at
    // nu 0.495 the bars' pressure is smoother with it (largest jump 0.31
    // against 0.49 of the range) (doc/results.md, "Automatic scheme")
    // The limiter's branch starts lower (nu >= 0.45): on the elastic torus
    // without the J law Barth-Jespersen let the dissipation fall on the
    // finer meshes (by 0.033 % of E0 on 1.4 mm tets), van Albada never
    const bool plastic = m.plastic();
    const bool nearlyIncompressible = m.mu() > 0 && m.nu() >= 0.49;
    const string kind
    (
        plastic ? "plastic"
      : nearlyIncompressible ? "nearly incompressible (nu >= 0.49)"
      : "compressible elastic"
    );

    secondOrder_ = choose("secondOrder", true, "second order everywhere");

    // J and its stabilisation where the volume change carries the physics:
    // near incompressibility and in plastic flow (locking, checkerboards)
    // and in shocks of pressure-dominated materials (A3's Hugoniot bars
    // reach -74.53 instead of -75.00 without it).  A compressible elastic
    // body keeps a smooth pressure with det F alone and loses less energy
    // (ring B1: D 21.6 -> 15.1 % on the default mesh, 7.4 % on level 2;
    // elastic car 29.0 -> 28.2 %, the same pressure extrema:
    // doc/results.md, "Automatic scheme"), and a small-strain material
    // takes its pressure from tr F: J would be carried along unused
    const bool pressureOnly = m.mu() <= 0;
    const bool needsJ =
        plastic || nearlyIncompressible || m.hugoniot() || pressureOnly;
    JLaw_ = choose
    (
        "JLaw", needsJ && !m.smallStrain(),
        m.smallStrain()
      ? string("small strain: the pressure comes from tr F, not J")
      : plastic || nearlyIncompressible
      ? kind + ": J and its stabilisation keep the pressure free of"
        " locking and checkerboards"
      : m.hugoniot() || pressureOnly
      ? string("pressure-dominated shocks: J and its stabilisation carry the"
        " volume change")
      : kind + ": det F carries the volume, with less damping"
    );
    HLaw_ = choose("HLaw", false, "H = cof F is exact and stores nothing");

    // A closed contact point's F keeps its normal on the deformed surface
    // (contactRotation.H): without it a contact corner's F turned under
    // compression until J < 0 (the nearly incompressible bars at cfl 0.3).
    // A rotation leaves a finite-strain energy unchanged, not a small-
    // strain one
    contactRotation_ = choose
    (
        "contactRotation", !m.smallStrain(),
        m.smallStrain()
      ? string("small strain: its energy is not invariant under rotation")
      : string("closed contact points keep their normal on the deformed"
        " surface")
    );
    if (contactRotation_ && m.smallStrain())
    {
        FatalIOErrorInFunction(dict_)
            << "contactRotation yes in " << dict_.name() << " needs a"
            << " finite-strain material (the rotation would change a"
            << " small-strain energy)." << nl
            << "    Valid for this material: no (or auto)"
            << exit(FatalIOError);
    }

    // (the list of solvers is checked by interiorRiemannSolver::New)
    riemannSolver_ = choose
    (
        "riemannSolver", wordList(),
        m.hugoniot() ? "hugoniot" : "acoustic",
        m.hugoniot()
      ? string("the material's Hugoniot sets the interior shock relation")
      : string("the material has no Hugoniot")
    );

    // With the upwind F flux off, bending keeps its energy (its traction
    // jump term damps bending with large rotation on coarse meshes).  In
    // a plane-wave impact (a flat patch across the body's section) the
    // scene turns it on (chooseFromScene) for elastic bodies, Hugoniot
    // and shear-free ones included (their onset peak falls from 29 to
    // 5-7 %, and it carries a bar on a wall to 2.5 c instead of 1.5 c);
    // not for plastic flow (it damps it).  Nearly incompressible bodies
    // only where the front stays plane, between symmetry planes (uniaxial
    // strain: a bar at nu 0.49 overshot by 32 % at onset without it, 1.1 %
    // with it): with free lateral faces their impact is mostly bulging,
    // whose pressure the term checkerboards (C3: 68 % of the points
    // extrema instead of 6 %; B2 loses 17.2 % instead of 12.3 %;
    // doc/results.md, "Nearly incompressible bars in uniaxial strain")
    FStabFromScene_ =
        automatic("FStabilisation") && !plastic && !nearlyIncompressible;
    FStabUniaxialFromScene_ =
        automatic("FStabilisation") && !plastic && nearlyIncompressible;
    FStabilisation_ = choose
    (
        "FStabilisation", false,
        FStabFromScene_
      ? string("no plane-wave impact (a flat patch across the body's"
        " section): it damps bending with large rotation")
      : plastic
      ? string("plastic: it damps the plastic flow")
      : string("nearly incompressible, no plane-wave impact in uniaxial"
        " strain (the other patches symmetry planes or parallel to the"
        " struck one): it checkerboards the pressure of a bulging body")
    );

    // Where the upwind F flux is off, it still runs for a short time at
    // contact onset on the edges of the points that have just closed and
    // their neighbours (solidBody::updateOnsetZone): with the central F
    // flux alone a struck point relaxes to its new state like a mass on a
    // spring, and its face overshoots by 19-24 % (A1, a bar on a wall;
    // a plastic bar on a wall 15.5 % on tets, 9.8 % on hexahedra); and
    // for a shorter time at a release, where the same spring leaves the
    // separating face in tension (A1 on 64 tets 6.3 %, 2.6 % with it).
    // Plastic bodies too, in plane-wave impacts: the upwind F flux damps
    // their flow, but the zone's few stages per point cost a copper bar
    // on a wall a third more numerical dissipation, 0.45 -> 0.58 % of
    // E0, for an onset within 3 % (doc/results.md, "Contact onset where
    // the F flux is central").
    // Not nearly incompressible bodies, whose pressure it
    // checkerboards (C3: 15 % of the points pressure extrema instead of
    // 6 %), nor pressure-dominated ones (Hugoniot or shear-free: their
    // planar impacts get the upwind F flux everywhere, and with it on the
    // zone only, Barth-Jespersen let a Hugoniot bar's step collapse after
    // its release from a wall, as with the term everywhere).  Decided once
    // the scene is known: contact or wall patches, the upwind F flux off
    // and, for elastic bodies, a limiter (unlimited, the Riemann boundary
    // slopes crushed A3's struck face; plastic bodies, unlimited on
    // tetrahedra and parallelepipeds, limit the zone's points with
    // Barth-Jespersen: solidBody::onsetLimiter_) (chooseFromScene)
    const bool pressureDominated = m.hugoniot() || m.shearFree();
    onsetFromScene_ =
        automatic("onsetStabilisation") && !nearlyIncompressible
     && !pressureDominated;
    plastic_ = plastic;
    onsetStabilisation_ = choose
    (
        "onsetStabilisation", false,
        onsetFromScene_
      ? string("no contact or rigid-wall patch")
      : nearlyIncompressible
      ? string("nearly incompressible: the upwind F flux checkerboards the"
        " pressure")
      : string("pressure-dominated (Hugoniot or shear-free): their planar"
        " impacts take the upwind F flux everywhere")
    );

    const wordList boundarySlopes({"interior", "riemann"});
    if (!secondOrder_)
    {
        // (a given boundarySlope is still checked: a typo is an error)
        if (!automatic("boundarySlope"))
        {
            given("boundarySlope", boundarySlopes);
        }
        limiter_ = "none";
        energyStable_ = false;
        shockStabilisation_ = false;
        shockFlattening_ = false;
        boundarySlope_ = "interior";
        boundaryExtrapolation_ = false;
        for
        (
            const word key
          : {
                "limiter", "energyStable", "shockStabilisation",
                "shockFlattening", "boundarySlope", "boundaryExtrapolation"
            }
        )
        {
            if (!automatic(key))
            {
                note(key, "-", "given, not used: first order");
            }
        }
        return;
    }

    // Without shear stiffness (the pressure-only Hugoniot bars) nothing
    // restores a transverse perturbation, and Barth-Jespersen's clipping,
    // which switches per component with the neighbourhood's extremes,
    // turns round-off into a transverse mode that grows by 1e10 within
    // 0.1 s of compression (doc/results.md, "Pressure-only bars")
    const bool noShear = m.shearFree();

    // Elastic bodies in curved impacts below shockMachThreshold: superbee.
    // Their energy is lost where the impact's fronts are captured, at a
    // rate set by the fronts' width, and superbee keeps a front within
    // about two cells (the ring B1 loses 3.7 % instead of 11.5 % on the
    // default mesh, converging at order 1.7 instead of 1.25, and its probe
    // histories are closer to the fine mesh's).  Its steepening of smooth
    // waves makes the fluxes produce energy, which energyStable takes out
    // (doc/results.md, "A compressive limiter for elastic bodies").
    // Behind strong shocks it leaves the plateau noisy (finite-strain bars
    // at Mach 0.086: 1.5 % off on the axis) or loses the bar (0.8 c_p); in
    // planar impacts it keeps the onset overshoot of the F flux (A1's L1
    // errors grow by 40 %); in plastic flow it over-spreads the Taylor
    // bar's foot (7.27 mm at N = 3, band 7.0-7.15) and lets the plastic
    // torus' D fall; with the upwind F flux its sharper release front
    // leaves a tension of 3-5 % of the contact stress at the separating
    // face
    const bool stiffVolume = m.mu() > 0 && m.nu() >= 0.45;
    limiterFromScene_ =
        automatic("limiter") && secondOrder_
     && !plastic && !noShear && !FStabilisation_;
    shockLimiter_ = stiffVolume ? "vanAlbada" : "barthJespersen";
    // Plastic bodies whose gradients are exact for linear fields
    // (tetrahedra, parallelepipeds): no limiter.  Van Albada's clipping of
    // the smooth plastic flow damps it there: the Taylor bar on
    // unstructured tets (4,828 points) reached 6.66 mm with it and 6.98 mm
    // without (band 7.0-7.15, superbee 7.18); a copper bar's plastic wave
    // on a wall holds the exact shocked state to 0.13-0.15 % without a
    // limiter and 2.3-2.6 % with van Albada on structured tets (40 and 200
    // m/s; without hardening 0.13 against 1.5 %), 0.03 against 1.85 % on
    // hexahedra; the plastic torus and car lose 9.0 and 7.8 % of E0
    // instead of 10.8 and 10.6 %, with fewer pressure extrema
    // (doc/results.md, "Plastic bodies on tetrahedra and
    // parallelepipeds").  Where the gradient is not exact, as on the
    // Taylor bar's hexahedral O-grid, van Albada also holds back the
    // gradient's own error and keeps the foot round (edge 6.95-6.99 mm at
    // N = 3; 6.76-7.10 without a limiter).  With the upwind F flux the
    // Riemann boundary slopes come too, which need a limiter: van Albada
    const bool plasticExactGradient =
        plastic && linearExact && !FStabilisation_;
    limiter_ = choose
    (
        "limiter", wordList(),
        plasticExactGradient ? "none"
      : plastic || noShear || FStabilisation_ ? "vanAlbada" : "superbee",
        limiterFromScene_
      ? string("for now: chosen from the scene's impact speeds")
      : plasticExactGradient
      ? kind + " on tetrahedra or parallelepipeds (gradients exact for"
        " linear fields): a limiter's clipping of the smooth plastic flow"
        " damps it"
      : plastic
      ? kind + ": Barth-Jespersen's per-point clipping of smooth velocity"
        " extrema locks plastic flow, superbee over-spreads it"
      : noShear
      ? string("no shear stiffness: Barth-Jespersen's clipping grows"
        " round-off into a transverse mode")
      : string("with the upwind F flux: a sharper release front leaves"
        " tension at the separating face")
    );

    // The edges of a plastic body's points that have not yielded: an
    // unlimited body limits them.  Where the material yields the
    // stress-strain curve has a kink (the tangent modulus drops from
    // K + 4/3 mu to about K), and across a kink a sharp, unlimited (or
    // Barth-Jespersen, monotonized central) reconstruction converges to a
    // pair of waves that the material does not admit: a copper bar on a
    // wall at 100 m/s (tests/solidBody/plasticWaves) carried its elastic
    // precursor 10-14 % below the yield point on 200-800 cells, where van
    // Albada or first order give the yield point itself, and the unlimited
    // precursor front rang ahead with a tension of 21-41 % of its amplitude
    // (40-200 m/s, not shrinking with the mesh).  So the edges that cross
    // the kink take van Albada (a point near its yield stress,
    // solidBody::nearYieldShare, or a yielded point at one end and one
    // that has not at the other), those of the other points that have not
    // yielded monotonized central (it stops the ringing too, and damps the
    // elastic waves of the unyielded parts less: the plastic torus 9.40 %
    // of E0 against 9.56 % with van Albada on them all).  Behind the plastic wave (yielded
    // points) the reconstruction stays unlimited: the shocked state within
    // 0.05-0.5 % instead of van Albada's standing pattern of 1.2-2.3 %
    // (doc/results.md, "Elastic precursors of plastic waves")
    if (plastic)
    {
        const bool unlimited = secondOrder_ && limiter_ == "none";
        elasticLimiter_ = choose
        (
            "elasticLimiter",
            {
                "vanAlbada", "monotonizedCentral", "superbee",
                "simpleWaveSuperbee", "none"
            },
            unlimited ? "monotonizedCentral" : limiter_,
            unlimited
          ? string("plastic without a limiter: the edges of points that have"
            " not yielded take monotonized central (no ringing ahead of"
            " elastic fronts), van Albada where such a point is near its"
            " yield stress (the elastic precursor of a plastic wave at the"
            " yield point)")
          : string("the body's limiter on every edge")
        );
    }
    else if (!automatic("elasticLimiter"))
    {
        FatalIOErrorInFunction(dict_)
            << "elasticLimiter in " << dict_.name()
            << " applies to plastic materials only (the limiter of the"
            << " edges of points that have not yielded); the material"
            << " is not plastic." << nl
            << "    Valid: remove it, or set 'limiter' for the whole"
            << " body" << exit(FatalIOError);
    }

    // A shear-free body's stress is a pressure times H.  With H N at the
    // points a uniform pressure pushes every point where H varies (the
    // discrete divergence of the points' cofactors is not zero), and at
    // strong impacts a transverse mode grows from it until the run stops
    // (two A3 bars at Mach 5 from a 1e-6 seed: 5.6 % of v0 by t = 0.3).
    // On the deformed dual's closed cells a uniform pressure is in
    // equilibrium exactly (doc/method.md, "Pressure on the deformed dual").
    // On tets the end faces' points have half cells of unequal depths
    // (threefold on structured tets), a struck face's points start apart,
    // and a shear-free body has nothing that pulls them back into line:
    // with H N a bar's face on a rigid wall drifts from the exact stress
    // (A3's material on 64 x 2 x 2 tets: 6.5-7 % at 1-2.5 c; 0.1-1.2 % on
    // the deformed dual), and a pair's faces slide sideways (3-4 % of v0)
    // and stop from 2.5 c.  On the deformed dual with vorticityDamping and
    // positionalF (below) the A3 pair on 64 tets holds its plateaus within
    // 0.04-0.5 % at Mach 1-2.5 (H N: 0.6-1.1 %, stops at 2.5); a face
    // driven by a prescribed velocity (which holds it from sliding) read
    // 1.1 % low at 2 c with H N and 4.3 % on the deformed dual, so bodies
    // on tets without a rigid wall or a contact pair keep H N
    // (doc/results.md, "Why the struck faces of tets go uneven")
    const bool deformable = pressureOnly && !m.smallStrain();
    bool pairPatches = false, wallPatches = false;
    if (solidProperties.isDict("boundaryConditions"))
    {
        for (const entry& e : solidProperties.subDict("boundaryConditions"))
        {
            const word type
            (
                e.isDict()
              ? e.dict().getOrDefault<word>("type", word::null)
              : word::null
            );
            pairPatches = pairPatches || type == "contact";
            wallPatches = wallPatches || type == "rigidWall";
        }
    }
    const string balanced
    (
        "shear-free: a uniform pressure on the closed dual cells of the"
        " deformed mesh exerts no force"
    );
    deformedPressure_ = choose
    (
        "deformedPressure",
        deformable && (!triangleBoundary || wallPatches || pairPatches),
        !deformable
      ? string("shear stiffness or small strain: H N carries the stress")
      : !triangleBoundary
      ? balanced
      : !(wallPatches || pairPatches)
      ? string("triangular boundary faces without a rigid wall or a"
        " contact pair: H N holds a driven face's stress closer on tets")
      : string
        (
            balanced
          + (
                pairPatches
              ? " (on tets with vorticityDamping and positionalF: the"
                " struck faces keep their stress)"
              : " (on tets at a rigid wall: the sliding struck face keeps"
                " its stress)"
            )
        )
    );
    if (deformedPressure_ && !deformable)
    {
        FatalIOErrorInFunction(dict_)
            << "deformedPressure yes in " << dict_.name() << " needs a"
            << " finite-strain material without shear stiffness (mu 0):"
            << " this one has "
            << (m.smallStrain() ? "small strain" : "shear stiffness")
            << " (its stress is not a pressure times cof F)." << nl
            << "    Valid for this material: no (or auto)"
            << exit(FatalIOError);
    }

    // The end faces of tets in a contact pair (above): the shear flow
    // their uneven half cells start is damped, and F follows the
    // positions.  Not at a rigid wall, which holds the face's points
    // level itself: there F from the positions sees the first layer's
    // tets invert at strong impacts (a bar at 2.5 c stopped at
    // t = 0.0008; its evolved F runs on, 1.1 % off) and the damping alone
    // moved the stress further off (1.8 %)
    const bool tetsPair =
        deformedPressure_ && triangleBoundary && pairPatches;
    vorticityDamping_ = choose
    (
        "vorticityDamping", tetsPair,
        tetsPair
      ? string("shear-free on tets in a contact pair: the struck faces'"
        " uneven half cells start a shear flow that nothing else resists")
      : string("no free struck face on uneven boundary cells")
    );
    if (vorticityDamping_ && !m.shearFree())
    {
        FatalIOErrorInFunction(dict_)
            << "vorticityDamping yes in " << dict_.name() << " needs a"
            << " material without shear stiffness (mu 0): this one's shear"
            << " waves damp its shear flow." << nl
            << "    Valid for this material: no (or auto)"
            << exit(FatalIOError);
    }
    positionalF_ = choose
    (
        "positionalF", tetsPair,
        tetsPair
      ? string("on the deformed dual on tets in a contact pair: F from the"
        " positions stays the deformed dual's map (the conserved F"
        " sheared at symmetry planes when the release arrived)")
      : string("F from its own conservation law")
    );
    if (positionalF_ && !deformedPressure_)
    {
        FatalIOErrorInFunction(dict_)
            << "positionalF yes in " << dict_.name() << " needs"
            << " deformedPressure (a stress that reads J and the deformed"
            << " dual only; elsewhere F carries the stress)." << nl
            << "    Valid: no (or auto), or deformedPressure yes"
            << exit(FatalIOError);
    }

    // The product's invariant: the numerical dissipation never decreases.
    // Where the fluxes would produce energy the stage blends towards first
    // order; elsewhere it costs one point pass (the bar impacts blend at
    // most 1 % of their stages and keep their plateaus to 4 digits; the
    // elastic car's dissipation fell by 0.0045 % of E0 without it:
    // doc/results.md, "Automatic scheme")
    energyStable_ = choose
    (
        "energyStable", true,
        "the numerical dissipation never decreases"
    );

    // Behind a shock of a material whose wave speed grows with compression
    // the limiter's switching leaves a standing pattern of F (a neo-Hookean
    // bar on a wall at 0.3 c_p: +-7 % about the exact stress), which the
    // average velocity of the F flux never damps.  The upwind F flux on
    // the edges a shock closes removes it (doc/results.md, "Shocks in
    // non-linear elastic bodies").  Its sensor also fires in the contact
    // zones of bending bodies, where the term doubles the dissipation (the
    // ring, at impact Mach number 0.013: 11.5 -> 23.4 %), and it harms
    // plastic and pressure-only flow.  So the automatic scheme uses it for
    // finite-strain elastic materials with shear stiffness and no Hugoniot,
    // in planar impacts (flat patches) strong enough to leave the noise
    // above 1 % (chooseShockStabilisation; 1.15 % at Mach number 0.1)
    shockFromScene_ =
        automatic("shockStabilisation") && !plastic && !m.smallStrain()
     && m.mu() > 0 && !m.hugoniot() && !FStabilisation_;
    shockStabilisation_ = choose
    (
        "shockStabilisation", false,
        shockFromScene_
      ? string("for now: chosen from the scene's impact speeds")
      : FStabilisation_
      ? string("the upwind F flux already upwinds F")
      : string("plastic, small-strain or pressure-dominated material:"
        " it would damp or stop the flow")
    );

    // A strong shock's captured profile forms at the struck face at second
    // order and sends a wave back into the compressed material, which rings
    // between the shock and the face (a Hugoniot pair at Mach 5: 7.5 %
    // beyond the contact-face plateau, whatever the limiter or the step;
    // at first order 0.2 %).  Flattening the edges the shock closes keeps
    // it at the first-order profile throughout (1.0 %; doc/results.md,
    // "Strong shocks: flattening the reconstruction").  With the upwind F
    // flux only: with the central one a first-order shock among
    // second-order edges let a Hugoniot bar's wall corner collapse (at c,
    // Barth-Jespersen).  Hugoniot materials only: on a neo-Hookean bar on a
    // wall it is mixed (the wall face's mean 0.57 -> 0.15 % off at 0.8 c_p,
    // but 0.23 -> 0.76 % at 0.3 c_p) (chooseFromScene)
    flatteningFromScene_ =
        automatic("shockFlattening") && m.hugoniot() && !FStabilisation_;
    shockFlattening_ = choose
    (
        "shockFlattening", m.hugoniot() && FStabilisation_,
        !m.hugoniot()
      ? string("no Hugoniot: on other materials' shocks it is mixed (a"
        " neo-Hookean bar on a wall: better at 0.8 c_p, worse at 0.3 c_p)")
      : FStabilisation_
      ? string(shockFlatteningWhy)
      : string("no plane-wave impact: without the upwind F flux a"
        " first-order shock among second-order edges collapses a struck"
        " corner")
    );

    boundarySlope_ = choose
    (
        "boundarySlope", boundarySlopes,
        FStabilisation_ ? "riemann" : "interior",
        FStabilisation_
      ? "the incoming waves' slope goes with the upwind F flux"
      : "Green-Gauss"
    );

    // A point's state is the mean over its dual cell: at a boundary point,
    // whose half cell lies inside the body, that is the value a quarter of
    // an edge inwards.  The boundary's Riemann problems then see the
    // solution's gradient across that distance as a jump, and upwind it
    // (a free surface in bending: |t|^2/Z of the half cell's mean
    // traction).  Extrapolated to the point, the state meets the boundary
    // condition to second order: the elastic torus lost 4.2 % of E0 at its
    // free surface and 13.0 % in all, 9.1 % in all with it (doc/results.md,
    // "Boundary states at the point").  The wave-split slopes of
    // boundarySlope riemann already place the value at the half cell's
    // centre, and with them it raised the release tension of a bar on a
    // wall from 2.1 to 4.0 % of the contact stress.
    // Only for compressible elastic bodies (those without the J law).
    // Measured with it: the Taylor bar's radius fell from 7.009 to 6.985
    // mm (band 7.0-7.15) and its numerical dissipation by 1.5e-4 of E0 over
    // its last 10 us; the nearly incompressible bars B2 stopped with J < 0
    // at a contact-face corner (step 820 of 2,794)
    extrapolationFromScene_ = automatic("boundaryExtrapolation");
    boundaryExtrapolation_ = choose
    (
        "boundaryExtrapolation",
        boundarySlope_ == "interior" && !FStabilisation_ && !needsJ,
        boundarySlope_ != "interior"
      ? string("the wave-split boundary slopes place the point's value at"
        " its half cell's centre")
      : FStabilisation_
      ? string("with the upwind F flux (plane-wave impacts) the points' own"
        " states")
      : needsJ
      ? kind + string(": measured on compressible elastic bodies only (the"
        " Taylor bar's radius left its band, a nearly incompressible bar's"
        " contact corner collapsed)")
      : string("the boundary's Riemann problems take the state at the"
        " point, not at its half cell's centroid")
    );
}


const Foam::scalar Foam::bodyScheme::shockMachThreshold = 0.08;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyScheme::setChoice(const word& key, const string& text)
{
    for (Tuple2<word, string>& c : choices_)
    {
        if (c.first() == key)
        {
            c.second() = text;
        }
    }
}


void Foam::bodyScheme::chooseFromScene
(
    const scalar planarMach,
    const scalar impactMach,
    const bool planeWave,
    const bool uniaxial,
    const bool contactPatches,
    const bool multirate
)
{
    // A plane-wave impact: the upwind F flux, with van Albada (Barth-
    // Jespersen's per-component clipping sends a precursor ahead of the
    // release wave that the face multiplies, superbee's sharper release
    // front leaves tension there; simpleWaveSuperbee, given by hand, is
    // made for it) and the incoming waves' boundary slopes
    // (without them a struck point's Green-Gauss slope hides the jump).
    // The bar tutorials' hand-made choice: doc/results.md, "Plane-wave
    // impacts".  Only with van Albada: not with another limiter given
    // (unlimited, the scheme crushes a bar's wall corner at cfl 1.5; with
    // Barth-Jespersen a Hugoniot bar on a wall at 2.5 c reached -747
    // instead of -875, and at c its step collapsed after the release)
    // (first order: no limiter to speak of)
    const bool limiterSuitsUpwindF =
        !secondOrder_ || automatic("limiter") || limiter_ == "vanAlbada"
     || limiter_ == "simpleWaveSuperbee";
    const bool upwindScene =
        (FStabFromScene_ && planeWave)
     || (FStabUniaxialFromScene_ && uniaxial);
    if (upwindScene && !limiterSuitsUpwindF)
    {
        setChoice
        (
            "FStabilisation",
            "no  (auto: a plane-wave impact, but the limiter " + limiter_
          + " is given: the upwind F flux is measured with vanAlbada)"
        );
    }
    else if (upwindScene)
    {
        FStabFromScene_ = false;
        FStabilisation_ = true;
        setChoice
        (
            "FStabilisation",
            FStabUniaxialFromScene_
          ? "yes  (auto: a plane-wave impact in uniaxial strain (a flat patch"
            " across the body's section, the other patches symmetry planes"
            " or parallel to it): onset and release without overshoot)"
          : "yes  (auto: a plane-wave impact (a flat patch across the body's"
            " section): onset and release without overshoot)"
        );
        if (FStabUniaxialFromScene_ && automatic("onsetStabilisation"))
        {
            setChoice
            (
                "onsetStabilisation",
                "no  (auto: the upwind F flux is on everywhere)"
            );
        }
        if (flatteningFromScene_)
        {
            flatteningFromScene_ = false;
            shockFlattening_ = true;
            setChoice
            (
                "shockFlattening",
                string("yes  (auto: ") + shockFlatteningWhy + ")"
            );
        }
        if (limiterFromScene_)
        {
            limiterFromScene_ = false;
            limiter_ = "vanAlbada";
            setChoice
            (
                "limiter",
                "vanAlbada  (auto: with the upwind F flux: a sharper release"
                " front leaves tension at the separating face)"
            );
        }
        if (shockFromScene_)
        {
            shockFromScene_ = false;
            shockStabilisation_ = false;
            setChoice
            (
                "shockStabilisation",
                "no  (auto: the upwind F flux already upwinds F)"
            );
        }
        if (secondOrder_ && automatic("boundarySlope"))
        {
            boundarySlope_ = "riemann";
            setChoice
            (
                "boundarySlope",
                "riemann  (auto: the incoming waves' slope goes with the"
                " upwind F flux)"
            );
        }
        if (secondOrder_ && extrapolationFromScene_)
        {
            // (a bar on a wall with the upwind F flux: the extrapolated
            // release raised its face tension from 2.1 to 4.0 % of the
            // contact stress with the wave-split slopes, and its rebound
            // velocity error from 0.4 to 1.4 % with interior ones)
            boundaryExtrapolation_ = false;
            setChoice
            (
                "boundaryExtrapolation",
                "no  (auto: with the upwind F flux (a plane-wave impact) the"
                " points' own states)"
            );
        }
    }

    if (limiterFromScene_)
    {
        // Curved impacts only: in a planar one the F flux's onset
        // overshoot travels with the front, and superbee keeps it (A1
        // without FStabilisation at 256 cells: L1 0.26 / 0.83 % against
        // 0.19 / 0.58 % with Barth-Jespersen)
        const bool curved = (planarMach <= 0 && impactMach > 0);
        const bool weak = (impactMach < shockMachThreshold);
        limiter_ = curved && weak ? word("superbee") : shockLimiter_;
        // (multirate stepping limits edge by edge: a level's edges are
        // evaluated in turns, so a point's clipping factor over all of its
        // edges has no one time)
        const bool perEdge = multirate && limiter_ == "barthJespersen";
        if (perEdge)
        {
            limiter_ = "vanAlbada";
        }
        OStringStream why;
        why << "auto: ";
        if (curved)
        {
            why << "curved impact at Mach number " << impactMach
                << (weak ? " < " : " >= ") << shockMachThreshold;
        }
        else
        {
            why << (planarMach > 0 ? "a planar impact" : "no impact");
        }
        why <<
        (
            curved && weak
          ? ": fronts kept within two cells, where their capture dissipates"
          : perEdge
          ? "; multirate stepping: limited per edge"
          : shockLimiter_ == "vanAlbada"
          ? "; nu >= 0.45: limited per edge"
          : "; per point, no new extrema"
        );
        setChoice("limiter", limiter_ + "  (" + why.str() + ")");
    }

    if (onsetFromScene_)
    {
        onsetFromScene_ = false;
        // Plastic bodies in plane-wave impacts only: in the plastic car
        // (a corner, not its section, strikes the wall) the zone's onsets
        // left a mode that the central F flux does not see, and after
        // the separation a front edge shortened steadily, to 37 % of its
        // length by 1 s (66 % without the zone; doc/results.md, "Contact
        // onset where the F flux is central")
        const bool noLimiter = secondOrder_ && limiter_ == "none";
        const bool unlimited = noLimiter && !plastic_;
        const bool plasticCurved = plastic_ && !planeWave;
        onsetStabilisation_ =
            contactPatches && !FStabilisation_ && !unlimited
         && !plasticCurved && !multirate;
        setChoice
        (
            "onsetStabilisation",
            onsetStabilisation_
          ? string
            (
                "yes  (auto: contact or wall patches: the upwind F flux on"
                " the points that have just closed or opened, for onset"
                " and release without overshoot"
            )
          + (noLimiter ? "; Barth-Jespersen on those points)" : ")")
          : FStabilisation_
          ? "no  (auto: the upwind F flux is on everywhere)"
          : contactPatches && multirate
          ? "no  (auto: multirate stepping: the onset zone's upwind F flux"
            " and Riemann slopes need one global step)"
          : unlimited
          ? "no  (auto: limiter none: unlimited, the Riemann boundary slopes"
            " crush a struck face)"
          : contactPatches && plasticCurved
          ? "no  (auto: plastic, no plane-wave impact: the zone's onsets"
            " leave a mode the central F flux does not see)"
          : "no  (auto: no contact or rigid-wall patch)"
        );
    }

    if (shockFlattening_ && !FStabilisation_)
    {
        FatalIOErrorInFunction(dict_)
            << "shockFlattening yes in " << dict_.name() << " needs the"
            << " upwind F flux (FStabilisation yes, chosen automatically in"
            << " plane-wave impacts): with the central F flux a first-order"
            << " shock among second-order edges collapses a struck corner."
            << nl << "    Valid here: shockFlattening no (or auto), or"
            << " FStabilisation yes"
            << exit(FatalIOError);
    }

    if (!shockFromScene_)
    {
        return;
    }
    shockStabilisation_ = (planarMach >= shockMachThreshold);
    OStringStream why;
    if (planarMach > 0)
    {
        why << "auto: planar impact at Mach number " << planarMach
            << (shockStabilisation_ ? " >= " : " < ") << shockMachThreshold
            << (
                   shockStabilisation_
                 ? ", where the limiter leaves noise behind the shocks"
                 : ": weak shocks"
               );
    }
    else
    {
        why << "auto: no planar impact (a flat wall or contact patch closing"
            << " at the initial velocities); in bending and curved contact"
            << " it doubles the dissipation";
    }
    setChoice
    (
        "shockStabilisation",
        word(shockStabilisation_ ? "yes" : "no") + "  (" + why.str() + ")"
    );
}


void Foam::bodyScheme::describe(Ostream& os, const word& indent) const
{
    for (const Tuple2<word, string>& c : choices_)
    {
        os  << indent << c.first().c_str();
        for (label k = c.first().size(); k < 23; ++k)
        {
            os  << ' ';
        }
        os  << c.second().c_str() << nl;
    }
}


// ************************************************************************* //
