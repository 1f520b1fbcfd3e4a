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

#include "Pa.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Pa, 0);
    addToRunTimeSelectionTable(joint, Pa, dictionary);
    addRigidBodyKeywords(joint, Pa, "axis");
}
}
}


Foam::RBD::joints::Pa::Pa(const vector& axis)
:
    joint(1),
    axis_(axis/mag(axis))
{
    const label k = coordinateAxis(axis_);
    unitColumn_ = k < 0 ? -1 : 3 + k;
}


Foam::RBD::joints::Pa::Pa(const dictionary& dict)
:
    joint(1),
    axis_(readAxis(dict, "axis"))
{
    const label k = coordinateAxis(axis_);
    unitColumn_ = k < 0 ? -1 : 3 + k;
}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Pa::clone() const
{
    return autoPtr<joint>(new Pa(*this));
}


void Foam::RBD::joints::Pa::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    J.X = spatialTransform(tensor::I, q[qIndex_]*axis_);
    J.S[0] = spatialVector(Zero, axis_);
    J.v = qDot[qIndex_]*J.S[0];
    J.c = Zero;
}


void Foam::RBD::joints::Pa::write(Ostream& os) const
{
    joint::write(os);
    os.writeEntry("axis", axis_);
}
