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

#include "Rs.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Rs, 0);
    addToRunTimeSelectionTable(joint, Rs, dictionary);
    addRigidBodyKeywords(joint, Rs);
}
}
}


Foam::RBD::joints::Rs::Rs()
:
    joint(3)
{}


Foam::RBD::joints::Rs::Rs(const dictionary&)
:
    joint(3)
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Rs::clone() const
{
    return autoPtr<joint>(new Rs(*this));
}


Foam::quaternion Foam::RBD::joints::Rs::Q(const scalarField& q) const
{
    const label i = qIndex_;
    const vector v(q[i], q[i + 1], q[i + 2]);

    return quaternion(sqrt(max(scalar(0), 1 - magSqr(v))), v);
}


void Foam::RBD::joints::Rs::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    const label i = qIndex_;

    J.X = spatialTransform(Q(q).R().T(), Zero);
    J.S[0] = spatialVector(1, 0, 0, 0, 0, 0);
    J.S[1] = spatialVector(0, 1, 0, 0, 0, 0);
    J.S[2] = spatialVector(0, 0, 1, 0, 0, 0);
    J.v = spatialVector(vector(qDot[i], qDot[i + 1], qDot[i + 2]), Zero);
    J.c = Zero;
}


void Foam::RBD::joints::Rs::integrate
(
    scalarField& q,
    const scalarField& q0,
    const scalarField& dq
) const
{
    const label i = qIndex_;
    const vector theta(dq[i], dq[i + 1], dq[i + 2]);
    const scalar magTheta = mag(theta);

    // Exponential of the body-frame rotation vector
    const scalar s =
        magTheta > 1e-8
      ? sin(0.5*magTheta)/magTheta
      : 0.5*(1 - sqr(magTheta)/24);

    quaternion Qn(Q(q0)*quaternion(cos(0.5*magTheta), s*theta));
    Qn.normalize();

    if (Qn.w() < 0)
    {
        Qn = -Qn;
    }

    q[i] = Qn.v().x();
    q[i + 1] = Qn.v().y();
    q[i + 2] = Qn.v().z();
}


void Foam::RBD::joints::Rs::checkState
(
    const scalarField& q,
    const dictionary& dict
) const
{
    const label i = qIndex_;
    const vector v(q[i], q[i + 1], q[i + 2]);

    if (magSqr(v) > 1 + 1e-10)
    {
        FatalIOErrorInFunction(dict.lookup("q"))
            << "Entry q: slots " << i << " to " << i + 2 << " " << v
            << " of the Rs joint are a unit quaternion's vector part and"
            << " must have length at most 1 (length " << mag(v) << ")" << nl
            << exit(FatalIOError);
    }
}
