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

#include "jointEndStop.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(jointEndStop, 0);
    addToRunTimeSelectionTable(restraint, jointEndStop, dictionary);
    addRigidBodyKeywords
    (
        restraint, jointEndStop, "minimum", "maximum", "stiffness", "damping"
    );
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::RBD::restraints::jointEndStop::force
(
    const label k,
    const scalar q,
    const scalar qDot
) const
{
    // The distance past the limit, d, and the spring's force's size there
    const scalar d =
        q > maximum_[k] ? q - maximum_[k]
      : q < minimum_[k] ? q - minimum_[k]
      : 0;
    const scalar spring = stiffness_[k]*mag(d);

    // The damper's force no larger than the spring's: the force is 0 at
    // the limit (continuous, so the step's last evaluation and its end
    // agree) and never pulls
    const scalar damper = max(min(damping_[k]*qDot, spring), -spring);
    return d == 0 ? 0 : -stiffness_[k]*d - damper;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::jointEndStop::jointEndStop
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::RBD::restraints::jointEndStop::read(const dictionary& dict)
{
    restraint::read(dict);

    minimum_ = readPerDoF(dict, "minimum", 0, true, true);
    maximum_ = readPerDoF(dict, "maximum", 0, true, true);
    stiffness_ = readPerDoF(dict, "stiffness", 0, true, false);
    damping_ = readPerDoF(dict, "damping", 0, false, false);

    forAll(minimum_, k)
    {
        if (!(maximum_[k] > minimum_[k]))
        {
            FatalIOErrorInFunction(dict.lookup("maximum"))
                << "Entry maximum of restraint " << name_ << ": "
                << maximum_ << " must be above minimum " << minimum_ << nl
                << exit(FatalIOError);
        }
        if (!(stiffness_[k] > 0))
        {
            FatalIOErrorInFunction(dict.lookup("stiffness"))
                << "Entry stiffness of restraint " << name_ << ": "
                << stiffness_ << " must be positive" << nl
                << exit(FatalIOError);
        }
    }

    return true;
}


void Foam::RBD::restraints::jointEndStop::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("minimum", minimum_);
    os.writeEntry("maximum", maximum_);
    os.writeEntry("stiffness", stiffness_);
    os.writeEntry("damping", damping_);
}


// ************************************************************************* //
