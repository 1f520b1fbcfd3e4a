#include "Aitken.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(Aitken, 0);
    addToRunTimeSelectionTable(couplingScheme, Aitken, dictionary);
    addRigidBodyKeywords(coupling, Aitken);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::Aitken::Aitken
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model),
    omega_(relaxation_),
    rPrev_(model.nDoF(), Zero)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::Aitken::correct
(
    const rigidBodyModelState&,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    // The products weigh rotations by their lengths squared, as
    // translations: the factor is the same at any Froude scale
    scalar rdr = 0, dr2 = 0;
    forAll(a, i)
    {
        const scalar r = a[i] - aGiven[i];
        const scalar dr = r - rPrev_[i];
        rdr += weight_[i]*rPrev_[i]*dr;
        dr2 += weight_[i]*sqr(dr);
        rPrev_[i] = r;
    }

    if (!firstSolve && dr2 > VSMALL)
    {
        omega_ = min(max(-omega_*rdr/dr2, scalar(0.01)), scalar(1));
    }
    else
    {
        omega_ = min(omega_, relaxation_);
    }

    forAll(a, i)
    {
        a[i] = omega_*a[i] + (1 - omega_)*aGiven[i];
    }
}
