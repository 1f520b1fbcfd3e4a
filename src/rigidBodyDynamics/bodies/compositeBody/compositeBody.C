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

#include "compositeBody.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(compositeBody, 0);
}
}


Foam::RBD::compositeBody::compositeBody(autoPtr<rigidBody> body)
:
    rigidBody(body->name(), *body),
    body_(std::move(body))
{}


Foam::RBD::compositeBody::compositeBody(const compositeBody& cb)
:
    rigidBody(cb),
    body_(cb.body_->clone())
{}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::compositeBody::clone() const
{
    return autoPtr<rigidBody>(new compositeBody(*this));
}


void Foam::RBD::compositeBody::write(Ostream& os) const
{
    body_->write(os);
}
