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
-------------------------------------------------------------------------------
    catenaryLine: a quasi-static mooring line (catenaryLine.H)
\*---------------------------------------------------------------------------*/

#include "catenaryLine.H"
#include "rigidBodyModel.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"
#include "unitConversion.H"
#include "vtkPolyline.H"
#include "Switch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(catenaryLine, 0);

    addToRunTimeSelectionTable
    (
        restraint,
        catenaryLine,
        dictionary
    );
    addRigidBodyKeywords
    (
        restraint, catenaryLine, "length", "wetWeight", "EA", "seabedFriction",
        "writeShape", "nShapePoints", "anchor", "refAttachmentPt", "seabed"
    );
}
}
}


namespace
{
    // The line's properties from the dictionary (checked by read())
    Foam::RBD::elasticCatenary::properties lineProperties
    (
        const Foam::dictionary& dict
    )
    {
        using namespace Foam;
        RBD::elasticCatenary::properties p;
        p.L = RBD::readPositive(dict, "length");
        p.w = RBD::readNonNegative(dict, "wetWeight");
        p.EA = RBD::readPositive(dict, "EA");
        p.CB =
            dict.found("seabedFriction")
          ? RBD::readNonNegative(dict, "seabedFriction")
          : 0;
        p.grounded = false;
        return p;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::RBD::restraints::catenaryLine::up() const
{
    const vector& g = model_.g();
    const scalar magG = mag(g);
    return magG > VSMALL ? -g/magG : vector(0, 0, 1);
}


Foam::vector Foam::RBD::restraints::catenaryLine::solve
(
    elasticCatenary& c,
    const vector& p,
    vector& across
) const
{
    up_ = up();
    const elasticCatenary::properties& lp = c.props();

    if (hasSeabed_ && (p & up_) < seabed_ - 1e-6*lp.L)
    {
        FatalIOErrorInFunction(coeffs_)
            << "catenaryLine " << name_ << ": the fairlead (refAttachmentPt "
            << refAttachmentPt_ << ", at " << p << ") is below the seabed "
            << seabed_ << " by " << seabed_ - (p & up_) << " m"
            << nl << exit(FatalIOError);
    }

    const vector r(p - anchor_);
    const scalar h = r & up_;
    const vector horizontal(r - h*up_);
    const scalar l = mag(horizontal);

    if (l > VSMALL)
    {
        across = horizontal/l;
    }

    if (!c.solve(l, h))
    {
        FatalIOErrorInFunction(coeffs_)
            << "catenaryLine " << name_ << ": no catenary found for the"
            << " fairlead " << l << " m from the anchor horizontally and "
            << h << " m above it (length " << lp.L << ", wetWeight " << lp.w
            << ", EA " << lp.EA << ")" << nl << exit(FatalIOError);
    }

    if
    (
        hasSeabed_ && !lp.grounded
     && (anchor_ & up_) + c.lowestHeight() < seabed_ - 1e-6*lp.L
    )
    {
        FatalIOErrorInFunction(coeffs_)
            << "catenaryLine " << name_ << ": the line hangs from an anchor"
            << " above the seabed " << seabed_ << " down to "
            << (anchor_ & up_) + c.lowestHeight() << ", below it: a"
            << " line resting on the seabed between two raised ends is not"
            << " modelled.  Put the anchor on the seabed (its height "
            << seabed_ << "), or shorten the line" << nl
            << exit(FatalIOError);
    }

    return -c.H()*across - c.V()*up_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::catenaryLine::catenaryLine
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    statefulRestraint(name, dict, model),
    anchor_(Zero),
    refAttachmentPt_(Zero),
    hasSeabed_(false),
    seabed_(0),
    line_(lineProperties(dict)),
    writeShape_(true),
    nShapePoints_(51),
    fairlead_(Zero),
    across_(1, 0, 0),
    up_(0, 0, 1),
    committed_(line_)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::RBD::restraints::catenaryLine::shapePoint
(
    const scalar s
) const
{
    const elasticCatenary::point pt(line_.shape(s));
    return anchor_ + pt.x*across_ + pt.z*up_;
}


void Foam::RBD::restraints::catenaryLine::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    fairlead_ = model_.globalPoint(bodyID_, refAttachmentPt_, ws);
    addForce(fx, fairlead_, solve(line_, fairlead_, across_));
}


void Foam::RBD::restraints::catenaryLine::start
(
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
)
{
    // From the line's own start, as its first trial solves it
    const vector p(model_.globalPoint(bodyID_, refAttachmentPt_, ws));
    committed_ = line_;
    vector across(across_);
    solve(committed_, p, across);
}


void Foam::RBD::restraints::catenaryLine::commit
(
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
)
{
    // The latest solve is the committed one if it was for this fairlead;
    // else the line is solved for it from there (the trial left as it is)
    const vector p(model_.globalPoint(bodyID_, refAttachmentPt_, ws));
    if (p == fairlead_)
    {
        committed_ = line_;
        return;
    }
    committed_ = line_;
    vector across(across_);
    solve(committed_, p, across);
}


void Foam::RBD::restraints::catenaryLine::describe
(
    const rigidBodyModelWorkspace& ws,
    restraintReport& report
) const
{
    // Its latest solve (the warm start) solved again for the fairlead
    elasticCatenary c(line_);
    const vector up(this->up());
    report.line = true;
    report.fairlead = model_.globalPoint(bodyID_, refAttachmentPt_, ws);
    report.force = c.fairleadForce(anchor_, report.fairlead, up);
    report.tension = c.tension();
    report.H = c.H();
    report.V = c.V();
    report.groundedLength = c.groundedLength();
    report.forceGradient =
        c.fairleadForceGradient(anchor_, report.fairlead, up);
}


Foam::vector Foam::RBD::restraints::catenaryLine::force() const
{
    return -line_.H()*across_ - line_.V()*up_;
}


Foam::tensor Foam::RBD::restraints::catenaryLine::forceGradient() const
{
    return line_.fairleadForceGradient(anchor_, fairlead_, up_);
}


void Foam::RBD::restraints::catenaryLine::addColumns(tableRow& row) const
{
    row.add(name_ + ".tension", committed_.tension());
    row.add(name_ + ".groundedLength", committed_.groundedLength());
    row.add
    (
        name_ + ".fairleadAngle",
        radToDeg(atan2(committed_.V(), committed_.H()))
    );
}


void Foam::RBD::restraints::catenaryLine::writeOutput
(
    const fileName& dir,
    const scalar t
) const
{
    if (!writeShape_)
    {
        return;
    }
    const label n = nShapePoints_;
    const scalar L = line_.props().L;
    vectorField points(n);
    scalarField tension(n);
    for (label i = 0; i < n; ++i)
    {
        points[i] = shapePoint(L*i/(n - 1));
        tension[i] = line_.shape(L*i/(n - 1)).T;
    }
    writeVtkPolyline
    (
        dir/name_ + ".vtk",
        "catenaryLine " + name_ + " at t = " + Foam::name(t),
        points,
        "tension",
        tension
    );
}


bool Foam::RBD::restraints::catenaryLine::read(const dictionary& dict)
{
    restraint::read(dict);

    writeShape_ = dict.getOrDefault<Switch>("writeShape", true);
    nShapePoints_ = dict.getOrDefault<label>("nShapePoints", 51);
    if (nShapePoints_ < 2)
    {
        FatalIOErrorInFunction(dict.lookup("nShapePoints"))
            << "Entry nShapePoints " << nShapePoints_ << " in "
            << dict.dictName() << " must be 2 or more" << nl
            << exit(FatalIOError);
    }

    anchor_ = dict.get<vector>("anchor");
    refAttachmentPt_ = dict.get<vector>("refAttachmentPt");

    elasticCatenary::properties p(lineProperties(dict));

    hasSeabed_ = dict.readIfPresent("seabed", seabed_);
    if (hasSeabed_)
    {
        if (!std::isfinite(seabed_))
        {
            FatalIOErrorInFunction(dict.lookup("seabed"))
                << "Entry seabed " << seabed_ << " in " << dict.dictName()
                << " must be a finite height" << nl << exit(FatalIOError);
        }
        const scalar anchorHeight = anchor_ & up();
        if (anchorHeight < seabed_ - 1e-6*p.L)
        {
            FatalIOErrorInFunction(dict.lookup("anchor"))
                << "Entry anchor " << anchor_ << " in " << dict.dictName()
                << " is below the seabed " << seabed_ << " by "
                << seabed_ - anchorHeight << " m: put it on the seabed or"
                << " above it" << nl << exit(FatalIOError);
        }
        p.grounded = anchorHeight <= seabed_ + 1e-6*p.L;
    }
    else if (p.CB > 0)
    {
        FatalIOErrorInFunction(dict.lookup("seabedFriction"))
            << "Entry seabedFriction " << p.CB << " in " << dict.dictName()
            << " needs a seabed (entry seabed, its height)" << nl
            << exit(FatalIOError);
    }

    line_ = elasticCatenary(p);

    return true;
}


void Foam::RBD::restraints::catenaryLine::write(Ostream& os) const
{
    restraint::write(os);
    const elasticCatenary::properties& p = line_.props();
    os.writeEntry("anchor", anchor_);
    os.writeEntry("refAttachmentPt", refAttachmentPt_);
    os.writeEntry("length", p.L);
    os.writeEntry("wetWeight", p.w);
    os.writeEntry("EA", p.EA);
    if (hasSeabed_)
    {
        os.writeEntry("seabed", seabed_);
        os.writeEntry("seabedFriction", p.CB);
    }
    os.writeEntry("writeShape", Switch(writeShape_));
    os.writeEntry("nShapePoints", nShapePoints_);
}


// ************************************************************************* //
