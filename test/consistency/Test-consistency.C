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

    A free body (a rotational joint on a massless Pxyz from the root, as a
    floating joint expands) is solved as one 6-degree-of-freedom joint:
    such trees are among the random ones, and each is checked against the
    same body on Px, Py and Pz one after another (the general algorithm),
    with and without bodies on it, joint forces, external forces on every
    body (the massless one's too) and rate constraints (motors) on the
    free body and on one of its children: the accelerations and the
    motors' moments agree to 1e-10.

    Body transforms X0 (made as copies and sums where no frame turns) are
    the products of the joints' transforms, and points' velocities the
    central differences of their positions, on a tree of slides, turning
    bodies, a massless frame and a merged body.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "Random.H"
#include "OStringStream.H"
#include <fenv.h>

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
    "{ type composite; joints ({ type Ry; } { type Pa; axis (0 1 1); }); }",
    "{ type composite; joints ({ type Pxyz; } { type Rs; }); }"
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


//- Random joint forces (within 10) and external forces (within 5)
void randomLoads(Random& rnd, scalarField& tau, Field<spatialVector>& fx)
{
    forAll(tau, i)
    {
        tau[i] = 10*(2*rnd.sample01<scalar>() - 1);
    }
    forAll(fx, i)
    {
        for (direction c = 0; c < 6; ++c)
        {
            fx[i][c] = 5*(2*rnd.sample01<scalar>() - 1);
        }
    }
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
    Field<spatialVector> fx(m.nBodies());
    randomLoads(rnd, tau, fx);

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

//- A body's absolute rotation rate about a global axis, its motor in the
//  joints below parentID (as restraints::prescribedRotation builds it)
class rotationRate
:
    public RBD::rateConstraint
{
public:

    label bodyID = -1;
    label parentID = 0;
    vector axis = Zero;

    explicit rotationRate(const label nDoF)
    :
        RBD::rateConstraint(nDoF)
    {}

    virtual void linearise
    (
        const RBD::rigidBodyModel& model,
        const RBD::rigidBodyModelWorkspace& ws
    )
    {
        model.angularRow(bodyID, parentID, axis, ws, *this);
    }
};


//- The body of a free-body model: on composite(TRANSLATION, ROTATION)
std::string freeBodyModel
(
    const std::string& translation,
    const std::string& rotation,
    const std::string& bodies
)
{
    return
        "solver { type Newmark; } g (0 0 -9.81); bodies { b { type rigidBody;"
        " parent root; mass 1.3; centreOfMass (0.1 -0.2 0.05);"
        " inertia (0.4 0.02 -0.01 0.3 0.03 0.5);"
        " transform (0 -1 0 1 0 0 0 0 1) (0.5 0.45 0.1);"
        " joint { type composite; joints (" + translation + " " + rotation
      + "); } } " + bodies + "}";
}


//- A free body on ROTATION, with nChildren bodies on it (a chain), against
//  the same on Px, Py and Pz one after another
void checkFreeBody(Random& rnd, const std::string& rotation, const label nChildren)
{
    std::string children;
    for (label i = 0; i < nChildren; ++i)
    {
        children +=
            "c" + std::to_string(i) + " { type cuboid; parent "
          + (i ? "c" + std::to_string(i - 1) : std::string("b"))
          + "; mass 0.7; L (0.2 0.1 0.3); centreOfMass (0 0 0.15);"
            " transform (1 0 0 0 0.6 0.8 0 -0.8 0.6) " + vec(rnd, 0.5)
          + "; joint { type " + (i % 2 ? "Rx" : "Ry") + "; } } ";
    }

    const RBD::rigidBodyModel free
    (
        test::dictFromString
        (
            freeBodyModel("{ type Pxyz; }", rotation, children)
        )
    );
    const RBD::rigidBodyModel chain
    (
        test::dictFromString
        (
            freeBodyModel
            (
                "{ type Px; } { type Py; } { type Pz; }", rotation, children
            )
        )
    );

    const std::string what =
        "free body on " + rotation + " with " + std::to_string(nChildren)
      + " bodies on it";
    test::check
    (
        free.isFree(free.bodyID("b")) && !chain.isFree(chain.bodyID("b")),
        "solved as a free body (and not on Px Py Pz), " + what
    );

    const label nDoF = free.nDoF();
    RBD::rigidBodyModelState sf(nDoF), sc(nDoF);
    forAll(sf.q(), i)
    {
        sf.q()[i] = 0.5*(2*rnd.sample01<scalar>() - 1);
        sf.qDot()[i] = 2*(2*rnd.sample01<scalar>() - 1);
    }
    sc.q() = sf.q();
    sc.qDot() = sf.qDot();

    scalarField tau(nDoF);
    forAll(tau, i)
    {
        tau[i] = 10*(2*rnd.sample01<scalar>() - 1);
    }

    // The same external forces by body: the massless body carrying the
    // rotation is b_joint0 of one, b_joint2 of the other
    Field<spatialVector> ff(free.nBodies(), Zero), fc(chain.nBodies(), Zero);
    for (direction c = 0; c < 6; ++c)
    {
        ff[free.bodyID("b")][c] = 5*(2*rnd.sample01<scalar>() - 1);
        ff[free.bodyID("b_joint0")][c] = 5*(2*rnd.sample01<scalar>() - 1);
        for (label i = 0; i < nChildren; ++i)
        {
            ff[free.bodyID("c" + std::to_string(i))][c] =
                5*(2*rnd.sample01<scalar>() - 1);
        }
    }
    fc[chain.bodyID("b")] = ff[free.bodyID("b")];
    fc[chain.bodyID("b_joint2")] = ff[free.bodyID("b_joint0")];
    for (label i = 0; i < nChildren; ++i)
    {
        const word c("c" + std::to_string(i));
        fc[chain.bodyID(c)] = ff[free.bodyID(c)];
    }

    // Motors: on the free body (reaction on the root, then on its massless
    // parent) and on its first child (reaction on the free body)
    const label nC = nChildren ? 3 : 2;
    PtrList<rotationRate> Cf(nC), Cc(nC);
    UPtrList<RBD::rateConstraint> CfList(nC), CcList(nC);
    forAll(Cf, s)
    {
        Cf.set(s, new rotationRate(free.nDoF()));
        Cc.set(s, new rotationRate(chain.nDoF()));
        CfList.set(s, &Cf[s]);
        CcList.set(s, &Cc[s]);
        Cf[s].axis = normalised(vector(0.3 + s, 1 - 0.4*s, 0.5));
        Cf[s].rate = 1 + s;
        Cf[s].acceleration = 2 - s;
        Cf[s].rateGain = 1/0.1;
        Cc[s].axis = Cf[s].axis;
        Cc[s].rate = Cf[s].rate;
        Cc[s].acceleration = Cf[s].acceleration;
        Cc[s].rateGain = Cf[s].rateGain;
    }
    Cf[0].bodyID = free.bodyID("b");
    Cc[0].bodyID = chain.bodyID("b");
    Cf[1].bodyID = free.bodyID("b");
    Cf[1].parentID = free.bodyID("b_joint0");
    Cc[1].bodyID = chain.bodyID("b");
    Cc[1].parentID = chain.bodyID("b_joint2");
    // Both motors on b about different axes; the second turned so that
    // they do not ask the same of it
    Cf[1].axis = Cc[1].axis = normalised(vector(-1, 0.2, 0.7));
    if (nChildren)
    {
        Cf[2].bodyID = free.bodyID("c0");
        Cf[2].parentID = free.bodyID("b");
        Cc[2].bodyID = chain.bodyID("c0");
        Cc[2].parentID = chain.bodyID("b");
        // The child turns about its joint's axis only
        Cf[2].axis = Cc[2].axis = Zero;
    }

    RBD::rigidBodyModelWorkspace wf(free), wc(chain);
    free.forwardDynamics(sf, wf, tau, ff);
    chain.forwardDynamics(sc, wc, tau, fc);
    const scalar scale = max(scalar(1), max(mag(sc.qDdot())));
    test::checkAbs
    (
        max(mag(sf.qDdot() - sc.qDdot()))/scale, 0, 1e-10,
        "accelerations as on Px Py Pz, " + what
    );

    // With the motors (a child's axis its joint's, now the pose is known)
    if (nChildren)
    {
        free.updateX0(wf);
        Cf[2].axis = Cc[2].axis =
            wf.X0[free.bodyID("c0")].E().T() & vector(0, 1, 0);
    }
    wf.setConstraints(free, Cf.size());
    wc.setConstraints(chain, Cc.size());
    free.kinematics(sf, wf);
    chain.kinematics(sc, wc);
    scalarField qf(nDoF), qc(nDoF);
    free.constrainedDynamics(tau, ff, CfList, wf, qf);
    chain.constrainedDynamics(tau, fc, CcList, wc, qc);
    const scalar scaleC = max(scalar(1), max(mag(qc)));
    test::checkAbs
    (
        max(mag(qf - qc))/scaleC, 0, 1e-10,
        "accelerations with motors as on Px Py Pz, " + what
    );
    scalar dMoment = 0, maxMoment = 1;
    forAll(Cf, s)
    {
        dMoment = max(dMoment, mag(Cf[s].force - Cc[s].force));
        maxMoment = max(maxMoment, mag(Cc[s].force));
    }
    test::checkAbs
    (
        dMoment/maxMoment, 0, 1e-10, "motors' moments as on Px Py Pz, " + what
    );
}

//- A massless frame on a floating joint with a hull merged into it (the
//  pendulum tutorial's masslessBody and mergeWith): the frame is free, and
//  massless until the hull is merged.  Built with floating-point traps on,
//  as an OpenFOAM application runs: no division by zero on the way; then
//  the same as the hull on the floating joint itself
void checkMergedFreeBody()
{
    const std::string hull =
        " type cuboid; mass 2; L (0.3 0.2 0.5);"
        " centreOfMass (0.02 -0.01 0.25);";
    const std::string frame =
        "solver { type Newmark; } g (0 0 -9.81); bodies {"
        " frame { type masslessBody; parent root;"
        " transform (1 0 0 0 1 0 0 0 1) (0.5 0.45 0.1);"
        " joint { type floating; } }"
        " hull {" + hull + " mergeWith frame;"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 0); } }";
    const std::string alone =
        "solver { type Newmark; } g (0 0 -9.81); bodies {"
        " hull {" + hull + " parent root;"
        " transform (1 0 0 0 1 0 0 0 1) (0.5 0.45 0.1);"
        " joint { type floating; } } }";

    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    const RBD::rigidBodyModel merged(test::dictFromString(frame));
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    const RBD::rigidBodyModel single(test::dictFromString(alone));

    test::check
    (
        merged.isFree(merged.bodyID("frame"))
     && !merged.isFree(merged.bodyID("hull")),
        "a massless floating frame with a hull merged into it is built with"
        " floating-point traps on, and is free"
    );

    RBD::rigidBodyModelState sm(6), ss(6);
    forAll(sm.q(), i)
    {
        sm.q()[i] = ss.q()[i] = 0.1*(i + 1);
        sm.qDot()[i] = ss.qDot()[i] = 0.3 - 0.1*i;
    }
    const scalarField tau(6, Zero);
    Field<spatialVector> fm(merged.nBodies(), Zero), fs(single.nBodies(), Zero);
    fm[merged.bodyID("frame")] = spatialVector(0.5, 1, 80, 0, 2, 0);
    fs[single.bodyID("hull")] = fm[merged.bodyID("frame")];
    RBD::rigidBodyModelWorkspace wm(merged), ws(single);
    merged.forwardDynamics(sm, wm, tau, fm);
    single.forwardDynamics(ss, ws, tau, fs);
    test::checkAbs
    (
        max(mag(sm.qDdot() - ss.qDdot()))/max(mag(ss.qDdot())), 0, 1e-12,
        "the frame with the hull merged moves as the hull on the floating"
        " joint"
    );
}

