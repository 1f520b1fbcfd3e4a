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
    lumpedMassLine: a dynamic mooring line (lumpedMassLine.H)
\*---------------------------------------------------------------------------*/

#include "lumpedMassLine.H"
#include "elasticCatenary.H"
#include "rigidBodyModel.H"
#include "rigidBodyEntries.H"
#include "vtkPolyline.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"
#include "Switch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(lumpedMassLine, 0);

    addToRunTimeSelectionTable
    (
        restraint,
        lumpedMassLine,
        dictionary
    );
    addRigidBodyKeywords
    (
        restraint, lumpedMassLine, "anchor", "refAttachmentPt", "length",
        "nSegments", "massPerLength", "diameter", "EA", "rhoWater", "Cdn",
        "Cdt", "Can", "Cat", "dampingRatio", "BA", "seabed", "seabedStiffness",
        "seabedDamping", "writeShape"
    );
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::RBD::restraints::lumpedMassLine::fairlead
(
    const rigidBodyModelWorkspace& ws
) const
{
    const vector p(model_.globalPoint(bodyID_, refAttachmentPt_, ws));
    const vector& g = model_.g();
    const vector up(mag(g) > VSMALL ? -g/mag(g) : vector(0, 0, 1));
    if (props_.hasSeabed && (p & up) < props_.seabed - 1e-6*props_.L)
    {
        FatalIOErrorInFunction(coeffs_)
            << "lumpedMassLine " << name_ << ": the fairlead (refAttachmentPt "
            << refAttachmentPt_ << ", at " << p << ") is below the seabed "
            << props_.seabed << nl << exit(FatalIOError);
    }
    return p;
}


Foam::RBD::lumpedLine& Foam::RBD::restraints::lumpedMassLine::line() const
{
    if (!line_)
    {
        FatalErrorInFunction
            << "lumpedMassLine " << name_ << ": its line is evaluated before"
            << " start() made it" << abort(FatalError);
    }
    return *line_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::lumpedMassLine::lumpedMassLine
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    statefulRestraint(name, dict, model),
    anchor_(Zero),
    refAttachmentPt_(Zero),
    props_(),
    writeShape_(true),
    committedTension_(0),
    committedAnchorTension_(0)
{
    read(dict);
}


Foam::RBD::restraints::lumpedMassLine::lumpedMassLine
(
    const lumpedMassLine& l
)
:
    statefulRestraint(l),
    anchor_(l.anchor_),
    refAttachmentPt_(l.refAttachmentPt_),
    props_(l.props_),
    writeShape_(l.writeShape_),
    line_(l.line_ ? new lumpedLine(*l.line_) : nullptr),
    pendingState_(l.pendingState_),
    committedTension_(l.committedTension_),
    committedAnchorTension_(l.committedAnchorTension_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::restraints::lumpedMassLine::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
) const
{
    const vector p(fairlead(ws));
    lumpedLine& l = line();
    l.advance(state.t(), p);
    addForce(fx, p, l.force());
}


void Foam::RBD::restraints::lumpedMassLine::start
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
)
{
    if (line_)
    {
        return;
    }

    lumpedLine::properties lp(props_);
    lp.g = model_.g();
    line_.reset
    (
        new lumpedLine
        (
            lp, anchor_, fairlead(ws), state.t(),
            model_.v(bodyID_, refAttachmentPt_, ws).l()
        )
    );
    if (pendingState_.size())
    {
        line_->readState(pendingState_);
    }
}


void Foam::RBD::restraints::lumpedMassLine::commit
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
)
{
    const vector p(fairlead(ws));
    lumpedLine& l = line();
    l.advance(state.t(), p);
    l.commit();
    committedTension_ = l.tension(props_.N - 1);
    committedAnchorTension_ = l.tension(0);
}


