/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "tvdRungeKutta2.H"

#include <functional>

Foam::scalar Foam::tvdRungeKutta2::stableDeltaT
(
    const PtrList<solidBody>& bodies,
    const PtrList<contactPair>& contacts,
    const scalar cfl
)
{
    // (a Hugoniot body's step anticipates the fastest impact it can meet)
    contactPair::anticipateImpacts(bodies, contacts);
    scalar dtStable = GREAT;
    for (const solidBody& b : bodies)
    {
        dtStable = min(dtStable, cfl*b.stableDeltaT());
    }
    scalar dt = dtStable;
    for (const contactPair& c : contacts)
    {
        dt = min(dt, c.deltaTLimit(0.25*dtStable));
    }
    return dt;
}


namespace
{

// The residuals of all bodies at time t, in the order of doc/stage.md,
// for the first stage of a step of dt or (second) its second, at its end
void residuals
(
    Foam::PtrList<Foam::solidBody>& bodies,
    Foam::PtrList<Foam::contactPair>& contacts,
    const Foam::scalar t,
    const Foam::scalar dt,
    const bool second
)
{
    for (Foam::solidBody& b : bodies)
    {
        b.startStage();
    }
    // Boundary and contact fluxes first: their Riemann states are the
    // boundary values of the interior reconstruction (greenGauss.H)
    for (Foam::solidBody& b : bodies)
    {
        b.addBoundaryFluxes(t, dt, second);
    }
    for (Foam::contactPair& c : contacts)
    {
        c.addFluxes();
    }
    for (Foam::solidBody& b : bodies)
    {
        b.addInteriorFluxes();
    }
    for (Foam::solidBody& b : bodies)
    {
        b.finishResiduals();
    }
}


} // End anonymous namespace


// The factor gamma <= 1 of the step's increment that keeps the numerical
// dissipation of every checking body from falling (doc/method.md, section
// 5): f(gamma) = E(U^n + gamma dU) - E^n - gamma dWext is convex with
// f(0) = 0 and nearly a parabola; its positive root, from f(1) and f(1/2).
// excess[b]: the energy a body's step would still create that is mostly
// the combination's (alpha <= beta) but has no usable root, because the
// stages' fluxes dissipate next to nothing (alpha ~ 0; 0: none)
Foam::scalar Foam::tvdRungeKutta2::stepRelaxation
(
    const PtrList<solidBody>& bodies,
    const boolList& check,
    scalarList& excess
)
{
    scalar scale = 0;
    for (const solidBody& b : bodies)
    {
        scale += b.stepStartEnergy();
    }
    const scalar tol = 1e-13*scale + VSMALL;

    scalar gamma = 1;
    excess.setSize(bodies.size());
    excess = 0;
    forAll(bodies, bi)
    {
        const solidBody& b = bodies[bi];
        if (!check[bi])
        {
            continue;
        }
        const scalar f1 = b.stepEnergyExcess(1);
        if (!(f1 > tol))
        {
            continue;
        }

        // Parabola f = alpha g + beta g^2 through f(1) and f(g); its root,
        // a little inside (the energy is not exactly quadratic).  Only the
        // two-stage combination's own error grows as g^2: a fall that does
        // not vanish with g (alpha >= 0: the work of the boundary and
        // contact fluxes, a quadrature, not balanced exactly), or a root
        // below one quarter, is not the combination's, and a shorter step
        // would not remove it: the step is left as it is.  (Roots of 0.44-
        // 0.5 are the combination's: the elastic torus with superbee in
        // free flight, alpha -1.3e-6 and beta 2.9e-6 of the energy, where
        // both stages' fluxes are blended to zero production.)
        scalar g = 0.5;
        scalar fg = b.stepEnergyExcess(g);
        scalar gb = 1;
        for (label iter = 0; iter < 4; ++iter)
        {
            // alpha + beta = f1, alpha g + beta g^2 = fg
            const scalar beta = (fg/g - f1)/(g - 1);
            const scalar alpha = f1 - beta;
            const scalar root = -alpha/max(beta, VSMALL)*(1 - 1e-6);
            if (!(alpha < 0 && beta > 0 && root >= 0.25 && root < 1))
            {
                if (iter == 0 && beta > 0 && alpha <= beta)
                {
                    excess[bi] = f1;
                }
                break;
            }
            const scalar fr = b.stepEnergyExcess(root);
            if (!(fr > tol))
            {
                gb = root;
                break;
            }
            g = root;
            fg = fr;
        }
        gamma = min(gamma, gb);
    }
    return gamma;
}


Foam::label Foam::tvdRungeKutta2::step
(
    PtrList<solidBody>& bodies,
    PtrList<contactPair>& contacts,
    const scalar t,
    const scalar dt,
    scalar& fraction
)
{
    fraction = 1;
    for (solidBody& b : bodies)
    {
        b.storeState();
    }
    for (contactPair& c : contacts)
    {
        c.startStep(dt);
    }
    // Each update of the state is followed by the constraints and the
    // check of the new state: returns the first body whose state became
    // invalid, or -1
    auto updateAll = [&bodies](const std::function<void(solidBody&)>& update)
    {
        forAll(bodies, b)
        {
            update(bodies[b]);
            bodies[b].applyConstraints();
            if (!bodies[b].updateConstitutive())
            {
                return b;
            }
        }
        return label(-1);
    };

    // The step's energy balance: the two-stage combination adds
    // dt^2/8 |R1 - R2|^2 to the energy, which no stage's residual sees;
    // where it would make the numerical dissipation fall, shorten the
    // increment of every body alike (contact impulses stay equal and
    // opposite).  Where both stages' fluxes dissipate next to nothing
    // (blended to zero production, as superbee's often are) a shorter step
    // does not help, since the excess then falls only as gamma^2 with
    // nothing to outweigh it: the step is taken again with stages that
    // dissipate the excess (one and a half times it, up to three tries)
    scalarList excess;
    scalarList required(bodies.size(), 0.0);
    boolList check(bodies.size());
    forAll(bodies, b)
    {
        check[b] = bodies[b].checksStepEnergy();
    }
    for (label attempt = 0; ; ++attempt)
    {
        residuals(bodies, contacts, t, dt, false);
        label failed = updateAll([dt](solidBody& b){ b.rkStage(dt, 0); });
        if (failed >= 0)
        {
            return failed;
        }
        residuals(bodies, contacts, t + dt, dt, true);
        failed = updateAll([dt](solidBody& b){ b.rkStage(dt, 0.5); });
        if (failed >= 0)
        {
            return failed;
        }

        const scalar gamma = stepRelaxation(bodies, check, excess);
        const bool retry = (attempt < 3 && max(excess) > 0);
        if (!retry)
        {
            forAll(bodies, b)
            {
                if (required[b] > 0)
                {
                    bodies[b].requireDissipation(0);
                }
            }
            if (gamma < 1)
            {
                fraction = gamma;
                return updateAll([gamma](solidBody& b){ b.relaxStep(gamma); });
            }
            return -1;
        }
        forAll(bodies, b)
        {
            required[b] += 1.5*excess[b]/dt;
            bodies[b].requireDissipation(required[b]);
            bodies[b].restoreState();
        }
        for (contactPair& c : contacts)
        {
            c.startStep(dt);
        }
    }
}


// ************************************************************************* //
