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
    restraint(name, dict, model),
    ancestorID_(model.jointAncestor(masterID_))
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
    omega_(pr.omega_->clone().ptr()),
    ancestorID_(pr.ancestorID_)
{}


void Foam::RBD::restraints::prescribedRotation::restrain
(
    scalarField&,
    Field<spatialVector>&,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace&
) const
{
    // No force of its own: the model's forward dynamics applies the moment
    // the prescription takes (prescribe())
}


void Foam::RBD::restraints::prescribedRotation::prescribe
(
    const rigidBodyModelState& state,
    const scalar deltaT,
    rateConstraint& c
) const
{
    const scalar t = state.t();

    c.bodyID = masterID_;
    c.parentID = ancestorID_;
    c.axis = axis_;
    c.rate = axis_ & omega_->value(t);

    if (deltaT > 0)
    {
        // The rate of one step ahead, reached by the end of the step
        c.acceleration =
            ((axis_ & omega_->value(t + deltaT)) - c.rate)/deltaT;
        c.horizon = deltaT;
    }
    else
    {
        // No step to correct within: the prescription's own rate of change
        const scalar h = 1e-6*max(mag(t), 1);
        c.acceleration =
            (axis_ & (omega_->value(t + h) - omega_->value(t - h)))/(2*h);
        c.horizon = VGREAT;
    }
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
