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
    system/controlDict: see solverTime.H (endTime, writeControl,
    writeInterval, cfl: time step = cfl times the stable step of the
    current state, stableTimeStep.H).

    Restart: a run starts from the newest complete time directory
    (startFrom latestTime) and reads every field it needs from it; each
    write marks its directory complete last (timeDirectory.H).  The end
    time is always written.  A numerical failure writes the last good
    state (if this run computed one) and stops saying where and when.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "sigFpe.H"
#include "solverTime.H"
#include "timeDirectory.H"
#include "checkedInput.H"
#include "regionProperties.H"
#include "runStatistics.H"
#include "solidBody.H"
#include "bodyMonitor.H"
#include "tvdRungeKutta2.H"
#include "multirateRungeKutta2.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit vertex-centred solver for large-strain solid contact"
        " dynamics"
    );

    #include "setRootCase.H"

    // The solver checks its state at every stage (J, det F, momentum
    // finite) and stops with where and when after writing the last good
    // state; a trapped floating-point exception would end the run with
    // neither
    sigFpe::unset();

    solverTime runTime(args);

    #include "createBodies.H"
    #include "createContacts.H"
    #include "createMultirate.H"

    runStatistics stats(runTime, nPoints, tvdRungeKutta2::nStages);
    scalar nextReport = 0;
    // A progress line every 5 % of the simulated time, and at least every
    // reportWallInterval seconds of wall time, so that a run whose step has
    // become small still shows where it is
    const scalar reportWallInterval = 30;
    scalar lastReportWall = 0;
    const scalar endTime = runTime.endTime().value();
    const scalar startTime = runTime.value();
    label stepsThisRun = 0;
    label lastWriteIndex = runTime.timeIndex();

    #include "checkTimes.H"

    // Fields, and the histories a restart carries on.  The directory is
    // complete only when its marker is written last (timeDirectory.H)
    auto writeState = [&]()
    {
        timeDirectory::beginWrite(runTime);
        for (solidBody& b : bodies)
        {
            b.write();
            timeDirectory::interruptIfRequested(runTime);
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
        timeDirectory::endWrite(runTime);
        lastWriteIndex = runTime.timeIndex();
    };

    #include "failureAdvice.H"

    // The step's collapse (checkDeltaT.H)
    const scalar collapseRatio = 1e-3;
    const label collapseSteps = 1000;
    // (a step below this share of the largest has collapsed at once: one
    // that falls by orders of magnitude per step would reach steps that no
    // longer advance the time within collapseSteps)
    const scalar suddenCollapseRatio = 1e-9;
    scalar largestStep = 0;
    scalar largestStepTime = startTime;
    label nCollapsedSteps = 0;

    Info<< "Starting time loop" << nl << endl;

    // The run ends exactly at endTime (the last step is shortened to land
    // there); Time::run() would stop up to half a step before it
    const scalar endTolerance = 1e-6*firstDeltaT;
    while (endTime - runTime.value() > endTolerance)
    {
        const scalar t0 = runTime.value();
        const scalar dt = runTime.stepToTargets
        (
            multirate.valid()
          ? multirate->deltaT(bodies, cfl)
          : tvdRungeKutta2::stableDeltaT(bodies, contacts, cfl)
        );
        #include "checkDeltaT.H"
        runTime.setDeltaT(dt, false);
        ++runTime;

        scalar stepFraction = 1;
        const label failed =
            multirate.valid()
          ? multirate->step(bodies, t0, runTime.deltaTValue(), stepFraction)
          : tvdRungeKutta2::step
            (
                bodies, contacts, t0, runTime.deltaTValue(), stepFraction
            );
        runTime.shortenStep(stepFraction);

        #include "checkState.H"

        ++stepsThisRun;
        if (multirate.valid())
        {
            // (each level committed its points' plastic state)
            stats.step(multirate->lastUpdates());
        }
        else
        {
            stats.step();
            for (solidBody& b : bodies)
            {
                b.endStep();
            }
        }

        forAll(monitors, b)
        {
            monitors[b].write(runTime.value());
        }

        // The end time is always written, whatever the write interval
        const bool last = !(endTime - runTime.value() > endTolerance);
        if (runTime.writeTime() || last)
        {
            writeState();
        }

        const scalar progress =
            (runTime.value() - startTime)/max(endTime - startTime, VSMALL);
        const scalar wall = stats.wallTime();
        if (progress >= nextReport || last
         || wall - lastReportWall >= reportWallInterval)
        {
            Info<< "t = " << runTime.timeName() << "  step " << stats.totalSteps()
                << "  dt " << runTime.deltaTValue()
                << "  " << label(100*progress + 0.5) << "%"
                << "  wall " << wall << " s  left "
                << (progress > 0 ? wall*(1 - progress)/progress : 0)
                << " s";
            if (multirate.valid())
            {
                Info<< "  points per level "
                    << flatOutput(multirate->pointsPerLevel());
            }
            Info<< endl;
            while (nextReport <= progress)
            {
                nextReport += 0.05;
            }
            lastReportWall = wall;
        }
    }

    Info<< nl;
    for (const contactPair& c : contacts)
    {
        Info<< "Contact " << c.name() << ": largest interpenetration "
            << c.maxPenetration() << " of the local edge length";
        if (c.nonMatching())
        {
            Info<< "; " << c.nMappings() << " AMI mappings in "
                << c.mappingTime() << " s";
        }
        const scalar wall = c.wallTime();
        Info<< "; the pair took " << wall << " s of wall time ("
            << std::round(1000*wall/max(stats.wallTime(), VSMALL))/10
            << " % of the run)" << nl;
    }
    for (const solidBody& b : bodies)
    {
        if (b.nEnergyLimitedStages())
        {
            Info<< "Body " << b.name() << ": energyStable blended the"
                << " interior fluxes towards first order in "
                << b.nEnergyLimitedStages();
            if (multirate.valid())
            {
                Info<< " level stages (multirate) this run";
            }
            else
            {
                Info<< " of " << stats.totalSteps()*tvdRungeKutta2::nStages
                    << " stages since t = 0";
            }
            Info<< " (smallest second-order weight "
                << b.minEnergyBlending() << ")" << nl;
        }
        for (const solidBoundaryCondition& bc : b.boundaryConditions())
        {
            bc.writeSummary(Info, b.name());
        }
        // (F from the positions is not turned: solidBody::applyConstraints)
        if
        (
            b.scheme().contactRotation() && !b.scheme().positionalF()
         && b.contactRotations().anyPoints()
        )
        {
            Info<< "Body " << b.name() << ": contactRotation turned the F"
                << " of closed contact points by at most "
                << b.contactRotations().largestTurn() << " degrees" << nl;
        }
        if (b.nRelaxedSteps())
        {
            Info<< "Body " << b.name() << ": the step's energy balance"
                << " shortened the increment of " << b.nRelaxedSteps()
                << " of " << stats.totalSteps() << " steps since t = 0"
                << " (smallest factor " << b.minRelaxation() << ")" << nl;
        }
        if (b.nDissipatingRetries())
        {
            Info<< "Body " << b.name() << ": the step's energy balance took "
                << b.nDissipatingRetries() << " step tries again with"
                << " dissipating stages since t = 0" << nl;
        }
    }
    stats.report(Info);
    Info<< endl;

    Info<< "End\n" << endl;
    return 0;
}

// ************************************************************************* //
