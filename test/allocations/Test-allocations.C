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
    Test-allocations

Description
    The hot loop allocates nothing: operator new is counted while a model
    that uses every joint and restraint type is advanced by each solver
    (newTime, solve), and while forward dynamics, inverse dynamics and the
    restraints are evaluated directly.  Expected count: 0.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
    std::atomic<long> nNew(0);
    std::atomic<bool> counting(false);
}

void* operator new(std::size_t n)
{
    if (counting)
    {
        ++nNew;
    }
    void* p = std::malloc(n ? n : 1);
    if (!p)
    {
        throw std::bad_alloc();
    }
    return p;
}

void* operator new[](std::size_t n)
{
    return operator new(n);
}

void operator delete(void* p) noexcept
{
    std::free(p);
}

void operator delete[](void* p) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}


using namespace Foam;

const char* model =
    "g (0 0 -9.81);"
    "bodies {"
    " a { type cuboid; parent root; mass 2; L (0.3 0.2 0.5);"
    "     centreOfMass (0 0 0); joint { type floating; } }"
    " b { type sphere; parent a; mass 1; radius 0.1; centreOfMass (0 0 -0.5);"
    "     joint { type Ry; } }"
    " c { type rigidBody; parent b; mass 1; centreOfMass (0 0 -0.2);"
    "     inertia (0.1 0 0 0.1 0 0.1); joint { type Rxyz; } }"
    " d { type rigidBody; parent c; mass 1; centreOfMass (0 0 -0.2);"
    "     inertia (0.1 0 0 0.1 0 0.1);"
    "     joint { type composite; joints ({ type Pa; axis (1 1 0); }"
    "     { type Ra; axis (0 1 1); }); } }"
    " e { type sphere; mergeWith d; mass 1; radius 0.1;"
    "     centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (0 0 -0.3); }"
    " f { type masslessBody; parent e; joint { type null; } }"
    " g1 { type cuboid; parent root; mass 1; L (1 1 1); centreOfMass (0 0 0);"
    "     joint { type Pxyz; } }"
    " h { type cuboid; parent g1; mass 1; L (1 1 1); centreOfMass (0 0 0);"
    "     joint { type Rzyx; } }"
    " i { type cuboid; parent h; mass 1; L (1 1 1); centreOfMass (0 0 0);"
    "     joint { type Ryxz; } }"
    " j { type cuboid; parent i; mass 1; L (1 1 1); centreOfMass (0 0 0);"
    "     joint { type Rs; } }"
    " k { type cuboid; parent j; mass 1; L (1 1 1); centreOfMass (0 0 0);"
    "     joint { type Px; } }"
    "}"
    "restraints {"
    " s { type linearSpring; body a; anchor (0 0 1); refAttachmentPt (0 0 0);"
    "     stiffness 100; damping 2; restLength 0.5; }"
    " d1 { type linearDamper; body a; coeff 1; }"
    " d2 { type sphericalAngularDamper; body a; coeff 1; }"
    " t { type linearAxialAngularSpring; body b; axis (0 1 0);"
    "     stiffness 10; damping 1; }"
    " t2 { type sphericalAngularSpring; body j; stiffness 10; damping 1; }"
    " f { type externalForce; body e; location (0 0 0); force (1 2 3); }"
    " w { type softWall; body a; anchor (0 0 0.5); wallNormal (0 0 -1);"
    "     refAttachmentPt (0 0 0); C 0.05; psi 0.1; }"
    " p { type prescribedRotation; body b; axis (0 1 0);"
    "     omega (0 1 0); }"
    "}"
    "qDot (0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.1 0.2 0.3 0.4 0.5 0.1 0.2 0.3"
    " 0.4 0.5 0.6 0.7 0.8 0.9 1 1.1 1.2 1.3);";


int main(int argc, char *argv[])
{
    // RK4 takes only the coupling schemes that do not learn from their
    // history (constant, addedMass fluid)
    const char* solvers[] =
        {"Newmark", "CrankNicolson", "symplectic", "Newmark", "RK4", "RK4"};
    const char* relaxations[] =
        {"quasiNewton", "Aitken", "constant", "addedMass", "constant",
         "addedMass"};

    // The counter sees an allocation made by OpenFOAM's containers
    {
        nNew = 0;
        counting = true;
        const scalarField f(10, Zero);
        counting = false;
        test::check(nNew > 0, "the operator new counter sees allocations");
    }

    for (label si = 0; si < 6; ++si)
    {
        const char* solver = solvers[si];
        autoPtr<RBD::rigidBodyMotion> m = test::motion
        (
            std::string("solver { type ") + solver + "; }"
            " nIter 3; accelerationRelaxation 0.7;"
            " accelerationRelaxationType "
          + relaxations[si] + ";" + model
        );

        const RBD::rigidBodyModel& model = m->model();
        const scalarField tau(model.nDoF(), Zero);
        const Field<spatialVector> fx(model.nBodies(), Zero);
        RBD::rigidBodyModelState state(m->state());
        RBD::rigidBodyModelWorkspace ws(model);
        scalarField tauID(model.nDoF());
        scalarField rtau(tau);
        Field<spatialVector> rfx(fx);

        nNew = 0;
        counting = true;

        for (label step = 1; step <= 100; ++step)
        {
            m->newTime();
            m->solve(step*1e-3, 1e-3, tau, fx);
            model.forwardDynamics(state, ws, tau, fx);
            model.inverseDynamics(state, ws, fx, tauID);
            m->restraintForces(rtau, rfx);
        }

        counting = false;

        test::checkAbs
        (
            nNew, 0, 0,
            std::string("allocations in 100 steps (3 solves each) of ")
          + std::to_string(model.nDoF()) + "-dof model, " + solver
          + ", " + relaxations[si] + " relaxation"
        );
        test::check
        (
            std::isfinite(m->state().q()[2]),
            std::string("model advanced to finite state, ") + solver
        );
    }

    return test::testResult();
}
