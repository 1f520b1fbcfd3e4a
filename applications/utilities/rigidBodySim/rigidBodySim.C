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
    rigidBodySim

Group
    grpRigidBodyDynamicsUtilities

Description
    Runs a rigid-body model from its dictionary, with no fluid: a dry run of
    the mechanism of a floating-body case, or a multibody simulation.

    The coefficients come from the rigidBodyMotionCoeffs sub-dictionary of
    constant/dynamicMeshDict (so an interDyMFoam case runs unchanged, without
    its fluid), or else from the top level of constant/rigidBodyMotionDict.
    A dynamicMeshDict whose motion solver is sixDoFRigidBodyMotion runs as
    the rigid-body model it maps to (Foam::RBD::sixDoFConverter): one body
    on a composite joint of the degrees of freedom its constraints leave
    free; -report prints that model's rigidBodyMotionCoeffs.
    Gravity is their g entry, or else constant/g.  system/controlDict gives
    deltaT, endTime and the write controls.

    It runs with the floating-point traps off (FOAM_SIGFPE has no effect):
    every step's state is checked instead, and a run that overflows stops
    with a FatalError naming the body, the quantity and the time, its last
    good state written (Foam::RBD::rigidBodyDriver), never with a signal.

    Its output follows system/controlDict, as an OpenFOAM application's
    does: at each write time (writeControl, writeInterval) the model state
    is written to <time>/uniform/rigidBodyMotionState (a run started from a
    written time, startFrom latestTime, continues from that state), every
    body named in bodies (merged bodies included) gets a row in its table
        postProcessing/rigidBodySim/<startTime>/<body>.dat
    (time, centre of rotation, orientation, linear and angular velocity,
    the body's joint positions q and velocities qDot, the restraints' force
    and moment, its kinetic and potential energy), and, with report on in
    the coefficients, "Time = t" and the status block of every body are
    printed; the start gets a row and, with report on, its status.  Nothing
    is printed or written per step otherwise: a line of progress at most
    every 5% of the run (time reached, steps per second, time left), and a
    summary at the end (steps, solves, wall time, time per step, the
    process CPU time of the loop: std::clock, microseconds).  With
    -everyStep the status and a table row follow every step.  The time
    stepping, restart, status and tables are Foam::RBD::rigidBodyDriver's,
    as for the mesh motion solver.

Usage
    rigidBodySim [-case DIR] [-everyStep] [-report]

    -report adds the model report (rigidBodySimReport.H): the model tree,
    masses and inertias, the restraints' natural periods against deltaT
    before the first step, each degree of freedom's range of motion after
    the last; also written to postProcessing/rigidBodySim/<startTime>/report.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "rigidBodyDriver.H"
#include "keywordTable.H"
#include "sixDoFConverter.H"
#include "rigidBodySimInput.H"
#include "rigidBodySimControls.H"
#include "rigidBodySimReport.H"
#include "clockTime.H"

#include <ctime>

using namespace Foam;

// The mesh motion's entries, which a dynamicMeshDict holds: rigidBodySim
// dry-runs one without the mesh motion's library, so it accepts them as
// rigidBodyMeshMotion.C registers them (test/keywords compares the lists)
addRigidBodyKeywords
(
    meshMotion, coefficients, "test", "rho", "rhoInf", "dynamicFvMesh",
    "dynamicFvMeshLibs", "motionSolver", "motionSolverLibs", "updateControl",
    "updateInterval"
);
addRigidBodyKeywords
(
    meshMotion, body, "patches", "innerDistance", "outerDistance",
    "translationDirection", "translationOuterDistance"
);

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The application's notes and options
void addOptions()
{
    argList::addNote
    (
        "Runs a rigid-body model from its dictionary, with no fluid."
    );
    argList::addNote("");
    argList::addNote
    (
        "Reads: the rigidBodyMotionCoeffs of constant/dynamicMeshDict (or"
        " its sixDoFRigidBodyMotion coefficients, as the model they map to),"
        " or else constant/rigidBodyMotionDict; g from them or constant/g;"
        " deltaT, endTime and the write controls from system/controlDict;"
        " <time>/uniform/rigidBodyMotionState (or, for a sixDoF dictionary,"
        " sixDoFRigidBodyMotionState) when started from a written time."
    );
    argList::addNote("");
    argList::addNote
    (
        "Writes, at write times: <time>/uniform/rigidBodyMotionState and"
        " <time>/uniform/time (to restart from), a row of"
        " postProcessing/rigidBodySim/<startTime>/<body>.dat for every body"
        " named in bodies, and with 'report on' every body's status on the"
        " log; a progress line at most every 5% of the run and a closing"
        " summary (steps, solves, wall and CPU time)."
    );
    argList::noParallel();
    argList::addBoolOption
    (
        "report",
        "also report the model (and, for a sixDoFRigidBodyMotion"
        " dictionary, the rigidBodyMotionCoeffs it maps to): before the"
        " first step its bodies (parent,"
        " joint, degrees of freedom, mass, centre of mass, inertia), total"
        " mass and restraints' natural periods against deltaT; after the"
        " last, each degree of freedom's range of motion (and which stayed"
        " unused); written to postProcessing/rigidBodySim/<startTime>/report"
    );
    argList::addBoolOption
    (
        "everyStep",
        "print the status of every body and write a table row after every"
        " time step, not only at write times"
    );
}


