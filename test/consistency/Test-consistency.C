/*---------------------------------------------------------------------------*\
Application
    Test-consistency

Description
    Forward dynamics (articulated-body algorithm), inverse dynamics
    (recursive Newton-Euler) and the mass matrix (composite-rigid-body
    algorithm) agree on random trees that mix every joint type, with random
    positions, velocities, joint forces and external forces:
        ID(q, qDot, ABA(q, qDot, tau, fx), fx) = tau
        H(q) qDdot + C(q, qDot, fx) = tau,   C = ID(q, qDot, 0, fx)
    to 1e-10 relative to the size of tau.  Also H is symmetric positive
    definite.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "Random.H"
#include "OStringStream.H"

using namespace Foam;

namespace consistencyTest
{

using Foam::sqrt;

const char* jointDicts[] =
{
    "{ type Px; }", "{ type Py; }", "{ type Pz; }",
    "{ type Pa; axis (1 2 3); }", "{ type Rx; }", "{ type Ry; }",
    "{ type Rz; }", "{ type Ra; axis (-1 0.5 2); }", "{ type Pxyz; }",
    "{ type Rxyz; }", "{ type Ryxz; }", "{ type Rzyx; }", "{ type Rs; }",
    "{ type floating; }", "{ type null; }",
    "{ type composite; joints ({ type Ry; } { type Pa; axis (0 1 1); }); }"
};
const label nJointTypes = sizeof(jointDicts)/sizeof(jointDicts[0]);


std::string num(const scalar x)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.17g", x);
    return buf;
}


std::string vec(Random& rnd, const scalar s)
{
    return
        "(" + num(s*(2*rnd.sample01<scalar>() - 1)) + " "
      + num(s*(2*rnd.sample01<scalar>() - 1)) + " "
      + num(s*(2*rnd.sample01<scalar>() - 1)) + ")";
}


//- A random tree of n bodies
std::string randomModel(Random& rnd, const label n, const label firstJoint)
{
    std::string bodies;
    for (label i = 0; i < n; ++i)
    {
        const std::string parent =
            i == 0 ? "root" : "b" + std::to_string(rnd.position<label>(0, i - 1));
        const tensor R
        (
            Ra
            (
                normalised
                (
                    vector(rnd.sample01<scalar>(), 0.3, rnd.sample01<scalar>())
                ),
                rnd.sample01<scalar>()*3
            )
        );
        std::string Rs = "(";
        for (const scalar c : R) Rs += num(c) + " ";
        Rs += ")";

        // Principal moments meeting the triangle inequality, rotated
        const vector ev
        (
            1 + rnd.sample01<scalar>(),
            1 + rnd.sample01<scalar>(),
            1 + rnd.sample01<scalar>()
        );
        const symmTensor I
        (
            transform(Rx(rnd.sample01<scalar>()), symmTensor(ev.x(), 0, 0, ev.y(), 0, ev.z()))
        );
        std::string Is = "(";
        for (const scalar c : I) Is += num(c) + " ";
        Is += ")";

        const label j = (firstJoint + i) % nJointTypes;

        bodies +=
            "b" + std::to_string(i) + " { type rigidBody; parent " + parent
          + "; mass " + num(0.5 + rnd.sample01<scalar>())
          + "; centreOfMass " + vec(rnd, 0.5) + "; inertia " + Is
          + "; transform " + Rs + " " + vec(rnd, 1) + "; joint "
          + jointDicts[j] + " } ";
    }

    return
        "solver { type Newmark; } g (0 0 -9.81); bodies { " + bodies + "}";
}


void checkTree(Random& rnd, const label n, const label firstJoint)
{
    const RBD::rigidBodyModel m
    (
        test::dictFromString(randomModel(rnd, n, firstJoint))
    );

    const label nDoF = m.nDoF();
    RBD::rigidBodyModelState state(nDoF);
    RBD::rigidBodyModelWorkspace ws(m);

    // Random state; quaternion slots within the unit ball
    forAll(state.q(), i)
    {
        state.q()[i] = 0.5*(2*rnd.sample01<scalar>() - 1);
        state.qDot()[i] = 2*(2*rnd.sample01<scalar>() - 1);
    }

    scalarField tau(nDoF);
    forAll(tau, i)
    {
        tau[i] = 10*(2*rnd.sample01<scalar>() - 1);
    }
    Field<spatialVector> fx(m.nBodies());
    forAll(fx, i)
    {
        for (direction c = 0; c < 6; ++c)
        {
            fx[i][c] = 5*(2*rnd.sample01<scalar>() - 1);
        }
    }

    const std::string what =
        std::to_string(n) + " bodies, " + std::to_string(nDoF)
      + " dof, joints from " + std::to_string(firstJoint);

    // Forward then inverse dynamics
    m.forwardDynamics(state, ws, tau, fx);
    scalarField tauID(nDoF);
    m.inverseDynamics(state, ws, fx, tauID);

    const scalar scale = max(scalar(1), max(mag(tau)));
    test::checkAbs
    (
        max(mag(tauID - tau))/scale, 0, 1e-10,
        "inverse dynamics of ABA accelerations returns tau, " + what
    );

    // Mass matrix and bias forces
    scalarSquareMatrix H(nDoF);
    m.massMatrix(state, ws, H);

    const scalarField qDdot(state.qDdot());
    state.qDdot() = Zero;
    scalarField C(nDoF);
    m.inverseDynamics(state, ws, fx, C);

    scalarField HqDdotC(C);
    scalar asym = 0;
    for (label i = 0; i < nDoF; ++i)
    {
        for (label j = 0; j < nDoF; ++j)
        {
            HqDdotC[i] += H(i, j)*qDdot[j];
            asym = max(asym, mag(H(i, j) - H(j, i)));
        }
    }

    test::checkAbs
    (
        max(mag(HqDdotC - tau))/scale, 0, 1e-10,
        "H qDdot + C = tau, " + what
    );
    test::checkAbs(asym, 0, 1e-12, "mass matrix symmetric, " + what);

    // Positive definite: Cholesky succeeds
    scalarSquareMatrix L(H);
    bool spd = true;
    for (label j = 0; j < nDoF && spd; ++j)
    {
        scalar d = L(j, j);
        for (label k = 0; k < j; ++k) d -= sqr(L(j, k));
        if (!(d > 0)) { spd = false; break; }
        L(j, j) = sqrt(d);
        for (label i = j + 1; i < nDoF; ++i)
        {
            scalar s = L(i, j);
            for (label k = 0; k < j; ++k) s -= L(i, k)*L(j, k);
            L(i, j) = s/L(j, j);
        }
    }
    test::check(spd, "mass matrix positive definite, " + what);

    // The model written and read back moves the same
    OStringStream os;
    os.precision(17);
    m.write(os);
    IStringStream is(os.str());
    const RBD::rigidBodyModel m2((dictionary(is)));

    RBD::rigidBodyModelState state2(m2.nDoF());
    state2.q() = state.q();
    state2.qDot() = state.qDot();
    RBD::rigidBodyModelWorkspace ws2(m2);
    m.forwardDynamics(state, ws, tau, fx);
    m2.forwardDynamics(state2, ws2, tau, fx);

    test::checkAbs
    (
        max(mag(state2.qDdot() - state.qDdot()))
       /max(scalar(1), max(mag(state.qDdot()))),
        0, 1e-12,
        "model written and read back gives the same accelerations, " + what
    );
}

} // End namespace consistencyTest


int main(int argc, char *argv[])
{
    using namespace consistencyTest;

    Random rnd(1234);

    for (label trial = 0; trial < 8; ++trial)
    {
        checkTree(rnd, 6 + trial, (3*trial) % nJointTypes);
    }
    checkTree(rnd, 1, 0);

    return test::testResult();
}
