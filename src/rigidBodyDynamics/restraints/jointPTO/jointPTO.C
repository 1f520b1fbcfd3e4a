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
    q0_(dofs_.size(), Zero),
    tau0_(dofs_.size(), Zero),
    powerDoF_(dofs_.size(), Zero),
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
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::restraints::jointPTO::restrain
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
        powerDoF_[k] = -f*state.qDot()[i];
        power_ += powerDoF_[k];
    }
    committed_ = true;
}


bool Foam::RBD::restraints::jointPTO::writeState(Ostream& os) const
{
    os.writeEntry("work", work_);
    os.writeEntry("q", q0_);
    os.writeEntry("force", tau0_);
    os.writeEntry("power", power_);
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
