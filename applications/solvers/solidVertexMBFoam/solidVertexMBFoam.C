/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
-------------------------------------------------------------------------------
Application
    solidVertexMBFoam

Description
    Explicit multi-body solver for large-strain solid contact dynamics on the
    median dual of each body's mesh (Total Lagrangian {p, F, H, J} system,
    upwind Riemann fluxes, TVD Runge-Kutta 2).

    Bodies are the regions listed under 'solid' in constant/regionProperties,
    or the single mesh in constant/polyMesh when there is no such file.  Each
    body is described by constant/<body>/solidProperties (see solidBody.H);
    contact pairs between bodies by constant/contactProperties (see
    contactPair.H).
    system/controlDict: endTime, writeControl (adjustableRunTime), and
        cfl     0.3;        // time step = cfl h_min / U_max

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "regionProperties.H"
#include "runStatistics.H"
#include "solidBody.H"
#include "bodyMonitor.H"
#include "tvdRungeKutta2.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit vertex-centred solver for large-strain solid contact"
        " dynamics"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createBodies.H"
    #include "createContacts.H"

    runStatistics stats(runTime, nPoints, tvdRungeKutta2::nStages);
    scalar nextReport = 0;
    const scalar endTime = runTime.endTime().value();
    const scalar startTime = runTime.value();

    // Fields, and the histories a restart carries on
    auto writeState = [&]()
    {
        for (const solidBody& b : bodies)
        {
            b.write();
        }
        for (const contactPair& c : contacts)
        {
            c.write();
        }
        for (bodyMonitor& m : monitors)
        {
            m.flush();
        }
        stats.write(runTime);
    };

    Info<< "Starting time loop" << nl << endl;

    while (runTime.run())
    {
        const scalar dt = min
        (
            tvdRungeKutta2::stableDeltaT(bodies, contacts, cfl),
            endTime - runTime.value()
        );
        runTime.setDeltaT(dt);
        const scalar t0 = runTime.value();
        ++runTime;

        const label failed =
            tvdRungeKutta2::step(bodies, contacts, t0, runTime.deltaTValue());
        stats.step();

        #include "checkState.H"

        for (solidBody& b : bodies)
        {
            b.endStep();
        }

        forAll(monitors, b)
        {
            monitors[b].write(runTime.value());
        }

        if (runTime.writeTime())
        {
            writeState();
        }

        const scalar progress =
            (runTime.value() - startTime)/max(endTime - startTime, VSMALL);
        if (progress >= nextReport || !runTime.run())
        {
            const scalar wall = stats.wallTime();
            Info<< "t = " << runTime.timeName() << "  step " << stats.totalSteps()
                << "  dt " << runTime.deltaTValue()
                << "  " << label(100*progress + 0.5) << "%"
                << "  wall " << wall << " s  left "
                << (progress > 0 ? wall*(1 - progress)/progress : 0)
                << " s" << endl;
            nextReport += 0.05;
        }
    }

    Info<< nl;
    for (const contactPair& c : contacts)
    {
        Info<< "Contact " << c.name() << ": largest interpenetration "
            << c.maxPenetration() << " of the local edge length" << nl;
    }
    for (const solidBody& b : bodies)
    {
        if (b.nEnergyLimitedStages())
        {
            Info<< "Body " << b.name() << ": energyStable blended the"
                << " interior fluxes towards first order in "
                << b.nEnergyLimitedStages() << " of "
                << stats.totalSteps()*tvdRungeKutta2::nStages
                << " stages since t = 0 (smallest second-order weight "
                << b.minEnergyBlending() << ")" << nl;
        }
    }
    stats.report(Info);
    Info<< endl;

    Info<< "End\n" << endl;
    return 0;
}

// ************************************************************************* //
