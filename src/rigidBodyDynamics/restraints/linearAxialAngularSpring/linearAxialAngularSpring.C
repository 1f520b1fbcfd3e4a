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

#include "linearAxialAngularSpring.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(linearAxialAngularSpring, 0);
    addToRunTimeSelectionTable(restraint, linearAxialAngularSpring, dictionary);
    addRigidBodyKeywords
    (
        restraint, linearAxialAngularSpring, "referenceOrientation", "axis",
        "stiffness", "damping"
    );
}
}
}


Foam::RBD::restraints::linearAxialAngularSpring::linearAxialAngularSpring
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


void Foam::RBD::restraints::linearAxialAngularSpring::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    // Rotation taking the body from its reference orientation to now
    const tensor R(model_.X0(bodyID_, ws).E().T() & refQ_);

    // Angle turned about the axis: that of the turned normal vector
    const vector turned(R & perp_);
    const scalar theta =
        atan2(axis_ & (perp_ ^ turned), perp_ & turned);

    const scalar omega = axis_ & model_.v(bodyID_, Zero, ws).w();

    addMoment(fx, -(stiffness_*theta + damping_*omega)*axis_);
}


void Foam::RBD::restraints::linearAxialAngularSpring::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    using constant::mathematical::twoPi;
    const scalar I = axis_ & (model_.bodies()[masterID_].Ic() & axis_);
    if (stiffness_ > 0)
    {
        report.addPeriod
        (
            "natural",
            "natural period",
            twoPi*sqrt(I/stiffness_)
        );
    }
}


bool Foam::RBD::restraints::linearAxialAngularSpring::read
(
    const dictionary& dict
)
{
    restraint::read(dict);

    refQ_ = checkRotation
    (
        dict,
        "referenceOrientation",
        dict.getOrDefault<tensor>("referenceOrientation", tensor::I)
    );

    axis_ = readAxis(dict, "axis");

    // Any unit vector normal to the axis
    const vector trial(mag(axis_.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0));
    perp_ = trial - (trial & axis_)*axis_;
    perp_ /= mag(perp_);

    stiffness_ = readNonNegative(dict, "stiffness");
    damping_ = readNonNegative(dict, "damping");

    return true;
}


void Foam::RBD::restraints::linearAxialAngularSpring::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("referenceOrientation", refQ_);
    os.writeEntry("axis", axis_);
    os.writeEntry("stiffness", stiffness_);
    os.writeEntry("damping", damping_);
}
