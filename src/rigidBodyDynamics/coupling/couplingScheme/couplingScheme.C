#include "couplingScheme.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(couplingScheme, 0);
    defineRunTimeSelectionTable(couplingScheme, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Read a factor in (0, 1], 1 if absent
Foam::scalar readFactor(const Foam::dictionary& dict, const Foam::word& key)
{
    using namespace Foam;

    const scalar f = dict.getOrDefault<scalar>(key, 1);

    if (!(f > 0 && f <= 1))
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << ' ' << f << " must be in (0, 1]" << nl
            << exit(FatalIOError);
    }

    return f;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingScheme::couplingScheme(const dictionary& dict)
:
    relaxation_(readFactor(dict, "accelerationRelaxation")),
    damping_(readFactor(dict, "accelerationDamping"))
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::RBD::couplingScheme> Foam::RBD::couplingScheme::New
(
    const dictionary& dict,
    const label nDoF
)
{
    const word schemeType
    (
        dict.getOrDefault<word>("accelerationRelaxationType", "constant")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(schemeType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "accelerationRelaxationType",
            schemeType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, nDoF);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::couplingScheme::relax
(
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    correct(aGiven, a, firstSolve);

    forAll(a, i)
    {
        a[i] *= damping_;
    }
}


void Foam::RBD::couplingScheme::write(Ostream& os) const
{
    os.writeEntry("accelerationRelaxationType", type());
    os.writeEntry("accelerationRelaxation", relaxation_);
    os.writeEntry("accelerationDamping", damping_);
}
