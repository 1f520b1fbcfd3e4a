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
    Prescribed rotation rates met exactly (rateConstraint), as
    Featherstone, Rigid Body Dynamics Algorithms (2008), section 9.2: each
    motor's response to a unit moment through the articulated-body
    algorithm's acceleration pass, the small system of the motors'
    moments (one equation per constraint) solved, and the responses added
    to the free accelerations; the same for impulses on the velocities.
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"
#include "spatialKernels.H"

using namespace Foam::RBD::spatialKernels;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::RBD::rigidBodyModel::rate
(
    const rateConstraint& c,
    const scalarField& qDot,
    const rigidBodyModelWorkspace& ws
) const
{
    if (c.dof >= 0)
    {
        return qDot[c.dof];
    }
    updateX0(ws);
    return (ws.X0[c.bodyID].E() & c.axis) & ws.v[c.bodyID].w();
}


void Foam::RBD::rigidBodyModel::constraintResiduals
(
    const UList<rateConstraint>& C,
    const scalarField& qDdot,
    rigidBodyModelWorkspace& ws
) const
{
    forAll(C, r)
    {
        const rateConstraint& c = C[r];
        if (c.dof >= 0)
        {
            // A joint's prescribed acceleration (its position and rate are
            // met at the end of each solve, constrainState)
            ws.motorMoments[r] = c.acceleration - qDdot[c.dof];
            continue;
        }
        const vector e(ws.X0[c.bodyID].E() & c.axis);
        const scalar omega = e & ws.v[c.bodyID].w();
        ws.motorMoments[r] =
            c.acceleration + (c.rate - omega)/c.horizon
          - (e & ws.a[c.bodyID].w());
    }
}


void Foam::RBD::rigidBodyModel::unitMotorResponses
(
    const UList<rateConstraint>& C,
    rigidBodyModelWorkspace& ws
) const
{
    const label nb = nBodies();

    forAll(C, s)
    {
        // The motor's unit moment about the axis on its body, the reaction
        // on the body the joint is relative to: as external forces, -X0* f
        // in the bias forces
        ws.responseBias = Zero;
        const rateConstraint& cs = C[s];

        // A joint's motor is a unit force of the joint itself (added to its
        // share u below); a rotation's, a unit moment about the axis
        const label motorJoint = cs.dof >= 0 ? cs.bodyID : -1;
        if (cs.dof < 0)
        {
            ws.responseBias[cs.bodyID] =
                spatialVector(-(ws.X0[cs.bodyID].E() & cs.axis), Zero);
            if (cs.parentID)
            {
                ws.responseBias[cs.parentID] =
                    spatialVector(ws.X0[cs.parentID].E() & cs.axis, Zero);
            }
        }

        // Articulated bias forces of the response, leaves to root: as in
        // articulatedBodyDynamics with no velocities, no gravity and no
        // joint forces, on its articulated inertias (U as it left them)
        for (label i = nb - 1; i > 0; --i)
        {
            const joint& Ji = joints_[i];
            const label n = Ji.nDoF();
            const label rotation = XlambdaRotation(i);
            const FixedList<spatialVector, joint::maxDoF>& U = ws.U[i];
            spatialVector pa(ws.responseBias[i]);
            vector& u = ws.responseJointBias[i];
            const label p = lambda_[i];

            if (freeChild_[i] >= 0)
            {
                continue;
            }
            else if (freeParent_[i] >= 0)
            {
                // A free body: as in articulatedBodyDynamics, with no joint
                // forces (its S_w^-T as that left it in Dinv)
                u = -pa.w();
                ws.responseJointBias[p] =
                    freeLinearForce(ws.Xlambda[i], Zero, ws.responseBias[p]) - pa.l();
                continue;
            }

            if (Ji.unitColumn() >= 0 && n == 1)
            {
                // U is Xlambda^T U: the parent's share is taken whole
                u.x() = -pa[Ji.unitColumn()] + (i == motorJoint ? 1 : 0);
                if (p)
                {
                    ws.responseBias[p] +=
                        transformForce(ws.Xlambda[i], rotation, pa)
                      + U[0]*(ws.Dinv[i].xx()*u.x());
                }
                continue;
            }

            for (label j = 0; j < n; ++j)
            {
                u[j] = -(ws.J[i].S[j] && pa);
            }
            if (i == motorJoint)
            {
                u[cs.dof - Ji.qIndex()] += 1;
            }
            const vector Dinvu(ws.Dinv[i] & u);
            for (label j = 0; j < n; ++j)
            {
                pa += U[j]*Dinvu[j];
            }
            if (p)
            {
                ws.responseBias[p] += transformForce(ws.Xlambda[i], rotation, pa);
            }
        }

        // Accelerations of the response, root to leaves
        accelerationPass(ws.responseJointBias, nullptr, Zero, ws, ws.responseAcceleration, ws.responseQDdot[s]);

        forAll(C, r)
        {
            const rateConstraint& cr = C[r];
            ws.constraintMatrix(r, s) = cr.dof >= 0
              ? ws.responseQDdot[s][cr.dof]
              : (ws.X0[cr.bodyID].E() & cr.axis)
              & ws.responseAcceleration[cr.bodyID].w();
        }
    }
}


