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
    Bench-stiffSpring

Description
    A 2 kg cuboid on a Pz joint, no gravity, on a linearSpring (k 50 N/m,
    omega = sqrt(k/m) = 5 rad/s) released from x0 = 0.1 m at rest,
    undamped or with damping ratio 0.05 (c = 1 N s/m), at time steps with
    omega deltaT = 0.3, 1.3 and 3 (about 21, 4.8 and 2.1 steps a period),
    for every solver and nIter 1, 2, 5, 20, over 50 periods.

    Prints markdown tables (see the header lines for the columns):
    - rho: the spectral radius of the one-step map of (x, v, a) (the step
      is linear in the state, so three steps of the library from the unit
      states give the map's matrix; rho from the norm of its 2^40-th
      power);
    - max|x|/x0 over the run (the run stops once it exceeds 1e12);
    - the amplitude and phase error at the end against the exact solution
      (z = x - i v/omega: |z|/|z_exact| and arg(z/z_exact), unwrapped step
      by step, in degrees);
    - the energy (1/2 m v^2 + 1/2 k x^2) at the end over the initial one
      (undamped) or over the exact one at the end (damped).
    The rows "Newmark, Aitken relaxation" relax the accelerations of the
    solves with Aitken's factor (accelerationRelaxationType Aitken, the
    coupling scheme); their step is not linear, so no rho, and "bounded"
    means max|x|/x0 <= 1 + 1e-6.
    Then, for each solver, the spectral radius for nIter 1 to 20 at each
    omega deltaT (how many solves a step needs to be stable); and Newmark
    at omega deltaT = 3 with each relaxation of its solves, nIter 1 to 20.

    Bench-stiffSpring -row SOLVER NITER OMEGADT ZETA prints, for one run,
    the final x and v with 17 digits, max|x|/x0 and E/E0 (compared with
    rigidBodySim on the same case by bench/hardCases/run).

\*---------------------------------------------------------------------------*/

#include "testModels.H"
#include "benchCases.H"
#include "mathematicalConstants.H"
#include <complex>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace Foam;
using hardCases::fmt;

