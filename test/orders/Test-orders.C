/*---------------------------------------------------------------------------*\
Application
    Test-orders

Description
    The order of convergence of each solver, by halving deltaT, on problems
    with exact or converged answers:
    - an undamped spring-mass (Pz joint, linearSpring): x(1 s) against
      x0 cos(omega t), omega = 5 rad/s, deltaT 0.02, 0.01, 0.005;
    - two cuboids, one on the other, on Pz joints, held by undamped springs
      at an angle, in gravity: q at 1 s against a run of Newmark with
      nIter 4 at deltaT/64 of the finest;
    - a torque-free asymmetric body (composite Pxyz Rs, inertia (1 2 3),
      omega (0.5 5 0.5) rad/s): its orientation at 1 s against a run of
      Newmark with nIter 4 at deltaT/64 of the finest, deltaT 0.02, 0.01,
      0.005.
    The order is log2 of the ratio of the errors of the last two halvings;
    every solver with one solve a step (nIter 1) is second order: within
    0.2 of 2.
\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

const char* solvers[] =
    {"type Newmark;", "type CrankNicolson;", "type symplectic;"};

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
scalarField twoCuboidsQ(const std::string& solver, const label nIter, const scalar dt)
{
    autoPtr<RBD::rigidBodyMotion> m = test::motion(twoCuboidsText(solver, nIter));
    test::runTo(m(), dt, 1);
    return m->state().q();
}

//- The orientation of the top at T with deltaT dt
tensor topOrientation(const std::string& solver, const label nIter, const scalar dt)
{
    autoPtr<RBD::rigidBodyMotion> m = test::motion(topText(solver, nIter));
    test::runTo(m(), dt, 1);
    return m->X0(m->model().bodyID("top")).E();
}

//- Check that errors e at deltaT 0.02, 0.01 and 0.005 fall at second order
void checkOrder(const std::string& what, const scalar e[3])
{
    test::checkAbs
    (
        std::log2(e[1]/e[2]), 2, 0.2,
        what + " nIter 1: order by halving deltaT 0.01 -> 0.005 (errors "
      + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ", "
      + std::to_string(e[2]) + ")"
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    const scalar dts[] = {0.02, 0.01, 0.005};

    // Spring-mass against its exact answer
    for (const char* solver : solvers)
    {
        scalar e[3];
        for (label i = 0; i < 3; ++i)
        {
            autoPtr<RBD::rigidBodyMotion> m = test::motion(springText(solver));
            test::runTo(m(), dts[i], 1);
            e[i] = mag(m->state().q()[0] - 0.1*std::cos(5.0));
        }
        checkOrder(std::string("spring-mass, ") + solver, e);
    }

    // Two cuboids on springs at an angle against a converged run
    {
        const scalarField ref(twoCuboidsQ("type Newmark;", 4, dts[2]/64));
        for (const char* solver : solvers)
        {
            scalar e[3];
            for (label i = 0; i < 3; ++i)
            {
                const scalarField q(twoCuboidsQ(solver, 1, dts[i]));
                e[i] = Foam::sqrt(sqr(q[0] - ref[0]) + sqr(q[1] - ref[1]));
            }
            checkOrder
            (
                std::string("two cuboids on springs at an angle, ") + solver,
                e
            );
        }
    }

    // Torque-free asymmetric body against a converged run
    const tensor ref(topOrientation("type Newmark;", 4, dts[2]/64));
    for (const char* solver : solvers)
    {
        scalar e[3];
        for (label i = 0; i < 3; ++i)
        {
            e[i] = mag(topOrientation(solver, 1, dts[i]) - ref);
        }
        checkOrder(std::string("torque-free top, ") + solver, e);
    }

    return test::testResult();
}
