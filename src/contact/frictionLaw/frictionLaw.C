/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"
#include "ITstream.H"

Foam::frictionLaw::frictionLaw(const dictionary& dict, const string& owner)
:
    model_(model::frictionless),
    k_(0)
{
    if (!dict.found("friction"))
    {
        return;
    }
    ITstream& is = dict.lookup("friction");
    const token tok(is);
    if (tok.isWord() && tok.wordToken() == "frictionless")
    {
        model_ = model::frictionless;
    }
    else if (tok.isWord() && tok.wordToken() == "stick")
    {
        model_ = model::stick;
    }
    else if (tok.isNumber() && tok.number() >= 0)
    {
        k_ = tok.number();
        model_ = (k_ > 0) ? model::coulomb : model::frictionless;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'friction' of " << owner.c_str() << " is " << tok
            << "; allowed: frictionless, stick, or a Coulomb coefficient >= 0"
            << exit(FatalIOError);
    }
}


Foam::vector Foam::frictionLaw::tangentialTraction
(
    const vector& ttStick,
    const scalar tn,
    bool& stick
) const
{
    switch (model_)
    {
        case model::stick:
        {
            stick = true;
            return ttStick;
        }
        case model::coulomb:
        {
            const scalar limit = -k_*tn;
            stick = (mag(ttStick) <= limit);
            return stick ? ttStick : (limit/mag(ttStick))*ttStick;
        }
        default:
        {
            stick = false;
            return Zero;
        }
    }
}


void Foam::frictionLaw::describe(Ostream& os) const
{
    switch (model_)
    {
        case model::frictionless: os << "frictionless"; break;
        case model::stick: os << "stick"; break;
        case model::coulomb: os << "Coulomb k = " << k_; break;
    }
}


// ************************************************************************* //
