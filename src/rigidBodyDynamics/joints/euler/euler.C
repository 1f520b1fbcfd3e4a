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

#include "euler.H"

namespace
{
    // Coordinate rotation about axis a (0 x, 1 y, 2 z) by angle q
    inline Foam::tensor Raxis(const Foam::label a, const Foam::scalar q)
    {
        if (a == 0)
        {
            return Foam::Rx(q);
        }
        else if (a == 1)
        {
            return Foam::Ry(q);
        }
        return Foam::Rz(q);
    }

    inline Foam::vector unitAxis(const Foam::label a)
    {
        Foam::vector e(Foam::Zero);
        e[a] = 1;
        return e;
    }
}


Foam::RBD::joints::euler::euler(const label a0, const label a1, const label a2)
:
    joint(3),
    axes_({a0, a1, a2})
{}


void Foam::RBD::joints::euler::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    const label i = qIndex_;

    const tensor E1(Raxis(axes_[0], q[i]));
    const tensor E2(Raxis(axes_[1], q[i + 1]));
    const tensor E3(Raxis(axes_[2], q[i + 2]));
    const tensor E32(E3 & E2);

    const vector s1(E32 & unitAxis(axes_[0]));
    const vector s2(E3 & unitAxis(axes_[1]));
    const vector s3(unitAxis(axes_[2]));

    J.X = spatialTransform(E32 & E1, Zero);
    J.S[0] = spatialVector(s1, Zero);
    J.S[1] = spatialVector(s2, Zero);
    J.S[2] = spatialVector(s3, Zero);

    const vector u1(qDot[i]*s1);
    const vector u2(qDot[i + 1]*s2);
    const vector u3(qDot[i + 2]*s3);

    J.v = spatialVector(u1 + u2 + u3, Zero);
    J.c = spatialVector((u1 ^ (u2 + u3)) + (u2 ^ u3), Zero);
}


bool Foam::RBD::joints::euler::nearSingularity(const scalarField& q) const
{
    // |cos(q1)| < sin(1 degree)
    return mag(cos(q[qIndex() + 1])) < 0.0174524064372835;
}
