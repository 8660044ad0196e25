/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "mooneyRivlin.H"
#include "tensorCross.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace materialModels
{
    defineTypeNameAndDebug(mooneyRivlin, 0);
    addToRunTimeSelectionTable(materialModel, mooneyRivlin, dictionary);
}
}


Foam::materialModels::mooneyRivlin::mooneyRivlin(const dictionary& dict, const label nPoints)
:
    materialModel(dict, nPoints)
,
    zeta_(0),
    xi_(readPositive(dict, "xi", true))
{
    if (3*sqrt(3.0)*xi_ > mu_)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'xi' = " << xi_ << " must be <= mu/(3 sqrt3) = "
            << mu_/(3*sqrt(3.0)) << exit(FatalIOError);
    }
    zeta_ = 0.5*(mu_ - 3*sqrt(3.0)*xi_);
}


void Foam::materialModels::mooneyRivlin::stress
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<fluxState>& q,
    const labelUList* points
) const
{
    forEachPoint(F.size(), points, [&](const label i)
    __attribute__((always_inline))
    {
        // Isochoric part from F and H (through det F), volumetric part
        // from the conserved J
        const scalar detF = (H[i] && F[i])/3.0;
        const scalar j23 = pow(detF, -2.0/3.0);
        const scalar FF = F[i] && F[i];
        const scalar HH = H[i] && H[i];
        const scalar d2 = detF*detF;
        const scalar sDet =
            -(2.0/3.0)*zeta_*j23*FF/detF
          - 2*xi_*HH*sqrt(HH)/(d2*detF);
        const scalar sJ = volumetricSigmaJ(J[i]);
        const tensor SigmaH((3*xi_*sqrt(HH)/d2)*H[i]);
        setFluxStress
        (
            q[i],
            2*zeta_*j23*F[i] + tensorCross(SigmaH, F[i])
          + (sDet + sJ + couplingPressure(detF, J[i]))*H[i],
            sJ + couplingSigmaJ(detF, J[i])
        );
    });
}


void Foam::materialModels::mooneyRivlin::energy
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<scalar>& W
) const
{
    forAll(F, i)
    {
        const scalar HH = H[i] && H[i];
        const scalar detF = (H[i] && F[i])/3.0;
        W[i] =
            zeta_*pow(detF, -2.0/3.0)*(F[i] && F[i])
          + xi_*HH*sqrt(HH)/sqr(detF)
          - 3*(zeta_ + sqrt(3.0)*xi_)
          + volumetricEnergy(J[i])
          + couplingEnergy(detF, J[i]);
    }
}


// ************************************************************************* //
