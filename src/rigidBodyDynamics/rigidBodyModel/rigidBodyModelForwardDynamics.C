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
    Forward dynamics by the articulated-body algorithm, after
    Featherstone, Rigid Body Dynamics Algorithms (2008), table 7.1: the
    kinematics from the root to the leaves (each body's transform from its
    parent, velocity and velocity product; its transform from the root on
    demand), the articulated inertias and bias forces from the leaves to
    the root, then the joint accelerations from the root to the leaves.
    The other algorithms start from the same kinematics.

    A free body (a floating joint: a massless body on Pxyz from the root,
    then the body on a rotational joint) is one joint of six degrees of
    freedom to the algorithm: its acceleration is its articulated
    inertia's inverse times its joint force less its bias (for a body with
    nothing on it the inverse is the model's, made once), and the joints'
    accelerations follow from it; nothing passes to the root.  The same
    answer as the two joints one after the other, for about a quarter of
    the instructions (callgrind, bench/README.md).
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

    // The velocities, for the rate constraints' rows (none: not sized)
    if (ws.qDot.size())
    {
        ws.qDot = qDot;
    }

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


void Foam::RBD::rigidBodyModel::articulatedBodyDynamics
(
    const scalarField& tau,
    const Field<spatialVector>& fx,
    rigidBodyModelWorkspace& ws,
    scalarField& qDdot
) const
{
    const label nb = nBodies();

    // Body inertias and bias forces, external forces taken to body axes
    for (label i = 1; i < nb; ++i)
    {
        const spatialVector& v = ws.v[i];
        ws.IA[i] = I_[i];
        ws.pA[i] = v ^ *(I_[i] & v);
        if (!isZero(fx[i]))
        {
            updateX0(ws);
            ws.pA[i] -= *ws.X0[i] & fx[i];
        }
    }

    // Articulated inertias and bias forces, leaves to root: Ia = IA -
    // U D^-1 U^T and pa = pA + Ia c + U D^-1 u, taken to the parent
    for (label i = nb - 1; i > 0; --i)
    {
        const joint& Ji = joints_[i];
        const label n = Ji.nDoF();
        const label k = Ji.unitColumn();
        const label qi = Ji.qIndex();
        articulatedInertia& Ia = ws.IA[i];
        spatialVector& pa = ws.pA[i];
        FixedList<spatialVector, joint::maxDoF>& U = ws.U[i];
        vector& u = ws.u[i];

        if (freeChild_[i] >= 0)
        {
            // The massless parent of a free body: its parent is the root
            continue;
        }
        else if (freeParent_[i] >= 0)
        {
            // A free body: its joint force f (S^T f = tau over the pair's
            // six degrees of freedom) less its bias, angular part in u[i],
            // linear in u[p], and its articulated inertia's inverse in
            // ws.IA[p], for the accelerations; nothing passes to the root
            const label p = freeParent_[i];
            const label qp = joints_[p].qIndex();
            ws.Dinv[i] = freeSinvT(ws.J[i]);
            u = (ws.Dinv[i] & vector(tau[qi], tau[qi + 1], tau[qi + 2]))
              - pa.w();
            ws.u[p] =
                freeLinearForce
                (
                    ws.Xlambda[i],
                    vector(tau[qp], tau[qp + 1], tau[qp + 2]),
                    ws.pA[p]
                )
              - pa.l();
            ws.IA[p] = freeIinvValid_[i] ? freeIinv_[i] : Ia.inverse();
            continue;
        }

        if (k >= 0 && n == 1)
        {
            // S = e_k: U is IA's column k, D its diagonal entry.  Ia c =
            // IA c - U D^-1 U^T c: IA c need not wait for the division
            const spatialVector& c = ws.c[i];
            U[0] = Ia.column(k);
            const scalar Dinv = 1/U[0][k];
            ws.Dinv[i].xx() = Dinv;
            u.x() = tau[qi] - pa[k];

            // Ia and pa go to the parent: none for a child of the root
            if (lambda_[i])
            {
                const spatialVector IAc(Ia & c);
                pa += IAc + U[0]*(Dinv*(u.x() - (U[0] && c)));
                Ia.subtractOuter(Dinv*U[0], U[0]);
            }

            // For the accelerations: U a = U (Xlambda a_parent + c) =
            // (Xlambda^T U) a_parent + U c, so that qDdot need not wait for
            // Xlambda a_parent.  Kept in U and u: u - U c, Xlambda^T U
            u.x() -= U[0] && c;
            U[0] = transformForce(ws.Xlambda[i], XlambdaRotation(i), U[0]);
        }
        else if (n)
        {
            const joint::XSvc& J = ws.J[i];
            tensor D(Zero);

            if (k >= 0)
            {
                // S = [e_k ...]: U is IA's columns, D a block of them
                for (label j = 0; j < n; ++j)
                {
                    U[j] = Ia.column(k + j);
                    u[j] = tau[qi + j] - pa[k + j];
                }
                for (label j = 0; j < n; ++j)
                {
                    for (label l = 0; l < n; ++l)
                    {
                        D(j, l) = U[l][k + j];
                    }
                }
            }
            else
            {
                // Columns of S that are purely angular (a revolute joint's)
                // or linear take half the product
                for (label j = 0; j < n; ++j)
                {
                    const spatialVector& S = J.S[j];
                    U[j] =
                        S.l() == vector::zero ? Ia.timesAngular(S.w())
                      : S.w() == vector::zero ? Ia.timesLinear(S.l())
                      : Ia & S;
                    u[j] = tau[qi + j] - (S && pa);
                }
                for (label j = 0; j < n; ++j)
                {
                    for (label l = j; l < n; ++l)
                    {
                        D(j, l) = D(l, j) = J.S[j] && U[l];
                    }
                }
            }

            const tensor& Dinv = ws.Dinv[i] = invD(D, n);
            if (!lambda_[i])
            {
                // Ia and pa go to the parent: none for a child of the root
                continue;
            }
            const vector Dinvu(Dinv & u);

            for (label j = 0; j < n; ++j)
            {
                spatialVector V(Zero);
                for (label l = 0; l < n; ++l)
                {
                    V += Dinv(j, l)*U[l];
                }
                Ia.subtractOuter(V, U[j]);
            }

            pa += Ia & ws.c[i];
            for (label j = 0; j < n; ++j)
            {
                pa += U[j]*Dinvu[j];
            }
        }
        else
        {
            pa += Ia & ws.c[i];
        }

        const label p = lambda_[i];
        if (p)
        {
            const label rotation = XlambdaRotation(i);
            Ia.transformAddTo(ws.Xlambda[i], ws.IA[p], rotation);
            ws.pA[p] += transformForce(ws.Xlambda[i], rotation, pa);
        }
    }

    // Accelerations, root to leaves; gravity as an upward acceleration of
    // the root
    accelerationPass(ws.u, &ws.c, spatialVector(Zero, -g_), ws, ws.a, qDdot);
}


