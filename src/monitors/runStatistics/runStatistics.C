/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "runStatistics.H"
#include "IFstream.H"
#include "Pstream.H"
#include "Ostream.H"

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

    os  << "Finished " << nSteps_ << " steps in " << wall << " s wall" << nl
        << "Throughput: "
        << scalar(nSteps_)*nStages_*nPoints_/wall/nProcs
        << " point-stage updates per second per core (" << nPoints_
        << " points, " << nProcs << " cores)" << nl
        << "Peak memory: " << memory/1048576 << " MB, "
        << memory/max(nPoints_, label(1)) << " bytes per point" << nl;
}


// ************************************************************************* //
