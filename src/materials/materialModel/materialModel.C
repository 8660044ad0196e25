/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "materialModel.H"
#include "checkedInput.H"

namespace Foam
{
    defineTypeNameAndDebug(materialModel, 0);
    defineRunTimeSelectionTable(materialModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::materialModel::readPositive
(
    const dictionary& dict,
    const word& key,
    const bool allowZero
)
{
    const scalar value = getFinite<scalar>(dict, key);
    if (value < 0 || (!allowZero && value == 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' = " << value << " must be "
            << (allowZero ? ">= 0" : "> 0") << exit(FatalIOError);
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialModel::materialModel
(
    const dictionary& dict,
    const label nPoints
)
:
    dict_(dict),
    rho_(readPositive(dict, "rho")),
    mu_(0),
    tieModulus_(0),
    kappa_(0),
    hugoniot_(dict.found("hugoniot")),
    s_(0)
{
    const bool byE = dict.found("E") || dict.found("nu");
    const bool byKappa = dict.found("kappa") || dict.found("mu");

    if (byE == byKappa)
    {
        FatalIOErrorInFunction(dict)
            << "Give the elastic constants either as 'E' and 'nu' or as"
            << " 'kappa' and 'mu' (one pair, not both)" << exit(FatalIOError);
    }
    if (byE)
    {
        const scalar E = readPositive(dict, "E");
        const scalar nu = getFinite<scalar>(dict, "nu");
        if (nu <= -1 || nu >= 0.5)
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'nu' = " << nu << " must be in (-1, 0.5)"
                << exit(FatalIOError);
        }
        mu_ = E/(2*(1 + nu));
        kappa_ = E/(3*(1 - 2*nu));
    }
    else
    {
        kappa_ = readPositive(dict, "kappa");
        mu_ = readPositive(dict, "mu", true);
    }

    tieModulus_ = max(mu_, 1e-3*kappa_);

    if (hugoniot_)
    {
        if (!dict.isDict("hugoniot"))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'hugoniot' must be a dictionary: hugoniot"
                << " { s 1.5; }" << exit(FatalIOError);
        }
        checkKeywords(dict.subDict("hugoniot"), {"s"});
        s_ = readPositive(dict.subDict("hugoniot"), "s", true);
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::materialModel> Foam::materialModel::New
(
    const dictionary& dict,
    const label nPoints
)
{
    const word modelType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown material type '" << modelType << "'" << nl
            << "Valid types: "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    autoPtr<materialModel> model(cstrIter()(dict, nPoints));
    checkKeywords(dict, model->keywords());
    return model;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::scalarList& Foam::materialModel::epsP() const
{
    static const scalarList empty;
    return empty;
}


void Foam::materialModel::describe(Ostream& os) const
{
    os  << dict_.get<word>("type") << ": rho " << rho_ << ", E " << E()
        << ", nu " << nu() << " (kappa " << kappa_ << ", mu " << mu_
        << "), c_p " << cp() << ", c_s " << cs();
    if (hugoniot_)
    {
        os  << ", Hugoniot pressure in compression, s " << s_;
    }
}


// ************************************************************************* //
