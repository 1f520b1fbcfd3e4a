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
    Test-connectedBodies

Description
    Bodies connected through restraints, against exact answers, without a
    fluid (docs/connected-bodies.md).

    Two equal masses m heave on Pz joints, the second's joint relative to
    the first, so its q is their relative heave y = x2 - x1.  Each is tied
    to the ground by a linearSpring k1; a power take-off, linearJointSpring
    (k2, c) on the second body's joint, acts between them.  Closed form
    (no gravity): the sum s = x1 + x2 swings undamped at omega_1 =
    Foam::sqrt(k1/m), the difference u = x1 - x2 at the damped
        omega_d = Foam::sqrt((k1 + 2 k2)/m - sigma^2),  sigma = c/m,
    with u(t) = u0 Foam::exp(-sigma t)(cos omega_d t + sigma/omega_d sin omega_d t)
    from rest.  m = 1 kg, k1 = 10 N/m, k2 = 20 N/m, c = 0.5 N s/m; released
    from rest at x1 = 0.1 m, x2 = 0.03 m; Newmark, 5 s.  Checks:
    - x1 and x2 follow the closed form within 2e-4 of the release (dt 1 ms;
      Newmark's phase error), and within 1/3 of that at dt 0.5 ms (second
      order: the error ratio near 4);
    - the decay rate of u, from the least-squares slope of ln|u| at its
      extremes, is sigma within 0.2%, and twice the mean interval between
      its crossings of zero is 2 pi/omega_d within 0.1%;
    - the work the PTO took equals the mechanical energy the bodies and the
      ground springs lost, within 1e-12 of the initial energy, at every
      step (converged steps, nIter 5: odd, as an even nIter grows, slowly,
      docs/limitations.md); its damper absorbed the energy of the
      out-of-phase mode (98-100% of it by 5 s, when 99.3% has decayed);
    - the force, power and work columns of the PTO: a row holds them, the
      force tau and the power -tau qDot at the committed state.

    Two free bodies (floating joints, no gravity) joined by a linearSpring
    and a linearDamper anchored on the other body: the forces on the two
    are equal and opposite, with no net force nor moment about the origin
    (1e-12); over 1 s the bodies' momentum and angular momentum are kept
    to 1e-3 at dt 0.1 ms, the error falling at second order with dt (the
    integrator's, in joint coordinates).

    externalForce on a turned free body: a force and a moment given in
    the body's axes at a point of the body, and a force and moment in
    global axes at a global point, add up to the force and moment about
    the origin computed from the body's transform, to 1e-12.

    The coupling residual beside a prescription (prescribedResidual): a
    joint heaved by prescribedJointMotion or turned by prescribedRotation
    at omega dt 0.63 has a residual of 0 (1e-12) at every step (measured
    along its motor, one relaxed solve a step, it is above the tolerance),
    while a free body beside it keeps its own: flagged as solved, and in
    more steps when 0.3 further off.

    prescribedJointMotion: a carrier heaved as 0.1 sin(2 pi 0.7 t) m on Pz,
    a pendulum hanging free from it on Ry, gravity, Newmark, 3 s: the heave
    is the sine at every step to 1e-12 of its amplitude, its rate to 1e-6
    (central differences); the driving force equals the inverse dynamics of
    the state to 1e-9 of its largest value, and the pendulum's joint needs
    none.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "linearJointSpring.H"
#include "couplingResidual.H"
#include "mathematicalConstants.H"
#include "OStringStream.H"

using namespace Foam;

namespace connectedBodiesTest
{

using test::check;
using test::checkRel;
using test::checkAbs;
using test::checkRange;

const scalar m = 1, k1 = 10, k2 = 20, c = 0.5;
const scalar x10 = 0.1, x20 = 0.03;

const scalar pi = constant::mathematical::pi;


//- The two-body model: nIter solves a step
std::string twoBodies(const label nIter)
{
    OStringStream os;
    os  << "solver { type Newmark; } nIter " << nIter << "; g (0 0 0);"
        << "q (" << x10 << " " << x20 - x10 << ");"
        << "bodies {"
        << " float { type rigidBody; parent root; mass " << m << ";"
        << " centreOfMass (0 0 0); inertia (0.01 0 0 0.01 0 0.01);"
        << " transform (1 0 0 0 1 0 0 0 1) (0 0 0); joint { type Pz; } }"
        << " reaction { type rigidBody; parent float; mass " << m << ";"
        << " centreOfMass (0 0 0); inertia (0.01 0 0 0.01 0 0.01);"
        << " transform (1 0 0 0 1 0 0 0 1) (1 0 0); joint { type Pz; } } }"
        << "restraints {"
        << " ground1 { type linearSpring; body float; anchor (0 0 -10);"
        << " refAttachmentPt (0 0 0); stiffness " << k1 << "; damping 0;"
        << " restLength 10; }"
        << " ground2 { type linearSpring; body reaction; anchor (1 0 -10);"
        << " refAttachmentPt (0 0 0); stiffness " << k1 << "; damping 0;"
        << " restLength 10; }"
        << " pto { type linearJointSpring; body reaction; stiffness " << k2
        << "; damping " << c << "; } }";
    return os.str();
}


//- The closed form: x1, x2 at t
void exact(const scalar t, scalar& x1, scalar& x2)
{
    const scalar w1 = Foam::sqrt(k1/m);
    const scalar sigma = c/m;
    const scalar wd = Foam::sqrt((k1 + 2*k2)/m - sqr(sigma));
    const scalar s = (x10 + x20)*Foam::cos(w1*t);
    const scalar u =
        (x10 - x20)*Foam::exp(-sigma*t)*(Foam::cos(wd*t) + sigma/wd*Foam::sin(wd*t));
    x1 = 0.5*(s + u);
    x2 = 0.5*(s - u);
}


//- The PTO of the motion
const RBD::restraints::linearJointSpring& pto(RBD::rigidBodyMotion& mo)
{
    return refCast<const RBD::restraints::linearJointSpring>
    (
        mo.restraints()[2]
    );
}


//- Mechanical energy of the bodies and the ground springs
scalar energy(const RBD::rigidBodyMotion& mo)
{
    const scalarField& q = mo.state().q();
    const scalarField& v = mo.state().qDot();
    const scalar x1 = q[0], x2 = q[0] + q[1];
    const scalar v1 = v[0], v2 = v[0] + v[1];
    return 0.5*m*(sqr(v1) + sqr(v2)) + 0.5*k1*(sqr(x1) + sqr(x2));
}


//- Run for 5 s at dt: the largest departure from the closed form, and the
//  series of u
scalar trajectory
(
    const scalar dt,
    DynamicList<scalar>& t,
    DynamicList<scalar>& u
)
{
    autoPtr<RBD::rigidBodyMotion> mo(test::motion(twoBodies(1)));
    scalar err = 0;
    test::run
    (
        mo(), dt, label(std::round(5/dt)),
        [&](RBD::rigidBodyMotion& m)
        {
            const scalar time = m.state().t();
            scalar x1, x2;
            exact(time, x1, x2);
            const scalar y1 = m.state().q()[0];
            const scalar y2 = y1 + m.state().q()[1];
            err = max(err, max(mag(y1 - x1), mag(y2 - x2)));
            t.append(time);
            u.append(y1 - y2);
        }
    );
    return err;
}


void modes()
{
    DynamicList<scalar> t, u, t2, u2;
    const scalar err = trajectory(1e-3, t, u);
    const scalar err2 = trajectory(5e-4, t2, u2);
    const scalar amp = max(mag(x10), mag(x20));

    check
    (
        err <= 2e-4*amp,
        "two bodies, a PTO between them: x1, x2 follow the closed form"
        " within 2e-4 of the release at dt 1 ms (" + std::to_string(err/amp)
      + ")"
    );
    check
    (
        err2 <= err/3,
        "... second order: at dt 0.5 ms the error falls by "
      + std::to_string(err/err2) + " (>= 3)"
    );

    // Crossings of zero of u, and its extremes between them
    DynamicList<scalar> crossings, extremeT, extremeLn;
    scalar peak = 0, peakT = 0;
    for (label i = 1; i < u.size(); ++i)
    {
        if (mag(u[i]) > peak)
        {
            peak = mag(u[i]);
            peakT = t[i];
        }
        if ((u[i - 1] < 0) != (u[i] < 0))
        {
            const scalar tc =
                t[i - 1] + (t[i] - t[i - 1])*u[i - 1]/(u[i - 1] - u[i]);
            if (crossings.size())
            {
                extremeT.append(peakT);
                extremeLn.append(Foam::log(peak));
            }
            crossings.append(tc);
            peak = 0;
        }
    }

    // Least-squares slope of ln|u| at the extremes
    const label n = extremeT.size();
    scalar st = 0, sl = 0, stt = 0, stl = 0;
    forAll(extremeT, i)
    {
        st += extremeT[i];
        sl += extremeLn[i];
        stt += sqr(extremeT[i]);
        stl += extremeT[i]*extremeLn[i];
    }
    const scalar slope = (n*stl - st*sl)/(n*stt - sqr(st));
    checkRel
    (
        -slope, c/m, 2e-3,
        "... decay rate of x1 - x2 at " + std::to_string(n)
      + " extremes, against sigma = c/m [1/s]"
    );

    const scalar wd = Foam::sqrt((k1 + 2*k2)/m - sqr(c/m));
    const scalar period =
        2*(crossings.last() - crossings.first())/(crossings.size() - 1);
    checkRel
    (
        period, 2*pi/wd, 1e-3,
        "... damped period of x1 - x2, twice the mean interval of "
      + std::to_string(crossings.size()) + " crossings, against 2 pi/omega_d"
        " [s]"
    );
}


void energyBalance()
{
    autoPtr<RBD::rigidBodyMotion> mo(test::motion(twoBodies(5)));
    mo->commitRestraints();
    const scalar E0 = energy(mo());
    scalar worst = 0;
    test::run
    (
        mo(), 1e-3, 5000,
        [&](RBD::rigidBodyMotion& m)
        {
            m.commitRestraints();
            worst = max(worst, mag(E0 - energy(m) - pto(m).work()));
        }
    );
    checkAbs
    (
        worst/E0, 0, 1e-12,
        "PTO: the work it took equals the mechanical energy lost, at every"
        " step of 5 s (nIter 5), over the initial energy"
    );
    // What it absorbed: its work less its own spring's energy gained; the
    // energy of the out-of-phase mode at the release, u0^2 (k1/4 + k2/2),
    // decays as Foam::exp(-2 sigma t): by 5 s, 99.3% of it
    const scalar y0 = x20 - x10, y = mo->state().q()[1];
    const scalar absorbed =
        pto(mo()).work() - 0.5*k2*(sqr(y) - sqr(y0));
    const scalar Eu = sqr(x10 - x20)*(k1/4 + k2/2);
    checkRange
    (
        absorbed/Eu, 0.98, 1,
        "... of which the damper absorbed the out-of-phase mode's energy"
        " (over it)"
    );

    RBD::tableRow row;
    row.start();
    pto(mo()).addColumns(row);
    row.end();
    const scalar qDot = mo->state().qDot()[1];
    const scalar q = mo->state().q()[1];
    const scalar power = (k2*q + c*qDot)*qDot;
    const scalar force = -(k2*q + c*qDot);
    check
    (
        row.size() == 3 && row.name(0) == "pto.force"
     && row.name(1) == "pto.power" && row.name(2) == "pto.work"
     && mag(row[0] - force) <= 1e-12*max(mag(force), SMALL)
     && mag(row[1] - power) <= 1e-12*max(mag(power), SMALL)
     && row[2] == pto(mo()).work(),
        "the PTO's table columns pto.force (tau), pto.power (-tau qDot) and"
        " pto.work"
    );
}

//- Two free bodies, a spring and a damper between points of each
void twoBodySpring()
{
    const std::string text =
        "solver { type Newmark; } g (0 0 0);"
        "q (0 0 0 0.1 0.2 0.3 0.5 0 0.1 -0.2 0.1 0.4);"
        "qDot (0.3 0 0 0 0.2 0 0 -0.1 0 0.5 0 0);"
        "bodies {"
        " a { type cuboid; parent root; mass 2; L (0.2 0.3 0.4);"
        " centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (0 0 0);"
        " joint { type floating; } }"
        " b { type cuboid; parent root; mass 1; L (0.1 0.2 0.3);"
        " centreOfMass (0 0 0.05); transform (1 0 0 0 1 0 0 0 1) (1 0 0);"
        " joint { type floating; } } }"
        "restraints {"
        " spring { type linearSpring; body b; anchorBody a;"
        " anchor (0.1 0.1 -0.2); refAttachmentPt (-0.05 0 0.1);"
        " stiffness 50; damping 2; restLength 0.5; }"
        " damper { type linearDamper; body b; anchorBody a; coeff 3;"
        " refAttachmentPt (0 0.1 0); } }";

    autoPtr<RBD::rigidBodyMotion> mo(test::motion(text));
    const RBD::rigidBodyModel& model = mo->model();
    const label a = model.bodyID("a"), b = model.bodyID("b");

    scalarField tau(model.nDoF(), Zero);
    Field<spatialVector> fx(model.nBodies(), Zero);
    mo->restraintForces(tau, fx);

    // Both about the global origin: equal and opposite forces on one line
    // each leave no total force nor moment
    const spatialVector total(fx[a] + fx[b]);
    const scalar scale = mag(fx[b].l())*(1 + mag(mo->X0(b).r()));
    check
    (
        mag(fx[b].l()) > 1 && mag(total.l()) <= 1e-12*scale
     && mag(total.w()) <= 1e-12*scale,
        "body-to-body linearSpring and linearDamper: equal and opposite"
        " forces, no net moment (" + std::to_string(mag(total.l())) + ", "
      + std::to_string(mag(total.w())) + " N m; force "
      + std::to_string(mag(fx[b].l())) + " N)"
    );

    // Free, without gravity: momentum and angular momentum kept, to the
    // integrator's error in joint coordinates, as the bodies swing and
    // the damper takes energy
    auto momentum = [&](RBD::rigidBodyMotion& m, vector& P, vector& L)
    {
        P = Zero;
        L = Zero;
        const RBD::rigidBodyModelWorkspace& ws = m.workspace();
        for (label i = 1; i < model.nBodies(); ++i)
        {
            const spatialVector h(model.bodies()[i] & ws.v[i]);
            const spatialVector h0(model.X0(i, ws).T() & h);
            P += h0.l();
            L += h0.w();
        }
    };
    auto drift = [&](const scalar dt, scalar& dP, scalar& dL)
    {
        autoPtr<RBD::rigidBodyMotion> m(test::motion(text));
        vector P0, L0, P, L;
        momentum(m(), P0, L0);
        dP = 0;
        dL = 0;
        test::run
        (
            m(), dt, label(std::round(1/dt)),
            [&](RBD::rigidBodyMotion& mm)
            {
                momentum(mm, P, L);
                dP = max(dP, mag(P - P0)/mag(P0));
                dL = max(dL, mag(L - L0)/mag(L0));
            }
        );
    };
    scalar dP1, dL1, dP2, dL2;
    drift(2e-4, dP1, dL1);
    drift(1e-4, dP2, dL2);
    check
    (
        dP2 <= 1e-3 && dL2 <= 1e-3 && dP1/dP2 >= 3 && dL1/dL2 >= 3,
        "... two free bodies for 1 s: momentum and angular momentum kept to "
      + std::to_string(dP2) + " and " + std::to_string(dL2) + " at dt 0.1"
        " ms (1e-3), the integrator's second-order error (falling by "
      + std::to_string(dP1/dP2) + " and " + std::to_string(dL1/dL2)
      + " from dt 0.2 ms, >= 3)"
    );
}


//- externalForce in the body's frame: its location and its axes turn with
//  the body; and its moment
void externalForceFrames()
{
    const std::string text =
        "solver { type Newmark; } g (0 0 0);"
        "q (0.2 0.1 -0.3 0.4 -0.2 0.7);"
        "bodies { a { type cuboid; parent root; mass 2; L (0.2 0.3 0.4);"
        " centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (1 2 3);"
        " joint { type floating; } } }"
        "restraints {"
        " thruster { type externalForce; body a; locationFrame body;"
        " location (-0.5 0.1 -0.2); forceFrame body;"
        " force constant (20 3 -1); moment constant (0.5 -2 1); }"
        " fixed { type externalForce; body a; location (0 1 0);"
        " force constant (0 0 7); moment constant (1 0 0); } }";

    autoPtr<RBD::rigidBodyMotion> mo(test::motion(text));
    const RBD::rigidBodyModel& model = mo->model();
    const label a = model.bodyID("a");

    scalarField tau(model.nDoF(), Zero);
    Field<spatialVector> fx(model.nBodies(), Zero);
    mo->restraintForces(tau, fx);

    // Expected: the body's point and axes from its transform now
    const spatialTransform X(mo->X0(a));
    const tensor Rt(X.E().T());
    const vector p(X.r() + (Rt & vector(-0.5, 0.1, -0.2)));
    const vector F1(Rt & vector(20, 3, -1)), M1(Rt & vector(0.5, -2, 1));
    const vector F2(0, 0, 7), M2(1, 0, 0);
    const vector F(F1 + F2);
    const vector M((p ^ F1) + M1 + (vector(0, 1, 0) ^ F2) + M2);

    check
    (
        mag(fx[a].l() - F) <= 1e-12*mag(F)
     && mag(fx[a].w() - M) <= 1e-12*mag(M),
        "externalForce: a force and moment in the body's axes at a point of"
        " the body (forceFrame body, locationFrame body) turn with it; the"
        " global ones do not (1e-12)"
    );
}

//- A heave prescribed as a sine, with a pendulum hanging free from the
//  heaving body: the joint follows the Function1, and its driving force
//  is the inverse dynamics of the motion
void prescribedHeave()
{
    const scalar A = 0.1, f = 0.7, w = 2*pi*f;
    const std::string text =
        "solver { type Newmark; } g (0 0 -9.81);"
        "q (0 0.3); qDot (" + std::to_string(A*w) + " 0);"
        "bodies {"
        " carrier { type rigidBody; parent root; mass 3;"
        " centreOfMass (0 0 0); inertia (0.1 0 0 0.1 0 0.1);"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 0); joint { type Pz; } }"
        " bob { type rigidBody; parent carrier; mass 1;"
        " centreOfMass (0 0 -0.5); inertia (0.01 0 0 0.01 0 0.01);"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 0); joint { type Ry; } } }"
        "restraints { heave { type prescribedJointMotion; body carrier;"
        " position sine; positionCoeffs { amplitude " + std::to_string(A)
      + "; frequency " + std::to_string(f) + "; scale 1; level 0; } } }";

    autoPtr<RBD::rigidBodyMotion> mo(test::motion(text));
    const RBD::rigidBodyModel& model = mo->model();
    RBD::rigidBodyModelWorkspace ws(model);
    scalarField tau(model.nDoF(), Zero);
    const Field<spatialVector> fx(model.nBodies(), Zero);

    scalar worstQ = 0, worstQDot = 0, worstForce = 0, worstFree = 0;
    scalar maxForce = 0, maxSwing = 0;
    test::run
    (
        mo(), 1e-3, 3000,
        [&](RBD::rigidBodyMotion& m)
        {
            const scalar t = m.state().t();
            worstQ = max(worstQ, mag(m.state().q()[0] - A*Foam::sin(w*t)));
            worstQDot = max
            (
                worstQDot,
                mag(m.state().qDot()[0] - A*w*Foam::cos(w*t))
            );
            model.inverseDynamics(m.state(), ws, fx, tau);
            const scalar force = m.prescriptions()[0].force;
            worstForce = max(worstForce, mag(force - tau[0]));
            worstFree = max(worstFree, mag(tau[1]));
            maxForce = max(maxForce, mag(force));
            maxSwing = max(maxSwing, mag(m.state().q()[1]));
        }
    );

    checkAbs
    (
        worstQ/A, 0, 1e-12,
        "prescribedJointMotion: the heave follows 0.1 sin(2 pi 0.7 t) at"
        " every step of 3 s, over the amplitude"
    );
    checkAbs
    (
        worstQDot/(A*w), 0, 1e-6,
        "... and its rate the sine's derivative (central differences),"
        " over the rate's amplitude"
    );
    checkAbs
    (
        worstForce/maxForce, 0, 1e-9,
        "... its driving force is the inverse dynamics of the motion, the"
        " pendulum swinging on it (largest " + std::to_string(maxForce)
      + " N), over the largest"
    );
    check
    (
        worstFree <= 1e-9*maxForce && maxSwing > 0.2,
        "... and the free pendulum needs no force of its own (inverse"
        " dynamics " + std::to_string(worstFree) + " N m); it swings to "
      + std::to_string(maxSwing) + " rad"
    );
}


