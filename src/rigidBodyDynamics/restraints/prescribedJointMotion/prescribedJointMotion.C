/*---------------------------------------------------------------------------*\
    Rigid-body dynamics for OpenFOAM v1912
    Copyright (C) the authors of this project (its git history names them)
-------------------------------------------------------------------------------
License
    This file is part of the rigid-body dynamics for OpenFOAM v1912.

    It is free software: you can redistribute it and/or modify it under the
    terms of the GNU General Public License as published by the Free
    Software Foundation, either version 3 of the License, or (at your
    option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT ANY
    WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License along
    with it (the file LICENSE at the top of the project).  If not, see
    <https://www.gnu.org/licenses/>.
\*---------------------------------------------------------------------------*/

#include "prescribedJointMotion.H"
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
    defineTypeNameAndDebug(prescribedJointMotion, 0);
    addToRunTimeSelectionTable(restraint, prescribedJointMotion, dictionary);
    addRigidBodyKeywords
    (
        restraint, prescribedJointMotion, "position", "positionCoeffs"
    );
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::prescribedJointMotion::prescribedJointMotion
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    prescription(name, dict, model),
    dof_(-1),
    positionNow_(0)
{
    read(dict);
}


Foam::RBD::restraints::prescribedJointMotion::prescribedJointMotion
(
    const prescribedJointMotion& pm
)
:
    prescription(pm),
    dof_(pm.dof_),
    position_(pm.position_->clone().ptr()),
    positionNow_(pm.positionNow_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::restraints::prescribedJointMotion::prescribe
(
    const rigidBodyModelState& state,
    const scalar deltaT
)
{
    const scalar t = state.t();
    const Function1<scalar>& f = position_();

    // Central differences: the rate over a thousandth of the step, the
    // acceleration over a hundredth (its round-off grows as 1/h^2)
    const scalar span = deltaT > 0 ? deltaT : 1e-3*max(mag(t), 1);
    const scalar hv = 1e-3*span, ha = 1e-2*span;

    // Position and rate are met at the end of each solve only
    // (rigidBodyModel::constrainState): no correction within it
    positionNow_ = f.value(t);
    rate = (f.value(t + hv) - f.value(t - hv))/(2*hv);
    acceleration =
        (f.value(t + ha) - 2*positionNow_ + f.value(t - ha))/sqr(ha);
    rateGain = 0;
}


void Foam::RBD::restraints::prescribedJointMotion::addMotorColumns
(
    tableRow& row
) const
{
    row.add(name_ + ".force", force);
}


void Foam::RBD::restraints::prescribedJointMotion::writeStatus
(
    const rigidBodyModelState& state,
    const spatialVector&
) const
{
    Info<< "    Prescribed motion " << name_ << ": q "
        << state.q()[dof_] << " (prescribed " << positionNow_ << "), qDot "
        << state.qDot()[dof_] << " (prescribed " << rate
        << "), driving force " << force << endl;
}


void Foam::RBD::restraints::prescribedJointMotion::writeWhat
(
    Ostream& os
) const
{
    os  << "the joint of body " << model_.name(bodyID_);
}


void Foam::RBD::restraints::prescribedJointMotion::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    report.otherBodyID = model_.jointAncestor(masterID_);
    report.onJoint = true;
}


bool Foam::RBD::restraints::prescribedJointMotion::read
(
    const dictionary& dict
)
{
    restraint::read(dict);

    const labelList dofs(model_.bodyDoFs(masterID_));
    if (dofs.size() != 1)
    {
        FatalIOErrorInFunction(dict)
            << "Restraint " << name_ << " (" << type() << ") prescribes the"
            << " joint of body " << dict.get<word>("body") << ", which has "
            << dofs.size() << " degrees of freedom: it drives a joint of"
            << " one (Px, Py, Pz, Pa, Rx, Ry, Rz, Ra)" << nl
            << exit(FatalIOError);
    }
    dof_ = dofs[0];

    // Its row: the degree of freedom's unit row, the motor's too
    row = Zero;
    motor = Zero;
    row[dof_] = 1;
    motor[dof_] = 1;

    position_ = readFunction1<scalar>(dict, "position");
    return true;
}


void Foam::RBD::restraints::prescribedJointMotion::write(Ostream& os) const
{
    restraint::write(os);
    position_->writeData(os);
}


// ************************************************************************* //
