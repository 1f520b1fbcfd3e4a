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
    Test-orders

Description
    The order of convergence of each solver, by halving deltaT, on problems
    with exact or converged answers:
    - an undamped spring-mass (Pz joint, linearSpring): x(1 s) against
      x0 cos(omega t), omega = 5 rad/s;
    - two cuboids, one on the other, on Pz joints, held by undamped springs
      at an angle, in gravity: q at 1 s against a reference run;
    - a torque-free asymmetric body (composite Pxyz Rs, inertia (1 2 3),
      omega (0.5 5 0.5) rad/s): its orientation at 1 s against a reference
      run.
    The reference runs are RK4 at deltaT 1/6400 s, its error far below
    the finest error measured (RK4's at 0.01 s); they are checked against
    Newmark with nIter 4 at 1/12800 s.  The order is log2 of the ratio of
    the errors of the last two halvings: the solvers with one solve a step
    (nIter 1) at deltaT 0.02, 0.01, 0.005 are second order, within 0.2 of
    2; RK4 at 0.04, 0.02, 0.01 (its errors at 0.005 near round-off on the
    spring) is fourth order, within 0.3 of 4.
\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include <iomanip>
#include <sstream>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A solver, the time steps its order is measured at, and its order
struct solverCase
{
    const char* solver;
    scalar dt[3];
    scalar order;
    scalar tolerance;
};

const solverCase cases[] =
{
    {"type Newmark;", {0.02, 0.01, 0.005}, 2, 0.2},
    {"type CrankNicolson;", {0.02, 0.01, 0.005}, 2, 0.2},
    {"type symplectic;", {0.02, 0.01, 0.005}, 2, 0.2},
    {"type RK4;", {0.04, 0.02, 0.01}, 4, 0.3}
};

//- The reference runs: solver, nIter, deltaT; and the cross-check's
const char* refSolver = "type RK4;";
const label refNIter = 1;
const scalar refDt = 1.0/6400;
const char* checkSolver = "type Newmark;";
const label checkNIter = 4;
const scalar checkDt = 1.0/12800;

std::string springText(const std::string& solver)
{
    // m 2 kg, k 50 N/m: omega 5 rad/s
    return
        "g (0 0 0); solver { " + solver + " } nIter 1;"
        " bodies { mass { type cuboid; parent root; mass 2;"
        " L (0.2 0.2 0.1); centreOfMass (0 0 0); joint { type Pz; } } }"
        " restraints { spring { type linearSpring; body mass;"
        " anchor (0 0 -1); refAttachmentPt (0 0 0); stiffness 50;"
        " damping 0; restLength 1; } } q (0.1);";
}

std::string topText(const std::string& solver, const label nIter)
{
    return
        "g (0 0 0); solver { " + solver + " } nIter "
      + std::to_string(nIter) + ";"
        " bodies { top { type rigidBody; parent root; mass 1;"
        " centreOfMass (0 0 0); inertia (1 0 0 2 0 3);"
        " joint { type composite; joints ({ type Pxyz; } { type Rs; }); } } }"
        " qDot (0 0 0 0.5 5 0.5);";
}

std::string twoCuboidsText(const std::string& solver, const label nIter)
{
    // Two cuboids, the second on the first, each on a Pz joint, held by
    // undamped springs at an angle to the joints
    return
        "g (0 0 -9.81); solver { " + solver + " } nIter "
      + std::to_string(nIter) + ";"
        " bodies {"
        " b1 { type cuboid; parent root; mass 2; L (0.2 0.2 0.1);"
        " centreOfMass (0 0 0); joint { type Pz; } }"
        " b2 { type cuboid; parent b1; mass 1; L (0.1 0.1 0.1);"
        " centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (0.5 0 0);"
        " joint { type Pz; } } }"
        " restraints {"
        " s1 { type linearSpring; body b1; anchor (-1 0 0.6);"
        " refAttachmentPt (0 0 0); stiffness 60; damping 0;"
        " restLength 1; }"
        " s2 { type linearSpring; body b2; anchor (1.3 0 -0.7);"
        " refAttachmentPt (0 0 0); stiffness 40; damping 0;"
        " restLength 0.9; } }"
        " q (0.05 -0.1);";
}

//- q of the two cuboids at T with deltaT dt
scalarField twoCuboidsQ
(
    const std::string& solver,
    const label nIter,
    const scalar dt
)
{
    autoPtr<RBD::rigidBodyMotion> m =
        test::motion(twoCuboidsText(solver, nIter));
    test::runTo(m(), dt, 1);
    return m->state().q();
}

//- The orientation of the top at T with deltaT dt
tensor topOrientation
(
    const std::string& solver,
    const label nIter,
    const scalar dt
)
{
    autoPtr<RBD::rigidBodyMotion> m = test::motion(topText(solver, nIter));
    test::runTo(m(), dt, 1);
    return m->X0(m->model().bodyID("top")).E();
}

//- x in scientific notation, 3 digits
std::string sci(const scalar x)
{
    std::ostringstream os;
    os << std::scientific << std::setprecision(2) << x;
    return os.str();
}

//- Check that the errors e at the solver's three time steps fall at its
//  order
void checkOrder
(
    const std::string& what,
    const solverCase& sc,
    const scalar e[3]
)
{
    test::checkAbs
    (
        std::log2(e[1]/e[2]), sc.order, sc.tolerance,
        what + ", " + sc.solver + " nIter 1: order by halving deltaT "
      + std::to_string(sc.dt[1]) + " -> " + std::to_string(sc.dt[2])
      + " (errors " + sci(e[0]) + ", " + sci(e[1]) + ", " + sci(e[2])
      + ")"
    );
}

//- Check that the reference run agrees with the cross-check's
void checkReference(const std::string& what, const scalar difference)
{
    test::checkAbs
    (
        difference, 0, 5e-8,
        what + ": reference (" + refSolver + " deltaT 1/6400) within 5e-8"
        " of " + checkSolver + " nIter 4 deltaT 1/12800 (whose own error,"
        " its error at 0.005 s over 64^2, is about 3e-8)"
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    // Spring-mass against its exact answer
    for (const solverCase& sc : cases)
    {
        scalar e[3];
        for (label i = 0; i < 3; ++i)
        {
            autoPtr<RBD::rigidBodyMotion> m =
                test::motion(springText(sc.solver));
            test::runTo(m(), sc.dt[i], 1);
            e[i] = mag(m->state().q()[0] - 0.1*std::cos(5.0));
        }
        checkOrder("spring-mass", sc, e);
    }

    // Two cuboids on springs at an angle against a converged run
    {
        const scalarField ref(twoCuboidsQ(refSolver, refNIter, refDt));
        const scalarField q(twoCuboidsQ(checkSolver, checkNIter, checkDt));
        checkReference
        (
            "two cuboids on springs at an angle",
            Foam::sqrt(sqr(q[0] - ref[0]) + sqr(q[1] - ref[1]))
        );

        for (const solverCase& sc : cases)
        {
            scalar e[3];
            for (label i = 0; i < 3; ++i)
            {
                const scalarField q(twoCuboidsQ(sc.solver, 1, sc.dt[i]));
                e[i] = Foam::sqrt(sqr(q[0] - ref[0]) + sqr(q[1] - ref[1]));
            }
            checkOrder("two cuboids on springs at an angle", sc, e);
        }
    }

    // Torque-free asymmetric body against a converged run
    const tensor ref(topOrientation(refSolver, refNIter, refDt));
    checkReference
    (
        "torque-free top",
        mag(topOrientation(checkSolver, checkNIter, checkDt) - ref)
    );
    for (const solverCase& sc : cases)
    {
        scalar e[3];
        for (label i = 0; i < 3; ++i)
        {
            e[i] = mag(topOrientation(sc.solver, 1, sc.dt[i]) - ref);
        }
        checkOrder("torque-free top", sc, e);
    }

    return test::testResult();
}
