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

#include "linearDamper.H"
#include "rigidBodyEntries.H"
#include "restraintReport.H"
#include "rigidBodyModel.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(linearDamper, 0);
    addToRunTimeSelectionTable(restraint, linearDamper, dictionary);
    addRigidBodyKeywords
    (
        restraint, linearDamper, "coeff", "refAttachmentPt", "anchorBody"
    );
}
}
}


Foam::RBD::restraints::linearDamper::linearDamper
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    statefulRestraint(name, dict, model),
    committed_(false),
    t0_(0),
    force0_(Zero),
    power_(0),
    work_(0)
{
    read(dict);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::RBD::restraints::linearDamper::forceBetween
(
    const rigidBodyModelWorkspace& ws
) const
{
    const rigidBodyModel::pointMotion pm
    (
        model_.globalPointMotion(bodyID_, refAttachmentPt_, ws)
    );
    const vector local(model_.X0(anchorBodyID_, ws).transformPoint(pm.x));
    return
        -coeff_
       *(pm.v - model_.globalPointMotion(anchorBodyID_, local, ws).v);
}


void Foam::RBD::restraints::linearDamper::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    const rigidBodyModel::pointMotion pm
    (
        model_.globalPointMotion(bodyID_, refAttachmentPt_, ws)
    );

    if (anchorBodyID_ < 0)
    {
        addForce(fx, pm.x, -coeff_*pm.v);
        return;
    }

    // The anchor body's point at the same place
    const vector local(model_.X0(anchorBodyID_, ws).transformPoint(pm.x));
    const rigidBodyModel::pointMotion am
    (
        model_.globalPointMotion(anchorBodyID_, local, ws)
    );
    const vector F(-coeff_*(pm.v - am.v));
    addForce(fx, pm.x, F);
    addReaction(fx, anchorMasterID_, pm.x, F);
}


void Foam::RBD::restraints::linearDamper::addColumns(tableRow& row) const
{
    if (anchorBodyID_ >= 0)
    {
        row.add(name_ + ".force", force0_);
        row.add(name_ + ".power", power_);
        row.add(name_ + ".work", work_);
    }
}


void Foam::RBD::restraints::linearDamper::commit
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
)
{
    if (anchorBodyID_ < 0)
    {
        return;
    }

    // Its power: -F.(v - vAnchor) = |F|^2/coeff
    const vector F(forceBetween(ws));
    const scalar P = coeff_ > 0 ? magSqr(F)/coeff_ : 0;

    // The trapezoidal rule over the step since the last commit, over its
    // deltaT (not the difference of the times, whose round-off differs
    // between a run and its restart)
    if (committed_ && state.t() != t0_)
    {
        work_ += 0.5*(power_ + P)*state.deltaT();
    }
    t0_ = state.t();
    force0_ = F;
    power_ = P;
    committed_ = true;
}


bool Foam::RBD::restraints::linearDamper::writeState(Ostream& os) const
{
    if (anchorBodyID_ < 0)
    {
        return false;
    }
    os.writeEntry("work", work_);
    os.writeEntry("t", t0_);
    os.writeEntry("force", force0_);
    os.writeEntry("power", power_);
    return true;
}


void Foam::RBD::restraints::linearDamper::readState(const dictionary& dict)
{
    if
    (
        dict.readIfPresent("work", work_)
     && dict.readIfPresent("t", t0_)
     && dict.readIfPresent("power", power_)
    )
    {
        dict.readIfPresent("force", force0_);
        committed_ = true;
    }
}


void Foam::RBD::restraints::linearDamper::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    report.otherBodyID = anchorBodyID_;
}


bool Foam::RBD::restraints::linearDamper::read(const dictionary& dict)
{
    statefulRestraint::read(dict);
    coeff_ = readNonNegative(dict, "coeff");
    refAttachmentPt_ =
        dict.getOrDefault<vector>("refAttachmentPt", Zero);

    anchorBodyID_ = readAnchorBody(dict);
    anchorMasterID_ =
        anchorBodyID_ >= 0 ? model_.masterID(anchorBodyID_) : -1;
    return true;
}


void Foam::RBD::restraints::linearDamper::write(Ostream& os) const
{
    statefulRestraint::write(os);
    os.writeEntry("coeff", coeff_);
    os.writeEntry("refAttachmentPt", refAttachmentPt_);
    if (anchorBodyID_ >= 0)
    {
        os.writeEntry("anchorBody", model_.name(anchorBodyID_));
    }
}
