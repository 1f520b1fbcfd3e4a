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

#include "jointPTO.H"
#include "rigidBodyModel.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalarField Foam::RBD::restraints::jointPTO::readPerDoF
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const bool required,
    const bool isSigned
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
        if (!std::isfinite(v) || (!isSigned && v < 0))
        {
            FatalIOErrorInFunction(dict.lookup(key))
                << "Entry " << key << " of restraint " << name_ << ": "
                << values << " must be finite"
                << (isSigned ? "" : " and not negative")
                << nl << exit(FatalIOError);
        }
    }
    return values;
}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::RBD::restraints::jointPTO::readControl(const dictionary& dict)
{
    const word keys[3] = {"latchTime", "declutchTime", "declutchVelocity"};
    scalar* values[3] = {&latchTime_, &declutchTime_, &declutchVelocity_};
    for (label j = 0; j < 3; ++j)
    {
        scalar& v = *values[j];
        if (dict.readIfPresent(keys[j], v) && !(v > 0 && v < GREAT))
        {
            FatalIOErrorInFunction(dict.lookup(keys[j]))
                << "Entry " << keys[j] << " of restraint " << name_ << ": "
                << v << " must be positive and finite" << nl
                << exit(FatalIOError);
        }
    }

    if (dict.found("controller"))
    {
        controller_ = ptoController::New(dict.subDict("controller"));
    }

    if
    (
        latchTime_ > 0 || declutchTime_ > 0 || declutchVelocity_ > 0
     || controller_.valid()
    )
    {
        if (dofs_.size() != 1)
        {
            FatalIOErrorInFunction(dict)
                << "Restraint " << name_ << ": latchTime, declutchTime,"
                << " declutchVelocity and controller need a joint of one"
                << " degree of freedom;"
                << " the joint of body " << model_.name(masterID_) << " has "
                << dofs_.size() << nl << exit(FatalIOError);
        }
        if (latchTime_ > 0 && (declutchTime_ > 0 || declutchVelocity_ > 0))
        {
            FatalIOErrorInFunction(dict.lookup("latchTime"))
                << "Restraint " << name_ << ": give latchTime (latching) or"
                << " declutchTime and declutchVelocity (declutching), not"
                << " both" << nl << exit(FatalIOError);
        }
    }

    // The latch: the joint's velocity held by its own force
    latch_.row[dofs_[0]] = 1;
    latch_.motor[dofs_[0]] = 1;
    latch_.active = false;
}


