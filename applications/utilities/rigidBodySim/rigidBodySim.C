/*---------------------------------------------------------------------------*\
Application
    rigidBodySim

Group
    grpRigidBodyDynamicsUtilities

Description
    Runs a rigid-body model from its dictionary, with no fluid: a dry run of
    the mechanism of a floating-body case, or a multibody simulation.

    The coefficients come from the rigidBodyMotionCoeffs sub-dictionary of
    constant/dynamicMeshDict (so an interDyMFoam case runs unchanged, without
    its fluid), or else from the top level of constant/rigidBodyMotionDict.
    Gravity is their g entry, or else constant/g.  system/controlDict gives
    deltaT, endTime and the write controls.

    Prints "Time = t" and the status block of every body named in bodies
    (merged bodies included), first for the initial state and then after
    every step.  Writes, for every body, the table
        postProcessing/rigidBodySim/<startTime>/<body>.dat
    of time, centre of rotation, orientation, linear and angular velocity,
    the body's joint positions q and velocities qDot, the restraints' force
    and moment, and its kinetic and potential energy.  At every write time
    the model state is written to <time>/uniform/rigidBodyMotionState; a run
    started from a written time (startFrom latestTime) continues from that
    state.  The time stepping, restart, status and tables are
    Foam::RBD::rigidBodyDriver's, as for the mesh motion solver.

Usage
    rigidBodySim [-case DIR]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "rigidBodyDriver.H"
#include "rigidBodySimInput.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Runs a rigid-body model from its dictionary, with no fluid"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    Sout.precision(IOstream::defaultPrecision());

    if (!(runTime.deltaTValue() > 0))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry deltaT " << runTime.deltaTValue()
            << " must be positive" << nl
            << exit(FatalIOError);
    }

    RBD::rigidBodyDriver driver
    (
        runTime,
        rigidBodySimCoeffs(runTime),
        "rigidBodySim",
        false
    );

    const RBD::rigidBodyModel& model = driver.model();

    Info<< "Model: " << model.bodyNames().size() - 1 << " bodies, "
        << model.nDoF() << " degrees of freedom, g " << model.g() << nl
        << endl;

    // No fluid: the restraints are the only forces besides gravity
    const Field<spatialVector> noExternalForces(model.nBodies(), Zero);

    auto report = [&]()
    {
        Info<< "Time = " << runTime.timeName() << endl;
        for (const label id : driver.bodyIDs())
        {
            driver.status(id);
        }
    };

    report();

    while (runTime.run())
    {
        ++runTime;

        driver.solve(noExternalForces);

        report();

        if (runTime.writeTime())
        {
            driver.writeState();
        }
    }

    Info<< "End" << nl << endl;

    return 0;
}
