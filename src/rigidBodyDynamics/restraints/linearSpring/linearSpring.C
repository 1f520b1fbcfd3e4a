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

#include "linearSpring.H"
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
    defineTypeNameAndDebug(linearSpring, 0);
    addToRunTimeSelectionTable(restraint, linearSpring, dictionary);
    addRigidBodyKeywords
    (
        restraint, linearSpring, "anchor", "anchorBody", "refAttachmentPt",
        "stiffness", "damping", "restLength"
    );
}
}
}


Foam::RBD::restraints::linearSpring::linearSpring
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    statefulRestraint(name, dict, model),
    committed_(false),
    length0_(0),
    tension0_(0),
    power_(0),
    work_(0)
{
    read(dict);
}


inline Foam::vector Foam::RBD::restraints::linearSpring::force
(
    const vector& r,
    const scalar L,
    const vector& rDot
) const
{
    const vector dir(r/L);
    const scalar LDot = dir & rDot;
    return -(stiffness_*(L - restLength_) + damping_*LDot)*dir;
}


void Foam::RBD::restraints::linearSpring::restrainBetween
(
    Field<spatialVector>& fx,
    const rigidBodyModelWorkspace& ws
) const
{
    const rigidBodyModel::pointMotion pm
    (
        model_.globalPointMotion(bodyID_, refAttachmentPt_, ws)
    );
    const rigidBodyModel::pointMotion am
    (
        model_.globalPointMotion(anchorBodyID_, anchor_, ws)
    );
    const vector r(pm.x - am.x);
    const scalar L = mag(r);

    if (L < VSMALL)
    {
        return;
    }

    const vector F(force(r, L, pm.v - am.v));
    addForce(fx, pm.x, F);
    addReaction(fx, anchorMasterID_, am.x, F);
}


void Foam::RBD::restraints::linearSpring::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    // Between two bodies in a function of its own, so that none of its work
    // (the anchor's motion, the relative velocity, the reaction) and none
    // of the registers it holds fall on a fixed anchor's path, the common
    // one: merged into it they cost a fixed spring 12% more instructions
    // (bench/forwardDynamics/README.md)
    if (anchorBodyID_ >= 0)
    {
        restrainBetween(fx, ws);
        return;
    }

    const rigidBodyModel::pointMotion pm
    (
        model_.globalPointMotion(bodyID_, refAttachmentPt_, ws)
    );
    const vector r(pm.x - anchor_);
    const scalar L = mag(r);

    if (L < VSMALL)
    {
        return;
    }

    addForce(fx, pm.x, force(r, L, pm.v));
}


void Foam::RBD::restraints::linearSpring::length
(
    const rigidBodyModelWorkspace& ws,
    scalar& L,
    scalar& LDot
) const
{
    const rigidBodyModel::pointMotion pm
    (
        model_.globalPointMotion(bodyID_, refAttachmentPt_, ws)
    );
    const rigidBodyModel::pointMotion am
    (
        model_.globalPointMotion(anchorBodyID_, anchor_, ws)
    );
    const vector r(pm.x - am.x);
    L = mag(r);
    LDot = L < VSMALL ? 0 : (r/L) & (pm.v - am.v);
}


void Foam::RBD::restraints::linearSpring::addColumns(tableRow& row) const
{
    if (anchorBodyID_ >= 0)
    {
        row.add(name_ + ".tension", tension0_);
        row.add(name_ + ".power", power_);
        row.add(name_ + ".work", work_);
    }
}


void Foam::RBD::restraints::linearSpring::commit
(
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
)
{
    if (anchorBodyID_ < 0)
    {
        return;
    }

    scalar L, LDot;
    length(ws, L, LDot);
    const scalar T = stiffness_*(L - restLength_) + damping_*LDot;

    // The trapezoidal rule over the step since the last commit
    if (committed_)
    {
        work_ += 0.5*(tension0_ + T)*(L - length0_);
    }
    length0_ = L;
    tension0_ = T;
    power_ = T*LDot;
    committed_ = true;
}


bool Foam::RBD::restraints::linearSpring::writeState(Ostream& os) const
{
    if (anchorBodyID_ < 0)
    {
        return false;
    }
    os.writeEntry("work", work_);
    os.writeEntry("length", length0_);
    os.writeEntry("tension", tension0_);
    os.writeEntry("power", power_);
    return true;
}


void Foam::RBD::restraints::linearSpring::readState(const dictionary& dict)
{
    if
    (
        dict.readIfPresent("work", work_)
     && dict.readIfPresent("length", length0_)
     && dict.readIfPresent("tension", tension0_)
    )
    {
        dict.readIfPresent("power", power_);
        committed_ = true;
    }
}


void Foam::RBD::restraints::linearSpring::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    using constant::mathematical::twoPi;
    report.otherBodyID = anchorBodyID_;
    const scalar m = model_.bodies()[masterID_].m();
    if (stiffness_ > 0)
    {
        report.addPeriod
        (
            "natural",
            "natural period",
            twoPi*sqrt(m/stiffness_)
        );
    }
}


bool Foam::RBD::restraints::linearSpring::read(const dictionary& dict)
{
    statefulRestraint::read(dict);

    anchor_ = dict.get<vector>("anchor");
    anchorBodyID_ = readAnchorBody(dict);
    anchorMasterID_ =
        anchorBodyID_ >= 0 ? model_.masterID(anchorBodyID_) : -1;
    refAttachmentPt_ = dict.get<vector>("refAttachmentPt");
    stiffness_ = readNonNegative(dict, "stiffness");
    damping_ = readNonNegative(dict, "damping");
    restLength_ = readNonNegative(dict, "restLength");

    return true;
}


void Foam::RBD::restraints::linearSpring::write(Ostream& os) const
{
    statefulRestraint::write(os);
    os.writeEntry("anchor", anchor_);
    if (anchorBodyID_ >= 0)
    {
        os.writeEntry("anchorBody", model_.name(anchorBodyID_));
    }
    os.writeEntry("refAttachmentPt", refAttachmentPt_);
    os.writeEntry("stiffness", stiffness_);
    os.writeEntry("damping", damping_);
    os.writeEntry("restLength", restLength_);
}
