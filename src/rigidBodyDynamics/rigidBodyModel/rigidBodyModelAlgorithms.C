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
    The model's algorithms, written after Featherstone, Rigid Body Dynamics
    Algorithms (2008): kinematics and the articulated-body algorithm (table
    7.1), recursive Newton-Euler (table 5.1), composite-rigid-body (table
    6.2).  Symbols as in the book; nothing here allocates.

    A free body (a floating joint: a massless body on Pxyz from the root,
    then the body on a rotational joint) is one joint of six degrees of
    freedom to the articulated-body algorithm: its acceleration is its
    articulated inertia's inverse times its joint force less its bias
    (for a body with nothing on it the inverse is the model's, made once),
    and the joints' accelerations follow from it; nothing passes to the
    root.  The same answer as the two joints one after the other, for
    about a quarter of the instructions (callgrind, docs/performance.md).
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- Inverse of the leading n x n block of D (n <= 3), padded with zeros
    inline tensor invD(const tensor& D, const label n)
    {
        if (n == 1)
        {
            return tensor(1.0/D.xx(), 0, 0, 0, 0, 0, 0, 0, 0);
        }
        else if (n == 2)
        {
            const scalar det = D.xx()*D.yy() - D.xy()*D.yx();
            return tensor
            (
                D.yy()/det, -D.xy()/det, 0,
               -D.yx()/det,  D.xx()/det, 0,
                0, 0, 0
            );
        }
        return inv(D);
    }

    //- E v (transpose: E^T v) for a rotation E about the coordinate axis
    //  k: with (i, j, k) cyclic, E_ii = E_jj = c and E_ij = -E_ji = s
    template<direction k, bool transpose>
    inline vector rotate(const tensor& E, const vector& v)
    {
        constexpr direction i = (k + 1) % 3;
        constexpr direction j = (k + 2) % 3;
        const scalar c = E(i, i);
        const scalar s = transpose ? -E(i, j) : E(i, j);

        vector Ev;
        Ev[k] = v[k];
        Ev[i] = c*v[i] + s*v[j];
        Ev[j] = c*v[j] - s*v[i];
        return Ev;
    }

    //- X & m for a motion vector m, given what X's rotation is (as
    //  rigidBodyModel::XlambdaRotation): 14 multiplications about a
    //  coordinate axis, 6 without rotation, 24 for any
    template<direction k>
    inline spatialVector motion
    (
        const spatialTransform& X,
        const spatialVector& m
    )
    {
        return spatialVector
        (
            rotate<k, false>(X.E(), m.w()),
            rotate<k, false>(X.E(), m.l() - (X.r() ^ m.w()))
        );
    }

    inline spatialVector transformMotion
    (
        const spatialTransform& X,
        const label rotation,
        const spatialVector& m
    )
    {
        switch (rotation)
        {
            case 0: return motion<0>(X, m);
            case 1: return motion<1>(X, m);
            case 2: return motion<2>(X, m);
            case 3: return spatialVector(m.w(), m.l() - (X.r() ^ m.w()));
            default: return X & m;
        }
    }

    //- X^T & f for a force f, given what X's rotation is
    template<direction k>
    inline spatialVector force
    (
        const spatialTransform& X,
        const spatialVector& f
    )
    {
        const vector ETfl(rotate<k, true>(X.E(), f.l()));
        return spatialVector
        (
            rotate<k, true>(X.E(), f.w()) + (X.r() ^ ETfl),
            ETfl
        );
    }

    inline spatialVector transformForce
    (
        const spatialTransform& X,
        const label rotation,
        const spatialVector& f
    )
    {
        switch (rotation)
        {
            case 0: return force<0>(X, f);
            case 1: return force<1>(X, f);
            case 2: return force<2>(X, f);
            case 3: return spatialVector(f.w() + (X.r() ^ f.l()), f.l());
            default: return X.T() & f;
        }
    }

    //- w x e_m, e_m the unit vector of coordinate axis m
    template<direction m>
    inline vector crossAxis(const vector& w)
    {
        constexpr direction i = (m + 1) % 3;
        constexpr direction j = (m + 2) % 3;
        vector we;
        we[m] = 0;
        we[i] = w[j];
        we[j] = -w[i];
        return we;
    }

    //- v x (qDot e_k): the velocity product of a joint of one degree of
    //  freedom whose motion subspace is the unit spatial vector e_k: 4
    //  multiplications instead of 18
    template<direction k>
    inline spatialVector crossUnit(const spatialVector& v, const scalar qDot)
    {
        if (k < 3)
        {
            return spatialVector
            (
                qDot*crossAxis<k % 3>(v.w()),
                qDot*crossAxis<k % 3>(v.l())
            );
        }
        return spatialVector(Zero, qDot*crossAxis<k % 3>(v.w()));
    }

    inline spatialVector velocityProduct
    (
        const RBD::joint::XSvc& J,
        const label k,
        const label nDoF,
        const spatialVector& v
    )
    {
        if (nDoF == 1)
        {
            switch (k)
            {
                case 0: return crossUnit<0>(v, J.v[0]);
                case 1: return crossUnit<1>(v, J.v[1]);
                case 2: return crossUnit<2>(v, J.v[2]);
                case 3: return crossUnit<3>(v, J.v[3]);
                case 4: return crossUnit<4>(v, J.v[4]);
                case 5: return crossUnit<5>(v, J.v[5]);
            }
        }
        return J.c + (v ^ J.v);
    }

    //- For a free body's rotational joint, S_w^-T: S_w the 3x3 matrix of
    //  the angular parts of its columns of S (the rows of the tensor built
    //  from them, so its inverse is S_w^-T)
    inline tensor freeSinvT(const RBD::joint::XSvc& J)
    {
        return inv(tensor(J.S[0].w(), J.S[1].w(), J.S[2].w()));
    }

    //- For a free body, the linear part of the force its massless parent
    //  passes on, in the body's axes: the parent's joint forces (Pxyz)
    //  less the linear part of the parent's bias pAp (from external forces
    //  on the parent; their moment goes to the root), rotated by the
    //  body's transform X from the parent.  The force acts at the
    //  rotational joint's centre, the body's origin
    inline vector freeLinearForce
    (
        const spatialTransform& X,
        const vector& tauP,
        const spatialVector& pAp
    )
    {
        return X.E() & (tauP - pAp.l());
    }

    //- Whether a spatial force is zero
    inline bool isZero(const spatialVector& f)
    {
        return
            f[0] == 0 && f[1] == 0 && f[2] == 0
         && f[3] == 0 && f[4] == 0 && f[5] == 0;
    }
}


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


