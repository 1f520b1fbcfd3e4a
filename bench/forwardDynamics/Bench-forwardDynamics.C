/*---------------------------------------------------------------------------*\
Application
    Bench-forwardDynamics (ours), Bench-forwardDynamics-stock (stock)

Description
    Time of one forward-dynamics call (restraints included) on chains of
    revolute links and on a floating body on a spring.  The same source is
    built against our library and, with -DSTOCK, against the stock one
    (run with /usr/lib's library by bench/run).  Prints one line per model:
        <model> <nDoF> <ns per call> <sum of qDdot (checksum)>

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IStringStream.H"
#include <chrono>
#include <string>

#ifdef STOCK
    #include "rigidBodyModel.H"
    #include "rigidBodyModelState.H"
#else
    #include "rigidBodyModel.H"
    #include "rigidBodyRestraint.H"
#endif

using namespace Foam;

std::string chain(const label n)
{
    std::string bodies;
    for (label i = 0; i < n; ++i)
    {
        bodies +=
            "l" + std::to_string(i) + " { type rigidBody; parent "
          + (i ? "l" + std::to_string(i - 1) : std::string("root"))
          + "; mass 1; centreOfMass (0.01 0 -0.25);"
            " inertia (0.02 0 0 0.021 0 0.01);"
            " transform (1 0 0 0 1 0 0 0 1) (0 0 "
          + (i ? "-0.5" : "0") + "); joint { type "
          + (i % 2 ? "Rx" : "Ry") + "; } } ";
    }
    return "g (0 0 -9.81); bodies { " + bodies + "}";
}


const char* floater =
    "g (0 0 -9.81);"
    "bodies { floater { type cuboid; parent root; mass 15;"
    " L (0.3 0.2 0.5); centreOfMass (0 0 0.25);"
    " transform (1 0 0 0 1 0 0 0 1) (0.5 0.45 0.1);"
    " joint { type composite; joints ({ type Py; } { type Ry; }); } } }"
    "restraints { spring { type linearSpring; body floater;"
    " anchor (0.5 0.45 0); refAttachmentPt (0 0 0); stiffness 100;"
    " damping 1; restLength 0.1; } }";


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"

    const std::pair<std::string, std::string> models[] =
    {
        {"chain1", chain(1)},
        {"chain10", chain(10)},
        {"chain30", chain(30)},
        {"floatingSpring", floater}
    };

    for (const auto& model : models)
    {
        IStringStream is(model.second);
        const dictionary dict(is);

        #ifdef STOCK
        RBD::rigidBodyModel m(runTime, dict);
        m.g() = dict.get<vector>("g");
        RBD::rigidBodyModelState state(m);
        #else
        RBD::rigidBodyModel m(dict);
        RBD::rigidBodyModelState state(m.nDoF());
        RBD::rigidBodyModelWorkspace ws(m);
        PtrList<RBD::restraint> restraints;
        if (dict.found("restraints"))
        {
            for (const entry& e : dict.subDict("restraints"))
            {
                restraints.append
                (
                    RBD::restraint::New(e.keyword(), e.dict(), m)
                );
            }
        }
        #endif

        forAll(state.q(), i)
        {
            state.q()[i] = 0.1*std::sin(i + 1.0);
            state.qDot()[i] = 0.2*std::cos(i + 1.0);
        }

        const scalarField tau0(m.nDoF(), Zero);
        const Field<spatialVector> fx0(m.nBodies(), Zero);
        scalarField tau(tau0);
        Field<spatialVector> fx(fx0);

        const label nCalls = max(label(2000), label(400000/m.nDoF()));
        double best = GREAT;
        scalar checksum = 0;

        for (label repeat = 0; repeat < 5; ++repeat)
        {
            const auto start = std::chrono::steady_clock::now();
            for (label call = 0; call < nCalls; ++call)
            {
                state.qDot()[0] += 1e-12;
                tau = tau0;
                fx = fx0;
                #ifdef STOCK
                m.forwardDynamicsCorrection(state);
                m.applyRestraints(tau, fx, state);
                m.forwardDynamics(state, tau, fx);
                #else
                m.kinematics(state, ws);
                forAll(restraints, ri)
                {
                    restraints[ri].restrain(tau, fx, state, ws);
                }
                m.articulatedBodyDynamics(tau, fx, ws, state.qDdot());
                #endif
            }
            const auto stop = std::chrono::steady_clock::now();
            best = min
            (
                best,
                std::chrono::duration<double, std::nano>(stop - start).count()
               /nCalls
            );
            checksum = sum(state.qDdot());
        }

        Info<< model.first.c_str() << ' ' << m.nDoF() << ' ' << best << ' '
            << checksum << endl;
    }

    return 0;
}
