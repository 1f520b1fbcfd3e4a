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
    Bench-forwardDynamics (ours), Bench-forwardDynamics-stock (stock)

Description
    Time of one forward-dynamics call (kinematics, restraints and the
    articulated-body algorithm) and of one whole time step (Newmark,
    nIter 1, through rigidBodyMotion::solve) on:
    - chainN: N revolute links (Rx and Ry in turn), N = 1, 10, 100, 1000;
    - floatingBase: a body on a floating joint with four legs of six
      revolute links each (30 degrees of freedom);
    - floatingSpring: a cuboid on Py + Ry held by a linearSpring;
    - floatingObjectPyRy, floatingObjectPyRyMerged, floatingObjectFloating:
      the body of the stock floatingObject tutorial on its Py + Ry joints,
      the same with a second body merged into it (mergeWith), and on a
      floating joint (6 degrees of freedom), under a constant force and
      moment as a fluid's (what a scene declares, what it costs).
    The same source is built against our library and, with -DSTOCK,
    against the stock one (run with /usr/lib's library by bench/run).
    Prints one line per model:
        <model> <nDoF> <ns per call> <sum of qDdot> <ns per step>
    (a step: the state set to that after a first step, newTime() and
    solve(), so every step starts from the same state)
    (the checksum after the calls, all at the same state, so the two
    libraries' agree to round-off).  -quick: a fifth of the calls.
    -model NAME: only that model (to profile it).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IStringStream.H"
#include "rigidBodyMotion.H"
#include <chrono>
#include <cmath>
#include <string>

#ifndef STOCK
    #include "rigidBodyRestraint.H"
#endif

using namespace Foam;

//- q and qDot entries: q_i = 0.1 sin(i + 1), qDot_i = 0.2 cos(i + 1)
std::string stateEntries(const label nDoF)
{
    std::string q, qDot;
    for (label i = 0; i < nDoF; ++i)
    {
        q += " " + std::to_string(0.1*std::sin(i + 1.0));
        qDot += " " + std::to_string(0.2*std::cos(i + 1.0));
    }
    return "q (" + q + "); qDot (" + qDot + ");";
}


//- A link of a chain: body NAME on PARENT, 1 kg, 0.5 m long
std::string link
(
    const std::string& name,
    const std::string& parent,
    const std::string& offset,
    const char* joint
)
{
    return
        name + " { type rigidBody; parent " + parent + "; mass 1;"
        " centreOfMass (0.01 0 -0.25); inertia (0.02 0 0 0.021 0 0.01);"
        " transform (1 0 0 0 1 0 0 0 1) " + offset + "; joint { type "
      + joint + "; } } ";
}


std::string chain(const label n)
{
    std::string bodies;
    for (label i = 0; i < n; ++i)
    {
        bodies += link
        (
            "l" + std::to_string(i),
            i ? "l" + std::to_string(i - 1) : std::string("root"),
            i ? "(0 0 -0.5)" : "(0 0 0)",
            i % 2 ? "Rx" : "Ry"
        );
    }
    return
        "g (0 0 -9.81); solver { type Newmark; } bodies { " + bodies + "} "
      + stateEntries(n);
}


std::string floatingBase()
{
    std::string bodies =
        "base { type cuboid; parent root; mass 20; L (0.8 0.4 0.2);"
        " centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (0 0 1);"
        " joint { type floating; } } ";

    const char* hips[] =
        {"(0.4 0.2 0)", "(0.4 -0.2 0)", "(-0.4 0.2 0)", "(-0.4 -0.2 0)"};
    const char* joints[] = {"Rz", "Rx", "Ry", "Ry", "Rx", "Ry"};

    for (label leg = 0; leg < 4; ++leg)
    {
        for (label j = 0; j < 6; ++j)
        {
            const std::string name =
                "leg" + std::to_string(leg) + "_" + std::to_string(j);
            bodies += link
            (
                name,
                j ? "leg" + std::to_string(leg) + "_" + std::to_string(j - 1)
                  : std::string("base"),
                j ? "(0 0 -0.5)" : hips[leg],
                joints[j]
            );
        }
    }
    return
        "g (0 0 -9.81); solver { type Newmark; } bodies { " + bodies + "} "
      + stateEntries(6 + 24);
}


//- floatingObject's body (the stock tutorial's cuboid, rho 500) on a
//  JOINT, optionally with a second part merged into it
std::string floatingObject(const std::string& joint, const bool merged)
{
    return
        "g (0 0 -9.81); solver { type Newmark; } bodies {"
        " floatingObject { type cuboid; parent root; mass 7.5;"
        " L (0.3 0.2 0.5); centreOfMass (0 0 0.25);"
        " transform (1 0 0 0 1 0 0 0 1) (0.5 0.45 0.1);"
        " joint { " + joint + " } }"
      + (
            merged
          ? " ballast { type sphere; mergeWith floatingObject; mass 2;"
            " radius 0.05; centreOfMass (0 0 0);"
            " transform (1 0 0 0 1 0 0 0 1) (0 0 0.1); }"
          : ""
        )
      + " }";
}


const char* floater =
    "g (0 0 -9.81); solver { type Newmark; }"
    "bodies { floater { type cuboid; parent root; mass 15;"
    " L (0.3 0.2 0.5); centreOfMass (0 0 0.25);"
    " transform (1 0 0 0 1 0 0 0 1) (0.5 0.45 0.1);"
    " joint { type composite; joints ({ type Py; } { type Ry; }); } } }"
    "restraints { spring { type linearSpring; body floater;"
    " anchor (0.5 0.45 0); refAttachmentPt (0 0 0); stiffness 100;"
    " damping 1; restLength 0.1; } }"
    "q (0.0841470984808 0.0909297426826);"
    "qDot (0.108060461174 -0.0832293673094);";


//- The best time per call [ns] of nCalls calls of f, over 5 repeats
template<class Function>
double bestTime(const label nCalls, const Function& f)
{
    double best = GREAT;
    for (label repeat = 0; repeat < 5; ++repeat)
    {
        const auto start = std::chrono::steady_clock::now();
        for (label call = 0; call < nCalls; ++call)
        {
            f();
        }
        const auto stop = std::chrono::steady_clock::now();
        best = min
        (
            best,
            std::chrono::duration<double, std::nano>(stop - start).count()
           /nCalls
        );
    }
    return best;
}


int main(int argc, char *argv[])
{
    argList::addBoolOption("quick", "a fifth of the calls");
    argList::addOption
    (
        "model",
        "name",
        "only this model (to profile it, with perf or callgrind)"
    );
    #include "setRootCase.H"
    #include "createTime.H"

    const label divisor = args.found("quick") ? 5 : 1;

    const std::string PyRy
    (
        "type composite; joints ({ type Py; } { type Ry; });"
    );

    // Name, dictionary, and the body a fluid's force acts on (if any)
    const std::string models[][3] =
    {
        {"chain1", chain(1), ""},
        {"chain10", chain(10), ""},
        {"chain100", chain(100), ""},
        {"chain1000", chain(1000), ""},
        {"floatingBase", floatingBase(), ""},
        {"floatingSpring", floater, ""},
        {"floatingObjectPyRy", floatingObject(PyRy, false), "floatingObject"},
        {
            "floatingObjectPyRyMerged",
            floatingObject(PyRy, true),
            "floatingObject"
        },
        {
            "floatingObjectFloating",
            floatingObject("type floating;", false),
            "floatingObject"
        }
    };

    const word only(args.getOrDefault<word>("model", word::null));

    for (const auto& model : models)
    {
        if (!only.empty() && model[0] != only)
        {
            continue;
        }

        IStringStream is(model[1]);
        const dictionary dict(is);

        #ifdef STOCK
        RBD::rigidBodyMotion motion(runTime, dict);
        motion.g() = dict.get<vector>("g");
        const RBD::rigidBodyModel& m = motion;
        RBD::rigidBodyModelState state(m, dict);
        #else
        RBD::rigidBodyMotion motion(dict, dictionary());
        const RBD::rigidBodyModel& m = motion.model();
        RBD::rigidBodyModelState state(motion.state());
        RBD::rigidBodyModelWorkspace ws(m);
        const PtrList<RBD::restraint>& restraints = motion.restraints();
        #endif

        const scalarField tau0(m.nDoF(), Zero);

        // A fluid's force: about the body's weight, up, with a moment
        Field<spatialVector> fx0(m.nBodies(), Zero);
        if (!model[2].empty())
        {
            fx0[m.bodyID(word(model[2]))] =
                spatialVector(vector(0, 2, 0), vector(0.5, 1, 80));
        }
        scalarField tau(tau0);
        Field<spatialVector> fx(fx0);

        const label nCalls =
            max(label(400), label(400000/m.nDoF()))/divisor;

        // Forward dynamics at one state (qDot nudged so that no call can
        // be skipped)
        const double fd = bestTime
        (
            nCalls,
            [&]()
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
        );
        const scalar checksum = sum(state.qDdot());

        // A whole step of 1 ms, always from the state after a first step
        // (so that a long chain does not fall far over the calls)
        motion.newTime();
        motion.solve(1e-3, 1e-3, tau0, fx0);
        const RBD::rigidBodyModelState state1(motion.state());
        const double step = bestTime
        (
            nCalls,
            [&]()
            {
                motion.state() = state1;
                motion.newTime();
                motion.solve(2e-3, 1e-3, tau0, fx0);
            }
        );

        Info<< model[0].c_str() << ' ' << m.nDoF() << ' ' << fd << ' '
            << checksum << ' ' << step << endl;
    }

    return 0;
}
