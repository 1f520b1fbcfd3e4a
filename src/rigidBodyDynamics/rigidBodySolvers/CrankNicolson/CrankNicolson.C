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

#include "CrankNicolson.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(CrankNicolson, 0);
    addToRunTimeSelectionTable(rigidBodySolver, CrankNicolson, dictionary);
    addRigidBodyKeywords(solver, CrankNicolson, "aoc", "voc");
}
}
}


Foam::RBD::rigidBodySolvers::CrankNicolson::CrankNicolson
(
    const rigidBodyModel& model,
    const dictionary& dict
)
:
    rigidBodySolver(model),
    aoc_(dict.getOrDefault<scalar>("aoc", 0.5)),
    voc_(dict.getOrDefault<scalar>("voc", 0.5))
{
    for (const scalar oc : {aoc_, voc_})
    {
        if (!(oc >= 0.5 && oc <= 1))
        {
            FatalIOErrorInFunction(dict)
                << "Entries aoc " << aoc_ << " and voc " << voc_
                << " of the CrankNicolson solver must be in [0.5, 1]"
                << " (below 0.5 the scheme is unstable)" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::RBD::rigidBodySolvers::CrankNicolson::update
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
        qDot[i] = qDot0[i] + dt*((1 - aoc_)*qDdot0[i] + aoc_*qDdot[i]);
        dq_[i] = dt*((1 - voc_)*qDot0[i] + voc_*qDot[i]);
    }

    integratePosition(state0, state);
}


void Foam::RBD::rigidBodySolvers::CrankNicolson::solve
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


void Foam::RBD::rigidBodySolvers::CrankNicolson::accelerationWeights
(
    const scalar deltaT,
    const bool,
    scalar& wq,
    scalar& wqDot
) const
{
    wq = voc_*aoc_*sqr(deltaT);
    wqDot = aoc_*deltaT;
}
