/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "tvdRungeKutta2.H"

Foam::scalar Foam::tvdRungeKutta2::stableDeltaT
(
    const PtrList<solidBody>& bodies,
    const PtrList<contactPair>& contacts,
    const scalar cfl
)
{
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

// The residuals of all bodies at time t, in the order of doc/stage.md
void residuals
(
    Foam::PtrList<Foam::solidBody>& bodies,
    Foam::PtrList<Foam::contactPair>& contacts,
    const Foam::scalar t
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
        b.addBoundaryFluxes(t);
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


Foam::label Foam::tvdRungeKutta2::step
(
    PtrList<solidBody>& bodies,
    PtrList<contactPair>& contacts,
    const scalar t,
    const scalar dt
)
{
    for (solidBody& b : bodies)
    {
        b.storeState();
    }
    for (contactPair& c : contacts)
    {
        c.startStep(dt);
    }
    residuals(bodies, contacts, t);
    forAll(bodies, b)
    {
        bodies[b].rkStage(dt, 0);
        bodies[b].applyConstraints();
        if (!bodies[b].updateConstitutive())
        {
            return b;
        }
    }
    residuals(bodies, contacts, t + dt);
    forAll(bodies, b)
    {
        bodies[b].rkStage(dt, 0.5);
        bodies[b].applyConstraints();
        if (!bodies[b].updateConstitutive())
        {
            return b;
        }
    }
    return -1;
}


// ************************************************************************* //
