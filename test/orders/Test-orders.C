/*---------------------------------------------------------------------------*\
Application
    Test-orders

Description
    The order of convergence of each solver, by halving deltaT, on problems
    with exact or converged answers:
    - an undamped spring-mass (Pz joint, linearSpring): x(1 s) against
      x0 cos(omega t), omega = 5 rad/s, deltaT 0.02, 0.01, 0.005;
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

//- The orientation of the top at T with deltaT dt
tensor topOrientation(const std::string& solver, const label nIter, const scalar dt)
{
    autoPtr<RBD::rigidBodyMotion> m = test::motion(topText(solver, nIter));
    test::runTo(m(), dt, 1);
    return m->X0(m->model().bodyID("top")).E();
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
        const scalar order = std::log2(e[1]/e[2]);
        test::checkAbs
        (
            order, 2, 0.2,
            std::string("spring-mass, ") + solver + " nIter 1: order by"
            " halving deltaT 0.01 -> 0.005 (errors " + std::to_string(e[0])
          + ", " + std::to_string(e[1]) + ", " + std::to_string(e[2]) + ")"
        );
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
        const scalar order = std::log2(e[1]/e[2]);
        test::checkAbs
        (
            order, 2, 0.2,
            std::string("torque-free top, ") + solver + " nIter 1: order by"
            " halving deltaT 0.01 -> 0.005 (errors " + std::to_string(e[0])
          + ", " + std::to_string(e[1]) + ", " + std::to_string(e[2]) + ")"
        );
    }

    return test::testResult();
}
