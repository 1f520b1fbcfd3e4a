#include "constant.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(couplingScheme, constant, dictionary);
    addRigidBodyKeywords(coupling, constant);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::constant::constant
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::constant::correct
(
    const rigidBodyModelState&,
    const scalarField& aGiven,
    scalarField& a,
    const bool
)
{
    const scalar omega = relaxation_;

    forAll(a, i)
    {
        a[i] = omega*a[i] + (1 - omega)*aGiven[i];
    }
}
