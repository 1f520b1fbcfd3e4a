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
-------------------------------------------------------------------------------
Description
    The model's kinematics, after Featherstone, Rigid Body Dynamics
    Algorithms (2008), the first pass of table 7.1: each body's transform
    from its parent, velocity and velocity product; its transform from the
    root on demand; and the bodies' accelerations for given joint
    accelerations (the second pass of table 5.1).
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"
#include "spatialKernels.H"

using namespace Foam::RBD::spatialKernels;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyModel::kinematics
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws
) const
{
    const scalarField& q = state.q();
    const scalarField& qDot = state.qDot();

    ws.v[0] = Zero;
    ws.X0valid = false;

    for (label i = 1; i < nBodies(); ++i)
    {
        joint::XSvc& J = ws.J[i];
        joints_[i].jcalc(J, q, qDot);

        const label p = lambda_[i];
        spatialTransform& Xlambda = ws.Xlambda[i];

        // Xlambda = XJ XT: a product of rotations only if XT rotates
        if (XTrotates_[i])
        {
            Xlambda = J.X & XT_[i];
        }
        else
        {
            Xlambda.E() = J.X.E();
            Xlambda.r() = XT_[i].r() + J.X.r();
        }

        ws.v[i] =
            p
          ? transformMotion(Xlambda, XlambdaRotation(i), ws.v[p]) + J.v
          : J.v;
        ws.c[i] =
            velocityProduct
            (
                J,
                joints_[i].unitColumn(),
                joints_[i].nDoF(),
                ws.v[i]
            );
    }
}


void Foam::RBD::rigidBodyModel::updateX0
(
    const rigidBodyModelWorkspace& ws
) const
{
    if (!ws.X0valid)
    {
        fillX0(ws);
    }
}


void Foam::RBD::rigidBodyModel::fillX0
(
    const rigidBodyModelWorkspace& ws
) const
{
    // X0 = Xlambda X0[parent]: a copy and a sum where the parent's X0 only
    // shifts (the root's: ws.X0[0] stays the identity) or Xlambda does
    for (label i = 1; i < nBodies(); ++i)
    {
        const label p = lambda_[i];
        const spatialTransform& Xl = ws.Xlambda[i];
        const spatialTransform& Xp = ws.X0[p];
        spatialTransform& X = ws.X0[i];

        if (!X0rotates_[p])
        {
            X.E() = Xl.E();
            X.r() = Xp.r() + Xl.r();
        }
        else if (XlambdaRotation(i) == 3)
        {
            X.E() = Xp.E();
            X.r() = Xp.r() + (Xl.r() & Xp.E());
        }
        else
        {
            X = Xl & Xp;
        }
    }
    ws.X0valid = true;
}


void Foam::RBD::rigidBodyModel::bodyAccelerations
(
    const scalarField& qDdot,
    rigidBodyModelWorkspace& ws
) const
{
    ws.a[0] = spatialVector(Zero, -g_);

    for (label i = 1; i < nBodies(); ++i)
    {
        const joint::XSvc& J = ws.J[i];
        const label qi = joints_[i].qIndex();

        const spatialVector& ap = ws.a[lambda_[i]];
        spatialVector a
        (
            transformMotion(ws.Xlambda[i], XlambdaRotation(i), ap) + ws.c[i]
        );
        for (label k = 0; k < joints_[i].nDoF(); ++k)
        {
            a += J.S[k]*qDdot[qi + k];
        }
        ws.a[i] = a;
    }
}


// ************************************************************************* //