void Foam::RBD::restraints::jointPTO::control
(
    const scalar qDot,
    const scalar qDotBefore,
    const scalar t,
    const scalar deltaT
)
{
    // A change of sign over the step just committed (a joint released
    // from rest, or from a latch, does not count until it moves)
    const bool reversed = qDotBefore*qDot < 0;

    if (latchTime_ > 0)
    {
        if (latch_.active)
        {
            // Released once it has held for latchTime (to half a step)
            latch_.active = (t - latchStart_ < latchTime_ - 0.5*deltaT);
        }
        else if (reversed)
        {
            latch_.active = true;
            latchStart_ = t;
        }
    }

    if (declutchTime_ > 0 || declutchVelocity_ > 0)
    {
        if (reversed)
        {
            declutchStart_ = t;
        }
        const bool justReversed =
            declutchTime_ > 0
         && t - declutchStart_ < declutchTime_ - 0.5*deltaT;
        declutched_ = justReversed || mag(qDot) < declutchVelocity_;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::jointPTO::jointPTO
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    statefulRestraint(name, dict, model),
    dofs_(model.bodyDoFs(masterID_)),
    committed_(false),
    t0_(-GREAT),
    q0_(dofs_.size(), Zero),
    tau0_(dofs_.size(), Zero),
    powerDoF_(dofs_.size(), Zero),
    power_(0),
    work_(0),
    latchTime_(0),
    latch_(model.nDoF()),
    latchStart_(0),
    declutchTime_(0),
    declutchVelocity_(0),
    declutched_(false),
    declutchStart_(-GREAT),
    qDot0_(0)
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
    readControl(dict);
}


Foam::RBD::restraints::jointPTO::jointPTO(const jointPTO& pto)
:
    statefulRestraint(pto),
    dofs_(pto.dofs_),
    committed_(pto.committed_),
    t0_(pto.t0_),
    q0_(pto.q0_),
    tau0_(pto.tau0_),
    powerDoF_(pto.powerDoF_),
    power_(pto.power_),
    work_(pto.work_),
    latchTime_(pto.latchTime_),
    latch_(pto.latch_),
    latchStart_(pto.latchStart_),
    declutchTime_(pto.declutchTime_),
    declutchVelocity_(pto.declutchVelocity_),
    declutched_(pto.declutched_),
    declutchStart_(pto.declutchStart_),
    qDot0_(pto.qDot0_),
    controller_
    (
        pto.controller_.valid() ? pto.controller_->clone().ptr() : nullptr
    ),
    controlled_(pto.controlled_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::restraints::jointPTO::start
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace&
)
{
    if (controller_.valid() && !committed_)
    {
        const label i = dofs_[0];
        controller_->update
        (
            state.t(), state.deltaT(), state.q()[i], state.qDot()[i],
            controlled_
        );
    }
}


void Foam::RBD::restraints::jointPTO::restrain
(
    scalarField& tau,
    Field<spatialVector>&,
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace&
) const
{
    // Held by the latch's motor, or free
    if (latched() || declutched_)
    {
        return;
    }

    forAll(dofs_, k)
    {
        const label i = dofs_[k];
        tau[i] += force(k, state.q()[i], state.qDot()[i]);
    }
    if (controller_.valid())
    {
        const label i = dofs_[0];
        tau[i] += controlForce(state.q()[i], state.qDot()[i]);
    }
}


void Foam::RBD::restraints::jointPTO::addColumns(tableRow& row) const
{
    if (dofs_.size() == 1)
    {
        row.add(name_ + ".force", tau0_[0]);
    }
    else
    {
        forAll(dofs_, k)
        {
            row.add(name_ + ".force" + Foam::name(dofs_[k]), tau0_[k]);
        }
        forAll(dofs_, k)
        {
            row.add(name_ + ".power" + Foam::name(dofs_[k]), powerDoF_[k]);
        }
    }
    row.add(name_ + ".power", power_);
    row.add(name_ + ".work", work_);
}


void Foam::RBD::restraints::jointPTO::commit
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace&
)
{
    // The same state committed again: nothing to add, and the control
    // already decided
    if (committed_ && state.t() == t0_)
    {
        return;
    }
    t0_ = state.t();

    power_ = 0;
    forAll(dofs_, k)
    {
        const label i = dofs_[k];
        const scalar q = state.q()[i];

        // The force the step's accelerations were computed with: the
        // latch's motor's while it holds, none while free, else the law's
        const scalar f =
            latched() ? latch_.force
          : declutched_ ? 0
          : force(k, q, state.qDot()[i])
          + (controller_.valid() ? controlForce(q, state.qDot()[i]) : 0);

        // The trapezoidal rule over the step since the last commit
        if (committed_)
        {
            work_ -= 0.5*(tau0_[k] + f)*(q - q0_[k]);
        }
        q0_[k] = q;
        tau0_[k] = f;
        powerDoF_[k] = -f*state.qDot()[i];
        power_ += powerDoF_[k];
    }

    // The impulse that caught the joint (once)
    if (latched())
    {
        work_ -= latch_.impulseWork;
        latch_.impulseWork = 0;
    }

    // The next step's control
    const scalar qDot = state.qDot()[dofs_[0]];
    control(qDot, qDot0_, state.t(), state.deltaT());
    qDot0_ = qDot;
    if (controller_.valid())
    {
        controller_->update
        (
            state.t(), state.deltaT(), state.q()[dofs_[0]], qDot, controlled_
        );
    }

    committed_ = true;
}


bool Foam::RBD::restraints::jointPTO::writeState(Ostream& os) const
{
    os.writeEntry("work", work_);
    os.writeEntry("q", q0_);
    os.writeEntry("force", tau0_);
    os.writeEntry("power", power_);
    os.writeEntry("powerDoF", powerDoF_);
    os.writeEntry("t", t0_);
    os.writeEntry("qDot", qDot0_);
    os.writeEntry("latched", latch_.active);
    os.writeEntry("latchStart", latchStart_);
    os.writeEntry("declutched", declutched_);
    os.writeEntry("declutchStart", declutchStart_);
    if (controller_.valid())
    {
        os.writeEntry
        (
            "controlled",
            FixedList<scalar, 4>
            ({
                controlled_.stiffness, controlled_.restPosition,
                controlled_.damping, controlled_.force
            })
        );
    }
    return true;
}


void Foam::RBD::restraints::jointPTO::readState(const dictionary& dict)
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
        scalarField p;
        if (dict.readIfPresent("powerDoF", p) && p.size() == powerDoF_.size())
        {
            powerDoF_ = p;
        }
        dict.readIfPresent("t", t0_);
        dict.readIfPresent("qDot", qDot0_);
        dict.readIfPresent("latched", latch_.active);
        dict.readIfPresent("latchStart", latchStart_);
        dict.readIfPresent("declutched", declutched_);
        dict.readIfPresent("declutchStart", declutchStart_);
        FixedList<scalar, 4> c;
        if (controller_.valid() && dict.readIfPresent("controlled", c))
        {
            controlled_.stiffness = c[0];
            controlled_.restPosition = c[1];
            controlled_.damping = c[2];
            controlled_.force = c[3];
        }
        committed_ = true;
    }
}


void Foam::RBD::restraints::jointPTO::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    report.otherBodyID = model_.jointAncestor(masterID_);
    report.onJoint = true;
}


// ************************************************************************* //
