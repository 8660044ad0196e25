/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "symmetry.H"
#include "unitConversion.H"
#include "acousticFormulas.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(symmetry, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, symmetry, dictionary);
}
}


Foam::solidBoundaryConditions::symmetry::symmetry
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    solidBoundaryCondition(dual, patchi, dict),
    curved_(false)
{
    // The planes the patch consists of: its sub-faces' normals, equal
    // within a degree, gathered from all processors
    const scalar tolerance = std::cos(degToRad(1.0));
    auto addPlane = [&](const vector& n, DynamicList<vector>& planes)
    {
        for (const vector& m : planes)
        {
            if ((n & m) > tolerance)
            {
                return;
            }
        }
        planes.append(n);
    };
    DynamicList<vector> local;
    for (const vector& A : dual.subFaces(patchi).area)
    {
        const scalar magA = mag(A);
        if (magA > VSMALL && local.size() <= maxPlanes)
        {
            addPlane(A/magA, local);
        }
    }
    List<List<vector>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    DynamicList<vector> planes;
    for (const List<vector>& proc : all)
    {
        for (const vector& n : proc)
        {
            addPlane(n, planes);
        }
    }
    curved_ = (planes.size() > maxPlanes);
    if (!curved_)
    {
        normals_.transfer(planes);
    }
}


Foam::scalar Foam::solidBoundaryConditions::symmetry::strikeSpeed
(
    const boundBox& v,
    const UList<vector>& u,
    const UList<fluxState>& q,
    const scalar t,
    const scalar window
) const
{
    return largestAtCorners
    (
        v,
        [this](const vector& vi)
        {
            scalar s = curved_ ? mag(vi) : 0;
            for (const vector& n : normals_)
            {
                s = max(s, vi & n);
            }
            return s;
        }
    );
}


Foam::scalar Foam::solidBoundaryConditions::symmetry::contactState
(
    const vector& n,
    const vector& N,
    const point& x,
    const point& x0,
    const vector& v,
    const vector& tL,
    const waveData& w,
    const scalar t,
    const stageStep& step,
    vector& tC,
    vector& vC
) const
{
    // The plane's own normal (the reference one): the deformed normal may
    // tilt, and its normal reaction would then push along the plane
    acousticFormulas::mixedState(tL, v, 0, Zero, N, w.Zp, w.Zs, tC, vC);
    return tC & vC;
}


void Foam::solidBoundaryConditions::symmetry::describe(Ostream& os) const
{
    os  << "symmetry plane";
}


// ************************************************************************* //
