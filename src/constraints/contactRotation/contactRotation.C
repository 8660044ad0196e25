/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "contactRotation.H"
#include "contact.H"
#include "dualMesh.H"
#include "syncTools.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The smallest rotation taking unit vector a onto unit vector b (identity
//  when they are opposite).  Not Foam::rotationTensor: it returns I below
//  a turn of about 3e-8 rad (a cut-off that let serial and parallel runs
//  part, see apply) and a reflection for opposite vectors
Foam::tensor rotationOnto(const Foam::vector& a, const Foam::vector& b)
{
    using namespace Foam;
    const vector w(a ^ b);
    const scalar c = a & b;
    if (c <= -1 + 1e-6)
    {
        return I;
    }
    const tensor W
    (
        0, -w.z(), w.y(),
        w.z(), 0, -w.x(),
        -w.y(), w.x(), 0
    );
    return I + W + (W & W)/(1 + c);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactRotation::contactRotation
(
    const dualMesh& dual,
    const PtrList<solidBoundaryCondition>& bcs
)
:
    dual_(dual),
    anyClosed_(false),
    marksChanged_(false),
    maxAngle_(0),
    anyPoints_(false)
{
    const polyMesh& mesh = dual.mesh();

    // The faces of every contact patch.  A point of a contact patch on
    // another processor may sit on this one without a patch face here (a
    // cell touching the patch at a vertex only): it is a contact point here
    // too, with no faces of its own, so that every copy of it turns alike
    boolList onPatch(mesh.nPoints(), false);
    DynamicList<face> faces;
    for (const solidBoundaryCondition& bc : bcs)
    {
        if (isA<solidBoundaryConditions::contact>(bc))
        {
            for (const face& f : mesh.boundaryMesh()[bc.patchi()])
            {
                faces.append(f);
                for (const label p : f)
                {
                    onPatch[p] = true;
                }
            }
        }
    }
    if (Pstream::parRun())
    {
        syncTools::syncPointList(mesh, onPatch, orEqOp<bool>(), false);
    }
    points_ = findIndices(onPatch, true);
    anyPoints_ = returnReduce(points_.size() > 0, orOp<bool>());
    forAll(points_, k)
    {
        index_.insert(points_[k], k);
    }

    // Faces over the points' indices, and each point's faces
    faces_.transfer(faces);
    labelList nFaces(points_.size(), 0);
    for (face& f : faces_)
    {
        for (label& p : f)
        {
            p = index_[p];
            ++nFaces[p];
        }
    }
    pointFacesStart_.setSize(points_.size() + 1);
    label n = 0;
    forAll(points_, k)
    {
        pointFacesStart_[k] = n;
        n += nFaces[k];
    }
    pointFacesStart_.last() = n;
    pointFaces_.setSize(n);
    nFaces = 0;
    forAll(faces_, fi)
    {
        for (const label k : faces_[fi])
        {
            pointFaces_[pointFacesStart_[k] + nFaces[k]++] = fi;
        }
    }
    faceArea_.setSize(faces_.size());
    sum1_.setSize(points_.size());

    closed_.setSize(points_.size(), 0);
    n_.setSize(points_.size());

    // Reference normals
    surfaceNormals(mesh.points(), nullptr, N_);
    forAll(N_, k)
    {
        N_[k] /= max(mag(N_[k]), VSMALL);
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::contactRotation::surfaceNormals
(
    const pointField& X,
    const UList<vector>* u,
    List<vector>& n
) const
{
    auto x = [&](const label k)
    {
        const label p = points_[k];
        return u ? X[p] + (*u)[p] : X[p];
    };

    // Area vectors of this processor's faces (twice the area, outward)
    forAll(faces_, fi)
    {
        const face& f = faces_[fi];
        const point x0(x(f[0]));
        vector A(Zero);
        for (label i = 1; i + 1 < f.size(); ++i)
        {
            A += ((x(f[i]) - x0) ^ (x(f[i + 1]) - x0));
        }
        faceArea_[fi] = A;
    }

    // First ring: each point's faces, summed over processors
    forAll(points_, k)
    {
        sum1_[k] = Zero;
        for (label j = pointFacesStart_[k]; j < pointFacesStart_[k + 1]; ++j)
        {
            sum1_[k] += faceArea_[pointFaces_[j]];
        }
    }
    const polyMesh& mesh = dual_.mesh();
    if (Pstream::parRun())
    {
        syncTools::syncPointList
        (
            mesh, points_, sum1_, plusEqOp<vector>(), vector::zero
        );
    }

    // Second ring: over the point's faces, the first-ring sums of their
    // points (faces belong to one processor: the parts add up)
    n.setSize(points_.size());
    forAll(points_, k)
    {
        n[k] = Zero;
        for (label j = pointFacesStart_[k]; j < pointFacesStart_[k + 1]; ++j)
        {
            for (const label q : faces_[pointFaces_[j]])
            {
                n[k] += sum1_[q];
            }
        }
    }
    if (Pstream::parRun())
    {
        syncTools::syncPointList
        (
            mesh, points_, n, plusEqOp<vector>(), vector::zero
        );
    }
}


void Foam::contactRotation::synchronise()
{
    if (Pstream::parRun())
    {
        syncTools::syncPointList
        (
            dual_.mesh(), points_, closed_, maxEqOp<label>(), label(0)
        );
    }
    bool any = false;
    for (const label c : closed_)
    {
        any = any || c;
    }
    anyClosed_ = returnReduce(any, orOp<bool>());
    marksChanged_ = false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactRotation::setClosed
(
    const labelUList& meshPoints,
    const UList<bool>& flag
)
{
    forAll(meshPoints, i)
    {
        const label k = index_.lookup(meshPoints[i], -1);
        if (k >= 0)
        {
            closed_[k] = flag[i];
        }
    }
    marksChanged_ = true;
}


void Foam::contactRotation::apply
(
    const UList<vector>& u,
    List<tensor>& F,
    List<tensor>* H,
    const UList<bool>* active
)
{
    if (marksChanged_)
    {
        synchronise();
    }
    if (!anyClosed_)
    {
        return;
    }

    surfaceNormals(dual_.mesh().points(), &u, n_);

    forAll(points_, k)
    {
        const scalar magN = mag(n_[k]);
        if (!closed_[k] || magN < VSMALL)
        {
            continue;
        }
        const label p = points_[k];
        if (active && !(*active)[p])
        {
            continue;
        }
        const vector nState
        (
            H ? ((*H)[p] & N_[k]) : (cof(F[p]) & N_[k])
        );
        const scalar magState = mag(nState);
        if (magState < VSMALL)
        {
            continue;
        }
        // (no threshold: the turn is smooth in the normals, and a cut-off
        // would let round-off decide between turning and not, so that
        // serial and parallel runs would part)
        const vector a(nState/magState), b(n_[k]/magN);
        const tensor R(rotationOnto(a, b));
        F[p] = R & F[p];
        if (H)
        {
            (*H)[p] = R & (*H)[p];
        }
        maxAngle_ = max(maxAngle_, radToDeg(acos(min(max(a & b, -1.0), 1.0))));
    }
}


Foam::scalar Foam::contactRotation::largestTurn() const
{
    return returnReduce(maxAngle_, maxOp<scalar>());
}


// ************************************************************************* //
