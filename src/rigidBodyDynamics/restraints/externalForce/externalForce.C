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

#include "externalForce.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(externalForce, 0);
    addToRunTimeSelectionTable(restraint, externalForce, dictionary);
    addRigidBodyKeywords
    (
        restraint, externalForce, "location", "force", "forceCoeffs",
        "moment", "momentCoeffs", "locationFrame", "forceFrame"
    );
}
}
}


const Foam::Enum<Foam::RBD::restraints::externalForce::frame>
Foam::RBD::restraints::externalForce::frameNames
({
    {frame::global, "global"},
    {frame::body, "body"}
});


Foam::RBD::restraints::externalForce::externalForce
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


Foam::RBD::restraints::externalForce::externalForce(const externalForce& ef)
:
    restraint(ef),
    location_(ef.location_),
    force_(ef.force_.valid() ? ef.force_->clone().ptr() : nullptr),
    moment_(ef.moment_.valid() ? ef.moment_->clone().ptr() : nullptr),
    locationFrame_(ef.locationFrame_),
    forceFrame_(ef.forceFrame_)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::RBD::restraints::externalForce::frame
Foam::RBD::restraints::externalForce::readFrame
(
    const dictionary& dict,
    const word& key
)
{
    const word name(dict.getOrDefault<word>(key, frameNames[frame::global]));
    if (!frameNames.found(name))
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << ' ' << name << " in " << dict.dictName()
            << ": valid frames are";
        forAll(frameNames, i)
        {
            FatalIOError
                << (i == 0 ? " " : i + 1 < frameNames.size() ? ", " : " and ")
                << frameNames.names()[i];
        }
        FatalIOError<< nl << exit(FatalIOError);
    }
    return frameNames.get(name);
}


void Foam::RBD::restraints::externalForce::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
) const
{
    const scalar t = state.t();
    vector F(force_.valid() ? force_->value(t) : Zero);
    vector M(moment_.valid() ? moment_->value(t) : Zero);

    const vector p
    (
        locationFrame_ == frame::body
      ? model_.globalPoint(bodyID_, location_, ws)
      : location_
    );
    if (forceFrame_ == frame::body)
    {
        // Body axes to global: E maps global vectors to the body's
        const tensor Et(model_.X0(bodyID_, ws).E().T());
        F = Et & F;
        M = Et & M;
    }

    addForce(fx, p, F);
    addMoment(fx, M);
}


bool Foam::RBD::restraints::externalForce::read(const dictionary& dict)
{
    restraint::read(dict);
    if (!dict.found("force") && !dict.found("moment"))
    {
        FatalIOErrorInFunction(dict)
            << "Restraint " << name_ << " (externalForce) has neither a"
            << " force nor a moment: give force, moment or both (each a"
            << " Function1 of time)" << nl << exit(FatalIOError);
    }

    // A force needs its line of action; a pure moment needs none
    force_.clear();
    location_ = Zero;
    if (dict.found("force"))
    {
        location_ = dict.get<vector>("location");
        force_ = readFunction1<vector>(dict, "force");
    }
    moment_.clear();
    if (dict.found("moment"))
    {
        moment_ = readFunction1<vector>(dict, "moment");
    }
    locationFrame_ = readFrame(dict, "locationFrame");
    forceFrame_ = readFrame(dict, "forceFrame");
    return true;
}


void Foam::RBD::restraints::externalForce::write(Ostream& os) const
{
    restraint::write(os);
    if (force_.valid())
    {
        os.writeEntry("location", location_);
        force_->writeData(os);
    }
    if (moment_.valid())
    {
        moment_->writeData(os);
    }
    os.writeEntry("locationFrame", frameNames[locationFrame_]);
    os.writeEntry("forceFrame", frameNames[forceFrame_]);
}
