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


Foam::contactRiemannSolvers::hugoniot::hugoniot(const dictionary& dict)
:
    s_(dict.get<scalar>("s"))
{
    if (s_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 's' = " << s_ << " must be >= 0" << exit(FatalIOError);
    }
}


void Foam::contactRiemannSolvers::hugoniot::normalState
(
    const side& L,
    const side& R,
    scalar& vnC,
    scalar& tnC
) const
{
    if (L.vn <= R.vn || s_ == 0)
    {
        acoustic::solve(L, R, vnC, tnC);
        return;
    }

    const scalar mL = L.Lambda*L.rho, mR = R.Lambda*R.rho;
    const scalar ZL = L.rho*L.c, ZR = R.rho*R.c;
    const scalar a = s_*(mR - mL);
    const scalar b = ZL + ZR - 2*s_*(mR*R.vn - mL*L.vn);
    const scalar c0 =
        -(R.tn - L.tn + ZL*L.vn + ZR*R.vn - s_*(mR*sqr(R.vn) - mL*sqr(L.vn)));

    if (mag(a) < 1e-12*mag(b))
    {
        vnC = -c0/b;
    }
    else
    {
        // The root that tends to -c0/b as a -> 0
        vnC = 2*(-c0)/(b + sqrt(max(b*b - 4*a*c0, scalar(0))));
    }
    tnC = L.tn + ZL*(vnC - L.vn) - s_*mL*sqr(vnC - L.vn);
}


// ************************************************************************* //
