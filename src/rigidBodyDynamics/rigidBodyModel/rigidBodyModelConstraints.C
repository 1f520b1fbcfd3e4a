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
    Prescribed rates met exactly (rateConstraint: a row in joint space and
    a target), as Featherstone, Rigid Body Dynamics Algorithms (2008),
    section 9.2: each motor's response to a unit force through the
    articulated-body algorithm's acceleration pass, the small system of the
    motors' forces (one equation per constraint) solved, and the responses
    added to the free accelerations; the same for impulses on the
    velocities.
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"
#include "spatialKernels.H"

using namespace Foam::RBD::spatialKernels;


namespace
{
    // a & qDot with a's zeros skipped: a unit a gives its entry of qDot
    // exactly
    Foam::scalar sparseDot
    (
        const Foam::scalarField& a,
        const Foam::scalarField& qDot
    )
    {
        Foam::scalar r = 0;
        forAll(a, j)
        {
            if (a[j] != 0)
            {
                r += a[j]*qDot[j];
            }
        }
        return r;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::RBD::rigidBodyModel::rate
(
    const rateConstraint& c,
    const scalarField& qDot
) const
{
    return sparseDot(c.row, qDot);
}


Foam::scalar Foam::RBD::rigidBodyModel::motorRate
(
    const rateConstraint& c,
    const scalarField& qDot
) const
{
    return sparseDot(c.motor, qDot);
}


void Foam::RBD::rigidBodyModel::angularRow
(
    const label bodyID,
    const label parentID,
    const vector& axis,
    const rigidBodyModelWorkspace& ws,
    rateConstraint& c
) const
{
    updateX0(ws);
    c.row = Zero;
    c.motor = Zero;
    c.bias = 0;

    // Up the tree from the body: each joint's angular columns, in its
    // child's axes, against the axis in those axes; the joints below
    // parentID hold the motor
    bool motor = true;
    for (label k = bodyID; k > 0; k = lambda_[k])
    {
        if (k == parentID)
        {
            motor = false;
        }
        const joint& Jk = joints_[k];
        const label qi = Jk.qIndex();
        const label unit = Jk.unitColumn();
        const vector e(ws.X0[k].E() & axis);

        for (label j = 0; j < Jk.nDoF(); ++j)
        {
            // A unit column e_(unit + j): angular if unit + j < 3
            const scalar r =
                unit >= 0
              ? (unit + j < 3 ? e[unit + j] : 0)
              : (e & ws.J[k].S[j].w());
            c.row[qi + j] = r;
            if (motor)
            {
                c.motor[qi + j] = r;
            }
        }

        // The velocity products' share of the body's angular acceleration
        c.bias += e & ws.c[k].w();
    }
}


void Foam::RBD::rigidBodyModel::constraintResiduals
(
    const UPtrList<rateConstraint>& C,
    const scalarField& qDdot,
    rigidBodyModelWorkspace& ws
) const
{
    forAll(C, r)
    {
        const rateConstraint& c = C[r];
        ws.motorMoments[r] =
            c.active
          ? c.acceleration + c.rateGain*(c.rate - rate(c, ws.qDot))
          - (rate(c, qDdot) + c.bias)
          : 0;
    }
}


void Foam::RBD::rigidBodyModel::linearise
(
    UPtrList<rateConstraint>& C,
    const rigidBodyModelWorkspace& ws
) const
{
    updateX0(ws);
    forAll(C, s)
    {
        C[s].linearise(*this, ws);
    }
}


void Foam::RBD::rigidBodyModel::unitMotorResponses
(
    const UPtrList<rateConstraint>& C,
    rigidBodyModelWorkspace& ws
) const
{
    const label nb = nBodies();

    forAll(C, s)
    {
        // One left out: no response, and its own row and column those of
        // the identity
        if (!C[s].active)
        {
            ws.responseQDdot[s] = Zero;
            forAll(C, r)
            {
                ws.constraintMatrix(r, s) = (r == s ? 1 : 0);
            }
            continue;
        }

        // The motor's unit force: joint forces, motor, and no others
        ws.responseBias = Zero;
        const scalarField& f = C[s].motor;

        // Articulated bias forces of the response, leaves to root: as in
        // articulatedBodyDynamics with no velocities, no gravity and the
        // motor's joint forces, on its articulated inertias (U as it left
        // them)
        for (label i = nb - 1; i > 0; --i)
        {
            const joint& Ji = joints_[i];
            const label n = Ji.nDoF();
            const label qi = Ji.qIndex();
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
                // A free body: as in articulatedBodyDynamics (its S_w^-T
                // as that left it in Dinv)
                const label qp = joints_[p].qIndex();
                u = (ws.Dinv[i] & vector(f[qi], f[qi + 1], f[qi + 2]))
                  - pa.w();
                ws.responseJointBias[p] =
                    freeLinearForce
                    (
                        ws.Xlambda[i],
                        vector(f[qp], f[qp + 1], f[qp + 2]),
                        ws.responseBias[p]
                    )
                  - pa.l();
                continue;
            }

            if (Ji.unitColumn() >= 0 && n == 1)
            {
                // U is Xlambda^T U: the parent's share is taken whole
                u.x() = f[qi] - pa[Ji.unitColumn()];
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
                u[j] = f[qi + j] - (ws.J[i].S[j] && pa);
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
            ws.constraintMatrix(r, s) =
                C[r].active ? rate(C[r], ws.responseQDdot[s]) : 0;
        }
    }
}


void Foam::RBD::rigidBodyModel::solveConstraints
(
    const UPtrList<rateConstraint>& C,
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
    const UPtrList<rateConstraint>& C,
    const label k,
    const rigidBodyModelWorkspace& ws
) const
{
    OSstream& os = FatalErrorInFunction;
    os  << "The prescription of ";
    C[k].writeWhat(os);
    os  << " cannot be met: its motor does not move it, or another"
        << " prescription already fixes it (the response of the"
        << " prescriptions to the motors' forces is singular: "
        << ws.constraintMatrix << ")"
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
    UPtrList<rateConstraint>& C,
    rigidBodyModelWorkspace& ws,
    scalarField& qDdot
) const
{
    articulatedBodyDynamics(tau, fx, ws, qDdot);

    if (C.empty())
    {
        return;
    }

    // The motors' forces: what each constraint asks less what its rate's
    // change is without them, through the responses to unit forces
    linearise(C, ws);
    constraintResiduals(C, qDdot, ws);
    unitMotorResponses(C, ws);
    solveConstraints(C, ws);

    addResponses(ws, qDdot);
    forAll(C, s)
    {
        C[s].force = ws.motorMoments[s];
    }
}


void Foam::RBD::rigidBodyModel::motorResponses
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    UPtrList<rateConstraint>& C
) const
{
    // The articulated inertias of the positions, with no forces
    kinematics(state, ws);
    articulatedBodyDynamics(ws.tauZero, ws.fxZero, ws, ws.qDdotScratch);
    linearise(C, ws);
    unitMotorResponses(C, ws);
}


void Foam::RBD::rigidBodyModel::constrainState
(
    rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    UPtrList<rateConstraint>& C
) const
{
    if (C.empty())
    {
        return;
    }

    // The prescribed positions, if any, met exactly
    forAll(C, r)
    {
        if (C[r].active)
        {
            C[r].place(state.q());
        }
    }

    // The responses to the motors' unit forces (they depend on the
    // positions only)
    motorResponses(state, ws, C);

    // The motors' impulses that bring the rates to the constraints'
    forAll(C, r)
    {
        ws.motorMoments[r] =
            C[r].active ? C[r].rate - rate(C[r], state.qDot()) : 0;
    }
    solveConstraints(C, ws);

    // Each impulse's work: the impulse times the mean of its motor's
    // rates before and after (their sum is the change of the kinetic
    // energy, (qDot0 + qDot1)/2 & H (qDot1 - qDot0))
    forAll(C, r)
    {
        C[r].impulseWork =
            0.5*ws.motorMoments[r]*motorRate(C[r], state.qDot());
    }
    addResponses(ws, state.qDot());
    forAll(C, r)
    {
        C[r].impulseWork +=
            0.5*ws.motorMoments[r]*motorRate(C[r], state.qDot());
    }

    // At the new velocities, the change of the motors' forces that gives
    // the rates' changes the constraints ask
    kinematics(state, ws);
    linearise(C, ws);
    constraintResiduals(C, state.qDdot(), ws);
    solveConstraints(C, ws);

    addResponses(ws, state.qDdot());

    // Each motor's force with the change that meets its constraint
    forAll(C, r)
    {
        C[r].force += ws.motorMoments[r];
    }
}


// ************************************************************************* //
