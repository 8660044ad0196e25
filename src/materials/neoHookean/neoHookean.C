/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "neoHookean.H"
#include "tensorCross.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace materialModels
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(materialModel, neoHookean, dictionary);
}
}


Foam::materialModels::neoHookean::neoHookean(const dictionary& dict, const label nPoints)
:
    materialModel(dict, nPoints)
{}


void Foam::materialModels::neoHookean::stress
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
        // Isochoric part from F (through det F = H:F/3), volumetric part
        // from the conserved J (see the class description)
        const scalar detF = (H[i] && F[i])/3.0;
        const scalar j23 = pow(detF, -2.0/3.0);
        const scalar FF = F[i] && F[i];
        const scalar sJ = volumetricSigmaJ(J[i]);
        setFluxStress
        (
            q[i],
            mu_*j23*F[i]
          + (
                sJ + couplingPressure(detF, J[i])
              - (mu_/3.0)*j23*FF/detF
            )*H[i],
            sJ + couplingSigmaJ(detF, J[i])
        );
    });
}


void Foam::materialModels::neoHookean::energy
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<scalar>& W
) const
{
    forAll(F, i)
    {
        const scalar detF = (H[i] && F[i])/3.0;
        W[i] =
            0.5*mu_*(pow(detF, -2.0/3.0)*(F[i] && F[i]) - 3)
          + volumetricEnergy(J[i])
          + couplingEnergy(detF, J[i]);
    }
}


// ************************************************************************* //
