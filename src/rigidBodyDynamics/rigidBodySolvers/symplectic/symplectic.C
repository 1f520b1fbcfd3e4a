#include "symplectic.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(symplectic, 0);
    addToRunTimeSelectionTable(rigidBodySolver, symplectic, dictionary);
}
}
}


Foam::RBD::rigidBodySolvers::symplectic::symplectic
(
    rigidBodyMotion& body,
    const dictionary&
)
:
    rigidBodySolver(body),
    qDotHalf_(body.nDoF(), Zero)
{}


void Foam::RBD::rigidBodySolvers::symplectic::update()
{
    const scalar dt = deltaT();
    const scalarField& qDdot = state().qDdot();
    scalarField& qDot = state().qDot();

    forAll(qDot, i)
    {
        qDot[i] = qDotHalf_[i] + 0.5*dt*qDdot[i];
    }
}


void Foam::RBD::rigidBodySolvers::symplectic::solve
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    const scalar dt = deltaT();
    const scalarField& qDot0 = state0().qDot();
    const scalarField& qDdot0 = state0().qDdot();

    // Kick and drift from the start of the step
    forAll(qDotHalf_, i)
    {
        qDotHalf_[i] = qDot0[i] + 0.5*dt*qDdot0[i];
        dq_[i] = dt*qDotHalf_[i];
    }
    integratePosition();

    // Velocities for the accelerations: the half step's at first, then the
    // latest end-of-step estimate
    if (body_.iteration() == 0)
    {
        state().qDot() = qDotHalf_;
    }

    forwardDynamics(tau, fx);

    // Kick
    update();
}
