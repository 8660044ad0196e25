/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "solverTime.H"
#include "timeDirectory.H"
#include "checkedInput.H"
#include "IFstream.H"
#include "Pstream.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::word& Foam::solverTime::checkControlDict(const argList& args)
{
    const fileName file
    (
        args.rootPath()/args.globalCaseName()/"system"/controlDictName
    );
    IFstream is(file);
    if (!is.good())
    {
        // Time reports the missing file itself
        return controlDictName;
    }
    const dictionary dict(is);

    checkKeywords
    (
        dict,
        {
            "application", "startFrom", "startTime", "stopAt", "endTime",
            "deltaT", "writeControl", "writeInterval", "cfl", "multirateLevels",
            "writeFormat",
            "writePrecision", "writeCompression", "timeFormat",
            "timePrecision", "runTimeModifiable", "purgeWrite",
            "DebugSwitches", "InfoSwitches", "OptimisationSwitches"
        }
    );

    auto oneOf = [&](const word& key, const wordList& allowed)
    {
        const word value(dict.getOrDefault<word>(key, allowed[0]));
        if (!allowed.found(value))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword '" << key << "' = " << value << " in " << file
                << " is not allowed" << nl << "Allowed values: "
                << flatOutput(allowed) << exit(FatalIOError);
        }
        return value;
    };
    const word startFrom
    (
        oneOf("startFrom", {"latestTime", "startTime", "firstTime"})
    );
    oneOf("stopAt", {"endTime"});
    const word writeControl
    (
        oneOf("writeControl", {"timeStep", "adjustableRunTime", "runTime"})
    );

    const scalar startTime = getFiniteOrDefault<scalar>(dict, "startTime", 0);
    const scalar endTime = getFinite<scalar>(dict, "endTime");
    if (startTime < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'startTime' = " << startTime << " in " << file
            << " must be >= 0" << exit(FatalIOError);
    }
    if (!(endTime > startTime) && startFrom != "latestTime")
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'endTime' = " << endTime << " in " << file
            << " must be larger than startTime = " << startTime
            << exit(FatalIOError);
    }
    if (!(endTime > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'endTime' = " << endTime << " in " << file
            << " must be > 0" << exit(FatalIOError);
    }

    const scalar writeInterval = getFinite<scalar>(dict, "writeInterval");
    if (writeControl == "timeStep")
    {
        if (writeInterval < 1 || writeInterval != label(writeInterval))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'writeInterval' = " << writeInterval << " in "
                << file << " must be a whole number of steps >= 1 with"
                << " writeControl timeStep" << exit(FatalIOError);
        }
    }
    else if (!(writeInterval > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'writeInterval' = " << writeInterval << " in "
            << file << " must be > 0 (a time between writes)"
            << exit(FatalIOError);
    }

    const scalar cfl = getFiniteOrDefault<scalar>(dict, "cfl", 0.9);
    if (!(cfl > 0) || cfl > 2)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'cfl' = " << cfl << " in " << file
            << " must be in (0, 2]" << exit(FatalIOError);
    }

    const label levels = dict.getOrDefault<label>("multirateLevels", 1);
    if (levels < 1 || levels > maxMultirateLevels)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'multirateLevels' = " << levels << " in " << file
            << " must be an integer from 1 (one global step) to "
            << maxMultirateLevels << " (steps down to 1/"
            << (label(1) << (maxMultirateLevels - 1)) << " of the largest)"
            << exit(FatalIOError);
    }

    return controlDictName;
}


void Foam::solverTime::restartFrom(const instant& t)
{
    scalar value = t.value();
    label index = 0;
    timeDirectory::readMarker(*this, t.name(), value, index);
    setTime(instant(value, t.name()), index);
    startTime_ = value;
    startTimeIndex_ = index;
    writeTimeIndex_ = 0;
    restart_ = true;
}


