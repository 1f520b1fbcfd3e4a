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
    restraint(name, dict, model)
{
    read(dict);
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
    restraint::read(dict);
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
    restraint::write(os);
    os.writeEntry("coeff", coeff_);
    os.writeEntry("refAttachmentPt", refAttachmentPt_);
    if (anchorBodyID_ >= 0)
    {
        os.writeEntry("anchorBody", model_.name(anchorBodyID_));
    }
}
