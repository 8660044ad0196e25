/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "stageResidual.H"
#include "dualMesh.H"

void Foam::stageResidual::setSize(const label nPoints, const bool JLaw)
{
    momentum.setSize(nPoints);
    F.setSize(nPoints);
    J.setSize(JLaw ? nPoints : 0);
    JLaw_ = JLaw;
    power = 0;
}


Foam::label Foam::stageResidual::releasePointLists()
{
    const label nPoints = momentum.size();
    momentum.clear();
    F.clear();
    J.clear();
    return nPoints;
}


void Foam::stageResidual::setBoundarySize
(
    const dualMesh& dual,
    const bool keep
)
{
    const label nPatches = dual.mesh().boundaryMesh().size();
    boundaryTraction.setSize(nPatches);
    boundaryVelocity.setSize(nPatches);
    boundarySet.setSize(nPatches, false);
    forAll(boundaryTraction, patchi)
    {
        const label n = keep ? dual.subFaces(patchi).point.size() : 0;
        // (zero until a stage gives them)
        boundaryTraction[patchi].setSize(n, Zero);
        boundaryVelocity[patchi].setSize(n, Zero);
    }
}


void Foam::stageResidual::reset()
{
    momentum = Zero;
    F = Zero;
    J = 0;
    power = 0;
    surfacePoints.clear();
    surfaceVelocities.clear();
    boundarySet = false;
}


void Foam::stageResidual::synchronise(const dualMesh& dual)
{
    dual.syncPointResidual(momentum);
    dual.syncPointResidual(F);
    // (collective: decided by the J law, not by this processor's size)
    if (JLaw_)
    {
        dual.syncPointResidual(J);
    }
}


// ************************************************************************* //
