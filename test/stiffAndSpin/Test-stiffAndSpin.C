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
    Test-stiffAndSpin

Description
    The headline findings of bench/hardCases (bench/hardCases/README.md):
    - a stiff spring at omega deltaT = 1.3 (4.8 steps a period), undamped,
      over 50 periods: Newmark with nIter 40 is the trapezoidal rule itself
      (its solves converge, the error shrinking by beta (omega deltaT)^2 =
      0.42 a solve: 1e-15 after 40), whose step turns (x, v/omega) through
      exactly 2 atan(omega deltaT/2): the final state is that rotation's,
      the energy exact; nIter 1 stays bounded; at omega deltaT = 3, where
      the solves diverge, Newmark with nIter 2 relaxed by Aitken's factor
      (accelerationRelaxationType Aitken) is the trapezoidal rule;
      symplectic keeps the energy within its exact band
      [1 - (omega deltaT)^2/4, 1];
    - the intermediate-axis flip at 50 rad/s (deltaT 1 ms, 100 flips, 39 s)
      with Newmark and with symplectic, nIter 4: kinetic energy and angular
      momentum (magnitude and direction, global axes) within bounds, the
      errors not drifting;
    - a 10-link chain in gravity, 10^5 steps of 1 ms with Newmark, nIter 4:
      the total energy within a bound, not drifting.
    Tolerances are stated with each check.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace stiffAndSpinTest
{

using test::check;
using test::checkAbs;
using test::checkRange;


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Largest |e| and the means of e over the first and the last tenth of a
//  run: bounded if the means differ by less than half the largest |e|
struct errorRecord
{
    scalar tEnd, max = 0, sumFirst = 0, nFirst = 0, sumLast = 0, nLast = 0;

    explicit errorRecord(const scalar T)
    :
        tEnd(T)
    {}

    void add(const scalar t, const scalar e)
    {
        max = std::isfinite(e) ? Foam::max(max, mag(e)) : GREAT;
        if (t <= 0.1*tEnd)
        {
            sumFirst += e;
            nFirst += 1;
        }
        if (t >= 0.9*tEnd)
        {
            sumLast += e;
            nLast += 1;
        }
    }

    scalar drift() const
    {
        return mag(sumLast/Foam::max(nLast, 1.0) - sumFirst/Foam::max(nFirst, 1.0));
    }
};


std::string springText
(
    const std::string& solver,
    const label nIter,
    const std::string& relaxation = ""
)
{
    return
        "g (0 0 0); solver { " + solver + " } " + relaxation
      + " nIter " + std::to_string(nIter)
      + "; bodies { mass { type cuboid; parent root; mass 2;"
        " L (0.2 0.2 0.1); centreOfMass (0 0 0); joint { type Pz; } } }"
        " restraints { spring { type linearSpring; body mass;"
        " anchor (0 0 -1); refAttachmentPt (0 0 0); stiffness 50;"
        " damping 0; restLength 1; } } q (0.1);";
}


void stiffSpring()
{
    const scalar m = 2, k = 50, w = 5, x0 = 0.1, wdt = 1.3, dt = wdt/w;
    const label n = 242;    // 50 periods: 50*2 pi/1.3 = 241.7 steps
    const scalar E0 = 0.5*k*sqr(x0);

    // Newmark, nIter 40: the trapezoidal rule, a rotation by
    // theta = 2 atan(omega deltaT/2) a step (with nIter 20 the solves stop
    // 0.42^20 = 3e-8 short of it, and the energy is 1e-5 off after 50
    // periods: bench/hardCases/README.md)
    {
        autoPtr<RBD::rigidBodyMotion> motion =
            test::motion(springText("type Newmark;", 40));
        scalar maxEErr = 0;
        test::run
        (
            motion(), dt, n,
            [&](RBD::rigidBodyMotion& mo)
            {
                const scalar x = mo.state().q()[0], v = mo.state().qDot()[0];
                maxEErr =
                    max(maxEErr, mag(0.5*m*sqr(v) + 0.5*k*sqr(x) - E0)/E0);
            }
        );

        const scalar theta = 2*std::atan(0.5*wdt);
        checkAbs
        (
            motion->state().q()[0], x0*std::cos(n*theta), 1e-12,
            "stiff spring omega dt 1.3, Newmark nIter 40, 50 periods:"
            " x of the trapezoidal rule's rotation (2 atan(omega dt/2) a step)"
        );
        checkAbs
        (
            motion->state().qDot()[0], -w*x0*std::sin(n*theta), 1e-12,
            "stiff spring omega dt 1.3, Newmark nIter 40: v of the rotation"
        );
        checkAbs
        (
            maxEErr, 0, 1e-11,
            "stiff spring omega dt 1.3, Newmark nIter 40: energy exact"
            " over 50 periods (max |E - E0|/E0)"
        );
    }

    // omega dt 3: the solves' fixed-point iteration diverges (its factor
    // -beta (omega dt)^2 = -2.25), but relaxed by Aitken's factor, which
    // is exact for one linear degree of freedom, two solves a step are
    // the trapezoidal rule
    {
        const scalar wdt3 = 3, dt3 = wdt3/w;
        const label n3 = 105;   // 50 periods: 50*2 pi/3 = 104.7 steps
        autoPtr<RBD::rigidBodyMotion> motion = test::motion
        (
            springText
            (
                "type Newmark;", 2,
                "accelerationRelaxationType Aitken; accelerationRelaxation 1;"
            )
        );
        scalar maxX = 0;
        test::run
        (
            motion(), dt3, n3,
            [&](RBD::rigidBodyMotion& mo)
            {
                maxX = max(maxX, mag(mo.state().q()[0])/x0);
            }
        );
        const scalar theta = 2*std::atan(0.5*wdt3);
        checkRange
        (
            maxX, 0, 1 + 1e-9,
            "stiff spring omega dt 3, Newmark nIter 2 with Aitken relaxation:"
            " bounded over 50 periods (max |x|/x0, tol 1e-9)"
        );
        checkAbs
        (
            motion->state().q()[0], x0*std::cos(n3*theta), 1e-12,
            "stiff spring omega dt 3, Newmark nIter 2 with Aitken relaxation:"
            " x of the trapezoidal rule's rotation after 50 periods"
        );
    }

    // omega dt 3 with addedMass (its default form, no fluid): Newton's
    // step with the solve's own Jacobian (beta dt^2 k, by finite
    // differences) lands on the implicit answer in one solve: the
    // trapezoidal rule from nIter 1 on, and further solves keep it
    for (const label nIter : {1, 3})
    {
        const scalar wdt3 = 3, dt3 = wdt3/w;
        const label n3 = 105;
        autoPtr<RBD::rigidBodyMotion> motion = test::motion
        (
            springText
            (
                "type Newmark;", nIter,
                "accelerationRelaxationType addedMass;"
                " accelerationRelaxation 0.7;"
            )
        );
        scalar maxX = 0;
        test::run
        (
            motion(), dt3, n3,
            [&](RBD::rigidBodyMotion& mo)
            {
                maxX = max(maxX, mag(mo.state().q()[0])/x0);
            }
        );
        const scalar theta = 2*std::atan(0.5*wdt3);
        const std::string what
        (
            "stiff spring omega dt 3, Newmark nIter " + std::to_string(nIter)
          + " with addedMass: "
        );
        checkRange
        (
            maxX, 0, 1 + 1e-6,
            what + "bounded over 50 periods (max |x|/x0, tol 1e-6)"
        );
        checkAbs
        (
            motion->state().q()[0], x0*std::cos(n3*theta), 1e-6*x0,
            what + "x of the trapezoidal rule's rotation after 50 periods"
            " (tol 1e-6 x0)"
        );
    }

    // Newmark, nIter 1 (the explicit predictor-corrector): bounded
    {
        autoPtr<RBD::rigidBodyMotion> motion =
            test::motion(springText("type Newmark;", 1));
        scalar maxX = 0;
        test::run
        (
            motion(), dt, n,
            [&](RBD::rigidBodyMotion& mo)
            {
                maxX = max(maxX, mag(mo.state().q()[0])/x0);
            }
        );
        checkRange
        (
            maxX, 0, 1,
            "stiff spring omega dt 1.3, Newmark nIter 1: bounded over 50"
            " periods (max |x|/x0)"
        );
    }

    // symplectic: E/E0 within the band of its exact invariant
    // 1/2 v^2 + 1/2 omega^2 x^2 (1 - (omega dt)^2/4)
    {
        autoPtr<RBD::rigidBodyMotion> motion =
            test::motion(springText("type symplectic;", 1));
        scalar minE = GREAT, maxE = 0;
        test::run
        (
            motion(), dt, n,
            [&](RBD::rigidBodyMotion& mo)
            {
                const scalar x = mo.state().q()[0], v = mo.state().qDot()[0];
                const scalar E = (0.5*m*sqr(v) + 0.5*k*sqr(x))/E0;
                minE = min(minE, E);
                maxE = max(maxE, E);
            }
        );
        checkRange
        (
            minE, 1 - 0.25*sqr(wdt) - 1e-9, 1,
            "stiff spring omega dt 1.3, symplectic: least E/E0 over 50"
            " periods in [1 - (omega dt)^2/4, 1] (tol 1e-9)"
        );
        checkRange
        (
            maxE, 1 - 0.25*sqr(wdt), 1 + 1e-9,
            "stiff spring omega dt 1.3, symplectic: largest E/E0 at most 1"
            " (tol 1e-9)"
        );
    }
}


void flip()
{
    // Inertia (1 2 3), omega (0.5 50 0.5): a flip every 0.391057 s
    const scalar tFlip = 0.391057, dt = 1e-3;
    const label n = label(std::round(100*tFlip/dt));

    for (const char* solver : {"Newmark", "symplectic"})
    {
        autoPtr<RBD::rigidBodyMotion> motion = test::motion
        (
            std::string("g (0 0 0); solver { type ") + solver + "; } nIter 4;"
            " bodies { book { type rigidBody; parent root; mass 1;"
            " centreOfMass (0 0 0); inertia (1 0 0 2 0 3);"
            " joint { type composite;"
            " joints ({ type Pxyz; } { type Rs; }); } } }"
            " qDot (0 0 0 0.5 50 0.5);"
        );

        const label id = motion->model().bodyID("book");
        auto momentum = [&](RBD::rigidBodyMotion& m)
        {
            const spatialTransform X(m.X0(id));
            const spatialVector v(m.workspace().v[id]);
            return vector(X.E().T() & (m.model().bodies()[id].Ic() & v.w()));
        };

        const vector L0(momentum(motion()));
        const scalar T0 = motion->model().kineticEnergy(motion->workspace());

        errorRecord eT(n*dt), eL(n*dt), eDir(n*dt);
        label flips = 0;
        scalar wyPrev = 50;

        test::run
        (
            motion(), dt, n,
            [&](RBD::rigidBodyMotion& m)
            {
                const scalar t = m.state().t();
                const scalar wy = m.state().qDot()[4];
                flips += (wy*wyPrev < 0);
                wyPrev = wy;

                const vector L(momentum(m));
                eT.add(t, (m.model().kineticEnergy(m.workspace()) - T0)/T0);
                eL.add(t, (mag(L) - mag(L0))/mag(L0));
                eDir.add(t, std::atan2(mag(L ^ L0), L & L0));
            }
        );

        const std::string what =
            std::string("50 rad/s intermediate-axis flip, ") + solver
          + " nIter 4, dt 1 ms, 100 flips: ";

        check
        (
            flips == 100,
            what + "flips 100 times (" + std::to_string(flips) + ")"
        );
        checkAbs(eT.max, 0, 2.5e-4, what + "max |T - T0|/T0");
        checkAbs(eL.max, 0, 1.3e-4, what + "max |(|L| - |L0|)|/|L0|");
        checkAbs(eDir.max, 0, 3e-4, what + "max angle(L, L0) [rad]");
        check
        (
            eT.drift() < 0.5*eT.max && eL.drift() < 0.5*eL.max,
            what + "T and |L| errors bounded (means over the first and last"
            " tenth differ by less than half the largest error)"
        );
    }
}


void chain()
{
    std::string bodies;
    for (label i = 0; i < 10; ++i)
    {
        bodies +=
            "l" + std::to_string(i) + " { type cuboid; parent "
          + (i ? "l" + std::to_string(i - 1) : std::string("root"))
          + "; mass 1; L (0.05 0.05 0.5); centreOfMass (0 0 -0.25);"
            " transform (1 0 0 0 1 0 0 0 1) (0 0 "
          + (i ? "-0.5" : "0") + "); joint { type Ry; } } ";
    }

    autoPtr<RBD::rigidBodyMotion> motion = test::motion
    (
        "g (0 0 -9.81); solver { type Newmark; } nIter 4; bodies { "
      + bodies + "} q (1 0 0 0 0 0 0 0 0 0);"
    );

    auto energy = [](RBD::rigidBodyMotion& m)
    {
        const RBD::rigidBodyModelWorkspace& ws = m.workspace();
        return m.model().kineticEnergy(ws) + m.model().potentialEnergy(ws);
    };

    const scalar dt = 1e-3;
    const label n = 100000;
    const scalar E0 = energy(motion());
    errorRecord eE(n*dt);

    test::run
    (
        motion(), dt, n,
        [&](RBD::rigidBodyMotion& m)
        {
            eE.add(m.state().t(), (energy(m) - E0)/mag(E0));
        }
    );

    checkAbs
    (
        eE.max, 0, 2e-4,
        "10-link chain, Newmark nIter 4, 10^5 steps of 1 ms:"
        " max |E - E0|/|E0| (E0 -132.5 J)"
    );
    check
    (
        eE.drift() < 0.5*eE.max,
        "10-link chain, Newmark nIter 4: energy error bounded (means over the"
        " first and last tenth differ by "
      + std::to_string(eE.drift()) + " < half the largest error)"
    );
}

} // End namespace stiffAndSpinTest


int main(int argc, char *argv[])
{
    using namespace stiffAndSpinTest;

    stiffSpring();
    flip();
    chain();

    return test::testResult();
}