void Foam::RBD::rigidBodyModel::accelerationPass
(
    const List<vector>& u,
    const List<spatialVector>* c,
    const spatialVector& a0,
    const rigidBodyModelWorkspace& ws,
    List<spatialVector>& A,
    scalarField& qDdot
) const
{
    A[0] = a0;

    for (label i = 1; i < nBodies(); ++i)
    {
        const joint& Ji = joints_[i];
        const label n = Ji.nDoF();
        const label k = Ji.unitColumn();
        const label qi = Ji.qIndex();
        const FixedList<spatialVector, joint::maxDoF>& U = ws.U[i];

        const spatialVector& ap = A[lambda_[i]];
        spatialVector& a = A[i];

        if (freeParent_[i] >= 0)
        {
            // A free body: done with its parent
            continue;
        }

        a = transformMotion(ws.Xlambda[i], XlambdaRotation(i), ap);
        if (c)
        {
            a += (*c)[i];
        }

        const label f = freeChild_[i];
        if (f >= 0)
        {
            // The massless parent of free body f (Pxyz: S = e3 e4 e5, so its
            // angular acceleration is a's): the free body's acceleration
            // from its articulated inertia's inverse, then the joints'.
            // From f's: angular, af.w = E a.w + cf.w + S_w qDdot_f; linear,
            // af.l = E (a.l + qDdot_p - r x a.w) + cf.l
            const spatialTransform& X = ws.Xlambda[f];
            const label qf = joints_[f].qIndex();
            spatialVector& af = A[f];
            af = ws.IA[i] & spatialVector(u[f], u[i]);
            spatialVector ar(af);
            if (c)
            {
                ar -= (*c)[f];
            }
            const vector qDdotf((ar.w() - (X.E() & a.w())) & ws.Dinv[f]);
            const vector al((ar.l() & X.E()) + (X.r() ^ a.w()));
            const vector qDdotp(al - a.l());
            a.l() = al;
            for (direction j = 0; j < 3; ++j)
            {
                qDdot[qi + j] = qDdotp[j];
                qDdot[qf + j] = qDdotf[j];
            }
            continue;
        }

        if (k >= 0 && n == 1)
        {
            // U and u as the backward pass left them: Xlambda^T U, u - U c
            const scalar qDdoti = ws.Dinv[i].xx()*(u[i].x() - (U[0] && ap));
            qDdot[qi] = qDdoti;
            a[k] += qDdoti;
        }
        else
        {
            const joint::XSvc& J = ws.J[i];
            vector uUa(Zero);
            for (label j = 0; j < n; ++j)
            {
                uUa[j] = u[i][j] - (U[j] && a);
            }
            const vector qDdoti(ws.Dinv[i] & uUa);

            for (label j = 0; j < n; ++j)
            {
                qDdot[qi + j] = qDdoti[j];
                a += J.S[j]*qDdoti[j];
            }
        }
    }
}


void Foam::RBD::rigidBodyModel::forwardDynamics
(
    rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    const scalarField& tau,
    const Field<spatialVector>& fx
) const
{
    kinematics(state, ws);
    articulatedBodyDynamics(tau, fx, ws, state.qDdot());
}


// ************************************************************************* //
