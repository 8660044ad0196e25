/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "runStatistics.H"
#include "IFstream.H"
#include "uniformStateIO.H"
#include "timeDirectory.H"
#include "Pstream.H"
#include "Ostream.H"


Foam::runStatistics::runStatistics
(
    const Time& runTime,
    const label nPoints,
    const label nStages
)
:
    clock_(),
    nPoints_(nPoints),
    nStages_(nStages),
    nSteps_(0),
    nUpdates_(0),
    multirate_(false),
    nStepsBefore_(0),
    wallBefore_(0),
    nRunsBefore_(0)
{
    if (timeDirectory::isRestart(runTime))
    {
        const autoPtr<IOdictionary> dict
        (
            readUniformState("runStatistics", runTime)
        );
        nStepsBefore_ = readUniformEntry<label>(*dict, "steps");
        wallBefore_ = readUniformEntry<scalar>(*dict, "wallTime");
        nRunsBefore_ = readUniformEntry<label>(*dict, "runs");
    }
}


void Foam::runStatistics::write(const Time& runTime) const
{
    dictionary dict;
    dict.add("steps", totalSteps());
    dict.add("wallTime", wallBefore_ + wallTime());
    dict.add("runs", nRunsBefore_ + 1);
    // Of this run so far (post-processing reads these, not the log)
    const scalar wall = max(wallTime(), scalar(1e-9));
    dict.add("points", nPoints_);
    dict.add("cores", Pstream::nProcs());
    dict.add
    (
        "throughput",
        nUpdates_/wall/Pstream::nProcs()
    );
    dict.add("peakMemory", returnReduce(peakMemory(), sumOp<scalar>()));
    writeUniformState("runStatistics", runTime, dict);
}

Foam::scalar Foam::runStatistics::peakMemory()
{
    IFstream is("/proc/self/status");
    if (!is.good())
    {
        return 0;
    }
    string line;
    while (is.good() && !is.eof())
    {
        is.getLine(line);
        if (line.compare(0, 6, "VmHWM:") == 0)
        {
            // "VmHWM:   123456 kB"
            return 1024*readScalar(line.substr(6, line.find("kB") - 6));
        }
    }
    return 0;
}


void Foam::runStatistics::report(Ostream& os) const
{
    const scalar wall = max(wallTime(), scalar(1e-9));
    const scalar memory = returnReduce(peakMemory(), sumOp<scalar>());
    const label nProcs = Pstream::nProcs();

    os  << "Finished " << nSteps_ << " steps in " << wall << " s wall" << nl;
    if (multirate_)
    {
        // The work in steps of every point, for comparison with one
        // global step
        os  << "Multirate: " << nUpdates_ << " point-stage updates, the"
            << " work of " << label(nUpdates_/(scalar(nStages_)*nPoints_))
            << " steps of every point" << nl;
    }
    os  << "Throughput: "
        << nUpdates_/wall/nProcs
        << " point-stage updates per second per core (" << nPoints_
        << " points, " << nProcs << " cores)" << nl
        << "Peak memory: " << memory/1048576 << " MB, "
        << memory/max(nPoints_, label(1)) << " bytes per point" << nl;
    if (nRunsBefore_)
    {
        os  << "Since t = 0: " << totalSteps() << " steps in "
            << wallBefore_ + wall << " s wall over " << nRunsBefore_ + 1
            << " runs (restarted)" << nl;
    }
}


// ************************************************************************* //