namespace
{

const scalar mass = 2, k = 50, omega = 5, x0 = 0.1;
const scalar periods = 50;

//- A spectral radius within this of 1 counts as 1 (the measurement's
//  resolution: rho - 1 is measured as up to +3e-12 for the schemes whose
//  eigenvalues are exactly on the unit circle)
const scalar rhoTol = 1e-11;

struct solverCase
{
    const char* name;
    const char* dict;   // the solver's entries
    const char* extra;  // top-level entries (the relaxation of the solves)
};

//- The solvers, and Newmark with its solves relaxed by Aitken's factor
//  (accelerationRelaxationType, the coupling scheme: it relaxes the
//  accelerations of every solve, not only a fluid's)
const solverCase solverCases[] =
{
    {"Newmark", "type Newmark;", ""},
    {"Newmark gamma 0.6 beta 0.3025", "type Newmark; gamma 0.6; beta 0.3025;", ""},
    {"CrankNicolson", "type CrankNicolson;", ""},
    {"CrankNicolson aoc 0.6 voc 0.55", "type CrankNicolson; aoc 0.6; voc 0.55;", ""},
    {"symplectic", "type symplectic;", ""},
    {
        "Newmark, Aitken relaxation",
        "type Newmark;",
        "accelerationRelaxationType Aitken; accelerationRelaxation 1;"
    }
};

//- Newmark with the other relaxations of its solves (omega dt 3 table)
const solverCase relaxedCases[] =
{
    {
        "constant 0.3 (1/(1 + beta (omega dt)^2) = 0.31 is the best)",
        "type Newmark;",
        "accelerationRelaxationType constant; accelerationRelaxation 0.3;"
    },
    {
        "Aitken, accelerationRelaxation 1",
        "type Newmark;",
        "accelerationRelaxationType Aitken; accelerationRelaxation 1;"
    },
    {
        "quasiNewton, accelerationRelaxation 0.7",
        "type Newmark;",
        "accelerationRelaxationType quasiNewton; accelerationRelaxation 0.7;"
    },
    {
        "addedMass, accelerationRelaxation 0.7",
        "type Newmark;",
        "accelerationRelaxationType addedMass; accelerationRelaxation 0.7;"
    }
};


std::string modelText
(
    const solverCase& s,
    const label nIter,
    const scalar zeta
)
{
    const scalar c = 2*zeta*std::sqrt(k*mass);
    char buf[1024];
    std::snprintf
    (
        buf, sizeof(buf),
        "g (0 0 0); solver { %s } %s nIter %d;"
        " bodies { mass { type cuboid; parent root; mass %.17g;"
        " L (0.2 0.2 0.1); centreOfMass (0 0 0); joint { type Pz; } } }"
        " restraints { spring { type linearSpring; body mass;"
        " anchor (0 0 -1); refAttachmentPt (0 0 0); stiffness %.17g;"
        " damping %.17g; restLength 1; } }"
        " q (%.17g);",
        s.dict, s.extra, int(nIter), mass, k, c, x0
    );
    return buf;
}


//- Exact x and v at t
void exact(const scalar zeta, const scalar t, scalar& x, scalar& v)
{
    const scalar wd = omega*std::sqrt(1 - zeta*zeta);
    const scalar d = std::exp(-zeta*omega*t);
    x = d*(x0*std::cos(wd*t) + (zeta*omega*x0/wd)*std::sin(wd*t));
    v = -d*x0*(omega*omega/wd)*std::sin(wd*t);
}


scalar springEnergy(const scalar x, const scalar v)
{
    return 0.5*mass*v*v + 0.5*k*x*x;
}


//- Spectral radius of the one-step map of (x, v, a), measured by stepping
//  the library from the three unit states (NAN with a relaxation of the
//  solves that learns its factor: the step is then not linear)
scalar spectralRadius
(
    const solverCase& s,
    const label nIter,
    const scalar zeta,
    const scalar dt
)
{
    if (*s.extra)
    {
        return NAN;
    }

    autoPtr<RBD::rigidBodyMotion> m =
        test::motion(modelText(s, nIter, zeta));

    // One step first, so that the start-of-step accelerations are known
    test::run(m(), dt, 1, [](RBD::rigidBodyMotion&){});

    tensor A(Zero);
    for (direction j = 0; j < 3; ++j)
    {
        m->state().q()[0] = (j == 0);
        m->state().qDot()[0] = (j == 1);
        m->state().qDdot()[0] = (j == 2);
        test::run(m(), dt, 1, [](RBD::rigidBodyMotion&){});
        A(0, j) = m->state().q()[0];
        A(1, j) = m->state().qDot()[0];
        A(2, j) = m->state().qDdot()[0];
    }

    // rho = lim |A^n|^(1/n), n = 2^40, by squaring with rescaling
    scalar logNorm = std::log(mag(A));
    tensor B(A/mag(A));
    const int nSquare = 40;
    for (int i = 0; i < nSquare; ++i)
    {
        B = B & B;
        const scalar n = mag(B);
        if (!(n > 0))
        {
            return 0;
        }
        logNorm = 2*logNorm + std::log(n);
        B /= n;
    }
    return std::exp(logNorm/std::pow(2.0, nSquare));
}


struct result
{
    scalar rho;
    scalar maxX;        // max |x|/x0
    label nSteps;       // steps run
    label nPlanned;
    scalar ampRatio;    // |z|/|z_exact| at the end
    scalar phaseDeg;    // unwrapped phase error at the end
    scalar energyRatio; // E/E0 (undamped) or E/E_exact (damped)
    scalar x, v;
};


result runCase
(
    const solverCase& s,
    const label nIter,
    const scalar omegaDt,
    const scalar zeta
)
{
    const scalar dt = omegaDt/omega;
    const label n =
        label(std::round(periods*constant::mathematical::twoPi/omegaDt));

    result r;
    r.rho = spectralRadius(s, nIter, zeta, dt);
    r.nPlanned = n;
    r.maxX = 1;

    autoPtr<RBD::rigidBodyMotion> motion =
        test::motion(modelText(s, nIter, zeta));
    RBD::rigidBodyMotion& m = motion();

    const scalarField tau(1, Zero);
    const Field<spatialVector> fx(m.model().nBodies(), Zero);

    const scalar E0 = springEnergy(x0, 0);
    scalar phase = 0;
    scalar prevArg = 0;
    bool lost = false;

    label step = 0;
    for (; step < n; ++step)
    {
        m.newTime();
        m.solve((step + 1)*dt, dt, tau, fx);

        const scalar x = m.state().q()[0];
        const scalar v = m.state().qDot()[0];
        r.maxX = max(r.maxX, mag(x)/x0);

        scalar xe, ve;
        exact(zeta, (step + 1)*dt, xe, ve);
        const std::complex<scalar> z(x, -v/omega), ze(xe, -ve/omega);
        const scalar a = std::arg(z/ze);
        scalar d = a - prevArg;
        while (d > constant::mathematical::pi) d -= constant::mathematical::twoPi;
        while (d < -constant::mathematical::pi) d += constant::mathematical::twoPi;
        phase += d;
        prevArg = a;

        if (!(r.maxX < 1e12))
        {
            lost = true;
            ++step;
            break;
        }
    }

    r.nSteps = step;
    r.x = m.state().q()[0];
    r.v = m.state().qDot()[0];

    scalar xe, ve;
    exact(zeta, step*dt, xe, ve);
    r.ampRatio =
        std::abs(std::complex<scalar>(r.x, -r.v/omega))
       /std::abs(std::complex<scalar>(xe, -ve/omega));
    r.phaseDeg = lost ? NAN : phase*180/constant::mathematical::pi;
    r.energyRatio =
        springEnergy(r.x, r.v)/(zeta > 0 ? springEnergy(xe, ve) : E0);

    return r;
}


void springTable(const scalar zeta)
{
    const scalar omegaDts[] = {0.3, 1.3, 3};
    const label nIters[] = {1, 2, 5, 20};

    std::printf
    (
        "\n| omega dt | solver | nIter | rho - 1 | max\\|x\\|/x0 | amplitude/exact"
        " | phase error [deg] | %s | verdict |\n|---|---|---|---|---|---|---|---|---|\n",
        zeta > 0 ? "E/E_exact" : "E/E0"
    );

    for (const scalar omegaDt : omegaDts)
    {
        for (const solverCase& s : solverCases)
        {
            for (const label nIter : nIters)
            {
                const result r = runCase(s, nIter, omegaDt, zeta);

                std::string verdict;
                if (r.nSteps < r.nPlanned)
                {
                    verdict = "diverges (past 1e12 x0 in period "
                      + std::to_string
                        (
                            label(std::ceil(r.nSteps*omegaDt/constant::mathematical::twoPi))
                        )
                      + ")";
                }
                else if (std::isnan(r.rho))
                {
                    verdict = r.maxX <= 1 + 1e-6 ? "bounded" : "grows";
                }
                else if (r.rho <= 1 + rhoTol)
                {
                    verdict = "stable";
                }
                else
                {
                    const scalar g = std::pow(r.rho, scalar(r.nPlanned));
                    verdict =
                        "unstable (rho^N = "
                      + (
                            g < 1.01
                          ? "1 + " + fmt("%.2g", g - 1)
                          : fmt("%.3g", g)
                        )
                      + " over the run)";
                }

                const bool lost = r.nSteps < r.nPlanned;
                std::printf
                (
                    "| %g | %s | %d | %s | %s | %s | %s | %s | %s |\n",
                    omegaDt, s.name, int(nIter),
                    std::isnan(r.rho) ? "-" : fmt("%+.2e", r.rho - 1).c_str(),
                    fmt("%.4g", r.maxX).c_str(),
                    lost ? "-" : fmt("%.4g", r.ampRatio).c_str(),
                    lost ? "-" : fmt("%.4g", r.phaseDeg).c_str(),
                    lost ? "-" : fmt("%.4g", r.energyRatio).c_str(),
                    verdict.c_str()
                );
                std::fflush(stdout);
            }
        }
    }
}


//- For each solver and omega dt: rho for nIter 1..20
void solvesTable()
{
    const scalar omegaDts[] = {0.05, 0.3, 1.3, 1.9, 2.1, 3};

    std::printf("\nSpectral radius against nIter, undamped (rho - 1; rho itself above 2):\n\n| solver | omega dt |");
    for (label n = 1; n <= 20; ++n)
    {
        std::printf(" %d |", int(n));
    }
    std::printf("\n|---|---|");
    for (label n = 1; n <= 20; ++n)
    {
        std::printf("---|");
    }
    std::printf("\n");

    for (const solverCase& s : solverCases)
    {
        if (*s.extra) continue;

        for (const scalar omegaDt : omegaDts)
        {
            std::printf("| %s | %g |", s.name, omegaDt);
            for (label n = 1; n <= 20; ++n)
            {
                const scalar rho =
                    spectralRadius(s, n, 0, omegaDt/omega);
                std::printf
                (
                    " %s |",
                    rho > 2 ? fmt("%.3g", rho).c_str() : fmt("%+.1e", rho - 1).c_str()
                );
            }
            std::printf("\n");
            std::fflush(stdout);
        }
    }
}

//- Newmark at omega dt 3 with its solves relaxed: max|x|/x0 and E/E0
//  at the end against nIter
void relaxedTable()
{
    const label nIters[] = {1, 2, 3, 4, 5, 10, 20};

    for (const scalar zeta : {0.0, 0.05})
    {
        std::printf
        (
            "\nNewmark at omega dt 3, %s, the solves relaxed:"
            " max|x|/x0 over 50 periods (%s at the end)\n\n| relaxation |",
            zeta > 0 ? "damping ratio 0.05" : "undamped",
            zeta > 0 ? "E/E_exact" : "E/E0"
        );
        for (const label n : nIters)
        {
            std::printf(" nIter %d |", int(n));
        }
        std::printf("\n|---|");
        for (label i = 0; i < 7; ++i)
        {
            std::printf("---|");
        }
        std::printf("\n");

        for (const solverCase& s : relaxedCases)
        {
            std::printf("| %s |", s.name);
            for (const label n : nIters)
            {
                const result r = runCase(s, n, 3, zeta);
                if (r.nSteps < r.nPlanned)
                {
                    std::printf(" > 1e12 |");
                }
                else
                {
                    std::printf
                    (
                        " %s (%s) |",
                        fmt("%.4g", r.maxX).c_str(),
                        fmt("%.4g", r.energyRatio).c_str()
                    );
                }
            }
            std::printf("\n");
            std::fflush(stdout);
        }
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    if (argc == 6 && std::strcmp(argv[1], "-row") == 0)
    {
        const solverCase* sc = nullptr;
        for (const solverCase& s : solverCases)
        {
            if (s.name == std::string(argv[2]))
            {
                sc = &s;
            }
        }
        if (!sc)
        {
            std::fprintf(stderr, "unknown solver %s\n", argv[2]);
            return 1;
        }
        const result r = runCase
        (
            *sc, std::atoi(argv[3]), std::atof(argv[4]), std::atof(argv[5])
        );
        std::printf
        (
            "steps %d x %.17g v %.17g maxX %.10g E/E0 %.10g\n",
            int(r.nSteps), r.x, r.v, r.maxX,
            springEnergy(r.x, r.v)/springEnergy(x0, 0)
        );
        return 0;
    }

    std::printf
    (
        "Stiff spring: m %g kg, k %g N/m, omega %g rad/s, x0 %g m, %g periods\n",
        mass, k, omega, x0, periods
    );

    std::printf("\nUndamped:\n");
    springTable(0);
    std::printf("\nDamping ratio 0.05:\n");
    springTable(0.05);
    solvesTable();
    relaxedTable();

    return 0;
}