void Foam::RBD::restraints::lumpedMassLine::describe
(
    const rigidBodyModelWorkspace& ws,
    restraintReport& report
) const
{
    using constant::mathematical::pi;
    const lumpedLine::properties& p = props_;
    const vector up(mag(p.g) > VSMALL ? -p.g/mag(p.g) : vector(0, 0, 1));

    elasticCatenary::properties cp;
    cp.L = p.L;
    cp.w = max((p.mu - p.rho*0.25*pi*sqr(p.d))*mag(p.g), scalar(0));
    cp.EA = p.EA;
    cp.CB = 0;
    cp.grounded =
        p.hasSeabed && mag((anchor_ & up) - p.seabed) <= 1e-6*p.L;

    report.fairlead = model_.globalPoint(bodyID_, refAttachmentPt_, ws);

    // Its stiffness: the catenary's at the fairlead, up against the
    // model's gravity
    {
        const vector& g = model_.g();
        const vector upModel(mag(g) > VSMALL ? -g/mag(g) : vector(0, 0, 1));
        elasticCatenary c(cp);
        report.line = true;
        report.force = c.fairleadForce(anchor_, report.fairlead, upModel);
        report.tension = c.tension();
        report.H = c.H();
        report.V = c.V();
        report.groundedLength = c.groundedLength();
        report.forceGradient =
            c.fairleadForceGradient(anchor_, report.fairlead, upModel);
    }

    // The transverse period at the catenary's tension there
    elasticCatenary solved(cp);
    solved.fairleadForce(anchor_, report.fairlead, up);
    const scalar A = 0.25*pi*sqr(p.d);
    const scalar T0 = solved.tension();
    report.addPeriod
    (
        "axial",
        "first axial period 2 L/sqrt(EA/mu)",
        2*p.L/sqrt(p.EA/p.mu)
    );
    report.addPeriod
    (
        "transverse",
        "first transverse period 2 L/sqrt(T/(mu + added))",
        T0 > 0 ? 2*p.L/sqrt(T0/(p.mu + p.rho*A*p.Can)) : GREAT
    );
    report.maxSubStep = line_ ? line_->maxSubStep() : 0;
}


bool Foam::RBD::restraints::lumpedMassLine::writeState(Ostream& os) const
{
    if (!line_)
    {
        return false;
    }
    line_->writeState(os);
    return true;
}


void Foam::RBD::restraints::lumpedMassLine::readState(const dictionary& dict)
{
    if (line_)
    {
        line_->readState(dict);
    }
    else
    {
        pendingState_ = dict;
    }
}


void Foam::RBD::restraints::lumpedMassLine::addColumns(tableRow& row) const
{
    row.add(name_ + ".tension", committedTension_);
    row.add(name_ + ".anchorTension", committedAnchorTension_);
}


void Foam::RBD::restraints::lumpedMassLine::writeOutput
(
    const fileName& dir,
    const scalar t
) const
{
    if (!writeShape_ || !line_)
    {
        return;
    }
    // At each node the mean of its segments' tensions
    const label N = props_.N;
    scalarField T(N + 1, Zero);
    for (label j = 0; j < N; ++j)
    {
        const scalar Tj = line_->tension(j);
        T[j] += (j == 0 ? 1 : 0.5)*Tj;
        T[j + 1] += (j == N - 1 ? 1 : 0.5)*Tj;
    }
    writeVtkPolyline
    (
        dir/name_ + ".vtk",
        "lumpedMassLine " + name_ + " at t = " + Foam::name(t),
        line_->nodes(),
        "tension",
        T
    );
}


