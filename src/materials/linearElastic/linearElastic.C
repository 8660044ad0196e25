/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "tensorCross.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace materialModels
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(materialModel, linearElastic, dictionary);
}
}


Foam::materialModels::linearElastic::linearElastic(const dictionary& dict, const label nPoints)
:
    materialModel(dict, nPoints)
{}


void Foam::materialModels::linearElastic::stress
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
        const tensor& f = F[i];
        const scalar trF = tr(f);
        const scalar sJ = volumetricSigmaJ(trF - 2);
        setFluxStress
        (
            q[i],
            mu_*(f + f.T() - (2.0/3.0)*trF*I) + sJ*I,
            sJ
        );
    });
}


void Foam::materialModels::linearElastic::energy
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<scalar>& W
) const
{
    forAll(F, i)
    {
        const symmTensor epsDev(dev(symm(F[i]) - I));
        W[i] = mu_*(epsDev && epsDev) + volumetricEnergy(tr(F[i]) - 2);
    }
}


// ************************************************************************* //
