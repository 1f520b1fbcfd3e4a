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
    Test-derivations

Description
    Tests that derive their expected values rather than repeat the code
    under test, so that a sign or convention error shared by the library's
    algorithms and by the consistency tests is still caught.

    1. Joints: S, v and c are derivatives of the joint's own transform.
       For every joint type (Px Py Pz Pa Pxyz Rx Ry Rz Ra Rxyz Ryxz Rzyx
       Rs, two composites, floating) at seeded random q and qDot, with q(t)
       advanced along qDot by the joint's own integrate() (for Rs, qDot is
       the body-frame angular velocity and q(t) = q0 * exp(t qDot/2)):
       - the joint velocity derived from the transform alone,
             (vJ x) = -dX/dt X^-1
         (X = XJ(q(t)) as the 6x6 Pluecker matrix [E 0; -E rx E] of
         Featherstone, RBDA (2008) section 2.8, the frame X maps to moving
         relative to the one it maps from; dX/dt by central differences),
         equals S qDot, and so does jcalc()'s J.v;
       - J.c equals the central difference in t of S(q(t)) qDot, qDot
         fixed, S's columns in child coordinates: the apparent derivative of
         S in the successor (child) frame, cJ = dS/dt qDot, the convention
         of joint.H (RBDA section 4.4);
       - Rs only: integrate() turns the body by exactly exp(t [qDot]x)
         (Rodrigues' formula, written here);
       - on a two-joint chain (a moving parent, then the joint) built by
         rigidBodyModel: the body velocity ws.v equals the velocity derived
         from ws.X0 alone as above, and the body acceleration the model
         implies for qDdot = 0, a_i = X_i,i-1 a_i-1 + ws.c[i] (root at
         rest), equals the central difference of ws.v's components in t.
         In body coordinates the spatial acceleration is the time
         derivative of the velocity's coordinates (a = dv/dt + v x v and
         v x v = 0), so this confirms end to end that c is the apparent
         derivative in the child frame and that kinematics() adds
         v_i x vJ to it.
       Composite and floating joints are never evaluated by jcalc() (the
       model expands them): their parts are checked by jcalc(), the whole
       by the model check.
       Step h = 1e-5: truncation error h^2/6 |X'''| ~ 1e-10 |qDot|^3 and
       round-off 1e-16/h ~ 1e-11; the tolerance 1e-7 (relative to
       max(1, |v|), max(1, |qDot|^2), max(1, |a|)) leaves a margin of about
       100 over that, while a wrong sign or a missing term is an O(1) error.

    2. Worked example: the Acrobot (planar two-link arm, both joints
       revolute, angles from the downward vertical, I1 and I2 the links'
       moments of inertia about their pivots) of R. Tedrake, Underactuated
       Robotics (course notes for MIT 6.832), chapter "Acrobots, Cart-Poles,
       and Quadrotors", section "The Acrobot", "Equations of motion", which
       prints the manipulator equations
           M(q) qDdot + C(q, qDot) qDot = tau_g(q) + B u
           M = [I1 + I2 + m2 l1^2 + 2 m2 l1 lc2 c2,  I2 + m2 l1 lc2 c2;
                I2 + m2 l1 lc2 c2,                   I2]
           C = [-2 m2 l1 lc2 s2 qDot2,  -m2 l1 lc2 s2 qDot2;
                 m2 l1 lc2 s2 qDot1,     0]
           tau_g = [-m1 g lc1 s1 - m2 g (l1 s1 + lc2 s12);  -m2 g lc2 s12]
       (the same expressions are restated at
       https://imrclab.github.io/kidyco/2nd_order/acrobot.html).  Featherstone's
       RBDA prints no numerical example that could be found with the
       search tools available, so this closed form is the published figure
       used.  The parameters are chosen here (not from the source); joint
       forces act at both joints (B u replaced by tau).  Checked at seeded
       random states: M from the model's kinetic energy (polarisation of
       T = qDot^T M qDot/2), the potential energy V = -m1 g lc1 c1
       - m2 g (l1 c1 + lc2 c12), and forwardDynamics() against
       M^-1 (tau + tau_g - C qDot).  The two sides are exact expressions
       that differ by round-off only: tolerances 1e-12 (energies, M) and
       1e-10 (accelerations, through solves with cond(M) < 1e3).

    3. Energy balance: on six seeded random trees (together they use every
       joint type; gravity; one merged body each) carrying linearSpring, linearDamper,
       linearAxialAngularSpring and sphericalAngularDamper restraints, built
       by restraint::New and applied by restrain(), the rate of change of
       E = kinetic + gravitational potential equals the power of the
       restraint forces, P = tau . qDot + sum_i fx_i . v_i (fx_i about the
       global origin in global axes, v_i the body's spatial velocity about
       the global origin in global axes, transformed here from ws.v and
       ws.X0).  dE/dt by a central difference of E over +-h along the
       motion, the state advanced by a second-order Taylor step with the
       forward-dynamics accelerations (quaternion joints through
       rigidBodyModel::integrate).  Both the Taylor step's error and the
       central difference's are O(h^2) in dE/dt (the O(h^2) error of qDot
       is even in h and cancels); with h = 2.5e-5 the measured error is at
       most ~5e-9 of the power scale |dT/dt| + |dV/dt| + sum |P_r| (and
       falls by 4 each time h is halved: truncation, no bias), round-off
       ~1e-11; tolerance 1e-6 of that scale, a margin of about 200, while a
       force in the wrong place or with the wrong sign is an O(1) error.

    Prints one PASS/FAIL line per joint type and check, per acrobot check
    and per tree, with the worst error measured.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "rigidBodyModel.H"
#include "rigidBodyRestraint.H"
#include "IStringStream.H"
#include "Random.H"

using namespace Foam;

namespace derivationsTest
{

using Foam::sqrt;
using Foam::sin;
using Foam::cos;

// * * * * * * * * * * * * * * * * Helpers  * * * * * * * * * * * * * * * * //

dictionary dictFromString(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}


std::string num(const scalar x)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.17g", x);
    return buf;
}


std::string fmt(const char* format, const double a, const double b = 0)
{
    char buf[256];
    std::snprintf(buf, sizeof(buf), format, a, b);
    return buf;
}


scalar uniform(Random& rnd, const scalar a)
{
    return a*(2*rnd.sample01<scalar>() - 1);
}


vector randomVector(Random& rnd, const scalar a)
{
    return vector(uniform(rnd, a), uniform(rnd, a), uniform(rnd, a));
}


std::string str(const vector& v)
{
    return "(" + num(v.x()) + " " + num(v.y()) + " " + num(v.z()) + ")";
}


std::string str(const tensor& T)
{
    std::string s = "(";
    for (direction i = 0; i < 9; ++i)
    {
        s += num(T[i]) + " ";
    }
    return s + ")";
}


//- Cross-product matrix: skew(a) & b = a ^ b
tensor skew(const vector& a)
{
    return tensor
    (
        0,      -a.z(),  a.y(),
        a.z(),   0,     -a.x(),
       -a.y(),   a.x(),  0
    );
}


//- Active rotation by the rotation vector theta (Rodrigues' formula)
tensor rodrigues(const vector& theta)
{
    const scalar angle = mag(theta);
    if (angle < 1e-300)
    {
        return tensor::I;
    }
    const vector n(theta/angle);
    const tensor K(skew(n));
    return tensor::I + sin(angle)*K + (1 - cos(angle))*(K & K);
}


//- A random rotation tensor
tensor randomRotation(Random& rnd)
{
    const vector axis(randomVector(rnd, 1) + vector(0.01, 0.02, 0.03));
    return rodrigues(axis/mag(axis)*uniform(rnd, 3));
}


scalar dot6(const spatialVector& a, const spatialVector& b)
{
    scalar s = 0;
    for (direction c = 0; c < 6; ++c)
    {
        s += a[c]*b[c];
    }
    return s;
}


scalar mag6(const spatialVector& a)
{
    return sqrt(dot6(a, a));
}


//- 6x6 matrices, row-major
struct Mat6
{
    scalar a[6][6];
};


//- The Pluecker motion transform of (E, r): [E 0; -E rx E]
//  (RBDA section 2.8), from the transform's data alone
Mat6 plucker(const spatialTransform& X)
{
    const tensor& E = X.E();
    const tensor Erx(E & skew(X.r()));
    Mat6 M;
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            M.a[i][j] = E(i, j);
            M.a[i][j + 3] = 0;
            M.a[i + 3][j] = -Erx(i, j);
            M.a[i + 3][j + 3] = E(i, j);
        }
    }
    return M;
}


//- Its inverse: [E^T 0; rx E^T E^T] (check: the product is the identity)
Mat6 pluckerInv(const spatialTransform& X)
{
    const tensor ET(X.E().T());
    const tensor rxET(skew(X.r()) & ET);
    Mat6 M;
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            M.a[i][j] = ET(i, j);
            M.a[i][j + 3] = 0;
            M.a[i + 3][j] = rxET(i, j);
            M.a[i + 3][j + 3] = ET(i, j);
        }
    }
    return M;
}


Mat6 mult(const Mat6& A, const Mat6& B)
{
    Mat6 C;
    for (label i = 0; i < 6; ++i)
    {
        for (label j = 0; j < 6; ++j)
        {
            scalar s = 0;
            for (label k = 0; k < 6; ++k)
            {
                s += A.a[i][k]*B.a[k][j];
            }
            C.a[i][j] = s;
        }
    }
    return C;
}


spatialVector mult(const Mat6& A, const spatialVector& v)
{
    spatialVector w;
    for (label i = 0; i < 6; ++i)
    {
        scalar s = 0;
        for (label k = 0; k < 6; ++k)
        {
            s += A.a[i][k]*v[k];
        }
        w[i] = s;
    }
    return w;
}


//- The velocity of the frame X(t) maps to, relative to the frame it maps
//  from, in the former's coordinates, from X at t - h, t, t + h:
//  (v x) = -dX/dt X^-1 = [wx 0; vx wx]  (coordinates of a vector fixed in
//  the "from" frame change in the moving frame as dm/dt = -v x m)
spatialVector velocityFromX
(
    const spatialTransform& Xm,
    const spatialTransform& X0,
    const spatialTransform& Xp,
    const scalar h
)
{
    const Mat6 A(plucker(Xm));
    const Mat6 B(plucker(Xp));
    Mat6 D;
    for (label i = 0; i < 6; ++i)
    {
        for (label j = 0; j < 6; ++j)
        {
            D.a[i][j] = -(B.a[i][j] - A.a[i][j])/(2*h);
        }
    }
    const Mat6 M(mult(D, pluckerInv(X0)));

    // Axial vectors of the two skew blocks (antisymmetric parts)
    const vector w
    (
        0.5*(M.a[2][1] - M.a[1][2]),
        0.5*(M.a[0][2] - M.a[2][0]),
        0.5*(M.a[1][0] - M.a[0][1])
    );
    const vector l
    (
        0.5*(M.a[5][1] - M.a[4][2]),
        0.5*(M.a[3][2] - M.a[5][0]),
        0.5*(M.a[4][0] - M.a[3][1])
    );
    return spatialVector(w, l);
}


// * * * * * * * * * * * * * * Part 1: joints  * * * * * * * * * * * * * * //

struct jointCase
{
    const char* name;
    const char* dict;
};

const jointCase jointCases[] =
{
    {"Px", "{ type Px; }"},
    {"Py", "{ type Py; }"},
    {"Pz", "{ type Pz; }"},
    {"Pa", "{ type Pa; axis (1 -2 0.5); }"},
    {"Pxyz", "{ type Pxyz; }"},
    {"Rx", "{ type Rx; }"},
    {"Ry", "{ type Ry; }"},
    {"Rz", "{ type Rz; }"},
    {"Ra", "{ type Ra; axis (-1 0.5 2); }"},
    {"Rxyz", "{ type Rxyz; }"},
    {"Ryxz", "{ type Ryxz; }"},
    {"Rzyx", "{ type Rzyx; }"},
    {"Rs", "{ type Rs; }"},
    {
        "composite (Ry Pa Rzyx)",
        "{ type composite; joints ({ type Ry; } { type Pa; axis (0 1 1); }"
        " { type Rzyx; }); }"
    },
    {
        "composite (Pxyz Rs)",
        "{ type composite; joints ({ type Pxyz; } { type Rs; }); }"
    },
    {"floating", "{ type floating; }"}
};
const label nJointCases = sizeof(jointCases)/sizeof(jointCases[0]);

const label nQ = 6;         // random positions per joint
const label nQDot = 3;      // random velocities per position
const scalar hJ = 1e-5;     // finite-difference step in t
const scalar tolJ = 1e-7;   // see the header


//- A random position for the joint's slots: quaternion vector parts within
//  the unit ball, angles and displacements in [-1, 1] (Euler angles well
//  away from gimbal lock)
void randomQ(Random& rnd, const RBD::joint& j, scalarField& q)
{
    const label i0 = j.qIndex();
    if (j.unitQuaternion())
    {
        vector v(randomVector(rnd, 1));
        v *= 0.95*rnd.sample01<scalar>()/max(mag(v), scalar(1e-3));
        for (label k = 0; k < 3; ++k)
        {
            q[i0 + k] = v[k];
        }
    }
    else
    {
        for (label k = 0; k < j.nDoF(); ++k)
        {
            q[i0 + k] = uniform(rnd, 1);
        }
    }
}


//- S qDot for the joint's n slots from i0
spatialVector Sq
(
    const RBD::joint::XSvc& J,
    const label n,
    const scalarField& qDot,
    const label i0
)
{
    spatialVector v(Zero);
    for (label k = 0; k < n; ++k)
    {
        v += J.S[k]*qDot[i0 + k];
    }
    return v;
}


//- S, v and c of one simple joint (slots from its qIndex in q of size nq)
//  against the derivatives of its own transform; worst errors returned
void checkSimpleJoint
(
    Random& rnd,
    const RBD::joint& j,
    const label nq,
    scalar& errV,
    scalar& errC,
    scalar& errRot
)
{
    const label n = j.nDoF();
    const label i0 = j.qIndex();

    scalarField q0(nq, Zero), qm(nq, Zero), qp(nq, Zero), qDot(nq, Zero);
    scalarField dq(nq, Zero);
    RBD::joint::XSvc J0, Jm, Jp;

    for (label iq = 0; iq < nQ; ++iq)
    {
        randomQ(rnd, j, q0);

        for (label iv = 0; iv < nQDot; ++iv)
        {
            for (label k = 0; k < n; ++k)
            {
                qDot[i0 + k] = uniform(rnd, 2);
            }

            // q(t -+ h) along qDot by the joint's own rule
            dq = -hJ*qDot;
            j.integrate(qm, q0, dq);
            dq = hJ*qDot;
            j.integrate(qp, q0, dq);

            j.jcalc(J0, q0, qDot);
            j.jcalc(Jm, qm, qDot);
            j.jcalc(Jp, qp, qDot);

            // Velocity: derived from X alone, and as jcalc gives it
            const spatialVector vX(velocityFromX(Jm.X, J0.X, Jp.X, hJ));
            const spatialVector vS(Sq(J0, n, qDot, i0));
            const scalar sV = max(scalar(1), mag6(vS));

            errV = max(errV, mag6(vX - vS)/sV);
            errV = max(errV, mag6(J0.v - vS)/sV);

            // Velocity product: apparent derivative of S qDot, qDot fixed
            const spatialVector cS
            (
                (Sq(Jp, n, qDot, i0) - Sq(Jm, n, qDot, i0))/(2*hJ)
            );
            scalar qDot2 = 0;
            for (label k = 0; k < n; ++k)
            {
                qDot2 += sqr(qDot[i0 + k]);
            }
            errC = max(errC, mag6(J0.c - cS)/max(scalar(1), qDot2));

            // Quaternion joints: a finite step turns the child frame by
            // exp(t [qDot]x) in its own axes, E(t) = exp(t [qDot]x)^T E0
            if (j.unitQuaternion())
            {
                const vector w(qDot[i0], qDot[i0 + 1], qDot[i0 + 2]);
                for (const scalar t : {-0.7, 0.3, 1.9})
                {
                    scalarField qt(nq, Zero);
                    dq = t*qDot;
                    j.integrate(qt, q0, dq);
                    RBD::joint::XSvc Jt;
                    j.jcalc(Jt, qt, qDot);
                    const tensor Eexp(rodrigues(t*w).T() & J0.X.E());
                    errRot = max(errRot, mag(Jt.X.E() - Eexp));
                    errRot = max(errRot, mag(Jt.X.r()));
                }
            }
        }
    }
}


//- The joint on a moving parent in a model: ws.v and ws.c against the
//  derivatives of ws.X0 and ws.v; worst errors returned
void checkModelJoint
(
    Random& rnd,
    const char* jointDict,
    scalar& errV,
    scalar& errA
)
{
    const tensor R1(randomRotation(rnd));
    const tensor R2(randomRotation(rnd));

    const std::string text =
        "bodies {"
        " parentBody { type rigidBody; parent root; mass 1.1;"
        " centreOfMass (0.1 0.2 -0.1); inertia (0.5 0 0 0.6 0 0.7);"
        " transform " + str(R1) + " " + str(randomVector(rnd, 1)) + ";"
        " joint { type composite; joints ({ type Pa; axis (1 1 0); }"
        " { type Ra; axis (0.3 -1 0.5); }); } }"
        " body { type rigidBody; parent parentBody; mass 1.3;"
        " centreOfMass (0.2 -0.1 0.3); inertia (0.4 0 0 0.5 0 0.6);"
        " transform " + str(R2) + " " + str(randomVector(rnd, 1)) + ";"
        " joint " + jointDict + " } }";

    const RBD::rigidBodyModel model(dictFromString(text));
    const label nb = model.nBodies();
    const label b = model.bodyID("body");

    if (b != nb - 1)
    {
        FatalErrorInFunction << "body is not last" << exit(FatalError);
    }

    RBD::rigidBodyModelWorkspace ws0(model), wsm(model), wsp(model);
    const label nDoF = model.nDoF();
    RBD::rigidBodyModelState s0(nDoF), sm(nDoF), sp(nDoF);

    for (label iq = 0; iq < nQ; ++iq)
    {
        // Every slot in [-0.5, 0.5]: quaternion vector parts stay inside
        // the unit ball, Euler angles far from gimbal lock
        forAll(s0.q(), k)
        {
            s0.q()[k] = uniform(rnd, 0.5);
        }
        for (label iv = 0; iv < nQDot; ++iv)
        {
            forAll(s0.qDot(), k)
            {
                s0.qDot()[k] = uniform(rnd, 2);
            }
            sm.qDot() = s0.qDot();
            sp.qDot() = s0.qDot();

            model.integrate(sm.q(), s0.q(), -hJ*s0.qDot());
            model.integrate(sp.q(), s0.q(), hJ*s0.qDot());

            model.kinematics(s0, ws0);
            model.kinematics(sm, wsm);
            model.kinematics(sp, wsp);

            // Body velocity from its global transform alone
            const spatialVector vX
            (
                velocityFromX
                (
                    model.X0(b, wsm),
                    model.X0(b, ws0),
                    model.X0(b, wsp),
                    hJ
                )
            );
            const spatialVector& v = ws0.v[b];
            errV = max(errV, mag6(vX - v)/max(scalar(1), mag6(v)));

            // Acceleration for qDdot = 0 from the model's velocity
            // products, body by body down the chain, the root at rest
            // (the model is a chain: the joints of parentBody's composite,
            // then body's, each body's parent the one before it)
            spatialVector a(Zero);
            for (label i = 1; i < nb; ++i)
            {
                const Mat6 Xrel
                (
                    mult
                    (
                        plucker(model.X0(i, ws0)),
                        pluckerInv(model.X0(i - 1, ws0))
                    )
                );
                a = mult(Xrel, a) + ws0.c[i];
            }

            const spatialVector aFD((wsp.v[b] - wsm.v[b])/(2*hJ));
            errA = max(errA, mag6(a - aFD)/max(scalar(1), mag6(a)));
        }
    }

}


void checkJoints(Random& rnd)
{
    for (label jc = 0; jc < nJointCases; ++jc)
    {
        const std::string name(jointCases[jc].name);
        autoPtr<RBD::joint> jPtr
        (
            RBD::joint::New(dictFromString(jointCases[jc].dict))
        );

        // The simple joints it is made of, with their slots
        PtrList<RBD::joint> parts;
        jPtr->expand(parts);
        label nq = 0;
        forAll(parts, k)
        {
            parts[k].setQIndex(nq);
            nq += parts[k].nDoF();
        }

        scalar errV = 0, errC = 0, errRot = 0;
        forAll(parts, k)
        {
            checkSimpleJoint(rnd, parts[k], nq, errV, errC, errRot);
        }

        const std::string of =
            parts.size() > 1 ? " (jcalc of each part)" : "";

        test::checkAbs
        (
            errV, 0, tolJ,
            name + of + ": S qDot and J.v equal the velocity -dX/dt X^-1"
            " derived from X(q(t)), worst of "
          + std::to_string(nQ*nQDot) + " random states, relative to"
            " max(1, |v|), h 1e-5"
        );
        test::checkAbs
        (
            errC, 0, tolJ,
            name + of + ": J.c equals d/dt [S(q(t)) qDot] (apparent"
            " derivative in the child frame), relative to max(1, |qDot|^2)"
        );
        bool quaternion = false;
        forAll(parts, k)
        {
            quaternion = quaternion || parts[k].unitQuaternion();
        }
        if (quaternion)
        {
            // Round-off of a few quaternion products only
            test::checkAbs
            (
                errRot, 0, 1e-12,
                name + ": integrate() turns the child by"
                " exp(t [qDot]x) in its own axes (Rodrigues),"
                " |E(t) - E_expected|"
            );
        }

        scalar errMV = 0, errMA = 0;
        checkModelJoint(rnd, jointCases[jc].dict, errMV, errMA);

        test::checkAbs
        (
            errMV, 0, tolJ,
            name + " on a moving parent: model's body velocity equals"
            " -dX0/dt X0^-1, relative to max(1, |v|)"
        );
        test::checkAbs
        (
            errMA, 0, tolJ,
            name + " on a moving parent: acceleration from ws.c (qDdot 0)"
            " equals d/dt of the body-frame velocity, relative to"
            " max(1, |a|)"
        );
    }
}


// * * * * * * * * * * * * * * Part 2: Acrobot  * * * * * * * * * * * * * //

void checkAcrobot(Random& rnd)
{
    // Parameters chosen here
    const scalar m1 = 1, m2 = 1.5, l1 = 1, lc1 = 0.5, lc2 = 0.8;
    const scalar Ic1 = 0.083, Ic2 = 0.33, g = 9.81;

    // Moments of inertia about the pivots, as in the source
    const scalar I1 = Ic1 + m1*sqr(lc1);
    const scalar I2 = Ic2 + m2*sqr(lc2);

    // Links hang along -z at q = 0 and turn about y; the mirror image of
    // the source's figure (x -> -x), which changes none of M, C, tau_g
    const std::string text =
        "g (0 0 " + num(-g) + ");"
        " bodies {"
        " link1 { type rigidBody; parent root; mass " + num(m1) + ";"
        " centreOfMass (0 0 " + num(-lc1) + ");"
        " inertia (" + num(Ic1) + " 0 0 " + num(Ic1) + " 0 0.001);"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 0); joint { type Ry; } }"
        " link2 { type rigidBody; parent link1; mass " + num(m2) + ";"
        " centreOfMass (0 0 " + num(-lc2) + ");"
        " inertia (" + num(Ic2) + " 0 0 " + num(Ic2) + " 0 0.001);"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 " + num(-l1) + ");"
        " joint { type Ry; } } }";

    const RBD::rigidBodyModel model(dictFromString(text));
    RBD::rigidBodyModelWorkspace ws(model);
    RBD::rigidBodyModelState state(model.nDoF());

    scalar errM = 0, errV = 0, errA = 0;
    const label nStates = 12;

    for (label n = 0; n < nStates; ++n)
    {
        const scalar q1 = uniform(rnd, constant::mathematical::pi);
        const scalar q2 = uniform(rnd, constant::mathematical::pi);
        const scalar qd1 = uniform(rnd, 3), qd2 = uniform(rnd, 3);
        const scalar t1 = uniform(rnd, 5), t2 = uniform(rnd, 5);

        const scalar s1 = sin(q1), c1 = cos(q1), s2 = sin(q2), c2 = cos(q2);
        const scalar s12 = sin(q1 + q2), c12 = cos(q1 + q2);

        // The source's closed form
        const scalar M11 = I1 + I2 + m2*sqr(l1) + 2*m2*l1*lc2*c2;
        const scalar M12 = I2 + m2*l1*lc2*c2;
        const scalar M22 = I2;
        const scalar Cqd1 = -2*m2*l1*lc2*s2*qd2*qd1 - m2*l1*lc2*s2*qd2*qd2;
        const scalar Cqd2 = m2*l1*lc2*s2*qd1*qd1;
        const scalar tg1 = -m1*g*lc1*s1 - m2*g*(l1*s1 + lc2*s12);
        const scalar tg2 = -m2*g*lc2*s12;
        const scalar V = -m1*g*lc1*c1 - m2*g*(l1*c1 + lc2*c12);

        // M from the model's kinetic energy
        state.q()[0] = q1;
        state.q()[1] = q2;
        auto T = [&](const scalar a, const scalar b)
        {
            state.qDot()[0] = a;
            state.qDot()[1] = b;
            model.kinematics(state, ws);
            return model.kineticEnergy(ws);
        };
        const scalar T10 = T(1, 0), T01 = T(0, 1), T11 = T(1, 1);
        const scalar H11 = 2*T10, H22 = 2*T01, H12 = T11 - T10 - T01;
        const scalar sM = M11;
        errM = max(errM, mag(H11 - M11)/sM);
        errM = max(errM, mag(H12 - M12)/sM);
        errM = max(errM, mag(H22 - M22)/sM);

        // Potential energy
        model.kinematics(state, ws);
        errV = max
        (
            errV,
            mag(model.potentialEnergy(ws) - V)/(g*(m1*lc1 + m2*(l1 + lc2)))
        );

        // Forward dynamics against M^-1 (tau + tau_g - C qDot)
        const scalar r1 = t1 + tg1 - Cqd1;
        const scalar r2 = t2 + tg2 - Cqd2;
        const scalar det = M11*M22 - M12*M12;
        const scalar a1 = (M22*r1 - M12*r2)/det;
        const scalar a2 = (-M12*r1 + M11*r2)/det;

        state.qDot()[0] = qd1;
        state.qDot()[1] = qd2;
        scalarField tau(2);
        tau[0] = t1;
        tau[1] = t2;
        const Field<spatialVector> fx(model.nBodies(), Zero);
        model.forwardDynamics(state, ws, tau, fx);

        const scalar sA = max(scalar(1), max(mag(a1), mag(a2)));
        errA = max(errA, mag(state.qDdot()[0] - a1)/sA);
        errA = max(errA, mag(state.qDdot()[1] - a2)/sA);
    }

    const std::string src = " (Tedrake, Underactuated Robotics, the Acrobot)";
    test::checkAbs
    (
        errM, 0, 1e-12,
        "acrobot: mass matrix from the kinetic energy equals the closed-form"
        " M(q)" + src + ", worst of 12 states, relative to M11"
    );
    test::checkAbs
    (
        errV, 0, 1e-12,
        "acrobot: potential energy equals -m1 g lc1 c1 - m2 g (l1 c1 +"
        " lc2 c12), relative to g (m1 lc1 + m2 (l1 + lc2))"
    );
    test::checkAbs
    (
        errA, 0, 1e-10,
        "acrobot: forwardDynamics equals M^-1 (tau + tau_g - C qDot)" + src
      + ", relative to max(1, |qDdot|)"
    );
}


// * * * * * * * * * * * * * Part 3: energy balance  * * * * * * * * * * * //

const char* treeJoints[] =
{
    "{ type Px; }", "{ type Py; }", "{ type Pz; }",
    "{ type Pa; axis (1 2 3); }", "{ type Rx; }", "{ type Ry; }",
    "{ type Rz; }", "{ type Ra; axis (-1 0.5 2); }", "{ type Pxyz; }",
    "{ type Rxyz; }", "{ type Ryxz; }", "{ type Rzyx; }", "{ type Rs; }",
    "{ type floating; }", "{ type null; }",
    "{ type composite; joints ({ type Ry; } { type Pa; axis (0 1 1); }); }",
    "{ type composite; joints ({ type Pxyz; } { type Rs; }); }"
};
const label nTreeJoints = sizeof(treeJoints)/sizeof(treeJoints[0]);


std::string bodyEntries(Random& rnd)
{
    const vector ev
    (
        1 + rnd.sample01<scalar>(),
        1 + rnd.sample01<scalar>(),
        1 + rnd.sample01<scalar>()
    );
    const tensor R(randomRotation(rnd));
    const tensor I(R & tensor(ev.x(), 0, 0, 0, ev.y(), 0, 0, 0, ev.z()) & R.T());

    return
        "mass " + num(0.5 + rnd.sample01<scalar>())
      + "; centreOfMass " + str(randomVector(rnd, 0.5))
      + "; inertia (" + num(I.xx()) + " " + num(I.xy()) + " " + num(I.xz())
      + " " + num(I.yy()) + " " + num(I.yz()) + " " + num(I.zz()) + ")"
      + "; transform " + str(randomRotation(rnd)) + " "
      + str(randomVector(rnd, 1)) + ";";
}


//- A random tree of n bodies with gravity, one merged body, and the
//  restraints' dictionary text
void randomTree
(
    Random& rnd,
    const label n,
    const label firstJoint,
    std::string& modelText,
    std::string& restraintsText
)
{
    std::string bodies;
    for (label i = 0; i < n; ++i)
    {
        const std::string parent =
            i == 0
          ? "root"
          : "b" + std::to_string(rnd.position<label>(0, i - 1));

        bodies +=
            "b" + std::to_string(i) + " { type rigidBody; parent " + parent
          + "; " + bodyEntries(rnd) + " joint "
          + treeJoints[(firstJoint + i) % nTreeJoints] + " } ";
    }
    bodies +=
        "m0 { type rigidBody; mergeWith b"
      + std::to_string(rnd.position<label>(0, n - 1)) + "; "
      + bodyEntries(rnd) + " } ";

    modelText = "g (0 0 -9.81); bodies { " + bodies + "}";

    // Two restraints of each type, on random bodies (the merged one too)
    auto body = [&]()
    {
        const label k = rnd.position<label>(0, n);
        return k == n ? std::string("m0") : "b" + std::to_string(k);
    };

    restraintsText.clear();
    for (label k = 0; k < 2; ++k)
    {
        const std::string s = std::to_string(k);
        restraintsText +=
            "spring" + s + " { type linearSpring; body " + body()
          + "; anchor " + str(randomVector(rnd, 1.5))
          + "; refAttachmentPt " + str(randomVector(rnd, 0.5))
          + "; stiffness " + num(20 + 60*rnd.sample01<scalar>())
          + "; damping " + num(5*rnd.sample01<scalar>())
          + "; restLength " + num(0.5*rnd.sample01<scalar>()) + "; } "
          + "damper" + s + " { type linearDamper; body " + body()
          + "; coeff " + num(0.5 + 3*rnd.sample01<scalar>()) + "; } "
          + "torsion" + s + " { type linearAxialAngularSpring; body "
          + body() + "; referenceOrientation " + str(randomRotation(rnd))
          + "; axis " + str(randomVector(rnd, 1) + vector(0.1, 0, 0))
          + "; stiffness " + num(5 + 30*rnd.sample01<scalar>())
          + "; damping " + num(2*rnd.sample01<scalar>()) + "; } "
          + "angularDamper" + s + " { type sphericalAngularDamper; body "
          + body() + "; coeff " + num(0.5 + 2*rnd.sample01<scalar>())
          + "; } ";
    }
}


//- Kinetic + potential energy of the state
scalar energy
(
    const RBD::rigidBodyModel& model,
    const RBD::rigidBodyModelState& state,
    RBD::rigidBodyModelWorkspace& ws,
    scalar& T,
    scalar& V
)
{
    model.kinematics(state, ws);
    T = model.kineticEnergy(ws);
    V = model.potentialEnergy(ws);
    return T + V;
}


void checkEnergyBalance
(
    Random& rnd,
    const label n,
    const label firstJoint,
    const label treeI
)
{
    std::string modelText, restraintsText;
    randomTree(rnd, n, firstJoint, modelText, restraintsText);

    const RBD::rigidBodyModel model(dictFromString(modelText));
    const dictionary restraintsDict(dictFromString(restraintsText));

    PtrList<RBD::restraint> restraints;
    for (const entry& e : restraintsDict)
    {
        restraints.append
        (
            RBD::restraint::New(e.keyword(), e.dict(), model).ptr()
        );
    }

    const label nDoF = model.nDoF();
    const label nb = model.nBodies();
    RBD::rigidBodyModelWorkspace ws(model);
    RBD::rigidBodyModelState state(model.nDoF()), sh(model.nDoF());

    const scalar h = 2.5e-5;
    scalar worst = 0, worstP = 0, minScale = GREAT;

    for (label trial = 0; trial < 4; ++trial)
    {
        // Every slot in [-0.5, 0.5] (quaternion parts inside the ball)
        forAll(state.q(), k)
        {
            state.q()[k] = uniform(rnd, 0.5);
        }
        forAll(state.qDot(), k)
        {
            state.qDot()[k] = uniform(rnd, 2);
        }

        // Restraint forces and their power at the state
        model.kinematics(state, ws);
        scalarField tau(nDoF, Zero);
        Field<spatialVector> fx(nb, Zero);

        // Spatial velocity of each body about the global origin, global
        // axes, from the body-frame velocity: w = E^T wb, and the velocity
        // of the body point at the origin, E^T vb + w ^ (0 - r)
        List<spatialVector> vGlobal(nb, Zero);
        for (label i = 1; i < nb; ++i)
        {
            const tensor ET(model.X0(i, ws).E().T());
            const vector w(ET & ws.v[i].w());
            vGlobal[i] =
                spatialVector
                (
                    w,
                    (ET & ws.v[i].l()) - (w ^ model.X0(i, ws).r())
                );
        }

        scalar P = 0, sumMagP = 0;
        forAll(restraints, ri)
        {
            scalarField taur(nDoF, Zero);
            Field<spatialVector> fxr(nb, Zero);
            restraints[ri].restrain(taur, fxr, state, ws);

            scalar Pr = 0;
            forAll(taur, k)
            {
                Pr += taur[k]*state.qDot()[k];
            }
            for (label i = 1; i < nb; ++i)
            {
                Pr += dot6(fxr[i], vGlobal[i]);
            }
            P += Pr;
            sumMagP += mag(Pr);
            tau += taur;
            fx += fxr;
        }

        model.forwardDynamics(state, ws, tau, fx);
        const scalarField qDdot(state.qDdot());

        // E at t -+ h by a second-order Taylor step
        scalar E[2], T[2], V[2];
        for (label s = 0; s < 2; ++s)
        {
            const scalar dt = s ? h : -h;
            model.integrate
            (
                sh.q(),
                state.q(),
                dt*state.qDot() + 0.5*sqr(dt)*qDdot
            );
            sh.qDot() = state.qDot() + dt*qDdot;
            E[s] = energy(model, sh, ws, T[s], V[s]);
        }

        const scalar dEdt = (E[1] - E[0])/(2*h);
        const scalar dTdt = (T[1] - T[0])/(2*h);
        const scalar dVdt = (V[1] - V[0])/(2*h);
        const scalar scale = mag(dTdt) + mag(dVdt) + sumMagP;

        const scalar err = mag(dEdt - P)/scale;
        if (err > worst)
        {
            worst = err;
        }
        worstP = max(worstP, mag(P));
        minScale = min(minScale, scale);
    }

    test::checkAbs
    (
        worst, 0, 1e-6,
        "tree " + std::to_string(treeI) + " (" + std::to_string(n)
      + " bodies + 1 merged, " + std::to_string(nDoF) + " dof, "
      + std::to_string(restraints.size()) + " restraints): dE/dt equals"
        " the restraints' power, worst of 4 states, relative to"
        " |dT/dt| + |dV/dt| + sum |P_r|, h 2.5e-5"
      + fmt(" (max |P| %.3g, min scale %.3g)", worstP, minScale)
    );
}

} // End namespace derivationsTest


int main(int argc, char *argv[])
{
    using namespace derivationsTest;

    Random rnd(20240611);

    checkJoints(rnd);
    checkAcrobot(rnd);

    for (label tree = 0; tree < 6; ++tree)
    {
        checkEnergyBalance(rnd, 6 + 2*tree, 3*tree, tree);
    }

    return test::testResult();
}


// ************************************************************************* //