void Foam::RBD::rigidBodyModel::solveConstraints
(
    const UList<rateConstraint>& C,
    rigidBodyModelWorkspace& ws
) const
{
    const label n = C.size();
    scalarSquareMatrix& LU = ws.constraintLU;
    LU = ws.constraintMatrix;

    scalar scale = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            scale = max(scale, mag(LU(i, j)));
        }
    }

    // A constraint no motor moves (a row of zeros, which LUDecompose
    // refuses without naming it), then a pivot of round-off (LUDecompose
    // puts SMALL in place of an exact zero)
    for (label r = 0; r < n; ++r)
    {
        scalar rowMax = 0;
        for (label j = 0; j < n; ++j)
        {
            rowMax = max(rowMax, mag(LU(r, j)));
        }
        if (!(rowMax > 1e-12*scale))
        {
            unmetConstraint(C, r, ws);
        }
    }

    LUDecompose(LU, ws.constraintPivots);

    for (label k = 0; k < n; ++k)
    {
        const scalar pivot = mag(LU(k, k));
        if (!(pivot > 1e-12*scale) || pivot == SMALL)
        {
            unmetConstraint(C, k, ws);
        }
    }

    LUBacksubstitute(LU, ws.constraintPivots, ws.motorMoments);
}


void Foam::RBD::rigidBodyModel::unmetConstraint
(
    const UList<rateConstraint>& C,
    const label k,
    const rigidBodyModelWorkspace& ws
) const
{
    if (C[k].dof >= 0)
    {
        FatalErrorInFunction
            << "The prescribed motion of degree of freedom " << C[k].dof
            << " (the joint of body " << bodies_[C[k].bodyID].name()
            << ") cannot be met: another prescription already fixes it"
            << " (the response of the prescriptions to the motors' forces"
            << " is singular: " << ws.constraintMatrix << ")"
            << exit(FatalError);
    }

    FatalErrorInFunction
        << "The prescribed rotation of body "
        << bodies_[C[k].bodyID].name() << " about " << C[k].axis
        << " cannot be met: its joint does not turn it about that"
        << " axis relative to "
        << bodies_[C[k].parentID].name()
        << ", or another prescription already fixes that rotation"
        << " (the response of the prescribed rates to the motors'"
        << " moments is singular: " << ws.constraintMatrix << ")"
        << exit(FatalError);
}


void Foam::RBD::rigidBodyModel::addResponses
(
    const rigidBodyModelWorkspace& ws,
    scalarField& x
) const
{
    forAll(ws.motorMoments, s)
    {
        const scalarField& r = ws.responseQDdot[s];
        forAll(x, j)
        {
            x[j] += ws.motorMoments[s]*r[j];
        }
    }
}


void Foam::RBD::rigidBodyModel::constrainedDynamics
(
    const scalarField& tau,
    const Field<spatialVector>& fx,
    UList<rateConstraint>& C,
    rigidBodyModelWorkspace& ws,
    scalarField& qDdot
) const
{
    articulatedBodyDynamics(tau, fx, ws, qDdot);

    if (C.empty())
    {
        return;
    }

    // The motors' moments: what each constraint asks less what the body's
    // acceleration is without them, through the responses to unit moments
    updateX0(ws);
    constraintResiduals(C, qDdot, ws);
    unitMotorResponses(C, ws);
    solveConstraints(C, ws);

    addResponses(ws, qDdot);
    forAll(C, s)
    {
        C[s].moment = ws.motorMoments[s];
    }
}


void Foam::RBD::rigidBodyModel::motorResponses
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    const UList<rateConstraint>& C
) const
{
    // The articulated inertias of the positions, with no forces
    kinematics(state, ws);
    articulatedBodyDynamics(ws.tauZero, ws.fxZero, ws, ws.qDdotScratch);
    updateX0(ws);
    unitMotorResponses(C, ws);
}


void Foam::RBD::rigidBodyModel::constrainState
(
    rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    UList<rateConstraint>& C
) const
{
    if (C.empty())
    {
        return;
    }

    // A joint's prescribed position, met exactly: its q alone moves
    forAll(C, r)
    {
        if (C[r].dof >= 0)
        {
            state.q()[C[r].dof] = C[r].position;
        }
    }

    // The responses to the motors' unit moments (they depend on the
    // positions only)
    motorResponses(state, ws, C);

    // The motors' impulses that bring the rates to the constraints'
    forAll(C, r)
    {
        ws.motorMoments[r] = C[r].rate - rate(C[r], state.qDot(), ws);
    }
    solveConstraints(C, ws);

    addResponses(ws, state.qDot());

    // At the new velocities, the change of the motors' moments that gives
    // the accelerations the constraints ask
    kinematics(state, ws);
    bodyAccelerations(state.qDdot(), ws);
    updateX0(ws);
    constraintResiduals(C, state.qDdot(), ws);
    solveConstraints(C, ws);

    addResponses(ws, state.qDdot());

    // A joint's driving force: with the change that meets its acceleration
    forAll(C, r)
    {
        if (C[r].dof >= 0)
        {
            C[r].moment += ws.motorMoments[r];
        }
    }
}


// ************************************************************************* //
