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

#include "rigidBodyRestraint.H"
#include "keywordTable.H"
#include "rigidBodyModel.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(restraint, 0);
    defineRunTimeSelectionTable(restraint, dictionary);
    addRigidBodyCommonKeywords(restraint, Restraint, "type", "body");
}
}


Foam::RBD::restraint::restraint
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    name_(name),
    coeffs_(dict),
    model_(model),
    bodyID_(model.bodyID(dict, "body")),
    masterID_(model.masterID(bodyID_))
{
    if (masterID_ == 0)
    {
        FatalIOErrorInFunction(dict)
            << "Restraint " << name << " acts on body "
            << dict.get<word>("body") << ", which is fixed to the root"
            << nl << exit(FatalIOError);
    }
}


Foam::autoPtr<Foam::RBD::restraint> Foam::RBD::restraint::New
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
{
    const word restraintType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(restraintType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "restraint",
            restraintType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(name, dict, model);
}


Foam::label Foam::RBD::restraint::readAnchorBody(const dictionary& dict) const
{
    if (!dict.found("anchorBody"))
    {
        return -1;
    }

    const label id = model_.bodyID(dict, "anchorBody");
    if (model_.masterID(id) == masterID_)
    {
        FatalIOErrorInFunction(dict.lookup("anchorBody"))
            << "Restraint " << name_ << ": anchorBody "
            << dict.get<word>("anchorBody") << " moves with body "
            << dict.get<word>("body") << " itself: the restraint would act"
            << " within one rigid body" << nl << exit(FatalIOError);
    }
    return id;
}


Foam::wordList Foam::RBD::restraint::tableColumns() const
{
    tableRow row;
    row.start();
    addColumns(row);
    row.end();
    return row.names();
}


void Foam::RBD::restraint::tableValues(scalarField& row, label& k) const
{
    tableRow r;
    r.start();
    addColumns(r);
    r.end();
    if (k + r.size() > row.size())
    {
        FatalErrorInFunction
            << "Restraint " << name_ << " has " << r.size() << " columns,"
            << " but the row has room for " << row.size() - k << nl
            << abort(FatalError);
    }
    for (label c = 0; c < r.size(); ++c)
    {
        row[k++] = r[c];
    }
}


bool Foam::RBD::restraint::read(const dictionary& dict)
{
    coeffs_ = dict;
    return true;
}


void Foam::RBD::restraint::write(Ostream& os) const
{
    os.writeEntry("type", type());
    os.writeEntry("body", model_.name(bodyID_));
}


