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

#include "linearJointSpring.H"
#include "rigidBodyEntries.H"
#include "restraintReport.H"
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
    defineTypeNameAndDebug(linearJointSpring, 0);
    addToRunTimeSelectionTable(restraint, linearJointSpring, dictionary);
    addRigidBodyKeywords
    (
        restraint, linearJointSpring, "stiffness", "damping", "restPosition",
        "forceLimit",
        "latchTime", "declutchTime", "declutchVelocity", "controller"
    );
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::RBD::restraints::linearJointSpring::force
(
    const label k,
    const scalar q,
    const scalar qDot
) const
{
    const scalar f =
        -stiffness_[k]*(q - restPosition_[k]) - damping_[k]*qDot;
    const scalar limit = forceLimit_[k];
    return limit > 0 ? min(max(f, -limit), limit) : f;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::linearJointSpring::linearJointSpring
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

void Foam::RBD::restraints::linearJointSpring::describe
(
    const rigidBodyModelWorkspace& ws,
    restraintReport& report
) const
{
    jointPTO::describe(ws, report);

    const joint& J = model_.joints()[masterID_];
    if (dofs_.size() != 1 || J.nDoF() != 1 || !(stiffness_[0] > 0))
    {
        return;
    }

    joint::XSvc xsvc;
    const scalarField zero(model_.nDoF(), Zero);
    J.jcalc(xsvc, zero, zero);
    const spatialVector& S = xsvc.S[0];
    const rigidBodyInertia& I = model_.bodies()[masterID_];

    // A rotation's inertia about its axis through the body's origin
    scalar inertia = I.m();
    if (mag(S.w()) > SMALL)
    {
        const vector w(S.w()/mag(S.w()));
        inertia = (w & (I.Ic() & w)) + I.m()*magSqr(w ^ I.c());
    }

    report.addPeriod
    (
        "natural",
        "natural period",
        constant::mathematical::twoPi*sqrt(inertia/stiffness_[0])
    );
}


bool Foam::RBD::restraints::linearJointSpring::read(const dictionary& dict)
{
    restraint::read(dict);

    stiffness_ = readPerDoF(dict, "stiffness", 0, true, false);
    damping_ = readPerDoF(dict, "damping", 0, true, false);
    restPosition_ = readPerDoF(dict, "restPosition", 0, false, true);
    forceLimit_ = readPerDoF(dict, "forceLimit", 0, false, false);

    if (dict.found("forceLimit"))
    {
        for (const scalar l : forceLimit_)
        {
            if (!(l > 0))
            {
                FatalIOErrorInFunction(dict.lookup("forceLimit"))
                    << "Entry forceLimit of restraint " << name_ << ": "
                    << forceLimit_ << " must be positive" << nl
                    << exit(FatalIOError);
            }
        }
    }

    return true;
}


void Foam::RBD::restraints::linearJointSpring::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("stiffness", stiffness_);
    os.writeEntry("damping", damping_);
    os.writeEntry("restPosition", restPosition_);
    if (max(forceLimit_) > 0)
    {
        os.writeEntry("forceLimit", forceLimit_);
    }
}


// ************************************************************************* //
