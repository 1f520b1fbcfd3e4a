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
\*---------------------------------------------------------------------------*/

#include "symplectic.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(symplectic, 0);
    addToRunTimeSelectionTable(rigidBodySolver, symplectic, dictionary);
    addRigidBodyKeywords(solver, symplectic);
}
}
}


Foam::RBD::rigidBodySolvers::symplectic::symplectic
(
    const rigidBodyModel& model,
    const dictionary&
)
:
    rigidBodySolver(model),
    qDotHalf_(model.nDoF(), Zero)
{}


void Foam::RBD::rigidBodySolvers::symplectic::solve
(
    const rigidBodyModelState& state0,
    rigidBodyModelState& state,
    accelerationFunction& f,
    const bool firstSolve
)
{
    const scalar dt = state.deltaT();
    const scalarField& qDot0 = state0.qDot();
    const scalarField& qDdot0 = state0.qDdot();

    // Kick and drift from the start of the step
    forAll(qDotHalf_, i)
    {
        qDotHalf_[i] = qDot0[i] + 0.5*dt*qDdot0[i];
        dq_[i] = dt*qDotHalf_[i];
    }
    integratePosition(state0, state);

    // Velocities for the accelerations: at first the end-of-step ones
    // predicted with the start's accelerations, qDot' + deltaT/2 qDdot0
    // (within deltaT^2 of the end's, which keeps the scheme second order
    // where the accelerations depend on qDot), then the latest end-of-step
    // estimate
    if (firstSolve)
    {
        scalarField& qDot = state.qDot();
        forAll(qDot, i)
        {
            qDot[i] = qDotHalf_[i] + 0.5*dt*qDdot0[i];
        }
    }

    f.accelerations(state, firstSolve);

    // Kick
    const scalarField& qDdot = state.qDdot();
    scalarField& qDot = state.qDot();
    forAll(qDot, i)
    {
        qDot[i] = qDotHalf_[i] + 0.5*dt*qDdot[i];
    }
}


void Foam::RBD::rigidBodySolvers::symplectic::accelerationWeights
(
    const scalar deltaT,
    const bool firstSolve,
    scalar& wq,
    scalar& wqDot
) const
{
    wq = 0;
    wqDot = firstSolve ? 0 : 0.5*deltaT;
}
