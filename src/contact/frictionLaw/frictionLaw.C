/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "frictionLaw.H"
#include "ITstream.H"
#include "FlatOutput.H"

namespace Foam
{
    defineTypeNameAndDebug(frictionLaw, 0);
    defineRunTimeSelectionTable(frictionLaw, dictionary);
}


Foam::autoPtr<Foam::frictionLaw> Foam::frictionLaw::New
(
    const dictionary& dict,
    const string& owner
)
{
    // A number selects Coulomb (k = 0: frictionless slip); a word any
    // other law by its type name
    word lawType("frictionless");
    if (dict.found("friction"))
    {
        ITstream& is = dict.lookup("friction");
        const token tok(is);
        if (tok.isNumber() && tok.number() >= 0)
        {
            lawType = (tok.number() > 0) ? "coulomb" : "frictionless";
        }
        else if
        (
            tok.isWord() && tok.wordToken() != "coulomb"
         && dictionaryConstructorTablePtr_->found(tok.wordToken())
        )
        {
            lawType = tok.wordToken();
        }
        else
        {
            wordList names;
            for (const word& n : dictionaryConstructorTablePtr_->sortedToc())
            {
                if (n != "coulomb")
                {
                    names.append(n);
                }
            }
            FatalIOErrorInFunction(dict)
                << "Keyword 'friction' of " << owner.c_str() << " is "
                << tok << "; allowed: " << flatOutput(names)
                << ", or a Coulomb coefficient >= 0" << exit(FatalIOError);
        }
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);
    return autoPtr<frictionLaw>(cstrIter()(dict));
}


// ************************************************************************* //
