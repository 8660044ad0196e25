/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "timeDirectory.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "IOdictionary.H"
#include "Pstream.H"

#include <csignal>
#include <sstream>

const Foam::word Foam::timeDirectory::markerName("time");
const Foam::word Foam::timeDirectory::writingName(".writing");


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::timeDirectory::beginWrite(const Time& runTime)
{
    const fileName dir(runTime.timePath()/"uniform");
    mkDir(dir);
    {
        OFstream os(dir/writingName);
        os << "solidVertexMBFoam is writing this time directory" << nl;
    }
    const fileName marker(dir/markerName);
    if (exists(marker))
    {
        rm(marker);
    }
}


void Foam::timeDirectory::interruptIfRequested(const Time& runTime)
{
    const std::string request(getEnv("SVMB_INTERRUPT_WRITE"));
    if (request.empty())
    {
        return;
    }
    // Plain text, not OpenFOAM tokens: a time name such as 0.1 would read
    // as a number
    std::istringstream is(request);
    std::string name, sig;
    is >> name >> sig;
    if (name != runTime.timeName())
    {
        return;
    }
    const int number =
        sig == "TERM" ? SIGTERM
      : sig == "INT" ? SIGINT
      : sig == "KILL" ? SIGKILL
      : 0;
    if (!number)
    {
        FatalErrorInFunction
            << "SVMB_INTERRUPT_WRITE=\"" << request.c_str() << "\": the "
            << "signal must be TERM, INT or KILL" << exit(FatalError);
    }
    std::raise(number);
}


void Foam::timeDirectory::endWrite(const Time& runTime)
{
    const fileName dir(runTime.timePath()/"uniform");
    mkDir(dir);
    const fileName tmp(dir/("." + markerName + ".writing"));
    {
        OFstream os(tmp);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << exit(FatalError);
        }
        IOobject io
        (
            markerName, runTime.timeName(), "uniform", runTime,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        );
        io.writeHeader(os, "dictionary");
        os.precision(17);
        os.writeEntry("value", runTime.value());
        os.writeEntry("name", string(runTime.timeName()));
        os.writeEntry("index", runTime.timeIndex());
        os.writeEntry("deltaT", runTime.deltaTValue());
        os.writeEntry("deltaT0", runTime.deltaT0Value());
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Writing " << tmp << " failed" << exit(FatalError);
        }
    }
    // Atomic: the marker appears complete or not at all
    if (!mv(tmp, dir/markerName))
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << dir/markerName
            << exit(FatalError);
    }
    rm(dir/writingName);
}


bool Foam::timeDirectory::completeLocal(const fileName& dir)
{
    return isFile(dir/"uniform"/markerName, false);
}


bool Foam::timeDirectory::complete(const Time& runTime, const word& name)
{
    return returnReduce
    (
        completeLocal(runTime.path()/name), andOp<bool>()
    );
}


bool Foam::timeDirectory::interrupted(const Time& runTime, const word& name)
{
    const fileName dir(runTime.path()/name);
    return returnReduce
    (
        isFile(dir/"uniform"/writingName, false) && !completeLocal(dir),
        orOp<bool>()
    );
}


void Foam::timeDirectory::readMarker
(
    const Time& runTime,
    const word& name,
    scalar& value,
    label& index
)
{
    const fileName file(runTime.path()/name/"uniform"/markerName);
    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(is)
            << "Cannot read the completion marker " << file
            << exit(FatalIOError);
    }
    const dictionary dict(is);
    value = dict.get<scalar>("value");
    index = dict.get<label>("index");
}


// ************************************************************************* //
