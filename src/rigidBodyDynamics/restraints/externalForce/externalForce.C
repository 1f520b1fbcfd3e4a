#include "externalForce.H"
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
    defineTypeNameAndDebug(externalForce, 0);
    addToRunTimeSelectionTable(restraint, externalForce, dictionary);
    addRigidBodyKeywords
    (
        restraint, externalForce, "location", "force", "forceCoeffs"
    );
}
}
}


Foam::RBD::restraints::externalForce::externalForce
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


Foam::RBD::restraints::externalForce::externalForce(const externalForce& ef)
:
    restraint(ef),
    location_(ef.location_),
    force_(ef.force_->clone().ptr())
{}


void Foam::RBD::restraints::externalForce::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace&
) const
{
    addForce(fx, location_, force_->value(state.t()));
}


bool Foam::RBD::restraints::externalForce::read(const dictionary& dict)
{
    restraint::read(dict);
    location_ = dict.get<vector>("location");
    force_ = readFunction1<vector>(dict, "force");
    return true;
}


void Foam::RBD::restraints::externalForce::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("location", location_);
    force_->writeData(os);
}
