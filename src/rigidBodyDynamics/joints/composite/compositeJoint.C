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

#include "compositeJoint.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(composite, 0);
    addToRunTimeSelectionTable(joint, composite, dictionary);
    addRigidBodyKeywords(joint, composite, "joints");
}
}
}


void Foam::RBD::joints::composite::setNDoF()
{
    nDoF_ = 0;
    forAll(joints_, i)
    {
        nDoF_ += joints_[i].nDoF();
    }
}


Foam::RBD::joints::composite::composite(PtrList<joint>&& joints)
:
    joint(0),
    joints_(std::move(joints))
{
    setNDoF();
}


Foam::RBD::joints::composite::composite(const dictionary& dict)
:
    joint(0)
{
    const List<dictionary> jointDicts(dict.lookup("joints"));

    if (jointDicts.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry joints of the composite joint is an empty list" << nl
            << exit(FatalIOError);
    }

    joints_.setSize(jointDicts.size());
    forAll(jointDicts, i)
    {
        joints_.set(i, joint::New(jointDicts[i]));
    }

    setNDoF();
}


Foam::RBD::joints::composite::composite(const composite& cj)
:
    joint(cj),
    joints_(cj.joints_.size())
{
    forAll(joints_, i)
    {
        joints_.set(i, cj.joints_[i].clone());
    }
}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::composite::clone() const
{
    return autoPtr<joint>(new composite(*this));
}


void Foam::RBD::joints::composite::expand(PtrList<joint>& joints) const
{
    forAll(joints_, i)
    {
        joints_[i].expand(joints);
    }
}


void Foam::RBD::joints::composite::jcalc
(
    XSvc&,
    const scalarField&,
    const scalarField&
) const
{
    FatalErrorInFunction
        << "A composite joint is expanded by the model, never evaluated"
        << abort(FatalError);
}


void Foam::RBD::joints::composite::write(Ostream& os) const
{
    joint::write(os);

    os  << indent << "joints" << nl
        << indent << token::BEGIN_LIST << incrIndent << nl;

    forAll(joints_, i)
    {
        os  << indent << token::BEGIN_BLOCK << incrIndent << nl;
        joints_[i].write(os);
        os  << decrIndent << indent << token::END_BLOCK << nl;
    }

    os  << decrIndent << indent << token::END_LIST
        << token::END_STATEMENT << nl;
}
