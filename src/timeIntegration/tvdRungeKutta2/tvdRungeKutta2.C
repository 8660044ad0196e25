/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "tvdRungeKutta2.H"

Foam::scalar Foam::tvdRungeKutta2::stableDeltaT
(
    const PtrList<solidBody>& bodies,
    const scalar cfl
)
{
    scalar hMin = GREAT, UMax = 0;
    for (const solidBody& b : bodies)
    {
        hMin = min(hMin, b.minLength());
        UMax = max(UMax, b.maxWaveSpeed());
    }
    return cfl*hMin/UMax;
}


bool Foam::tvdRungeKutta2::step
(
    PtrList<solidBody>& bodies,
    const scalar t,
    const scalar dt
)
{
    bool ok = true;
    for (solidBody& b : bodies)
    {
        b.storeState();
        b.assembleResiduals(t);
    }
    for (solidBody& b : bodies)
    {
        b.rkStage(dt, 0);
        ok = b.updateConstitutive() && ok;
    }
    if (!ok)
    {
        return false;
    }
    for (solidBody& b : bodies)
    {
        b.assembleResiduals(t + dt);
    }
    for (solidBody& b : bodies)
    {
        b.rkStage(dt, 0.5);
        ok = b.updateConstitutive() && ok;
    }
    return ok;
}


// ************************************************************************* //
