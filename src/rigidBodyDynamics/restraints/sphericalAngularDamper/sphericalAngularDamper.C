#include "sphericalAngularDamper.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(sphericalAngularDamper, 0);
    addToRunTimeSelectionTable(restraint, sphericalAngularDamper, dictionary);
    addRigidBodyKeywords(restraint, sphericalAngularDamper, "coeff");
}
}
}


Foam::RBD::restraints::sphericalAngularDamper::sphericalAngularDamper
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    restraint(name, dict, model)
{
    read(dict);
}


void Foam::RBD::restraints::sphericalAngularDamper::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    addMoment(fx, -coeff_*model_.v(bodyID_, Zero, ws).w());
}


bool Foam::RBD::restraints::sphericalAngularDamper::read
(
    const dictionary& dict
)
{
    restraint::read(dict);
    coeff_ = readNonNegative(dict, "coeff");
    return true;
}


void Foam::RBD::restraints::sphericalAngularDamper::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("coeff", coeff_);
}
