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
        "forceLimit"
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


Foam::scalarField Foam::RBD::restraints::linearJointSpring::readPerDoF
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const bool required
) const
{
    const label n = dofs_.size();
    if (!dict.found(key))
    {
        if (required)
        {
            // OpenFOAM's message for the missing entry
            dict.get<scalar>(key);
        }
        return scalarField(n, deflt);
    }

    // One number for every degree of freedom, or a list of one each
    scalarField values;
    if (dict.lookup(key)[0].isNumber())
    {
        values = scalarField(n, dict.get<scalar>(key));
    }
    else
    {
        values = dict.get<scalarField>(key);
    }

    if (values.size() != n)
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << " of restraint " << name_ << " has "
            << values.size() << " values; the joint of body "
            << model_.name(masterID_) << " has " << n << " degrees of"
            << " freedom: give one number, or " << n << nl
            << exit(FatalIOError);
    }
    for (const scalar v : values)
    {
        if (!std::isfinite(v) || (key != "restPosition" && v < 0))
        {
            FatalIOErrorInFunction(dict.lookup(key))
                << "Entry " << key << " of restraint " << name_ << ": "
                << values << " must be finite"
                << (key != "restPosition" ? " and not negative" : "")
                << nl << exit(FatalIOError);
        }
    }
    return values;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::linearJointSpring::linearJointSpring
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    statefulRestraint(name, dict, model),
    dofs_(model.bodyDoFs(masterID_)),
    committed_(false),
    q0_(dofs_.size(), Zero),
    tau0_(dofs_.size(), Zero),
    power_(0),
    work_(0)
{
    // A quaternion's components are no angles
    const label ancestor = model.jointAncestor(masterID_);
    for (label i = masterID_; i != ancestor; i = model.lambda()[i])
    {
        if (model.joints()[i].unitQuaternion())
        {
            FatalIOErrorInFunction(dict)
                << "Restraint " << name << " acts on the joint of body "
                << model.name(masterID_) << ", whose q holds a quaternion"
                << " (" << model.joints()[i].type() << "): its degrees of"
                << " freedom are no angles.  Use a joint of angles (Rx,"
                << " Ry, Rz, Rxyz, Ryxz, Rzyx) or of translations" << nl
                << exit(FatalIOError);
        }
    }
    if (dofs_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Restraint " << name << ": the joint of body "
            << model.name(masterID_) << " has no degree of freedom" << nl
            << exit(FatalIOError);
    }

    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::restraints::linearJointSpring::restrain
(
    scalarField& tau,
    Field<spatialVector>&,
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace&
) const
{
    forAll(dofs_, k)
    {
        const label i = dofs_[k];
        tau[i] += force(k, state.q()[i], state.qDot()[i]);
    }
}


void Foam::RBD::restraints::linearJointSpring::addColumns
(
    tableRow& row
) const
{
    row.add(name_ + ".power", power_);
    row.add(name_ + ".work", work_);
}


void Foam::RBD::restraints::linearJointSpring::commit
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace&
)
{
    power_ = 0;
    forAll(dofs_, k)
    {
        const label i = dofs_[k];
        const scalar q = state.q()[i];
        const scalar f = force(k, q, state.qDot()[i]);

        // The trapezoidal rule over the step since the last commit
        if (committed_)
        {
            work_ -= 0.5*(tau0_[k] + f)*(q - q0_[k]);
        }
        q0_[k] = q;
        tau0_[k] = f;
        power_ -= f*state.qDot()[i];
    }
    committed_ = true;
}


bool Foam::RBD::restraints::linearJointSpring::writeState(Ostream& os) const
{
    os.writeEntry("work", work_);
    os.writeEntry("q", q0_);
    os.writeEntry("force", tau0_);
    os.writeEntry("power", power_);
    return true;
}


void Foam::RBD::restraints::linearJointSpring::readState
(
    const dictionary& dict
)
{
    scalarField q, f;
    if
    (
        dict.readIfPresent("work", work_)
     && dict.readIfPresent("q", q) && q.size() == q0_.size()
     && dict.readIfPresent("force", f) && f.size() == tau0_.size()
    )
    {
        q0_ = q;
        tau0_ = f;
        dict.readIfPresent("power", power_);
        committed_ = true;
    }
}


void Foam::RBD::restraints::linearJointSpring::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    report.otherBodyID = model_.jointAncestor(masterID_);
    report.onJoint = true;

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

    stiffness_ = readPerDoF(dict, "stiffness", 0, true);
    damping_ = readPerDoF(dict, "damping", 0, true);
    restPosition_ = readPerDoF(dict, "restPosition", 0, false);
    forceLimit_ = readPerDoF(dict, "forceLimit", 0, false);

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
