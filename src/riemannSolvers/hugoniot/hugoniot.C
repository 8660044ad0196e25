/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "hugoniot.H"
#include "acoustic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactRiemannSolvers
{
    defineTypeNameAndDebug(hugoniot, 0);
    addToRunTimeSelectionTable(contactRiemannSolver, hugoniot, dictionary);
}
}


Foam::contactRiemannSolvers::hugoniot::hugoniot(const dictionary&)
{}


void Foam::contactRiemannSolvers::hugoniot::normalState
(
    const side& L,
    const side& R,
    scalar& vnC,
    scalar& tnC
) const
{
    if (L.vn <= R.vn || (L.s == 0 && R.s == 0))
    {
        acoustic::solve(L, R, vnC, tnC);
        return;
    }

    const scalar mL = L.Lambda*L.rho, mR = R.Lambda*R.rho;
    const scalar ZL = L.rho*L.c, ZR = R.rho*R.c;
    const scalar sL = L.s*mL, sR = R.s*mR;
    const scalar a = sR - sL;
    const scalar b = ZL + ZR - 2*(sR*R.vn - sL*L.vn);
    const scalar c0 =
        -(R.tn - L.tn + ZL*L.vn + ZR*R.vn - (sR*sqr(R.vn) - sL*sqr(L.vn)));

    if (mag(a) < 1e-12*mag(b))
    {
        vnC = -c0/b;
    }
    else
    {
        // The root that tends to -c0/b as a -> 0
        vnC = 2*(-c0)/(b + sqrt(max(b*b - 4*a*c0, scalar(0))));
    }
    tnC = L.tn + ZL*(vnC - L.vn) - L.s*mL*sqr(vnC - L.vn);
}


// ************************************************************************* //
