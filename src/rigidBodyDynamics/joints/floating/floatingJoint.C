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

#include "floatingJoint.H"
#include "Pxyz.H"
#include "Rzyx.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(floating, 0);
    addToRunTimeSelectionTable(joint, floating, dictionary);
    addRigidBodyKeywords(joint, floating);
}
}
}


namespace
{
    Foam::PtrList<Foam::RBD::joint> PxyzRzyx()
    {
        Foam::PtrList<Foam::RBD::joint> joints(2);
        joints.set(0, new Foam::RBD::joints::Pxyz());
        joints.set(1, new Foam::RBD::joints::Rzyx());
        return joints;
    }
}


Foam::RBD::joints::floating::floating(const dictionary&)
:
    composite(PxyzRzyx())
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::floating::clone() const
{
    return autoPtr<joint>(new floating(*this));
}


void Foam::RBD::joints::floating::write(Ostream& os) const
{
    joint::write(os);
}
