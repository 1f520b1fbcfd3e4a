#include "linearDamper.H"
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
    defineTypeNameAndDebug(linearDamper, 0);
    addToRunTimeSelectionTable(restraint, linearDamper, dictionary);
    addRigidBodyKeywords(restraint, linearDamper, "coeff");
}
}
}


Foam::RBD::restraints::linearDamper::linearDamper
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


void Foam::RBD::restraints::linearDamper::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    const rigidBodyModel::pointMotion pm
    (
        model_.globalPointMotion(bodyID_, Zero, ws)
    );
    addForce(fx, pm.x, -coeff_*pm.v);
}


bool Foam::RBD::restraints::linearDamper::read(const dictionary& dict)
{
    restraint::read(dict);
    coeff_ = readNonNegative(dict, "coeff");
    return true;
}


void Foam::RBD::restraints::linearDamper::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("coeff", coeff_);
}
