/*---------------------------------------------------------------------------*\
    The model's algorithms, written after Featherstone, Rigid Body Dynamics
    Algorithms (2008): kinematics and the articulated-body algorithm (table
    7.1), recursive Newton-Euler (table 5.1), composite-rigid-body (table
    6.2).  Symbols as in the book; nothing here allocates.
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- Outer product a b^T of two spatial vectors
    inline spatialTensor spatialOuter(const spatialVector& a, const spatialVector& b)
    {
        spatialTensor T;
        for (direction i = 0; i < 6; ++i)
        {
            for (direction j = 0; j < 6; ++j)
            {
                T(i, j) = a[i]*b[j];
            }
        }
        return T;
    }

    //- X^T I X: a spatial inertia in the parent's frame, by 3x3 blocks.
    //  With I = [A B; B^T C] (A, C symmetric) and X = (E, r):
    //      A' = E^T A E,  B' = E^T B E,  C' = E^T C E
    //      X^T I X = [A' - B' rx + rx B'^T - rx C' rx,  B' + rx C';
    //                 (B' + rx C')^T,                    C']
    //  (rx the cross-product matrix of r): about a quarter of the work of
    //  two dense 6x6 products
    inline spatialTensor transformInertia
    (
        const spatialTransform& X,
        const spatialTensor& I
    )
    {
        const tensor A
        (
            I(0, 0), I(0, 1), I(0, 2),
            I(1, 0), I(1, 1), I(1, 2),
            I(2, 0), I(2, 1), I(2, 2)
        );
        const tensor B
        (
            I(0, 3), I(0, 4), I(0, 5),
            I(1, 3), I(1, 4), I(1, 5),
            I(2, 3), I(2, 4), I(2, 5)
        );
        const tensor C
        (
            I(3, 3), I(3, 4), I(3, 5),
            I(4, 3), I(4, 4), I(4, 5),
            I(5, 3), I(5, 4), I(5, 5)
        );

        const tensor& E = X.E();
        const tensor ET(E.T());
        const tensor rx(RBD::crossMatrix(X.r()));

        const tensor Ap((ET & A) & E);
        const tensor Bp((ET & B) & E);
        const tensor Cp((ET & C) & E);

        const tensor TR(Bp + (rx & Cp));
        const tensor TL(Ap - (Bp & rx) + (rx & Bp.T()) - ((rx & Cp) & rx));

        return spatialTensor
        (
            TL, TR,
            TR.T(), Cp
        );
    }

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

    ws.X0[0] = spatialTransform();
    ws.v[0] = Zero;

    for (label i = 1; i < nBodies(); ++i)
    {
        joint::XSvc& J = ws.J[i];
        joints_[i].jcalc(J, q, qDot);

        const label p = lambda_[i];

        ws.Xlambda[i] = J.X & XT_[i];
        ws.X0[i] = ws.Xlambda[i] & ws.X0[p];
        ws.v[i] = (ws.Xlambda[i] & ws.v[p]) + J.v;
        ws.c[i] = J.c + (ws.v[i] ^ J.v);
    }
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
        ws.pA[i] = (v ^ *(I_[i] & v)) - (*ws.X0[i] & fx[i]);
    }

    // Articulated inertias and bias forces, leaves to root
    for (label i = nb - 1; i > 0; --i)
    {
        const joint::XSvc& J = ws.J[i];
        const label n = joints_[i].nDoF();
        const label qi = joints_[i].qIndex();
        const spatialTensor& IA = ws.IA[i];
        const spatialVector& pA = ws.pA[i];

        // Ia = IA - U D^-1 U^T,  pa = pA + Ia c + U D^-1 u
        spatialTensor Ia(IA);
        spatialVector pa(pA);

        if (n)
        {
            FixedList<spatialVector, joint::maxDoF>& U = ws.U[i];
            tensor D(Zero);
            vector& u = ws.u[i];

            for (label k = 0; k < n; ++k)
            {
                U[k] = IA & J.S[k];
                u[k] = tau[qi + k] - (J.S[k] && pA);
            }
            for (label j = 0; j < n; ++j)
            {
                for (label k = 0; k < n; ++k)
                {
                    D(j, k) = J.S[j] && U[k];
                }
            }

            const tensor& Dinv = ws.Dinv[i] = invD(D, n);
            const vector Dinvu(Dinv & u);

            for (label j = 0; j < n; ++j)
            {
                spatialVector UDinv(Zero);
                for (label k = 0; k < n; ++k)
                {
                    UDinv += Dinv(j, k)*U[k];
                }
                Ia -= spatialOuter(UDinv, U[j]);
                pa += U[j]*Dinvu[j];
            }
        }

        pa += Ia & ws.c[i];

        const label p = lambda_[i];
        if (p)
        {
            ws.IA[p] += transformInertia(ws.Xlambda[i], Ia);
            ws.pA[p] += ws.Xlambda[i].T() & pa;
        }
    }

    // Accelerations, root to leaves; gravity as an upward acceleration of
    // the root
    ws.a[0] = spatialVector(Zero, -g_);

    for (label i = 1; i < nb; ++i)
    {
        const joint::XSvc& J = ws.J[i];
        const label n = joints_[i].nDoF();
        const label qi = joints_[i].qIndex();

        spatialVector a((ws.Xlambda[i] & ws.a[lambda_[i]]) + ws.c[i]);

        if (n)
        {
            const FixedList<spatialVector, joint::maxDoF>& U = ws.U[i];
            vector uUa(Zero);
            for (label k = 0; k < n; ++k)
            {
                uUa[k] = ws.u[i][k] - (U[k] && a);
            }
            const vector qDdoti(ws.Dinv[i] & uUa);

            for (label k = 0; k < n; ++k)
            {
                qDdot[qi + k] = qDdoti[k];
                a += J.S[k]*qDdoti[k];
            }
        }

        ws.a[i] = a;
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


void Foam::RBD::rigidBodyModel::inverseDynamics
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    const Field<spatialVector>& fx,
    scalarField& tau
) const
{
    kinematics(state, ws);

    const scalarField& qDdot = state.qDdot();
    const label nb = nBodies();

    ws.a[0] = spatialVector(Zero, -g_);

    // Accelerations and the forces each body needs, root to leaves
    for (label i = 1; i < nb; ++i)
    {
        const joint::XSvc& J = ws.J[i];
        const label qi = joints_[i].qIndex();

        spatialVector a((ws.Xlambda[i] & ws.a[lambda_[i]]) + ws.c[i]);
        for (label k = 0; k < joints_[i].nDoF(); ++k)
        {
            a += J.S[k]*qDdot[qi + k];
        }
        ws.a[i] = a;

        const spatialVector& v = ws.v[i];
        ws.pA[i] =
            (I_[i] & a) + (v ^ *(I_[i] & v)) - (*ws.X0[i] & fx[i]);
    }

    // Joint forces, leaves to root
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
            ws.IA[p] += transformInertia(ws.Xlambda[i], ws.IA[i]);
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
