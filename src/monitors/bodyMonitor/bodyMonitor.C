/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "bodyMonitor.H"
#include "checkedInput.H"
#include "timeDirectory.H"
#include "Time.H"
#include "IOmanip.H"
#include "IFstream.H"
#include "OSspecific.H"
#include <algorithm>

namespace
{

// A run stopped or killed after its last write left rows past the time a
// restart starts from: drop them (keeping the header), so that the
// restarted run's rows follow on without repeating or mixing times.  The
// kept rows go to a temporary file that then replaces the original.
void dropRowsAfter(const Foam::fileName& file, const Foam::scalar t)
{
    using namespace Foam;
    if (!isFile(file))
    {
        return;
    }
    const scalar tMax = t + 1e-9*mag(t);
    const fileName tmp(file + ".tmp");
    label nDropped = 0;
    {
        IFstream is(file);
        OFstream os(tmp);
        string line;
        label nColumns = -1;
        while (is.good() && !is.eof())
        {
            is.getLine(line);
            if (line.empty())
            {
                continue;
            }
            const label nCommas = std::count(line.begin(), line.end(), ',');
            if (nColumns < 0)
            {
                nColumns = nCommas;
            }
            // (A row cut short by the kill has fewer columns)
            else if
            (
                nCommas != nColumns
             || readScalar(line.substr(0, line.find(','))) > tMax
            )
            {
                ++nDropped;
                continue;
            }
            os << line.c_str() << nl;
        }
    }
    mv(tmp, file);
    if (nDropped)
    {
        Info<< "    restart: dropped " << nDropped << " rows after t = " << t
            << " from " << file.name() << " (written after the last write"
            << " time)" << nl;
    }
}

}

Foam::bodyMonitor::bodyMonitor(const solidBody& body)
:
    body_(body),
    probePoints_(),
    probeLocations_()
{
    if (body.dict().found("probes"))
    {
        const dictionary& probes = body.dict().subDict("probes");
        checkKeywords(probes, {"locations"});
        probeLocations_ = probes.get<pointField>("locations");
    }
    probePoints_.setSize(probeLocations_.size());
    forAll(probeLocations_, k)
    {
        probePoints_[k] = body.findPoint(probeLocations_[k]);
    }

    // A restart appends to the files of the earlier run (collective check)
    const Time& runTime = body.mesh().time();
    const bool append = timeDirectory::isRestart(runTime);
    if (Pstream::master())
    {
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/body.name()
        );
        mkDir(dir);
        if (append)
        {
            dropRowsAfter(dir/"energy.csv", runTime.startTime().value());
            dropRowsAfter(dir/"probes.csv", runTime.startTime().value());
        }
        energyFile_.reset
        (
            new OFstream
            (
                dir/"energy.csv",
                IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, append
            )
        );
        probeFile_.reset
        (
            new OFstream
            (
                dir/"probes.csv",
                IOstream::ASCII, IOstream::currentVersion,
                IOstream::UNCOMPRESSED, append
            )
        );
        energyFile_().precision(12);
        probeFile_().precision(12);
        if (!append)
        {
            energyFile_()
                << "t,kinetic,strain,plastic,externalWork,total,"
                << "numericalDissipation,px,py,pz" << nl;
            probeFile_() << "t";
            forAll(probeLocations_, k)
            {
                for (const char* c : {"vx","vy","vz","ux","uy","uz",
                     "sxx","syy","szz","sxy","syz","sxz"})
                {
                    probeFile_() << ',' << c << k;
                }
            }
            probeFile_() << nl;
        }
    }

    Info<< "    monitors   postProcessing/" << body.name()
        << "/energy.csv, probes.csv (" << probeLocations_.size()
        << " probes)" << nl;
    // A location within a body lies within an edge's length of a mesh
    // point: one farther away is outside it (a typing error, other units,
    // the wrong body), and its nearest point would be recorded silently
    scalar longestEdge = 0;
    if (probeLocations_.size())
    {
        const pointField& X = body.mesh().points();
        const labelList& es = body.dual().edgeStart();
        const labelList& ee = body.dual().edgeEnd();
        forAll(es, e)
        {
            longestEdge = max(longestEdge, magSqr(X[ee[e]] - X[es[e]]));
        }
        longestEdge = Foam::sqrt(returnReduce(longestEdge, maxOp<scalar>()));
    }
    forAll(probeLocations_, k)
    {
        point p(Zero);
        if (probePoints_[k] >= 0)
        {
            p = body.mesh().points()[probePoints_[k]];
        }
        reduce(p, sumOp<vector>());
        Info<< "    probe " << k << " at " << probeLocations_[k]
            << ": point at " << p << nl;
        const scalar distance = mag(p - probeLocations_[k]);
        if (distance > longestEdge)
        {
            FatalIOErrorInFunction(body.dict().subDict("probes"))
                << "Probe " << k << " of body " << body.name()
                << ": locations entry " << probeLocations_[k]
                << " is outside the body: its nearest mesh point " << p
                << " is " << distance << " away, farther than the mesh's"
                << " longest edge (" << longestEdge << ")." << nl
                << "    A probe records the mesh point nearest to a location"
                << " in the body's initial configuration (same units as"
                << " the mesh)." << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::bodyMonitor::write(const scalar t)
{
    const scalar KE = body_.kineticEnergy();
    const scalar SE = body_.strainEnergy();
    const scalar Dp = body_.plasticDissipation();
    const scalar Wext = body_.externalWork();
    const scalar E = KE + SE;
    const scalar Dnum = body_.initialEnergy() + Wext - E - Dp;
    const vector pm(body_.linearMomentum());

    List<scalar> values(12*probePoints_.size(), 0.0);
    forAll(probePoints_, k)
    {
        const label i = probePoints_[k];
        if (i >= 0)
        {
            const vector v(fluxVelocity(body_.q()[i]));
            const vector& u = body_.u()[i];
            const symmTensor s(body_.cauchyStress(i));
            const scalar row[12] =
                {v.x(), v.y(), v.z(), u.x(), u.y(), u.z(),
                 s.xx(), s.yy(), s.zz(), s.xy(), s.yz(), s.xz()};
            for (label c = 0; c < 12; ++c)
            {
                values[12*k + c] = row[c];
            }
        }
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(values, plusEqOp<scalar>());
    }

    if (Pstream::master())
    {
        energyFile_()
            << t << ',' << KE << ',' << SE << ',' << Dp << ',' << Wext
            << ',' << E << ',' << Dnum << ',' << pm.x() << ',' << pm.y()
            << ',' << pm.z() << endl;
        probeFile_() << t;
        forAll(values, c)
        {
            probeFile_() << ',' << values[c];
        }
        probeFile_() << endl;
    }

    return Dnum;
}


void Foam::bodyMonitor::flush()
{
    if (energyFile_.valid())
    {
        energyFile_().flush();
        probeFile_().flush();
    }
}


// ************************************************************************* //