//- A positive deltaT, and an endTime after the time the run starts from
void checkTimes(const Time& runTime)
{
    if (!(runTime.deltaTValue() > 0))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry deltaT " << runTime.deltaTValue()
            << " must be positive" << nl
            << exit(FatalIOError);
    }

    if (!(runTime.value() < runTime.endTime().value()))
    {
        // With startFrom latestTime, an earlier run's last time is the
        // usual cause: say how to start again
        const dictionary& cd = runTime.controlDict();
        const bool earlierRun =
            cd.getOrDefault<word>("startFrom", "latestTime") == "latestTime"
         && runTime.value() > cd.getOrDefault<scalar>("startTime", 0);

        FatalIOErrorInFunction(cd)
            << "Entry endTime " << runTime.endTime().value() << " is not"
            << " after the time the run starts from, " << runTime.timeName()
            << ": nothing would run";
        if (earlierRun)
        {
            FatalIOError
                << nl << "startFrom latestTime starts from the last time an"
                << " earlier run wrote here.  To run from the start again,"
                << " remove its times: ./Allclean in a tutorial, or"
                << " foamListTimes -rm";
        }
        FatalIOError << nl << exit(FatalIOError);
    }
}


//- The model in one line: the bodies named in bodies, merged ones, the
//  degrees of freedom and g
void printModelSummary(const RBD::rigidBodyDriver& driver)
{
    const RBD::rigidBodyModel& model = driver.model();

    // The bodies named in bodies: the tree's own (not the massless bodies
    // a composite joint is expanded into) and the merged ones
    const label nBodies = driver.bodyIDs().size();
    label nMerged = 0;
    for (const label id : driver.bodyIDs())
    {
        nMerged += RBD::rigidBodyModel::isMerged(id);
    }
    Info<< "Model: " << countOf(nBodies, "body", "bodies").c_str();
    if (nMerged)
    {
        Info<< " (" << nMerged << " merged into another)";
    }
    Info<< ", " << countOf(model.nDoF(), "degree", "degrees").c_str()
        << " of freedom, g " << model.g() << nl << endl;
}


//- Every body's status, after the time
void printStatus(const Time& runTime, RBD::rigidBodyDriver& driver)
{
    Info<< "Time = " << runTime.timeName() << endl;
    for (const label id : driver.bodyIDs())
    {
        driver.status(id);
    }
}


//- One time step, the time already moved on: its one solve (the step's
//  final), the model report's tracking, the status where due and, at a
//  write time, the time's own record and the bodies' state.  Returns the
//  time integrator's solves
label takeStep
(
    Time& runTime,
    RBD::rigidBodyDriver& driver,
    rigidBodySimReport* modelReport,
    const bool everyStep,
    const Field<spatialVector>& fx
)
{
    driver.solve(fx, true);
    if (modelReport)
    {
        modelReport->track();
    }

    if (everyStep || (driver.report() && runTime.writeTime()))
    {
        printStatus(runTime, driver);
    }

    if (runTime.writeTime())
    {
        runTime.write();
        driver.writeState();
    }

    return driver.step().nSolves();
}


//- With -report, the model's report, its model printed before the first
//  step; else none
autoPtr<rigidBodySimReport> newModelReport
(
    const argList& args,
    const Time& runTime,
    RBD::rigidBodyDriver& driver,
    const dictionary& coeffs
)
{
    autoPtr<rigidBodySimReport> modelReport;
    if (args.found("report"))
    {
        modelReport.reset(new rigidBodySimReport(driver));
        modelReport->printModel
        (
            runTime.deltaTValue(),
            coeffs.subDict("solver").get<word>("type")
        );
    }
    return modelReport;
}