//- Body transforms X0 and points' motion on a tree where slides follow
//  slides and frames do not turn (X0 made as a copy and a sum), slides
//  follow turning bodies, a massless frame carries a body, and a body is
//  merged: X0 against the product of the Xlambdas up to the root, the
//  points' velocities against central differences of their positions,
//  globalPointMotion against globalPoint and v, and forward against
//  inverse dynamics
void checkBodyTransforms(Random& rnd)
{
    const std::string I3 = "transform (1 0 0 0 1 0 0 0 1) ";
    const std::string cuboid =
        " type cuboid; mass 2; L (0.3 0.2 0.5); centreOfMass (0 0 0.1);";
    const std::string model =
        "solver { type Newmark; } g (0 0 -9.81); bodies {"
        " a {" + cuboid + " parent root; " + I3 + "(0.5 0.45 0.1);"
        " joint { type composite; joints ({ type Py; } { type Ry; }); } }"
        " b {" + cuboid + " parent a; " + I3 + "(0 0 0.3); joint { type Pz; } }"
        " c {" + cuboid + " parent b; " + I3 + "(0.1 0 0); joint { type Rx; } }"
        " d {" + cuboid + " parent root; " + I3 + "(1 0 0); joint { type Px; } }"
        " e {" + cuboid + " parent d; " + I3 + "(0 1 0); joint { type Pxyz; } }"
        " f {" + cuboid + " parent e; transform (0 1 0 -1 0 0 0 0 1) (0 0 0.2);"
        " joint { type Pz; } }"
        " g {" + cuboid + " parent f; " + I3 + "(0 0 0.1); joint { type Py; } }"
        " k { type masslessBody; parent d; " + I3 + "(0 0.2 0);"
        " joint { type Rz; } }"
        " l {" + cuboid + " parent k; " + I3 + "(0.3 0 0); joint { type Px; } }"
        " h { type sphere; mass 1; radius 0.1; centreOfMass (0 0 0);"
        " mergeWith c; transform (0 0 1 0 1 0 -1 0 0) (0.1 0.2 0.3); } }";

    const RBD::rigidBodyModel m(test::dictFromString(model));
    const label nDoF = m.nDoF();
    RBD::rigidBodyModelState state(nDoF);
    forAll(state.q(), i)
    {
        state.q()[i] = 0.5*(2*rnd.sample01<scalar>() - 1);
        state.qDot()[i] = 2*(2*rnd.sample01<scalar>() - 1);
    }
    RBD::rigidBodyModelWorkspace ws(m);
    m.kinematics(state, ws);
    m.updateX0(ws);

    // X0 against the product of the Xlambdas
    scalar errX0 = 0;
    for (label i = 1; i < m.nBodies(); ++i)
    {
        spatialTransform X(ws.Xlambda[i]);
        for (label p = m.lambda()[i]; p; p = m.lambda()[p])
        {
            X = X & ws.Xlambda[p];
        }
        errX0 = max(errX0, cmptMax(cmptMag(X.E() - ws.X0[i].E())));
        errX0 = max(errX0, cmptMax(cmptMag(X.r() - ws.X0[i].r())));
    }
    test::checkAbs
    (
        errX0, 0, 1e-14,
        "X0 of every body is the product of the Xlambdas up to the root"
        " (slides on slides, on turning bodies, a massless frame)"
    );

    // Points' motion: against globalPoint and v, and against central
    // differences of the positions (no quaternion: q moves as qDot)
    const vector p0(0.05, -0.1, 0.2);
    const scalar dt = 1e-5;
    RBD::rigidBodyModelState sp(state), sm(state);
    sp.q() += dt*state.qDot();
    sm.q() -= dt*state.qDot();
    RBD::rigidBodyModelWorkspace wp(m), wm(m);
    m.kinematics(sp, wp);
    m.kinematics(sm, wm);

    scalar errSame = 0, errFD = 0;
    for (const word& name : m.bodyNames())
    {
        const label id = m.bodyID(name);
        const RBD::rigidBodyModel::pointMotion pm
        (
            m.globalPointMotion(id, p0, ws)
        );
        errSame = max(errSame, mag(pm.x - m.globalPoint(id, p0, ws)));
        errSame = max(errSame, mag(pm.v - m.v(id, p0, ws).l()));
        const vector vFD
        (
            (m.globalPoint(id, p0, wp) - m.globalPoint(id, p0, wm))/(2*dt)
        );
        errFD = max(errFD, mag(pm.v - vFD)/max(scalar(1), mag(vFD)));
    }
    test::checkAbs
    (
        errSame, 0, 1e-15,
        "globalPointMotion gives globalPoint and v's linear part (every body,"
        " the merged one too)"
    );
    test::checkAbs
    (
        errFD, 0, 1e-8,
        "a point's velocity from globalPointMotion is the central difference"
        " of its positions (every body, the merged one too)"
    );

    // Forward then inverse dynamics, with forces on every body (the
    // massless frame's too)
    scalarField tau(nDoF);
    Field<spatialVector> fx(m.nBodies());
    randomLoads(rnd, tau, fx);
    m.forwardDynamics(state, ws, tau, fx);
    scalarField tauID(nDoF);
    m.inverseDynamics(state, ws, fx, tauID);
    test::checkAbs
    (
        max(mag(tauID - tau))/max(scalar(1), max(mag(tau))), 0, 1e-10,
        "inverse dynamics of ABA accelerations returns tau on the tree of"
        " slides, a massless frame and a merged body"
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

    // A floating joint from the root, with bodies on it and alone, and the
    // same made of Pxyz and a quaternion joint
    checkTree(rnd, 6, 13);
    checkTree(rnd, 1, 13);
    checkTree(rnd, 5, nJointTypes - 1);

    checkMergedFreeBody();
    checkBodyTransforms(rnd);

    for
    (
        const std::string rotation
      : {"{ type Rzyx; }", "{ type Rxyz; }", "{ type Ryxz; }", "{ type Rs; }"}
    )
    {
        for (const label nChildren : {0, 1, 2})
        {
            checkFreeBody(rnd, rotation, nChildren);
        }
    }

    return test::testResult();
}
