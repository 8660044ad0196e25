/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "energyStability.H"
#include "dualMesh.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::energyStability::energyStability(const dualMesh& dual, const bool JLaw)
:
    edgeAreaSum_(dual.mesh().nPoints(), Zero),
    edgeAreaMag_(dual.mesh().nPoints(), Zero),
    JLaw_(JLaw),
    firstOrder_()
{
    const labelList& es = dual.edgeStart();
    const labelList& ee = dual.edgeEnd();
    const vectorField& Ne = dual.edgeNormals();
    const scalarField& Ae = dual.edgeMagSf();
    forAll(es, e)
    {
        edgeAreaSum_[es[e]] += Ae[e]*Ne[e];
        edgeAreaSum_[ee[e]] -= Ae[e]*Ne[e];
        edgeAreaMag_[es[e]] += Ae[e];
        edgeAreaMag_[ee[e]] += Ae[e];
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector2D Foam::energyStability::production
(
    const stageResidual& R,
    const List<vector>& v,
    const List<tensor>& P,
    const List<scalar>& SigmaJ
) const
{
    vector2D prod(Zero);
    forAll(R.momentum, i)
    {
        prod.x() +=
            (v[i] & R.momentum[i]) + (P[i] && R.F[i])
          - (v[i] & (P[i] & edgeAreaSum_[i]));
        prod.y() += mag(v[i])*mag(P[i])*edgeAreaMag_[i];
    }
    if (JLaw_)
    {
        forAll(R.J, i)
        {
            prod.x() += SigmaJ[i]*R.J[i];
        }
    }
    return prod;
}


// ************************************************************************* //
