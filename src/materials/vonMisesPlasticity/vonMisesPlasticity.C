/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "vonMisesPlasticity.H"
#include "pointFieldIO.H"
#include "addToRunTimeSelectionTable.H"

#include <Eigen/Eigenvalues>

namespace Foam
{
namespace materialModels
{
    defineTypeNameAndDebug(vonMisesPlasticity, 0);
    addToRunTimeSelectionTable(materialModel, vonMisesPlasticity, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::materialModels::vonMisesPlasticity::returnMap
(
    const tensor& F,
    const scalar J,
    const symmTensor& CpInv,
    const scalar epsP,
    vector& lnLam,
    tensor& dirs,
    vector& tauDev,
    scalar& dgamma,
    scalar& Jp,
    tensor& Fbar
) const
{
    // Give F the conserved volume so the volumetric part is not locked
    Fbar = cbrt(J/det(F))*F;
    const symmTensor be(symm(Fbar & CpInv & Fbar.T()));

    Eigen::Matrix3d m;
    m << be.xx(), be.xy(), be.xz(),
         be.xy(), be.yy(), be.yz(),
         be.xz(), be.yz(), be.zz();
    // The closed-form (trigonometric) solution of the symmetric 3x3
    // problem: the iterative QR solver made this function half of a
    // plastic run's time
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(m);

    const scalar lnJ3 = log(J)/3.0;
    for (direction a = 0; a < 3; ++a)
    {
        lnLam[a] = 0.5*log(eig.eigenvalues()(a));
        for (direction k = 0; k < 3; ++k)
        {
            dirs(a, k) = eig.eigenvectors()(k, a);
        }
        tauDev[a] = 2*mu_*(lnLam[a] - lnJ3);
    }

    const scalar normTrial = mag(tauDev);
    const scalar f =
        sqrt(1.5)*normTrial - (yieldStress_ + hardening_*epsP);

    dgamma = 0;
    if (f > 0)
    {
        dgamma = f/(3*mu_ + hardening_);
        const scalar s = sqrt(2.0/3.0)*normTrial;
        for (direction a = 0; a < 3; ++a)
        {
            const scalar nu = tauDev[a]/s;
            lnLam[a] -= dgamma*nu;
        }
        tauDev *= (1 - 2*mu_*dgamma/s);
    }

    Jp = J*volumetricSigmaJHencky(J);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModels::vonMisesPlasticity::vonMisesPlasticity
(
    const dictionary& dict,
    const label nPoints
)
:
    materialModel(dict, nPoints),
    yieldStress_(readPositive(dict, "yieldStress")),
    hardening_(readPositive(dict, "hardening", true)),
    CpInv_(nPoints, symmTensor::I),
    epsP_(nPoints, 0.0),
    returnedCpInv_(nPoints, symmTensor::I),
    returnedEpsP_(nPoints, 0.0),
    returnedDissipation_(nPoints, 0.0),
    returnedEnergy_(nPoints, 0.0)
{
    if (mu_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "vonMisesPlasticity needs a shear modulus mu > 0"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::materialModels::vonMisesPlasticity::stress
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<fluxState>& q
) const
{
    vector lnLam, tauDev;
    tensor dirs, Fbar;
    scalar dgamma, Jp;

    forAll(F, i)
    {
        returnMap
        (
            F[i], J[i], CpInv_[i], epsP_[i],
            lnLam, dirs, tauDev, dgamma, Jp, Fbar
        );

        // Isochoric (deviatoric Kirchhoff) part through F, pressure from
        // the conserved J: P = tau' F^-T + (U'(J) + tie) cof F.  The
        // J stabilisation uses Sigma_J = dW/dJ (the tie's energy,
        // materialModel.H), so in the elastic range the energy balance is
        // exact, as for the hyperelastic models
        tensor tauDevTensor(Zero);
        for (direction a = 0; a < 3; ++a)
        {
            const vector n(dirs.row(a));
            tauDevTensor += tauDev[a]*(n*n);
        }
        const scalar detF = det(F[i]);
        setFluxStress
        (
            q[i],
            (tauDevTensor & inv(F[i]).T())
          + (Jp/J[i] + couplingPressure(detF, J[i]))*H[i],
            Jp/J[i] + couplingSigmaJ(detF, J[i])
        );

        // The returned state, for updateState() and energy()
        const scalar lnJ3 = log(J[i])/3.0;
        returnedEnergy_[i] =
            mu_*(sqr(lnLam[0] - lnJ3) + sqr(lnLam[1] - lnJ3)
               + sqr(lnLam[2] - lnJ3))
          + volumetricEnergyHencky(J[i])
          + couplingEnergy(detF, J[i]);
        returnedEpsP_[i] = epsP_[i] + dgamma;
        returnedDissipation_[i] = 0;
        if (dgamma > 0)
        {
            symmTensor be(Zero);
            for (direction a = 0; a < 3; ++a)
            {
                const vector n(dirs.row(a));
                be += exp(2*lnLam[a])*sqr(n);
            }
            const tensor FbarInv(inv(Fbar));
            returnedCpInv_[i] = symm(FbarInv & be & FbarInv.T());
            returnedDissipation_[i] = dgamma*sqrt(1.5)*mag(tauDev);
        }
    }
}


void Foam::materialModels::vonMisesPlasticity::energy
(
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<scalar>& W
) const
{
    scalar dD;
    forAll(F, i)
    {
        W[i] = trialPointEnergy(i, F[i], J[i], dD);
    }
}


Foam::scalar Foam::materialModels::vonMisesPlasticity::trialPointEnergy
(
    const label i,
    const tensor& F,
    const scalar J,
    scalar& dD
) const
{
    vector lnLam, tauDev;
    tensor dirs, Fbar;
    scalar dgamma, Jp;
    returnMap
    (
        F, J, CpInv_[i], epsP_[i],
        lnLam, dirs, tauDev, dgamma, Jp, Fbar
    );
    dD = dgamma > 0 ? dgamma*sqrt(1.5)*mag(tauDev) : 0;
    const scalar lnJ3 = log(J)/3.0;
    return
        mu_*(sqr(lnLam[0] - lnJ3) + sqr(lnLam[1] - lnJ3)
           + sqr(lnLam[2] - lnJ3))
      + volumetricEnergyHencky(J)
      + couplingEnergy(det(F), J);
}


void Foam::materialModels::vonMisesPlasticity::trialEnergy
(
    const label start,
    const UList<tensor>& F,
    const UList<tensor>& H,
    const UList<scalar>& J,
    UList<scalar>& W,
    UList<scalar>& dD
) const
{
    forAll(F, k)
    {
        W[k] = trialPointEnergy(start + k, F[k], J[k], dD[k]);
    }
}


void Foam::materialModels::vonMisesPlasticity::dissipationOfLastStress
(
    UList<scalar>& dD
) const
{
    forAll(dD, i)
    {
        dD[i] = returnedEpsP_[i] > epsP_[i] ? returnedDissipation_[i] : 0;
    }
}


bool Foam::materialModels::vonMisesPlasticity::energyOfLastStress
(
    UList<scalar>& W
) const
{
    // The returned energy is also the energy of the state once
    // updateState() committed it
    forAll(W, i)
    {
        W[i] = returnedEnergy_[i];
    }
    return true;
}


void Foam::materialModels::vonMisesPlasticity::updateState
(
    const UList<tensor>& F,
    const UList<scalar>& J,
    UList<scalar>& dD
)
{
    // Commit the returned state of the final stress evaluation (of this
    // F): the stress of the state is unchanged by it, since its trial
    // state is now the returned one
    forAll(F, i)
    {
        dD[i] = 0;
        if (returnedEpsP_[i] > epsP_[i])
        {
            CpInv_[i] = returnedCpInv_[i];
            epsP_[i] = returnedEpsP_[i];
            dD[i] = returnedDissipation_[i];
        }
    }
}


void Foam::materialModels::vonMisesPlasticity::readState(const polyMesh& mesh)
{
    readPointField(mesh, "Cpinv", CpInv_);
    readPointField(mesh, "epsP", epsP_);
}


void Foam::materialModels::vonMisesPlasticity::writeState
(
    const polyMesh& mesh
) const
{
    writePointField(mesh, "Cpinv", CpInv_, dimless);
    writePointField(mesh, "epsP", epsP_, dimless);
}


void Foam::materialModels::vonMisesPlasticity::describe(Ostream& os) const
{
    materialModel::describe(os);
    os  << ", yield stress " << yieldStress_ << ", hardening "
        << hardening_;
}


// ************************************************************************* //
