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

#include "Ry.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Ry, 0);
    addToRunTimeSelectionTable(joint, Ry, dictionary);
    addRigidBodyKeywords(joint, Ry);
}
}
}


Foam::RBD::joints::Ry::Ry()
:
    Ra(vector(0, 1, 0))
{}


Foam::RBD::joints::Ry::Ry(const dictionary&)
:
    Ra(vector(0, 1, 0))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Ry::clone() const
{
    return autoPtr<joint>(new Ry(*this));
}


void Foam::RBD::joints::Ry::write(Ostream& os) const
{
    joint::write(os);
}