Foam::scalar Foam::RBD::rigidBodyModel::rate
(
    const rateConstraint& c,
    const rigidBodyModelWorkspace& ws
) const
{
    updateX0(ws);
    return (ws.X0[c.bodyID].E() & c.axis) & ws.v[c.bodyID].w();
}


void Foam::RBD::rigidBodyModel::constraintResiduals
(
    const UList<rateConstraint>& C,
    rigidBodyModelWorkspace& ws
) const
{
    forAll(C, r)
    {
        const rateConstraint& c = C[r];
        const vector e(ws.X0[c.bodyID].E() & c.axis);
        const scalar omega = e & ws.v[c.bodyID].w();
        ws.bR[r] =
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
        ws.pR = Zero;
        const rateConstraint& cs = C[s];
        ws.pR[cs.bodyID] =
            spatialVector(-(ws.X0[cs.bodyID].E() & cs.axis), Zero);
        if (cs.parentID)
        {
            ws.pR[cs.parentID] =
                spatialVector(ws.X0[cs.parentID].E() & cs.axis, Zero);
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
            spatialVector pa(ws.pR[i]);
            vector& u = ws.uR[i];
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
                ws.uR[p] =
                    freeLinearForce(ws.Xlambda[i], Zero, ws.pR[p]) - pa.l();
                continue;
            }

            if (Ji.unitColumn() >= 0 && n == 1)
            {
                // U is Xlambda^T U: the parent's share is taken whole
                u.x() = -pa[Ji.unitColumn()];
                if (p)
                {
                    ws.pR[p] +=
                        transformForce(ws.Xlambda[i], rotation, pa)
                      + U[0]*(ws.Dinv[i].xx()*u.x());
                }
                continue;
            }

            for (label j = 0; j < n; ++j)
            {
                u[j] = -(ws.J[i].S[j] && pa);
            }
            const vector Dinvu(ws.Dinv[i] & u);
            for (label j = 0; j < n; ++j)
            {
                pa += U[j]*Dinvu[j];
            }
            if (p)
            {
                ws.pR[p] += transformForce(ws.Xlambda[i], rotation, pa);
            }
        }

        // Accelerations of the response, root to leaves
        accelerationPass(ws.uR, nullptr, Zero, ws, ws.aR, ws.qDdotR[s]);

        forAll(C, r)
        {
            const rateConstraint& cr = C[r];
            ws.AR(r, s) =
                (ws.X0[cr.bodyID].E() & cr.axis) & ws.aR[cr.bodyID].w();
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
    scalarSquareMatrix& L = ws.LR;
    scalarField& b = ws.bR;
    L = ws.AR;

    scalar scale = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            scale = max(scale, mag(L(i, j)));
        }
    }

    // Gaussian elimination with partial pivoting
    for (label k = 0; k < n; ++k)
    {
        label pivot = k;
        for (label i = k + 1; i < n; ++i)
        {
            if (mag(L(i, k)) > mag(L(pivot, k)))
            {
                pivot = i;
            }
        }

        if (!(mag(L(pivot, k)) > 1e-12*scale))
        {
            FatalErrorInFunction
                << "The prescribed rotation of body "
                << bodies_[C[k].bodyID].name() << " about " << C[k].axis
                << " cannot be met: its joint does not turn it about that"
                << " axis relative to "
                << bodies_[C[k].parentID].name()
                << ", or another prescription already fixes that rotation"
                << " (the response of the prescribed rates to the motors'"
                << " moments is singular: " << ws.AR << ")"
                << exit(FatalError);
        }

        if (pivot != k)
        {
            for (label j = 0; j < n; ++j)
            {
                std::swap(L(k, j), L(pivot, j));
            }
            std::swap(b[k], b[pivot]);
        }

        for (label i = k + 1; i < n; ++i)
        {
            const scalar f = L(i, k)/L(k, k);
            for (label j = k; j < n; ++j)
            {
                L(i, j) -= f*L(k, j);
            }
            b[i] -= f*b[k];
        }
    }

    for (label k = n - 1; k >= 0; --k)
    {
        for (label j = k + 1; j < n; ++j)
        {
            b[k] -= L(k, j)*b[j];
        }
        b[k] /= L(k, k);
    }
}


