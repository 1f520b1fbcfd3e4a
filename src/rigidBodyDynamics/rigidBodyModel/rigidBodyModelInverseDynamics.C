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
    Inverse dynamics by the recursive Newton-Euler algorithm, after
    Featherstone, Rigid Body Dynamics Algorithms (2008), table 5.1: the
    bodies' accelerations from the root to the leaves, the forces each
    body needs for them, then the joint forces from the leaves to the
    root.
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"
#include "spatialKernels.H"

using namespace Foam::RBD::spatialKernels;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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


void Foam::RBD::rigidBodyModel::inverseDynamics
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    const Field<spatialVector>& fx,
    scalarField& tau
) const
{
    kinematics(state, ws);
    bodyAccelerations(state.qDdot(), ws);

    const label nb = nBodies();

    // The forces each body needs, then the joint forces, leaves to root
    for (label i = 1; i < nb; ++i)
    {
        const spatialVector& v = ws.v[i];
        ws.pA[i] = (I_[i] & ws.a[i]) + (v ^ *(I_[i] & v));
        if (!isZero(fx[i]))
        {
            updateX0(ws);
            ws.pA[i] -= *ws.X0[i] & fx[i];
        }
    }

    for (label i = nb - 1; i > 0; --i)
    {
        const joint::XSvc& J = ws.J[i];
        const label qi = joints_[i].qIndex();

        for (label k = 0; k < joints_[i].nDoF(); ++k)
        {
            tau[qi + k] = J.S[k] && ws.pA[i];
        }

        const label p = lambda_[i];
        if (p)
        {
            ws.pA[p] += ws.Xlambda[i].T() & ws.pA[i];
        }
    }
}


// ************************************************************************* //
