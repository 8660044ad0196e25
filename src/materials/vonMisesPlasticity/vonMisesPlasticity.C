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


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// The elastic strain of a metal stays small however large the plastic
// flow, so ln(I + X) and exp(X) of tensors X of the order of the elastic
// strain are summed as series: 8 and 6 terms within the Frobenius norm
// 0.03 of X (truncation below 0.03^8/9 = 7e-14 and 0.03^7/7! = 4e-15 of
// the result), 16 and 10 terms within 0.12 (1e-16 and 2e-18; soft
// materials, whose yield strain is larger), and the eigen-solve beyond.
// The closed-form eigen-solve (atan2, sincos and the eigenvector kernel)
// was a third of a Taylor bar's run time
const Foam::scalar seriesRadius = 0.03;
const Foam::scalar longSeriesRadius = 0.12;

// a & b for symmetric tensors that commute (polynomials in one tensor):
// the product is symmetric, so six of its nine components
inline Foam::symmTensor commutingProduct
(
    const Foam::symmTensor& a,
    const Foam::symmTensor& b
)
{
    return Foam::symmTensor
    (
        a.xx()*b.xx() + a.xy()*b.xy() + a.xz()*b.xz(),
        a.xx()*b.xy() + a.xy()*b.yy() + a.xz()*b.yz(),
        a.xx()*b.xz() + a.xy()*b.yz() + a.xz()*b.zz(),
        a.xy()*b.xy() + a.yy()*b.yy() + a.yz()*b.yz(),
        a.xy()*b.xz() + a.yy()*b.yz() + a.yz()*b.zz(),
        a.xz()*b.xz() + a.yz()*b.yz() + a.zz()*b.zz()
    );
}

// Apply f to the eigenvalues of a symmetric tensor (the fall-back beyond
// the series' radius)
template<class Function>
Foam::symmTensor spectralFunction(const Foam::symmTensor& t, Function f)
{
    Eigen::Matrix3d m;
    m << t.xx(), t.xy(), t.xz(),
         t.xy(), t.yy(), t.yz(),
         t.xz(), t.yz(), t.zz();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(m);
    Foam::symmTensor result(Foam::Zero);
    for (Foam::direction a = 0; a < 3; ++a)
    {
        const Foam::vector n
        (
            eig.eigenvectors()(0, a),
            eig.eigenvectors()(1, a),
            eig.eigenvectors()(2, a)
        );
        result += f(eig.eigenvalues()(a))*Foam::sqr(n);
    }
    return result;
}

// ln(I + X): X (c1 + X (c2 + ...)), c_k = (-1)^(k+1)/k
Foam::symmTensor logOnePlus(const Foam::symmTensor& X)
{
    const Foam::scalar rho2 = Foam::magSqr(X);
    if (rho2 > Foam::sqr(longSeriesRadius))
    {
        return spectralFunction
        (
            Foam::symmTensor::I + X,
            [](const Foam::scalar lambda){ return Foam::log(lambda); }
        );
    }
    const int n = rho2 > Foam::sqr(seriesRadius) ? 16 : 8;
    Foam::symmTensor q(Foam::symmTensor::I*((n % 2 ? 1.0 : -1.0)/n));
    for (int k = n - 1; k >= 1; --k)
    {
        q = commutingProduct(X, q);
        const Foam::scalar c = (k % 2 ? 1.0 : -1.0)/k;
        q.xx() += c;
        q.yy() += c;
        q.zz() += c;
    }
    return commutingProduct(X, q);
}

