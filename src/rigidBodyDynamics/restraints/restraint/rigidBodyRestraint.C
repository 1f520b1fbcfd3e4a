#include "rigidBodyRestraint.H"
#include "keywordTable.H"
#include "rigidBodyModel.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(restraint, 0);
    defineRunTimeSelectionTable(restraint, dictionary);
    addRigidBodyCommonKeywords(restraint, Restraint, "type", "body");
}
}


Foam::RBD::restraint::restraint
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    name_(name),
    coeffs_(dict),
    model_(model),
    bodyID_(model.bodyID(dict, "body")),
    masterID_(model.masterID(bodyID_))
{
    if (masterID_ == 0)
    {
        FatalIOErrorInFunction(dict)
            << "Restraint " << name << " acts on body "
            << dict.get<word>("body") << ", which is fixed to the root"
            << nl << exit(FatalIOError);
    }
}


Foam::autoPtr<Foam::RBD::restraint> Foam::RBD::restraint::New
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
{
    const word restraintType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(restraintType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "restraint",
            restraintType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(name, dict, model);
}


void Foam::RBD::restraint::prescribe
(
    const rigidBodyModelState&,
    const scalar,
    rateConstraint&
) const
{
    FatalErrorInFunction
        << "Restraint " << name_ << " of type " << type()
        << " prescribes no motion" << abort(FatalError);
}


bool Foam::RBD::restraint::read(const dictionary& dict)
{
    coeffs_ = dict;
    return true;
}


void Foam::RBD::restraint::write(Ostream& os) const
{
    os.writeEntry("type", type());
    os.writeEntry("body", model_.name(bodyID_));
}


