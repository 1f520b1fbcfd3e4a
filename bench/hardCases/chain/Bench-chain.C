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
    Bench-chain

Description
    A planar chain of 10 links (each a 1 kg cuboid 0.05 x 0.05 x 0.5 m, its
    centre of mass mid-link, joined end to end by Ry joints, the first to
    the root at the origin) in gravity (0 0 -9.81), no damping, released at
    rest from straight at 1 rad from hanging (q0 = 1, the others 0).  Runs
    10^6 steps of deltaT = 1 ms (1000 s) and of 0.5 ms (500 s) with every
    solver and nIter 1 and 4, and prints a markdown table of the total
    energy's error (E = kinetic + potential, the potential zero at the
    origin; E0 = -132.5 J, the fall from the start to hanging straight
    112.7 J): max |E - E0|/|E0| over the run, the slope of the
    least-squares line through (E - E0)/|E0| against t [1/s], the error's
    mean over each tenth of the run, whether it drifts or stays bounded
    (driftStats.H: the means over the first and the last tenth differ by
    more than half the largest error, or not), and the CPU time.  A run
    whose energy error passes 1 (100% of |E0|) stops there.

Usage
    Bench-chain [-steps N] [-dt DT] [-solver NAME] [-nIter N]
    (-dt: that time step only)

\*---------------------------------------------------------------------------*/

#include "testModels.H"
#include "driftStats.H"
#include "benchCases.H"
#include <chrono>
#include <cstdio>
#include <string>

using namespace Foam;

namespace
{

const label nLinks = 10;

using hardCases::solverCase;
using hardCases::solverCases;
using hardCases::fmt;


std::string modelText(const std::string& solverDict, const label nIter)
{
    std::string bodies;
    for (label i = 0; i < nLinks; ++i)
    {
        bodies +=
            "l" + std::to_string(i) + " { type cuboid; parent "
          + (i ? "l" + std::to_string(i - 1) : std::string("root"))
          + "; mass 1; L (0.05 0.05 0.5); centreOfMass (0 0 -0.25);"
            " transform (1 0 0 0 1 0 0 0 1) (0 0 "
          + (i ? "-0.5" : "0") + "); joint { type Ry; } } ";
    }

    std::string q = "1";
    for (label i = 1; i < nLinks; ++i)
    {
        q += " 0";
    }

    return
        "g (0 0 -9.81); solver { " + solverDict + " } nIter "
      + std::to_string(nIter) + "; bodies { " + bodies + "} q (" + q + ");";
}


void runCase
(
    const solverCase& s,
    const label nIter,
    const scalar dt,
    const label nSteps
)
{
    autoPtr<RBD::rigidBodyMotion> motion =
        test::motion(modelText(s.dict, nIter));
    RBD::rigidBodyMotion& m = motion();

    auto energy = [](RBD::rigidBodyMotion& mo)
    {
        const RBD::rigidBodyModelWorkspace& ws = mo.workspace();
        return mo.model().kineticEnergy(ws) + mo.model().potentialEnergy(ws);
    };

    const scalar E0 = energy(m);
    const scalar tEnd = nSteps*dt;
    hardCases::driftStats sE(tEnd);

    const scalarField tau(m.model().nDoF(), Zero);
    const Field<spatialVector> fx(m.model().nBodies(), Zero);

    scalar tLost = -1;
    const auto start = std::chrono::steady_clock::now();

    for (label step = 0; step < nSteps; ++step)
    {
        m.newTime();
        m.solve((step + 1)*dt, dt, tau, fx);

        const scalar e = (energy(m) - E0)/mag(E0);
        if (!(mag(e) < 1))
        {
            tLost = m.state().t();
            break;
        }
        sE.add(m.state().t(), e);
    }

    const scalar cpu = std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - start
    ).count();

    if (tLost >= 0)
    {
        std::printf
        (
            "| %g | %s | %d | \\|E - E0\\| > \\|E0\\| at t = %.4g s (step %d) | | | | %.1f |\n",
            dt, s.name, int(nIter), tLost, int(std::round(tLost/dt)), cpu
        );
    }
    else
    {
        std::string tenths;
        for (int i = 0; i < 10; ++i)
        {
            tenths += (i ? " " : "") + fmt("%+.1e", sE.meanTenth(i));
        }
        std::printf
        (
            "| %g | %s | %d | %s | %s | %s | %s | %.1f |\n",
            dt, s.name, int(nIter),
            fmt("%.2e", sE.largest()).c_str(),
            fmt("%+.2e", sE.slope()).c_str(),
            tenths.c_str(),
            sE.secular() ? "drifts" : "bounded",
            cpu
        );
    }
    std::fflush(stdout);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    hardCases::options o;
    o.length = 1000000;
    if (!hardCases::readOptions(argc, argv, "-steps", o))
    {
        return 1;
    }
    const label nSteps = label(o.length);

    {
        autoPtr<RBD::rigidBodyMotion> m =
            test::motion(modelText("type Newmark;", 1));
        const RBD::rigidBodyModelWorkspace& ws = m->workspace();
        std::printf
        (
            "Chain of %d links released from 1 rad: E0 = %.6g J;"
            " %d steps\n\n",
            int(nLinks), m->model().potentialEnergy(ws), int(nSteps)
        );
    }

    std::printf
    (
        "| dt [s] | solver | nIter | max \\|E - E0\\|/\\|E0\\| | slope [1/s]"
        " | mean (E - E0)/\\|E0\\| over each tenth of the run | energy | CPU [s] |\n"
        "|---|---|---|---|---|---|---|---|\n"
    );

    for (const scalar dt : {1e-3, 5e-4})
    {

        for (const solverCase& s : solverCases)
        {
            if (!o.runs(dt, s.name)) continue;

            for (const label nIter : {1, 4})
            {
                if (o.nIter && nIter != o.nIter) continue;

                runCase(s, nIter, dt, nSteps);
            }
        }
    }

    return 0;
}