bool Foam::RBD::restraints::lumpedMassLine::read(const dictionary& dict)
{
    restraint::read(dict);

    anchor_ = dict.get<vector>("anchor");
    refAttachmentPt_ = dict.get<vector>("refAttachmentPt");

    lumpedLine::properties& p = props_;
    p.L = readPositive(dict, "length");
    p.N = dict.get<label>("nSegments");
    if (p.N < 1)
    {
        FatalIOErrorInFunction(dict.lookup("nSegments"))
            << "Entry nSegments " << p.N << " in " << dict.dictName()
            << " must be 1 or more" << nl << exit(FatalIOError);
    }
    p.mu = readPositive(dict, "massPerLength");
    p.d = readPositive(dict, "diameter");
    p.EA = readPositive(dict, "EA");
    p.rho = readNonNegative(dict, "rhoWater");

    auto optional = [&](const word& key, const scalar deflt)
    {
        return dict.found(key) ? readNonNegative(dict, key) : deflt;
    };
    p.Cdn = optional("Cdn", 1);
    p.Cdt = optional("Cdt", 0);
    p.Can = optional("Can", 1);
    p.Cat = optional("Cat", 0);

    if (dict.found("dampingRatio") && dict.found("BA"))
    {
        FatalIOErrorInFunction(dict.lookup("BA"))
            << "Entries dampingRatio and BA in " << dict.dictName()
            << " both give the line's internal damping: give one" << nl
            << exit(FatalIOError);
    }
    p.BA =
        dict.found("BA")
      ? readNonNegative(dict, "BA")
      : optional("dampingRatio", 0)*2*(p.L/p.N)*sqrt(p.EA*p.mu);

    p.g = model_.g();
    const vector up
    (
        mag(p.g) > VSMALL ? -p.g/mag(p.g) : vector(0, 0, 1)
    );
    p.hasSeabed = dict.readIfPresent("seabed", p.seabed);
    if (p.hasSeabed)
    {
        if (!std::isfinite(p.seabed))
        {
            FatalIOErrorInFunction(dict.lookup("seabed"))
                << "Entry seabed " << p.seabed << " in " << dict.dictName()
                << " must be a finite height" << nl << exit(FatalIOError);
        }
        if ((anchor_ & up) < p.seabed - 1e-6*p.L)
        {
            FatalIOErrorInFunction(dict.lookup("anchor"))
                << "Entry anchor " << anchor_ << " in " << dict.dictName()
                << " is below the seabed " << p.seabed << ": put it on the"
                << " seabed or above it" << nl << exit(FatalIOError);
        }
    }
    else
    {
        p.seabed = 0;
    }
    p.kSeabed = optional("seabedStiffness", 3e6);
    p.cSeabed = optional("seabedDamping", 3e5);

    // MoorDyn's default seabed damping is a full-scale value in Pa s/m:
    // against the critical damping of a node on the seabed's spring,
    // 2 sqrt(kSeabed mu/d), it scales as sqrt(lambda); say what it is for
    // this line (docs/coupling.md, "Right at any scale")
    if (p.hasSeabed && !dict.found("seabedDamping") && p.kSeabed > 0)
    {
        Info<< "lumpedMassLine " << dict.dictName() << ": seabedDamping "
            << p.cSeabed << " Pa s/m (MoorDyn's default, an absolute"
            << " value) is " << p.cSeabed/(2*sqrt(p.kSeabed*p.mu/p.d))
            << " times critical for a node of this line on the seabed;"
            << " give seabedDamping to set it" << endl;
    }

    writeShape_ = dict.getOrDefault<Switch>("writeShape", true);

    return true;
}


void Foam::RBD::restraints::lumpedMassLine::write(Ostream& os) const
{
    restraint::write(os);
    const lumpedLine::properties& p = props_;
    os.writeEntry("anchor", anchor_);
    os.writeEntry("refAttachmentPt", refAttachmentPt_);
    os.writeEntry("length", p.L);
    os.writeEntry("nSegments", p.N);
    os.writeEntry("massPerLength", p.mu);
    os.writeEntry("diameter", p.d);
    os.writeEntry("EA", p.EA);
    os.writeEntry("BA", p.BA);
    os.writeEntry("Cdn", p.Cdn);
    os.writeEntry("Cdt", p.Cdt);
    os.writeEntry("Can", p.Can);
    os.writeEntry("Cat", p.Cat);
    os.writeEntry("rhoWater", p.rho);
    if (p.hasSeabed)
    {
        os.writeEntry("seabed", p.seabed);
        os.writeEntry("seabedStiffness", p.kSeabed);
        os.writeEntry("seabedDamping", p.cSeabed);
    }
    os.writeEntry("writeShape", Switch(writeShape_));
}


// ************************************************************************* //
