#include "prescribedRotation.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(prescribedRotation, 0);
    addToRunTimeSelectionTable(restraint, prescribedRotation, dictionary);
}
}
}


Foam::RBD::restraints::prescribedRotation::prescribedRotation
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


Foam::RBD::restraints::prescribedRotation::prescribedRotation
(
    const prescribedRotation& pr
)
:
    restraint(pr),
    axis_(pr.axis_),
    omega_(pr.omega_->clone().ptr())
{}


void Foam::RBD::restraints::prescribedRotation::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
) const
{
    if (!(state.deltaT() > 0))
    {
        return;
    }

    // Moment of inertia about the axis through the centre of mass
    const tensor E(model_.X0(masterID_, ws).E());
    const vector aBody(E & axis_);
    const scalar Ia = aBody & (model_.bodies()[masterID_].Ic() & aBody);

    const scalar w = axis_ & model_.v(bodyID_, Zero, ws).w();
    const scalar wSet = axis_ & omega_->value(state.t());

    addMoment(fx, Ia*(wSet - w)/state.deltaT()*axis_);
}


bool Foam::RBD::restraints::prescribedRotation::read(const dictionary& dict)
{
    restraint::read(dict);
    axis_ = readAxis(dict, "axis");
    omega_ = Function1<vector>::New("omega", dict);
    return true;
}


void Foam::RBD::restraints::prescribedRotation::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("axis", axis_);
    omega_->writeData(os);
}
