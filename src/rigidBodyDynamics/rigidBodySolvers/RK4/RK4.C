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

#include "RK4.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(RK4, 0);
    addToRunTimeSelectionTable(rigidBodySolver, RK4, dictionary);
    addRigidBodyKeywords(solver, RK4);
}
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The first slot of each of the model's quaternion joints
Foam::labelList quaternionSlots(const Foam::RBD::rigidBodyModel& model)
{
    Foam::DynamicList<Foam::label> slots;
    for (Foam::label i = 1; i < model.nBodies(); ++i)
    {
        if (model.joints()[i].unitQuaternion())
        {
            slots.append(model.joints()[i].qIndex());
        }
    }
    return Foam::labelList(slots);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodySolvers::RK4::RK4
(
    const rigidBodyModel& model,
    const dictionary&
)
:
    rigidBodySolver(model),
    quaternionSlots_(quaternionSlots(model)),
    stage_(model.nDoF()),
    qDdotStage_(scalarField(model.nDoF(), Zero)),
    D_(model.nDoF(), Zero),
    sumD_(model.nDoF(), Zero),
    sumQDdot_(model.nDoF(), Zero)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodySolvers::RK4::positionRate(const scalarField& qDot)
{
    forAll(D_, i)
    {
        D_[i] = qDot[i];
    }

    // q = q0 exp(Theta) with body-frame angular velocity w:
    // dTheta/dt = dexp^-1_(-Theta) w, to third order in Theta
    for (const label i : quaternionSlots_)
    {
        const vector Theta(dq_[i], dq_[i + 1], dq_[i + 2]);
        const vector w(qDot[i], qDot[i + 1], qDot[i + 2]);
        const vector Thetaw(Theta ^ w);
        const vector rate(w + 0.5*Thetaw + (Theta ^ Thetaw)/12);

        D_[i] = rate.x();
        D_[i + 1] = rate.y();
        D_[i + 2] = rate.z();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodySolvers::RK4::solve
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

    // A new step: each stage is first relaxed against the start's
    // accelerations, then against its own of the previous solve
    if (firstSolve)
    {
        for (scalarField& qDdot : qDdotStage_)
        {
            forAll(qDdot, i)
            {
                qDdot[i] = qDdot0[i];
            }
        }
    }

    // Stage 1: the start of the step (Theta = 0, so D = qDot0)
    forAll(sumD_, i)
    {
        D_[i] = qDot0[i];
        sumD_[i] = qDot0[i];
        sumQDdot_[i] = qDdot0[i];
    }
    const scalarField* qDdotPrev = &qDdot0;

    // Stages 2, 3 and 4: time fraction and weight
    const scalar c[3] = {0.5, 0.5, 1};
    const scalar w[3] = {2, 2, 1};

    stage_.deltaT() = dt;

    for (label s = 0; s < 3; ++s)
    {
        const scalarField& qDdotStart = *qDdotPrev;
        scalarField& qDot = stage_.qDot();
        scalarField& qDdot = stage_.qDdot();

        forAll(qDot, i)
        {
            dq_[i] = c[s]*dt*D_[i];
            qDot[i] = qDot0[i] + c[s]*dt*qDdotStart[i];
            qDdot[i] = qDdotStage_[s][i];
        }
        integratePosition(state0, stage_);
        stage_.t() = state0.t() + c[s]*dt;

        f.accelerations(stage_, firstSolve);

        positionRate(qDot);

        scalarField& qDdotKept = qDdotStage_[s];
        forAll(qDdot, i)
        {
            qDdotKept[i] = qDdot[i];
            sumD_[i] += w[s]*D_[i];
            sumQDdot_[i] += w[s]*qDdot[i];
        }
        qDdotPrev = &qDdotKept;
    }

    // The end of the step, and its accelerations, relaxed against those
    // the state holds (the previous solve's, or the start's)
    scalarField& qDot = state.qDot();
    forAll(qDot, i)
    {
        dq_[i] = dt/6*sumD_[i];
        qDot[i] = qDot0[i] + dt/6*sumQDdot_[i];
    }
    integratePosition(state0, state);

    f.accelerations(state, firstSolve);
}


void Foam::RBD::rigidBodySolvers::RK4::accelerationWeights
(
    const scalar,
    const bool,
    scalar& wq,
    scalar& wqDot
) const
{
    wq = 0;
    wqDot = 0;
}