// exp(X): I + X (I + X/2 (I + X/3 (...)))
Foam::symmTensor exponential(const Foam::symmTensor& X)
{
    const Foam::scalar rho2 = Foam::magSqr(X);
    if (rho2 > Foam::sqr(longSeriesRadius))
    {
        return spectralFunction
        (
            X,
            [](const Foam::scalar x){ return Foam::exp(x); }
        );
    }
    const int n = rho2 > Foam::sqr(seriesRadius) ? 10 : 6;
    Foam::symmTensor r(Foam::symmTensor::I);
    for (int k = n; k >= 1; --k)
    {
        r = commutingProduct(X, r)/Foam::scalar(k);
        r.xx() += 1;
        r.yy() += 1;
        r.zz() += 1;
    }
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::materialModels::vonMisesPlasticity::returnMap
(
    const tensor& F,
    const scalar J,
    const symmTensor& CpInv,
    const scalar epsP,
    symmTensor& e,
    scalar& dgamma,
    scalar& Jp
) const
{
    // The trial elastic left Cauchy-Green tensor be = Fbar Cp^-1 Fbar^T,
    // Fbar = (J/det F)^1/3 F (F with the conserved volume, so the
    // volumetric part is not locked).  Only its deviatoric logarithm
    // enters the stress, so any multiple of it serves: F Cp^-1 F^T scaled
    // to trace 3, which is I + X with X of the order of the elastic strain
    const symmTensor B(transform(F, CpInv));
    const symmTensor X(B*(3/tr(B)) - symmTensor::I);

    // Deviatoric elastic logarithmic strain e = dev(ln be)/2, the
    // deviatoric Kirchhoff stress tau' = 2 mu e
    e = 0.5*dev(logOnePlus(X));

    const scalar normTrial = 2*mu_*mag(e);
    const scalar f =
        sqrt(1.5)*normTrial - (yieldStress_ + hardening_*epsP);

    dgamma = 0;
    if (f > 0)
    {
        // Radial return: ln lam_a -= dgamma nu_a, nu = tau'/sqrt(2/3
        // tau':tau'), scales e
        dgamma = f/(3*mu_ + hardening_);
        const scalar s = sqrt(2.0/3.0)*normTrial;
        e *= 1 - 2*mu_*dgamma/s;
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
    UList<fluxState>& q,
    const labelUList* points
) const
{
    symmTensor e;
    scalar dgamma, Jp;

    forEachPoint(F.size(), points, [&](const label i)
    __attribute__((always_inline))
    {
        returnMap(F[i], J[i], CpInv_[i], epsP_[i], e, dgamma, Jp);

        // Isochoric (deviatoric Kirchhoff) part through F, pressure from
        // the conserved J: P = tau' F^-T + (U'(J) + tie) cof F.  The
        // J stabilisation uses Sigma_J = dW/dJ (the tie's energy,
        // materialModel.H), so in the elastic range the energy balance is
        // exact, as for the hyperelastic models
        const tensor Finv(inv(F[i]));
        const scalar detF = det(F[i]);
        setFluxStress
        (
            q[i],
            ((2*mu_)*e & Finv.T())
          + (Jp/J[i] + couplingPressure(detF, J[i]))*H[i],
            Jp/J[i] + couplingSigmaJ(detF, J[i])
        );

        // The returned state, for updateState() and energy()
        returnedEnergy_[i] =
            mu_*magSqr(e)
          + volumetricEnergyHencky(J[i])
          + couplingEnergy(detF, J[i]);
        returnedEpsP_[i] = epsP_[i] + dgamma;
        returnedDissipation_[i] = 0;
        if (dgamma > 0)
        {
            // Cp^-1 = Fbar^-1 be Fbar^-T with be = J^2/3 exp(2 e):
            // det(F)^2/3 F^-1 exp(2 e) F^-T
            returnedCpInv_[i] =
                cbrt(sqr(detF))*transform(Finv, exponential(2*e));
            returnedDissipation_[i] = plasticDissipation(dgamma, e);
        }
    });
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
    symmTensor e;
    scalar dgamma, Jp;
    returnMap(F, J, CpInv_[i], epsP_[i], e, dgamma, Jp);
    dD = plasticDissipation(dgamma, e);
    return
        mu_*magSqr(e)
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
    UList<scalar>& dD,
    const labelUList* points
)
{
    // Commit the returned state of the final stress evaluation (of this
    // F): the stress of the state is unchanged by it, since its trial
    // state is now the returned one
    forEachPoint(F.size(), points, [&](const label i)
    __attribute__((always_inline))
    {
        dD[i] = 0;
        if (returnedEpsP_[i] > epsP_[i])
        {
            CpInv_[i] = returnedCpInv_[i];
            epsP_[i] = returnedEpsP_[i];
            dD[i] = returnedDissipation_[i];
        }
    });
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
