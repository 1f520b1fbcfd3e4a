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

#include "Newmark.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(Newmark, 0);
    addToRunTimeSelectionTable(rigidBodySolver, Newmark, dictionary);
    addRigidBodyKeywords(solver, Newmark, "gamma", "beta");
}
}
}


Foam::RBD::rigidBodySolvers::Newmark::Newmark
(
    const rigidBodyModel& model,
    const dictionary& dict
)
:
    rigidBodySolver(model),
    gamma_(dict.getOrDefault<scalar>("gamma", 0.5)),
    beta_(dict.getOrDefault<scalar>("beta", 0.25))
{
    if (!(gamma_ >= 0.5 && gamma_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry gamma " << gamma_ << " of the Newmark solver must be"
            << " in [0.5, 1] (below 0.5 the scheme is unstable)" << nl
            << exit(FatalIOError);
    }
    if (!(beta_ >= 0 && beta_ <= 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "Entry beta " << beta_ << " of the Newmark solver must be"
            << " in [0, 0.5]" << nl
            << exit(FatalIOError);
    }
    if (beta_ < 0.25*sqr(gamma_ + 0.5) - SMALL)
    {
        WarningInFunction
            << "Newmark beta " << beta_ << " is below (gamma + 1/2)^2/4 = "
            << 0.25*sqr(gamma_ + 0.5) << ": the scheme is only"
            << " conditionally stable.  beta is used as given." << endl;
    }
}


void Foam::RBD::rigidBodySolvers::Newmark::update
(
    const rigidBodyModelState& state0,
    rigidBodyModelState& state
)
{
    const scalar dt = state.deltaT();
    const scalarField& qDot0 = state0.qDot();
    const scalarField& qDdot0 = state0.qDdot();
    const scalarField& qDdot = state.qDdot();
    scalarField& qDot = state.qDot();

    forAll(qDot, i)
    {
        qDot[i] = qDot0[i] + dt*((1 - gamma_)*qDdot0[i] + gamma_*qDdot[i]);
        dq_[i] =
            dt*qDot0[i]
          + sqr(dt)*((0.5 - beta_)*qDdot0[i] + beta_*qDdot[i]);
    }

    integratePosition(state0, state);
}


void Foam::RBD::rigidBodySolvers::Newmark::solve
(
    const rigidBodyModelState& state0,
    rigidBodyModelState& state,
    accelerationFunction& f,
    const bool firstSolve
)
{
    update(state0, state);
    f.accelerations(state, firstSolve);
    update(state0, state);
}


void Foam::RBD::rigidBodySolvers::Newmark::accelerationWeights
(
    const scalar deltaT,
    const bool,
    scalar& wq,
    scalar& wqDot
) const
{
    wq = beta_*sqr(deltaT);
    wqDot = gamma_*deltaT;
}
