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

#include "Ra.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Ra, 0);
    addToRunTimeSelectionTable(joint, Ra, dictionary);
    addRigidBodyKeywords(joint, Ra, "axis");
}
}
}


Foam::RBD::joints::Ra::Ra(const vector& axis)
:
    joint(1),
    axis_(axis/mag(axis))
{
    unitColumn_ = coordinateAxis(axis_);
}


Foam::RBD::joints::Ra::Ra(const dictionary& dict)
:
    joint(1),
    axis_(readAxis(dict, "axis"))
{
    unitColumn_ = coordinateAxis(axis_);
}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Ra::clone() const
{
    return autoPtr<joint>(new Ra(*this));
}


void Foam::RBD::joints::Ra::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    const scalar angle = q[qIndex_];

    // About a coordinate axis the rotation is written out (Foam::Ra's
    // values for that axis)
    if (unitColumn_ < 0)
    {
        J.X = spatialTransform(Foam::Ra(axis_, angle), Zero);
    }
    else
    {
        const scalar s = std::sin(angle);
        const scalar c = std::cos(angle);
        J.X.r() = Zero;
        J.X.E() =
            unitColumn_ == 0 ? tensor(1, 0, 0, 0, c, s, 0, -s, c)
          : unitColumn_ == 1 ? tensor(c, 0, -s, 0, 1, 0, s, 0, c)
          : tensor(c, s, 0, -s, c, 0, 0, 0, 1);
    }
    J.S[0] = spatialVector(axis_, Zero);
    J.v = qDot[qIndex_]*J.S[0];
    J.c = Zero;
}


void Foam::RBD::joints::Ra::write(Ostream& os) const
{
    joint::write(os);
    os.writeEntry("axis", axis_);
}
