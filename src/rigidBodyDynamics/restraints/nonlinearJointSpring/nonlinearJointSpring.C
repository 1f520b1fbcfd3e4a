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

#include "nonlinearJointSpring.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(nonlinearJointSpring, 0);
    addToRunTimeSelectionTable(restraint, nonlinearJointSpring, dictionary);
    addRigidBodyKeywords
    (
        restraint, nonlinearJointSpring, "stiffness", "damping",
        "restPosition", "quadraticDamping", "coulombFriction",
        "coulombVelocity", "dampingForce",
        "latchTime", "declutchTime", "declutchVelocity", "controller"
    );
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::RBD::restraints::nonlinearJointSpring::force
(
    const label k,
    const scalar q,
    const scalar qDot
) const
{
    // The linear part first, as linearJointSpring's (the same round-off)
    scalar f = -stiffness_[k]*(q - restPosition_[k]) - damping_[k]*qDot;
    f -= quadraticDamping_[k]*mag(qDot)*qDot;
    f -= coulombFriction_[k]*qDot/max(mag(qDot), coulombVelocity_[k]);
    if (dampingForce_.valid())
    {
        f -= dampingForce_->value(qDot);
    }
    return f;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::nonlinearJointSpring::nonlinearJointSpring
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    jointPTO(name, dict, model)
{
    read(dict);
}


Foam::RBD::restraints::nonlinearJointSpring::nonlinearJointSpring
(
    const nonlinearJointSpring& pto
)
:
    jointPTO(pto),
    stiffness_(pto.stiffness_),
    damping_(pto.damping_),
    restPosition_(pto.restPosition_),
    quadraticDamping_(pto.quadraticDamping_),
    coulombFriction_(pto.coulombFriction_),
    coulombVelocity_(pto.coulombVelocity_),
    dampingForce_
    (
        pto.dampingForce_.valid() ? pto.dampingForce_->clone().ptr() : nullptr
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::RBD::restraints::nonlinearJointSpring::read
(
    const dictionary& dict
)
{
    restraint::read(dict);

    stiffness_ = readPerDoF(dict, "stiffness", 0, false, true);
    damping_ = readPerDoF(dict, "damping", 0, false, true);
    restPosition_ = readPerDoF(dict, "restPosition", 0, false, true);
    quadraticDamping_ = readPerDoF(dict, "quadraticDamping", 0, false, false);
    coulombFriction_ = readPerDoF(dict, "coulombFriction", 0, false, false);
    coulombVelocity_ = readPerDoF(dict, "coulombVelocity", 1e-3, false, false);
    dampingForce_.clear();
    if (dict.found("dampingForce"))
    {
        dampingForce_ = readFunction1<scalar>(dict, "dampingForce");
    }

    for (const scalar v : coulombVelocity_)
    {
        if (!(v > 0))
        {
            FatalIOErrorInFunction(dict.lookup("coulombVelocity"))
                << "Entry coulombVelocity of restraint " << name_ << ": "
                << coulombVelocity_ << " must be positive" << nl
                << exit(FatalIOError);
        }
    }

    // Reactive control: accepted, and said once
    for (const word key : {"stiffness", "damping"})
    {
        const scalarField& values =
            key == "stiffness" ? stiffness_ : damping_;
        if (min(values) < 0)
        {
            WarningInFunction
                << "Restraint " << name_ << " has a negative " << key
                << " " << values << ": it feeds energy into the motion"
                << " (reactive control)" << endl;
        }
    }

    return true;
}


void Foam::RBD::restraints::nonlinearJointSpring::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("stiffness", stiffness_);
    os.writeEntry("damping", damping_);
    os.writeEntry("restPosition", restPosition_);
    os.writeEntry("quadraticDamping", quadraticDamping_);
    os.writeEntry("coulombFriction", coulombFriction_);
    os.writeEntry("coulombVelocity", coulombVelocity_);
    if (dampingForce_.valid())
    {
        dampingForce_->writeData(os);
    }
}


// ************************************************************************* //