void Foam::solverTime::selectStartTime()
{
    const word startFrom
    (
        controlDict().getOrDefault<word>("startFrom", "latestTime")
    );

    if (startFrom != "latestTime")
    {
        // Time has moved to startTime (or the first time directory)
        if (timeDirectory::complete(*this, timeName()))
        {
            restartFrom(instant(value(), timeName()));
        }
        else if (timeDirectory::interrupted(*this, timeName()))
        {
            FatalIOErrorInFunction(controlDict())
                << "The start time directory " << path()/timeName()
                << " is incomplete (uniform/" << timeDirectory::writingName
                << " without uniform/" << timeDirectory::markerName
                << ": its write was interrupted)." << nl
                << "    Restart from a complete time (startFrom latestTime"
                << " skips incomplete ones), or remove the directory to"
                << " start from the initial conditions."
                << exit(FatalIOError);
        }
        return;
    }

    // Newest complete time directory; the processors share the master's
    // list (a time missing on some processor is incomplete there)
    const scalar t0 = controlDict().getOrDefault<scalar>("startTime", 0);
    instantList times(this->times());
    Pstream::scatter(times);
    for (label i = times.size() - 1; i >= 0; --i)
    {
        if (times[i].name() == constant())
        {
            continue;
        }
        if (timeDirectory::complete(*this, times[i].name()))
        {
            restartFrom(times[i]);
            return;
        }
        if (times[i].name() != timeName(t0))
        {
            WarningInFunction
                << "Skipping the incomplete time directory "
                << path()/times[i].name() << " (no uniform/"
                << timeDirectory::markerName << ": its write was"
                << " interrupted, or it was not written by the solver)"
                << endl;
        }
    }

    // No complete time: a fresh run at startTime
    setTime(t0, 0);
    startTime_ = t0;
    startTimeIndex_ = 0;
    writeTimeIndex_ = 0;
    if (timeDirectory::interrupted(*this, timeName()))
    {
        FatalIOErrorInFunction(controlDict())
            << "No complete time directory to restart from, and the start"
            << " time directory " << path()/timeName() << " holds an"
            << " interrupted write." << nl
            << "    Remove it to start from the initial conditions."
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::solverTime::stepToTargets(const scalar dt) const
{
    // The next target: endTime, or the next write time if earlier
    scalar toTarget = endTime_ - value();
    if (writeControl_ == wcAdjustableRunTime)
    {
        toTarget = min
        (
            toTarget,
            writesBeforeStart_ >= 0
          ? firstStart_
          + (writesBeforeStart_ + writeTimeIndex_ + 1)*writeInterval_
          - value()
          : (writeTimeIndex_ + 1)*writeInterval_ - (value() - startTime_)
        );
    }
    if (!(toTarget > 0) || !(dt > 0))
    {
        return dt;
    }
    // Equal steps up to the target, none longer than dt
    const scalar nSteps = std::ceil(toTarget/dt*(1 - 1e-12));
    return (nSteps <= 1) ? min(dt, toTarget) : min(dt, toTarget/nSteps);
}


void Foam::solverTime::shortenStep(const scalar fraction)
{
    if (!(fraction < 1))
    {
        return;
    }
    const scalar dt = deltaTValue();
    if (writeTime_ && writeControl_ == wcAdjustableRunTime)
    {
        writeTime_ = false;
        --writeTimeIndex_;
    }
    setTime(value() - (1 - fraction)*dt, timeIndex());
    setDeltaT(fraction*dt, false);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solverTime::solverTime(const argList& args)
:
    Time(checkControlDict(args), args),
    restart_(false),
    cfl_(controlDict().getOrDefault<scalar>("cfl", 0.9)),
    multirateLevels_(controlDict().getOrDefault<label>("multirateLevels", 1)),
    firstStart_(controlDict().getOrDefault<scalar>("startTime", 0)),
    writesBeforeStart_(-1)
{
    selectStartTime();
    if (writeControl_ == wcAdjustableRunTime)
    {
        const scalar n = (startTime_ - firstStart_)/writeInterval_;
        if (n > -0.5 && mag(n - std::round(n)) < 1e-6)
        {
            writesBeforeStart_ = label(std::round(n));
        }
    }

    if (restart_)
    {
        Info<< "Restart from the complete time directory " << timeName()
            << " (t = " << value() << ", step " << timeIndex() << ")"
            << nl << endl;
    }
    else
    {
        Info<< "Fresh run from the initial conditions at t = " << value()
            << nl << endl;
    }
}


// ************************************************************************* //
