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

Foam::RBD::couplingScheme::couplingScheme
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    model_(model),
    relaxation_(readFactor(dict, "accelerationRelaxation")),
    damping_(readFactor(dict, "accelerationDamping")),
    residual_(0)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::RBD::couplingScheme> Foam::RBD::couplingScheme::New
(
    const dictionary& dict,
    const rigidBodyModel& model
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

    return cstrIter()(dict, model);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::RBD::couplingScheme::relativeSize
(
    const scalar r,
    const scalarField& a,
    const scalarField& aGiven
) const
{
    scalar a2 = 0, g2 = 0;
    forAll(a, i)
    {
        a2 += sqr(a[i]);
        g2 += sqr(aGiven[i]);
    }

    // Relative to the accelerations, or to gravity's where they are
    // smaller (a floating body's accelerations are small and noisy)
    return r/max(max(sqrt(max(a2, g2)), mag(model_.g())), VSMALL);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::couplingScheme::relax
(
    const rigidBodyModelState& state,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    scalar r2 = 0;
    forAll(a, i)
    {
        r2 += sqr(a[i] - aGiven[i]);
    }
    residual_ = relativeSize(sqrt(r2), a, aGiven);

    if (debug)
    {
        Info<< type() << ": given " << aGiven << " new " << a << endl;
    }

    correct(state, aGiven, a, firstSolve);

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
