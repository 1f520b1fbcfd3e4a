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
    Bench-spin

Description
    A torque-free asymmetric body (mass 1 kg, inertia (1 2 3) kg m^2 about
    its centre of mass, on a composite (Pxyz Rs) joint, no gravity) spinning
    at 50 rad/s about its intermediate axis y, perturbed by 0.5 rad/s about
    x and z, so that it flips over and back every 0.391 s (half the period
    of Euler's equations: 2 K(k)/p, by the complete elliptic integral).
    Run for T seconds (1000 flips by default) at two time steps, 50 deltaT
    = 0.05 and 0.025, with every solver and nIter 1 and 4.

    Prints a markdown table: the flips counted (sign changes of omega_y;
    the exact count is the number asked for), the error of the time from
    the first to the last (exactly (flips - 1) times the flip time), the
    kinetic energy's relative error after 10 flips; for the kinetic energy T, the magnitude |L|
    and the direction of the angular momentum in global axes
    (L = E^T Ic omega, E the body's orientation), the relative error's
    drift per second (slope of the least-squares line), its largest value,
    and the growth: its largest value over the last tenth of the run over
    that over the first tenth (about 1 for a bounded error, 10 for a
    linear drift, 100 for a quadratic one), and whether it drifts or stays
    bounded (driftStats.H); the direction's error is the angle between L
    and L0 [rad]; the kinetic energy and the body-frame angular velocity
    at the end (the damped schemes end up wobbling about the major axis
    z, where omega_y still changes sign: "flips" counts those too); the
    CPU time of the run.  A run whose
    kinetic energy passes 1e3 times the initial stops there.

Usage
    Bench-spin [-flips N] [-dt DT] [-solver NAME] [-nIter N]
    (-dt, -solver, -nIter: only the runs that match)

\*---------------------------------------------------------------------------*/

#include "testModels.H"
#include "driftStats.H"
#include "benchCases.H"
#include "mathematicalConstants.H"
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace Foam;

namespace
{

const scalar I1 = 1, I2 = 2, I3 = 3;
const scalar spin = 50, perturbation = 0.5;

using hardCases::solverCase;
using hardCases::solverCases;
using hardCases::fmt;


//- Complete elliptic integral of the first kind K(k), by the
//  arithmetic-geometric mean
scalar ellipticK(const scalar k)
{
    scalar a = 1, b = std::sqrt(1 - k*k);
    while (std::fabs(a - b) > 1e-15*a)
    {
        const scalar an = 0.5*(a + b);
        b = std::sqrt(a*b);
        a = an;
    }
    return constant::mathematical::pi/(2*a);
}


//- Time between flips: half the period of Euler's equations (Landau and
//  Lifshitz, Mechanics, 37), for L^2 > 2 T I2 (omega_z keeps its sign)
scalar flipTime()
{
    const scalar w1 = perturbation, w2 = spin, w3 = perturbation;
    const scalar twoT = I1*w1*w1 + I2*w2*w2 + I3*w3*w3;
    const scalar L2 = sqr(I1*w1) + sqr(I2*w2) + sqr(I3*w3);
    const scalar p = std::sqrt((I3 - I2)*(L2 - twoT*I1)/(I1*I2*I3));
    const scalar k2 = (I2 - I1)*(twoT*I3 - L2)/((I3 - I2)*(L2 - twoT*I1));
    return 2*ellipticK(std::sqrt(k2))/p;
}


std::string modelText(const std::string& solverDict, const label nIter)
{
    char buf[1024];
    std::snprintf
    (
        buf, sizeof(buf),
        "g (0 0 0); solver { %s } nIter %d;"
        " bodies { book { type rigidBody; parent root; mass 1;"
        " centreOfMass (0 0 0); inertia (%g 0 0 %g 0 %g);"
        " joint { type composite; joints ({ type Pxyz; } { type Rs; }); } } }"
        " qDot (0 0 0 %.17g %.17g %.17g);",
        solverDict.c_str(), int(nIter), I1, I2, I3,
        perturbation, spin, perturbation
    );
    return buf;
}


//- Angular momentum in global axes
vector angularMomentum(RBD::rigidBodyMotion& m, const label id)
{
    const label master = m.model().masterID(id);
    const spatialTransform X(m.X0(id));
    const spatialVector v(m.workspace().v[master]);
    return X.E().T() & (m.model().bodies()[master].Ic() & v.w());
}


scalar angle(const vector& a, const vector& b)
{
    return std::atan2(mag(a ^ b), a & b);
}


std::string verdict(const hardCases::driftStats& s)
{
    return s.secular() ? "drifts" : "bounded";
}


void runCase
(
    const solverCase& s,
    const label nIter,
    const scalar dt,
    const scalar tEnd,
    const scalar tFlip
)
{
    autoPtr<RBD::rigidBodyMotion> motion = test::motion(modelText(s.dict, nIter));
    RBD::rigidBodyMotion& m = motion();
    const label id = m.model().bodyID("book");

    const vector L0(angularMomentum(m, id));
    const scalar T0 = m.model().kineticEnergy(m.workspace());

    hardCases::driftStats sT(tEnd), sL(tEnd), sDir(tEnd);
    label flips = 0;
    scalar tFirstFlip = 0, tLastFlip = 0;
    scalar wyPrev = m.state().qDot()[4];
    scalar tBlowUp = -1;
    scalar dT10 = NAN;
    const label step10 = label(std::round(10*tFlip/dt));

    const scalarField tau(m.model().nDoF(), Zero);
    const Field<spatialVector> fx(m.model().nBodies(), Zero);

    const label n = label(std::round(tEnd/dt));
    const auto start = std::chrono::steady_clock::now();

    for (label step = 0; step < n; ++step)
    {
        m.newTime();
        m.solve((step + 1)*dt, dt, tau, fx);

        const scalar t = m.state().t();
        const scalar wy = m.state().qDot()[4];
        if (wy*wyPrev < 0)
        {
            ++flips;
            tLastFlip = t - dt*wy/(wy - wyPrev);
            if (flips == 1)
            {
                tFirstFlip = tLastFlip;
            }
        }
        wyPrev = wy;

        const vector L(angularMomentum(m, id));
        const scalar T = m.model().kineticEnergy(m.workspace());

        if (!(std::isfinite(T) && T < 1e3*T0))
        {
            tBlowUp = t;
            break;
        }

        sT.add(t, (T - T0)/T0);
        if (step + 1 == step10)
        {
            dT10 = (T - T0)/T0;
        }
        sL.add(t, (mag(L) - mag(L0))/mag(L0));
        sDir.add(t, angle(L, L0));
    }

    const scalar cpu = std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - start
    ).count();

    if (tBlowUp >= 0)
    {
        std::printf
        (
            "| %g | %s | %d | %d | blows up: T > 1e3 T0 at t = %.4g s"
            " | | | | | | | | | %.1f |\n",
            spin*dt, s.name, int(nIter), int(flips), tBlowUp, cpu
        );
    }
    else
    {
        // The flips are tFlip apart (the first comes after less than
        // tFlip/2: omega_y is near, not at, its largest value at t = 0)
        std::printf
        (
            "| %g | %s | %d | %d | %s | %s | %s / %s / %s | %s | %s / %s / %s | %s"
            " | %s / %s / %s | %s | %.3g, (%.3g %.3g %.3g) | %.1f |\n",
            spin*dt, s.name, int(nIter), int(flips),
            fmt("%+.4f", tLastFlip - tFirstFlip - (flips - 1)*tFlip).c_str(),
            fmt("%+.2e", dT10).c_str(),
            fmt("%+.2e", sT.slope()).c_str(),
            fmt("%.2e", sT.largest()).c_str(),
            fmt("%.3g", sT.growth()).c_str(),
            verdict(sT).c_str(),
            fmt("%+.2e", sL.slope()).c_str(),
            fmt("%.2e", sL.largest()).c_str(),
            fmt("%.3g", sL.growth()).c_str(),
            verdict(sL).c_str(),
            fmt("%+.2e", sDir.slope()).c_str(),
            fmt("%.2e", sDir.largest()).c_str(),
            fmt("%.3g", sDir.growth()).c_str(),
            verdict(sDir).c_str(),
            m.model().kineticEnergy(m.workspace())/T0,
            m.state().qDot()[3], m.state().qDot()[4], m.state().qDot()[5],
            cpu
        );
    }
    std::fflush(stdout);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    hardCases::options o;
    o.length = 1000;
    if (!hardCases::readOptions(argc, argv, "-flips", o))
    {
        return 1;
    }
    const scalar nFlips = scalar(o.length);

    const scalar tFlip = flipTime();
    const scalar tEnd = nFlips*tFlip;

    std::printf
    (
        "Intermediate-axis spin: inertia (%g %g %g), omega (%g %g %g) rad/s,"
        " a flip every %.6f s (exact), %g s run: %g flips\n\n",
        I1, I2, I3, perturbation, spin, perturbation, tFlip, tEnd, nFlips
    );
    std::printf
    (
        "| 50 dt | solver | nIter | flips | error of last - first flip time [s] | dT/T0 after 10 flips | dT/T0: drift [1/s] / max / growth"
        " | T | d\\|L\\|/\\|L0\\|: drift [1/s] / max / growth | \\|L\\|"
        " | angle(L, L0): drift [rad/s] / max [rad] / growth | direction | end: T/T0, omega [rad/s] | CPU [s] |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
    );

    for (const scalar dt : {1e-3, 5e-4})
    {

        for (const solverCase& s : solverCases)
        {
            if (!o.runs(dt, s.name)) continue;

            for (const label nIter : {1, 4})
            {
                if (o.nIter && nIter != o.nIter) continue;

                runCase(s, nIter, dt, tEnd, tFlip);
            }
        }
    }

    return 0;
}
