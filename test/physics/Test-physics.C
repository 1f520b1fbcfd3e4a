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
    Test-physics

Description
    Exact answers: free fall, the damped spring-mass, the pendulum period
    (small and large angle, by the complete elliptic integral), the
    torque-free symmetric top, the intermediate-axis flip with energy and
    angular momentum conserved, spin through many turns on a quaternion
    joint; each solver's order of convergence.  Tolerances are stated with
    each check.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace physicsTest
{

using Foam::sqrt;
using Foam::exp;
using Foam::sin;
using Foam::cos;
using test::check;
using test::checkAbs;
using test::checkRel;
using test::checkRange;

const char* solvers[] = {"Newmark", "CrankNicolson", "symplectic", "RK4"};


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

std::string header(const std::string& solver, const std::string& g = "(0 0 0)")
{
    return
        "solver { type " + solver + "; } g " + g + "; ";
}


void freeFall()
{
    for (const char* solver : solvers)
    {
        autoPtr<RBD::rigidBodyMotion> m = test::motion
        (
            header(solver, "(0 0 -9.81)")
          + "bodies { ball { type sphere; parent root; mass 2; radius 0.1;"
            " centreOfMass (0 0 0); joint { type Pxyz; } } }"
            " qDot (1 0 2);"
        );

        test::runTo(m(), 0.01, 1.0);
        const scalarField& q = m->state().q();
        const scalar t = m->state().t();

        checkAbs
        (
            q[2], 2*t - 0.5*9.81*sqr(t), 1e-10,
            std::string("free fall height, ") + solver
        );
        checkAbs(q[0], t, 1e-12, std::string("free fall drift, ") + solver);
    }
}


//- Damped spring-mass on Pz: error at t = 1 s
scalar springMassError
(
    const std::string& solver,
    const scalar dt,
    const label nIter
)
{
    const scalar m = 2, k = 50, c = 1, x0 = 0.1;

    autoPtr<RBD::rigidBodyMotion> motion = test::motion
    (
        header(solver) + "nIter " + std::to_string(nIter) + "; "
      + "bodies { mass { type cuboid; parent root; mass 2; L (0.1 0.1 0.1);"
        " centreOfMass (0 0 0); joint { type Pz; } } }"
        " restraints { spring { type linearSpring; body mass;"
        " anchor (0 0 -1); refAttachmentPt (0 0 0); stiffness 50;"
        " damping 1; restLength 1; } }"
        " q (0.1);"
    );

    test::runTo(motion(), dt, 1.0);

    const scalar t = motion->state().t();
    const scalar w0 = sqrt(k/m);
    const scalar zeta = c/(2*sqrt(k*m));
    const scalar wd = w0*sqrt(1 - sqr(zeta));
    const scalar exact =
        exp(-zeta*w0*t)
       *(x0*cos(wd*t) + (zeta*w0*x0/wd)*sin(wd*t));

    return mag(motion->state().q()[0] - exact);
}


void springMass()
{
    // Accuracy at dt = 1 ms
    checkAbs
    (
        springMassError("Newmark", 1e-3, 1), 0, 5e-6,
        "damped spring-mass at t = 1 s, Newmark, dt 1 ms"
    );
    checkAbs
    (
        springMassError("CrankNicolson", 1e-3, 1), 0, 5e-6,
        "damped spring-mass at t = 1 s, CrankNicolson, dt 1 ms"
    );

    // Order of convergence: error ratio on halving dt from dt0 (symplectic
    // with one solve too: its damper is evaluated at the predicted end
    // velocity; RK4 from 40 ms, its error at 1 ms near round-off)
    struct orderCase
    {
        const char* solver;
        label nIter;
        scalar dt0, lo, hi;
    };
    const orderCase cases[] =
    {
        {"Newmark", 1, 4e-3, 3.6, 4.4},
        {"CrankNicolson", 1, 4e-3, 3.6, 4.4},
        {"Newmark", 3, 4e-3, 3.6, 4.4},
        {"symplectic", 1, 4e-3, 3.6, 4.4},
        {"symplectic", 4, 4e-3, 3.6, 4.4},
        {"RK4", 1, 4e-2, 14.4, 17.6},
        {"RK4", 3, 4e-2, 14.4, 17.6}
    };

    for (const orderCase& oc : cases)
    {
        const scalar e1 = springMassError(oc.solver, oc.dt0, oc.nIter);
        const scalar e2 = springMassError(oc.solver, oc.dt0/2, oc.nIter);
        const scalar e3 = springMassError(oc.solver, oc.dt0/4, oc.nIter);

        Info<< "    spring-mass errors " << oc.solver << " nIter "
            << oc.nIter << ": " << e1 << ' ' << e2 << ' ' << e3 << endl;

        checkRange
        (
            sqrt((e1/e2)*(e2/e3)), oc.lo, oc.hi,
            std::string("error ratio on halving dt, damped spring-mass, ")
          + oc.solver + " nIter " + std::to_string(oc.nIter)
        );
    }
}


//- Complete elliptic integral of the first kind K(k), by the AGM
scalar ellipticK(const scalar k)
{
    scalar a = 1, b = sqrt(1 - sqr(k));
    while (mag(a - b) > 1e-15*a)
    {
        const scalar an = 0.5*(a + b);
        b = sqrt(a*b);
        a = an;
    }
    return constant::mathematical::pi/(2*a);
}


void pendulum(const scalar theta0, const scalar tol)
{
    const scalar m = 1, r = 0.1, L = 1, g = 9.81;
    const scalar Ipivot = 0.4*m*sqr(r) + m*sqr(L);
    const scalar w0 = sqrt(m*g*L/Ipivot);
    const scalar exactT = 4*ellipticK(sin(0.5*theta0))/w0;

    autoPtr<RBD::rigidBodyMotion> motion = test::motion
    (
        header("Newmark", "(0 0 -9.81)")
      + "bodies { bob { type sphere; parent root; mass 1; radius 0.1;"
        " centreOfMass (0 0 -1); joint { type Ry; } } }"
        " q (" + std::to_string(theta0) + ");"
    );

    // Times at which q crosses zero
    DynamicList<scalar> crossings;
    scalar qPrev = theta0, tPrev = 0;

    test::run
    (
        motion(), 1e-4, label(2.2*exactT/1e-4),
        [&](RBD::rigidBodyMotion& mo)
        {
            const scalar q = mo.state().q()[0];
            const scalar t = mo.state().t();
            if (q*qPrev < 0)
            {
                crossings.append(tPrev + (t - tPrev)*qPrev/(qPrev - q));
            }
            qPrev = q;
            tPrev = t;
        }
    );

    if
    (
        check
        (
            crossings.size() >= 3,
            "pendulum swings through zero at least three times"
        )
    )
    {
        checkRel
        (
            crossings[2] - crossings[0], exactT, tol,
            "pendulum period, amplitude " + std::to_string(theta0)
          + " rad (elliptic integral), Newmark dt 0.1 ms"
        );
    }
}


void symmetricTop()
{
    // I = diag(1 1 2), omega = (1 0 2): the body-frame angular velocity
    // precesses at (I3 - I1)/I1 omega3 = 2 rad/s: omega = (cos 2t, sin 2t, 2)
    autoPtr<RBD::rigidBodyMotion> motion = test::motion
    (
        header("Newmark")
      + "bodies { top { type rigidBody; parent root; mass 1;"
        " centreOfMass (0 0 0); inertia (1 0 0 1 0 2);"
        " joint { type composite;"
        " joints ({ type Pxyz; } { type Rs; }); } } }"
        " qDot (0 0 0 1 0 2);"
    );

    test::runTo(motion(), 1e-3, 1.0);

    const scalarField& qDot = motion->state().qDot();
    const scalar t = motion->state().t();

    checkAbs(qDot[3], cos(2*t), 1e-5, "symmetric top omega_x = cos 2t at 1 s");
    checkAbs(qDot[4], sin(2*t), 1e-5, "symmetric top omega_y = sin 2t at 1 s");
    checkAbs(qDot[5], 2, 1e-12, "symmetric top omega_z constant");
}


void intermediateAxis()
{
    // Spin about the intermediate axis flips; energy and angular momentum
    // are conserved
    autoPtr<RBD::rigidBodyMotion> motion = test::motion
    (
        header("Newmark")
      + "bodies { book { type rigidBody; parent root; mass 1;"
        " centreOfMass (0 0 0); inertia (1 0 0 2 0 3);"
        " joint { type composite;"
        " joints ({ type Pxyz; } { type Rs; }); } } }"
        " qDot (0 0 0 0.01 2 0.01);"
    );

    const label id = motion->model().bodyID("book");

    auto momentum = [&](RBD::rigidBodyMotion& m)
    {
        const spatialTransform X(m.X0(id));
        const spatialVector v(m.workspace().v[m.model().masterID(id)]);
        return vector(X.E().T() & (m.model().bodies()[m.model().masterID(id)].Ic() & v.w()));
    };

    const vector L0(momentum(motion()));
    const scalar T0 = motion->model().kineticEnergy(motion->workspace());

    scalar minOmegaY = GREAT;
    scalar maxLErr = 0, maxTErr = 0;

    test::run
    (
        motion(), 1e-3, 20000,
        [&](RBD::rigidBodyMotion& m)
        {
            minOmegaY = min(minOmegaY, m.state().qDot()[4]);
            maxLErr = max(maxLErr, mag(momentum(m) - L0)/mag(L0));
            maxTErr =
                max(maxTErr, mag(m.model().kineticEnergy(m.workspace()) - T0)/T0);
        }
    );

    check
    (
        minOmegaY < -1.9,
        "spin about the intermediate axis flips (min omega_y "
      + std::to_string(minOmegaY) + " < -1.9)"
    );
    checkAbs
    (
        maxTErr, 0, 1e-6,
        "intermediate-axis spin: kinetic energy conserved over 20 s"
    );
    checkAbs
    (
        maxLErr, 0, 1e-5,
        "intermediate-axis spin: angular momentum conserved over 20 s"
    );
}


void spinThroughPi()
{
    // Constant spin of 10 rad/s about z for 1 s on a floating joint: the
    // quaternion passes pi three times; orientation = Rz(10)
    for (const char* solver : solvers)
    {
        autoPtr<RBD::rigidBodyMotion> motion = test::motion
        (
            header(solver)
          + "bodies { wheel { type rigidBody; parent root; mass 1;"
            " centreOfMass (0 0 0); inertia (1 0 0 1 0 2);"
            " joint { type composite;"
        " joints ({ type Pxyz; } { type Rs; }); } } }"
            " qDot (0 0 0 0 0 10);"
        );

        test::runTo(motion(), 1e-3, 1.0);

        const tensor E(motion->X0(motion->model().bodyID("wheel")).E());
        checkAbs
        (
            mag(E - Rz(10.0)), 0, 1e-9,
            std::string("spin through pi on the Rs joint: orientation ")
          + "Rz(10 rad) after 1 s, " + solver
        );
    }
}


void compositeVersusSimple()
{
    // composite (Px Py Pz) moves as Pxyz, composite (Rx Ry Rz) as Rxyz
    const std::string body =
        " parent root; mass 2; centreOfMass (0.1 0.2 -0.3);"
        " inertia (0.3 0.01 0.02 0.4 0.03 0.5);";

    const std::pair<std::string, std::string> pairs[] =
    {
        {"{ type Pxyz; }",
         "{ type composite; joints ({ type Px; } { type Py; } { type Pz; }); }"},
        {"{ type Rxyz; }",
         "{ type composite; joints ({ type Rx; } { type Ry; } { type Rz; }); }"},
        {"{ type Rzyx; }",
         "{ type composite; joints ({ type Rz; } { type Ry; } { type Rx; }); }"},
        {"{ type Ryxz; }",
         "{ type composite; joints ({ type Ry; } { type Rx; } { type Rz; }); }"}
    };

    for (const auto& p : pairs)
    {
        autoPtr<RBD::rigidBodyMotion> a = test::motion
        (
            header("Newmark", "(0 0 -9.81)")
          + "bodies { b { type rigidBody;" + body + " joint " + p.first
          + " } } q (0.3 -0.2 0.1); qDot (1 -2 0.5);"
        );
        autoPtr<RBD::rigidBodyMotion> b = test::motion
        (
            header("Newmark", "(0 0 -9.81)")
          + "bodies { b { type rigidBody;" + body + " joint " + p.second
          + " } } q (0.3 -0.2 0.1); qDot (1 -2 0.5);"
        );

        test::runTo(a(), 1e-3, 0.5);
        test::runTo(b(), 1e-3, 0.5);

        const spatialTransform Xa(a->X0(a->model().bodyID("b")));
        const spatialTransform Xb(b->X0(b->model().bodyID("b")));

        checkAbs
        (
            mag(Xa.E() - Xb.E()) + mag(Xa.r() - Xb.r()), 0, 1e-10,
            "composite " + p.second.substr(0, 60) + "... moves as "
          + p.first
        );
    }
}


void torsionSpring()
{
    // Cuboid on Ry held by a linearAxialAngularSpring: q = q0 cos(w t),
    // w = sqrt(k/Iyy), Iyy = m (Lx^2 + Lz^2)/12 (the stock library's spring
    // pushes away from the reference orientation instead)
    const scalar m = 3, Lx = 0.4, Lz = 0.2, k = 2, q0 = 0.3;
    const scalar w = sqrt(k/(m*(sqr(Lx) + sqr(Lz))/12));

    for (const char* solver : solvers)
    {
        autoPtr<RBD::rigidBodyMotion> motion = test::motion
        (
            header(solver) + "nIter 2; "
          + "bodies { flap { type cuboid; parent root; mass 3;"
            " L (0.4 0.1 0.2); centreOfMass (0 0 0); joint { type Ry; } } }"
            " restraints { hinge { type linearAxialAngularSpring;"
            " body flap; axis (0 1 0); stiffness 2; damping 0; } }"
            " q (0.3);"
        );

        test::runTo(motion(), 1e-3, 0.6);

        const scalar t = motion->state().t();
        checkAbs
        (
            motion->state().q()[0], q0*cos(w*t), 1e-5,
            std::string("torsion spring (linearAxialAngularSpring) angle")
          + " q0 cos(w t) at 0.6 s, " + solver
        );
    }
}

//- A body in a fluid whose force lags one solve behind (the added-mass
//  force of partitioned coupling, -Ma times the latest acceleration),
//  solved with nIter solves per step: error at 1 s against the exact
//  oscillation of mass m + Ma, or GREAT if the iterations diverge
scalar addedMassError
(
    const std::string& relaxation,
    const scalar Ma,
    const label nOuter = 20
)
{
    const scalar m = 1, k = 100, x0 = 0.1;

    autoPtr<RBD::rigidBodyMotion> motion = test::motion
    (
        header("Newmark") + relaxation
      + "bodies { b { type sphere; parent root; mass 1; radius 0.1;"
        " centreOfMass (0 0 0); joint { type Pz; } } }"
        " restraints { s { type linearSpring; body b; anchor (0 0 -1);"
        " refAttachmentPt (0 0 0); stiffness 100; damping 0;"
        " restLength 1; } } q (0.1);"
        " qDdot (" + std::to_string(-k*x0/(m + Ma)) + ");"
    );
    RBD::rigidBodyMotion& mo = motion();

    const scalarField tau(mo.model().nDoF(), Zero);
    Field<spatialVector> fx(mo.model().nBodies(), Zero);
    const label b = mo.model().bodyID("b");
    const scalar dt = 1e-3;

    for (label step = 0; step < 1000; ++step)
    {
        mo.newTime();
        for (label iter = 0; iter < nOuter; ++iter)
        {
            fx[b] = spatialVector(0, 0, 0, 0, 0, -Ma*mo.state().qDdot()[0]);
            mo.solve((step + 1)*dt, dt, tau, fx);
        }
        if (!(mag(mo.state().q()[0]) < 1e3))
        {
            return GREAT;
        }
    }

    const scalar w = sqrt(k/(m + Ma));
    return mag(mo.state().q()[0] - x0*cos(w*mo.state().t()));
}


void addedMass()
{
    // Ma/m = 3: plain iteration diverges (factor -3), Aitken converges
    checkRange
    (
        addedMassError
        (
            "accelerationRelaxation 1; accelerationRelaxationType constant;", 3
        ),
        1, GREAT,
        "added mass 3 m, constant relaxation 1: the iterations diverge"
    );

    // addedMass learnt: Newton's step with the added mass learnt from the
    // solves, for any ratio, in the three outer correctors of a typical
    // case (the force here answers the acceleration exactly linearly, so
    // the learnt added mass is exact and the full step,
    // accelerationRelaxation 1, converges at once)
    for (const scalar Ma : {0.2, 3.0, 1e3, 1e4})
    {
        checkAbs
        (
            addedMassError
            (
                "accelerationRelaxation 1;"
                " accelerationRelaxationType addedMass; addedMass learnt;",
                Ma,
                3
            ),
            0, 1e-5,
            "added mass " + std::to_string(Ma) + " m, addedMass coupling,"
            " 3 solves a step: oscillation of mass m + Ma"
        );
    }
    checkAbs
    (
        addedMassError
        (
            "accelerationRelaxation 1; accelerationRelaxationType Aitken;", 3
        ),
        0, 1e-5,
        "added mass 3 m, Aitken relaxation: oscillation of mass m + Ma"
    );
    checkAbs
    (
        addedMassError
        (
            "accelerationRelaxation 0.7; accelerationRelaxationType Aitken;",
            0.2
        ),
        0, 1e-5,
        "added mass 0.2 m, Aitken relaxation: oscillation of mass m + Ma"
    );
    checkAbs
    (
        addedMassError
        (
            "accelerationRelaxation 0.7;"
            " accelerationRelaxationType quasiNewton;",
            3
        ),
        0, 1e-5,
        "added mass 3 m, quasi-Newton relaxation: oscillation of mass m + Ma"
    );
    checkAbs
    (
        addedMassError
        (
            "accelerationRelaxation 0.7;"
            " accelerationRelaxationType quasiNewton;",
            20
        ),
        0, 1e-5,
        "added mass 20 m, quasi-Newton relaxation: oscillation of mass m + Ma"
    );
}

//- A ball moving at 1 m/s into a softWall: an undamped contact lasts C
//  and returns the speed; damping ratio psi returns
//  exp(-psi pi/sqrt(1 - psi^2)) of it
void softWall()
{
    for (const scalar psi : {0.0, 0.2})
    {
        autoPtr<RBD::rigidBodyMotion> motion = test::motion
        (
            header("Newmark")
          + "bodies { ball { type sphere; parent root; mass 2; radius 0.1;"
            " centreOfMass (0 0 0); joint { type Pz; } } }"
            " restraints { floor { type softWall; body ball;"
            " anchor (0 0 0); wallNormal (0 0 2);"
            " refAttachmentPt (0 0 -0.1); C 0.05; psi "
          + std::to_string(psi) + "; } }"
            " q (0.5); qDot (-1);"
        );

        test::runTo(motion(), 1e-5, 0.6);

        const scalar e = exp(-psi*constant::mathematical::pi/sqrt(1 - sqr(psi)));
        checkAbs
        (
            motion->state().qDot()[0], e, 2e-3,
            "softWall bounce: speed after contact, psi "
          + std::to_string(psi)
        );
        if (psi == 0)
        {
            checkAbs
            (
                motion->state().q()[0], 0.1 + 0.15, 2e-3,
                "softWall bounce: contact lasts C = 0.05 s (position at 0.6 s)"
            );
        }
    }
}

} // End namespace physicsTest


int main(int argc, char *argv[])
{
    using namespace physicsTest;

    freeFall();
    springMass();
    pendulum(0.1, 5e-6);
    pendulum(2.5, 5e-6);
    symmetricTop();
    intermediateAxis();
    spinThroughPi();
    compositeVersusSimple();
    torsionSpring();
    addedMass();
    softWall();

    return test::testResult();
}