//- The coupling residual beside a prescription: a carrier heaved as a
//  sine and a rudder turned as one (prescribedRotation), both at omega dt
//  = 0.63 (5 Hz, dt 20 ms), and a free body on a spring beside them,
//  external forces on the carrier and the free body.  The prescribed heave cannot be
//  off, so its residual is 0 at every step (above the tolerance when
//  measured along its motor, the check's counterpart: one relaxed solve a
//  step, as a fluid's corrector is); the free body keeps its own, flagged
//  as solved and more so with a further error of 0.3 of its acceleration
void prescribedResidual()
{
    const scalar A = 0.01, f = 5, w = 2*pi*f, dt = 0.02;
    const std::string text =
        "solver { type Newmark; } g (0 0 -9.81); nIter 1;"
        "accelerationRelaxation 0.7;"
        "qDot (" + std::to_string(A*w) + " 0 0);"
        "bodies {"
        " carrier { type rigidBody; parent root; mass 3;"
        " centreOfMass (0 0 0); inertia (0.1 0 0 0.1 0 0.1);"
        " transform (1 0 0 0 1 0 0 0 1) (0 0 0); joint { type Pz; } }"
        " float { type rigidBody; parent root; mass 1;"
        " centreOfMass (0 0 0); inertia (0.01 0 0 0.01 0 0.01);"
        " transform (1 0 0 0 1 0 0 0 1) (2 0 0); joint { type Px; } }"
        " rudder { type rigidBody; parent root; mass 2;"
        " centreOfMass (0 0 -0.3); inertia (0.1 0 0 0.1 0 0.1);"
        " transform (1 0 0 0 1 0 0 0 1) (4 0 0); joint { type Ry; } } }"
        "restraints { turn { type prescribedRotation; body rudder;"
        " axis (0 1 0); omega sine; omegaCoeffs { amplitude 1;"
        " frequency " + std::to_string(f) + "; scale (0 1 0);"
        " level (0 0 0); } }"
        " heave { type prescribedJointMotion; body carrier;"
        " position sine; positionCoeffs { amplitude " + std::to_string(A)
      + "; frequency " + std::to_string(f) + "; scale 1; level 0; } }"
        " spring { type linearSpring; body float; anchor (0 0 0);"
        " refAttachmentPt (0 0 0); stiffness 40; damping 0;"
        " restLength 2; } }";

    autoPtr<RBD::rigidBodyMotion> mo(test::motion(text));
    RBD::rigidBodyMotion& m = mo();
    const RBD::rigidBodyModel& model = m.model();
    RBD::couplingResidual with
    (
        test::dictFromString("couplingTolerance 0.1;"), model, true
    );
    RBD::couplingResidual without(with), offFree(with);

    const scalarField tau(model.nDoF(), Zero);
    Field<spatialVector> fx(model.nBodies(), Zero);
    scalarField d(model.nDoF());
    scalar worstWith = 0, worstWithout = 0;
    for (label step = 0; step < 100; ++step)
    {
        const scalar t = (step + 1)*dt;
        fx[model.bodyID("carrier")] = spatialVector(Zero, vector(0, 0, 5));
        fx[model.bodyID("float")] =
            spatialVector(Zero, vector(2*Foam::sin(3*t), 0, 0));
        m.newTime();
        m.solve(t, dt, tau, fx);

        const scalarField& a = m.state().qDdot();
        d = m.coupling().distance();
        with.measure(d, a, m.constraints());
        without.measure(d, a);
        d[1] += 0.3*a[1];
        offFree.measure(d, a, m.constraints());
        worstWith = max
        (
            worstWith,
            max(with.residual()[0], with.residual()[2])
        );
        worstWithout = max
        (
            worstWithout,
            min(without.residual()[0], without.residual()[2])
        );
        for (RBD::couplingResidual* r : {&with, &without, &offFree})
        {
            r->solved();
            r->endStep(a, t);
        }
    }

    OStringStream largest;
    largest << worstWith;
    check
    (
        worstWith <= 1e-12 && worstWithout > with.tolerance(),
        "couplingResidual: a joint heaved by prescribedJointMotion and one"
        " turned by prescribedRotation at omega dt 0.63 have no residual at"
        " any step (largest " + largest.str() + ", 1e-12; measured along"
        " their motors both reached " + std::to_string(worstWithout)
      + ", above the tolerance 0.1)"
    );
    check
    (
        with.nFlagged() > 0 && with.worstDoF() == 1
     && offFree.nFlagged() > with.nFlagged() && offFree.worstDoF() == 1,
        "... while the free body beside it keeps its own: one relaxed solve"
        " a step leaves it off, flagged in " + std::to_string(with.nFlagged())
      + " of 100 steps, and " + std::to_string(offFree.nFlagged())
      + " with its accelerations a further 0.3 of themselves off"
    );
}

} // End namespace connectedBodiesTest


int main(int argc, char *argv[])
{
    using namespace connectedBodiesTest;

    modes();
    energyBalance();
    twoBodySpring();
    externalForceFrames();
    prescribedHeave();
    prescribedResidual();

    return test::testResult();
}
