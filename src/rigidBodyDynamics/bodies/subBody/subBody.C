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

#include "subBody.H"

Foam::RBD::subBody::subBody
(
    autoPtr<rigidBody> body,
    const word& masterName,
    const label masterID,
    const spatialTransform& masterXT
)
:
    body_(std::move(body)),
    masterName_(masterName),
    masterID_(masterID),
    masterXT_(masterXT)
{}


Foam::RBD::subBody::subBody(const subBody& sb)
:
    body_(sb.body_->clone()),
    masterName_(sb.masterName_),
    masterID_(sb.masterID_),
    masterXT_(sb.masterXT_)
{}
