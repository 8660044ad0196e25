/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "traction.H"
#include "checkedInput.H"
#include "acousticFormulas.H"
#include "hugoniot.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidBoundaryConditions
{
    defineTypeNameAndDebug(traction, 0);
    addToRunTimeSelectionTable(solidBoundaryCondition, traction, dictionary);
}
}


Foam::solidBoundaryConditions::traction::traction
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    solidBoundaryCondition(dual, patchi, dict)
,
    traction_
    (
        dict.found("traction")
      ? Function1<vector>::New("traction", dict)
      : autoPtr<Function1<vector>>
        (
            new Function1Types::Constant<vector>("traction", Zero)
        )
    )
{
    checkFiniteAtStart(dict, "traction", patchName(), traction_->value(0));
}


Foam::scalar Foam::solidBoundaryConditions::traction::contactState
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
    tC = traction_->value(t);
    vC = acousticFormulas::tractionVelocity(tL, v, tC, n, w.Zp, w.Zs);
    // A Hugoniot body pressed by the traction: the shock relation of its
    // side, t^C = t + Zp dv_n - shockMass dv_n^2 (as at a rigid wall),
    // gives the face's velocity; the acoustic one, dt/Zp, drove the face
    // of A3's material pressed to its shocked stress at 2 c three times
    // too fast, and it folded in the first step
    const scalar dtn = (tC - tL) & n;
    vC +=
    (
        contactRiemannSolvers::hugoniot::rigidShockJump(dtn, w.Zp, w.shockMass)
      - dtn/w.Zp
    )*n;
    return tC & vC;
}


Foam::scalar Foam::solidBoundaryConditions::traction::drivingTractionJump
(
    const UList<fluxState>& q,
    const scalar t
) const
{
    scalar jump = 0;
    if (dict_.found("traction"))
    {
        const vector tbar(traction_->value(t));
        const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi());
        forAll(sf.point, s)
        {
            const scalar a = mag(sf.area[s]);
            if (a > VSMALL)
            {
                const vector N(sf.area[s]/a);
                const vector tL(fluxStress(q[sf.point[s]]) & N);
                jump = max(jump, (tL - tbar) & N);
            }
        }
    }
    return returnReduce(jump, maxOp<scalar>());
}


void Foam::solidBoundaryConditions::traction::describe(Ostream& os) const
{
    os  << "traction " << traction_->value(0) << " (at t = 0)";
}


// ************************************************************************* //