//- The closing summary: steps, solves, wall and CPU time
void printSummary
(
    const label nSteps,
    const label nSolves,
    const scalar wall,
    const std::clock_t cpu0
)
{
    Info<< "rigidBodySim: " << nSteps << " steps, " << nSolves << " solves, "
        << 1e-3*label(1e3*wall + 0.5) << " s of wall time, "
        << 1e-3*label(1e9*wall/max(nSteps, 1) + 0.5) << " us per step, "
        << scalar(std::clock() - cpu0)/CLOCKS_PER_SEC << " s of CPU time"
        << nl << "End" << nl << endl;
}


//- The progress line: at most every 5% of the run, and at most once a
//  second of wall time but for the last line
class progressLine
{
    //- The run's start time and span [s]
    const scalar t0_;
    const scalar span_;

    //- The fraction of the run at which the next line is due, and the wall
    //  time of the last line [s]
    scalar next_;
    scalar lastWall_;

public:

    //- Construct for the run of runTime
    explicit progressLine(const Time& runTime)
    :
        t0_(runTime.value()),
        span_(max(runTime.endTime().value() - t0_, VSMALL)),
        next_(0.05),
        lastWall_(0)
    {}

    //- After a step: print the line if it is due; last: after the run's
    //  last step (a step at the end time leaves its line to that call)
    void step
    (
        const Time& runTime,
        const label nSteps,
        const clockTime& clock,
        const bool last
    )
    {
        const scalar done = (runTime.value() - t0_)/span_;
        if (!last && (done < next_ - SMALL || done > 1 - SMALL))
        {
            return;
        }
        const scalar wall = clock.elapsedTime();
        if (last || wall - lastWall_ >= 1)
        {
            lastWall_ = wall;
            const scalar left =
                done > 0 ? max(wall*(1 - done)/done, 0) : 0;
            Info<< "rigidBodySim: t = " << runTime.timeName() << " s ("
                << label(100*done + 0.5) << "%), " << nSteps
                << " steps, " << label(wall > 0 ? nSteps/wall : 0)
                << " steps/s";
            if (!last && left >= 1)
            {
                Info<< ", about " << label(left + 0.5) << " s left";
            }
            else if (!last)
            {
                Info<< ", under a second left";
            }
            Info<< endl;
        }
        while (next_ <= done + SMALL)
        {
            next_ += 0.05;
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    addOptions();

    #include "setRootCase.H"

    // No input ends in a signal: with the floating-point traps off, a
    // number OpenFOAM's reader cannot hold (1e400) is its FatalIOError at
    // the entry, an overflow in a check an infinity the check refuses, and
    // a step that overflows a FatalError of the driver's checks, which
    // name the body, the quantity and the time
    RBD::floatingPointTraps traps;

    checkRunControls(args);

    #include "createTime.H"

    Sout.precision(IOstream::defaultPrecision());

    checkTimes(runTime);

    const bool everyStep = args.found("everyStep");

    dictionary startState;
    const dictionary coeffs
    (
        rigidBodySimCoeffs(runTime, args.found("report"), &startState)
    );
    RBD::rigidBodyDriver driver
    (
        runTime, coeffs, "rigidBodySim", false, startState
    );
    const word startTimeName(runTime.timeName());
    driver.tableEveryStep(everyStep);

    const RBD::rigidBodyModel& model = driver.model();

    printModelSummary(driver);

    autoPtr<rigidBodySimReport> modelReport
    (
        newModelReport(args, runTime, driver, coeffs)
    );

    // No fluid: the restraints are the only forces besides gravity
    const Field<spatialVector> noExternalForces(model.nBodies(), Zero);

    if (everyStep || driver.report())
    {
        printStatus(runTime, driver);
    }

    progressLine progress(runTime);
    label nSteps = 0;
    label nSolves = 0;
    clockTime clock;
    const std::clock_t cpu0 = std::clock();

    while (runTime.run())
    {
        ++runTime;
        ++nSteps;
        nSolves += takeStep
        (
            runTime, driver, modelReport.get(), everyStep, noExternalForces
        );

        if (!everyStep)
        {
            progress.step(runTime, nSteps, clock, false);
        }
    }
    if (!everyStep)
    {
        progress.step(runTime, nSteps, clock, true);
    }

    // The tables flushed
    driver.end();

    const scalar wall = clock.elapsedTime();

    if (modelReport.valid())
    {
        modelReport->printRanges
        (
            runTime.globalPath()/"postProcessing"/"rigidBodySim"
           /startTimeName
        );
    }

    printSummary(nSteps, nSolves, wall, cpu0);

    return 0;
}
