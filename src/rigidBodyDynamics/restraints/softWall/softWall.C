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

#include "softWall.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(softWall, 0);
    addToRunTimeSelectionTable(restraint, softWall, dictionary);
    addRigidBodyKeywords
    (
        restraint, softWall, "anchor", "wallNormal", "refAttachmentPt", "C",
        "psi"
    );
}
}
}


Foam::RBD::restraints::softWall::softWall
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


void Foam::RBD::restraints::softWall::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    const vector p(model_.globalPoint(bodyID_, refAttachmentPt_, ws));
    const scalar d = wallNormal_ & (p - anchor_);

    if (d < 0)
    {
        const scalar dDot =
            wallNormal_ & model_.v(bodyID_, refAttachmentPt_, ws).l();
        const scalar m = model_.bodies()[masterID_].m();
        const scalar wn = constant::mathematical::pi/C_;

        addForce
        (
            fx,
            p,
            -m*(sqr(wn)*d + 2*psi_*wn*dDot)*wallNormal_
        );
    }
}


void Foam::RBD::restraints::softWall::describe
(
    const rigidBodyModelWorkspace&,
    restraintReport& report
) const
{
    report.addPeriod("natural", "natural period", 2*C_);
}


bool Foam::RBD::restraints::softWall::read(const dictionary& dict)
{
    restraint::read(dict);

    // A wall fixed in space: it has no body to move with
    if (dict.found("anchorBody"))
    {
        FatalIOErrorInFunction(dict.lookup("anchorBody"))
            << "Entry anchorBody of restraint " << name_ << ": a softWall is"
            << " a wall fixed in space, its anchor a global point.  For a"
            << " stop between two bodies use jointEndStop on the joint"
            << " between them (a PTO's stroke)" << nl
            << exit(FatalIOError);
    }

    anchor_ = dict.get<vector>("anchor");
    wallNormal_ = readAxis(dict, "wallNormal");
    refAttachmentPt_ = dict.get<vector>("refAttachmentPt");
    C_ = readPositive(dict, "C");
    psi_ = readNonNegative(dict, "psi");

    if (psi_ >= 1)
    {
        FatalIOErrorInFunction(dict.lookup("psi"))
            << "Entry psi " << psi_ << " (damping ratio) must be below 1"
            << nl << exit(FatalIOError);
    }

    return true;
}


void Foam::RBD::restraints::softWall::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("anchor", anchor_);
    os.writeEntry("wallNormal", wallNormal_);
    os.writeEntry("refAttachmentPt", refAttachmentPt_);
    os.writeEntry("C", C_);
    os.writeEntry("psi", psi_);
}
