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

#include "Pxyz.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Pxyz, 0);
    addToRunTimeSelectionTable(joint, Pxyz, dictionary);
    addRigidBodyKeywords(joint, Pxyz);
}
}
}


Foam::RBD::joints::Pxyz::Pxyz()
:
    joint(3)
{
    unitColumn_ = 3;
}


Foam::RBD::joints::Pxyz::Pxyz(const dictionary&)
:
    joint(3)
{
    unitColumn_ = 3;
}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Pxyz::clone() const
{
    return autoPtr<joint>(new Pxyz(*this));
}


void Foam::RBD::joints::Pxyz::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    const label i = qIndex_;

    J.X = spatialTransform(tensor::I, vector(q[i], q[i + 1], q[i + 2]));
    J.S[0] = spatialVector(0, 0, 0, 1, 0, 0);
    J.S[1] = spatialVector(0, 0, 0, 0, 1, 0);
    J.S[2] = spatialVector(0, 0, 0, 0, 0, 1);
    J.v = spatialVector(Zero, vector(qDot[i], qDot[i + 1], qDot[i + 2]));
    J.c = Zero;
}