void Foam::RBD::rigidBodyModel::addResponses
(
    const rigidBodyModelWorkspace& ws,
    scalarField& x
) const
{
    forAll(ws.bR, s)
    {
        const scalarField& r = ws.qDdotR[s];
        forAll(x, j)
        {
            x[j] += ws.bR[s]*r[j];
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
    constraintResiduals(C, ws);
    unitMotorResponses(C, ws);
    solveConstraints(C, ws);

    addResponses(ws, qDdot);
    forAll(C, s)
    {
        C[s].moment = ws.bR[s];
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
    const UList<rateConstraint>& C
) const
{
    if (C.empty())
    {
        return;
    }

    // The responses to the motors' unit moments (they depend on the
    // positions only)
    motorResponses(state, ws, C);

    // The motors' impulses that bring the rates to the constraints'
    forAll(C, r)
    {
        ws.bR[r] = C[r].rate - rate(C[r], ws);
    }
    solveConstraints(C, ws);

    addResponses(ws, state.qDot());

    // At the new velocities, the change of the motors' moments that gives
    // the accelerations the constraints ask
    kinematics(state, ws);
    bodyAccelerations(state.qDdot(), ws);
    updateX0(ws);
    constraintResiduals(C, ws);
    solveConstraints(C, ws);

    addResponses(ws, state.qDdot());
}


void Foam::RBD::rigidBodyModel::massMatrix
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    scalarSquareMatrix& H
) const
{
    kinematics(state, ws);

    const label nb = nBodies();

    H = Zero;

    // Composite inertias, leaves to root
    for (label i = 1; i < nb; ++i)
    {
        ws.IA[i] = I_[i];
    }
    for (label i = nb - 1; i > 0; --i)
    {
        const label p = lambda_[i];
        if (p)
        {
            ws.IA[i].transformAddTo
            (
                ws.Xlambda[i],
                ws.IA[p],
                XlambdaRotation(i)
            );
        }
    }

    for (label i = 1; i < nb; ++i)
    {
        const joint::XSvc& Ji = ws.J[i];
        const label qi = joints_[i].qIndex();

        for (label k = 0; k < joints_[i].nDoF(); ++k)
        {
            spatialVector F(ws.IA[i] & Ji.S[k]);

            for (label l = 0; l < joints_[i].nDoF(); ++l)
            {
                H(qi + l, qi + k) = Ji.S[l] && F;
            }

            label j = i;
            while (lambda_[j])
            {
                F = ws.Xlambda[j].T() & F;
                j = lambda_[j];

                const label qj = joints_[j].qIndex();
                for (label l = 0; l < joints_[j].nDoF(); ++l)
                {
                    H(qj + l, qi + k) = ws.J[j].S[l] && F;
                    H(qi + k, qj + l) = H(qj + l, qi + k);
                }
            }
        }
    }
}
