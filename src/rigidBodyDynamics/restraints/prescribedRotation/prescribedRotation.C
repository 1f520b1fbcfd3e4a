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

#include "prescribedRotation.H"
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
    defineTypeNameAndDebug(prescribedRotation, 0);
    addToRunTimeSelectionTable(restraint, prescribedRotation, dictionary);
    addRigidBodyKeywords
    (
        restraint, prescribedRotation, "axis", "omega", "omegaCoeffs"
    );
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
    prescription(name, dict, model),
    ancestorID_(model.jointAncestor(masterID_))
{
    read(dict);
}


Foam::RBD::restraints::prescribedRotation::prescribedRotation
(
    const prescribedRotation& pr
)
:
    prescription(pr),
    axis_(pr.axis_),
    omega_(pr.omega_->clone().ptr()),
    ancestorID_(pr.ancestorID_)
{}


void Foam::RBD::restraints::prescribedRotation::prescribe
(
    const rigidBodyModelState& state,
    const scalar deltaT
)
{
    const scalar t = state.t();

    rate = axis_ & omega_->value(t);

    if (deltaT > 0)
    {
        // The rate of one step ahead, reached by the end of the step
        acceleration = ((axis_ & omega_->value(t + deltaT)) - rate)/deltaT;
        rateGain = 1/deltaT;
    }
    else
    {
        // No step to correct within: the prescription's own rate of change
        const scalar h = 1e-6*max(mag(t), 1);
        acceleration =
            (axis_ & (omega_->value(t + h) - omega_->value(t - h)))/(2*h);
        rateGain = 0;
    }
}


void Foam::RBD::restraints::prescribedRotation::linearise
(
    const rigidBodyModel& model,
    const rigidBodyModelWorkspace& ws
)
{
    model.angularRow(masterID_, ancestorID_, axis_, ws, *this);
}


void Foam::RBD::restraints::prescribedRotation::addMotorForce
(
    scalarField&,
    Field<spatialVector>& fx
) const
{
    const vector M(force*axis_);
    fx[masterID_] += spatialVector(M, Zero);
    fx[ancestorID_] -= spatialVector(M, Zero);
}


void Foam::RBD::restraints::prescribedRotation::writeStatus
(
    const rigidBodyModelState&,
    const spatialVector& v
) const
{
    Info<< "    Prescribed rotation " << name_ << ": omega "
        << (axis_ & v.w()) << " rad/s about " << axis_
        << " (prescribed " << rate << "), motor moment "
        << force << " N m" << endl;
}


void Foam::RBD::restraints::prescribedRotation::checkMotor
(
    const rigidBodyModelWorkspace& ws,
    const scalar response,
    const dictionary& dict
) const
{
    // The motor's response, against that of the body on its own
    const rigidBodyInertia& body = model_.bodies()[masterID_];
    const vector e(model_.X0(masterID_, ws).E() & axis_);
    const scalar Ia = e & (body.Ic() & e);

    if (!(response > 1e-9/max(Ia, VSMALL)))
    {
        const joint& J = model_.joints()[masterID_];
        FatalIOErrorInFunction(dict)
            << "Restraint " << name_ << " (" << type()
            << ") prescribes the rotation of body "
            << model_.name(bodyID_) << " about " << axis_
            << ", but its joint (" << J.type() << ") does not turn it"
            << " about that axis relative to "
            << model_.bodies()[ancestorID_].name() << "." << nl
            << "Give the body a joint that does (for an axis along a"
            << " coordinate axis, e.g. Rx, Ry or Rz; for any axis, Ra"
            << " with that axis, or Rs), or prescribe another axis."
            << nl << exit(FatalIOError);
    }
}


void Foam::RBD::restraints::prescribedRotation::writeWhat(Ostream& os) const
{
    os  << "the rotation of body " << model_.name(bodyID_) << " about "
        << axis_;
}


bool Foam::RBD::restraints::prescribedRotation::read(const dictionary& dict)
{
    restraint::read(dict);
    axis_ = readAxis(dict, "axis");
    omega_ = readFunction1<vector>(dict, "omega");
    return true;
}


void Foam::RBD::restraints::prescribedRotation::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("axis", axis_);
    omega_->writeData(os);
}
