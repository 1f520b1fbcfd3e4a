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

#include "masslessBody.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(masslessBody, 0);
    addToRunTimeSelectionTable(rigidBody, masslessBody, dictionary);
    addRigidBodyKeywords(body, masslessBody);
}
}


Foam::RBD::masslessBody::masslessBody(const word& name)
:
    rigidBody(name, rigidBodyInertia())
{}


Foam::RBD::masslessBody::masslessBody(const word& name, const dictionary&)
:
    rigidBody(name, rigidBodyInertia())
{}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::masslessBody::clone() const
{
    return autoPtr<rigidBody>(new masslessBody(*this));
}


void Foam::RBD::masslessBody::write(Ostream& os) const
{
    os.writeEntry("type", type());
}
