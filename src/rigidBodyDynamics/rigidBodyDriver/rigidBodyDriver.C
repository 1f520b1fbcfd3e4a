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

#include "rigidBodyDriver.H"
#include "keywordTable.H"
#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(rigidBodyDriver, 0);
}
}

addRigidBodyCommonKeywords(coefficients, Driver, "report", "startFromDictionary");

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The live drivers
Foam::DynamicList<Foam::RBD::rigidBodyDriver*>& liveDrivers()
{
    static Foam::DynamicList<Foam::RBD::rigidBodyDriver*> drivers;
    return drivers;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyDriver::registerForExit(rigidBodyDriver* driver)
{
    // A FatalError elsewhere (the flow's, a function object's) ends the
    // process with exit(), which destroys no driver: its summary is then
    // printed and its tables flushed by endAtExit
    // The list made before endAtExit is registered: its destructor then
    // runs after endAtExit, not before (exit runs them in reverse order)
    DynamicList<rigidBodyDriver*>& drivers = liveDrivers();
    static bool registered = false;
    if (!registered)
    {
        registered = (std::atexit(endAtExit) == 0);
    }
    drivers.append(driver);
}


void Foam::RBD::rigidBodyDriver::unregisterForExit(rigidBodyDriver* driver)
{
    DynamicList<rigidBodyDriver*>& drivers = liveDrivers();
    DynamicList<rigidBodyDriver*> others(drivers.size());
    for (rigidBodyDriver* d : drivers)
    {
        if (d != driver)
        {
            others.append(d);
        }
    }
    drivers.transfer(others);
}


void Foam::RBD::rigidBodyDriver::endAtExit()
{
    // Nothing that can fail: no step is committed here (the one open at a
    // FatalError is unfinished)
    for (rigidBodyDriver* d : liveDrivers())
    {
        d->atExit();
    }
    liveDrivers().clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyDriver::rigidBodyDriver
(
    const Time& runTime,
    const dictionary& coeffs,
    const dictionary& stateDict,
    const word& name,
    const bool externalForces
)
:
    time_(runTime),
    name_(name),
    constructionTraps_(),
    motion_(motionDict(runTime, coeffs, externalForces), stateDict),
    report_(coeffs.getOrDefault<Switch>("report", false)),
    externalForces_(externalForces),
    tableEveryStep_(true),
    residual_(coeffs, motion_.model(), externalForces),
    step_(),
    unsaidFinal_(false),
    tables_
    (
        runTime.globalPath()/"postProcessing"/name/runTime.timeName(),
        coeffs,
        motion_.model(),
        externalForces
    ),
    failure_(runTime, name, tables_.dir(), coeffs),
    tau_(motion_.model().nDoF(), Zero),
    fx_(motion_.model().nBodies(), Zero)
{
    checkSignature(stateDict);

    // The motion's amplitudes for the coupling's residual, if written
    residual_.readAmplitudes(stateDict);
    reportFloors();

    // A state that does not say when it is starts at the case's start time
    if (!coeffs.found("t") && !stateDict.found("t"))
    {
        motion_.state().t() = runTime.value();
    }

    // A prescription that starts off its rate, said once (not on restart)
    if (!stateDict.found("t"))
    {
        motion_.checkPrescribedStart();
    }

    // The start committed as the first step's (the restraints' own states
    // start there), with its row where its forces are known (no external
    // forces: a fluid's are known only once the first solve has computed
    // them)
    commitState(!externalForces_, false);

    registerForExit(this);

    constructionTraps_.release();
}


Foam::RBD::rigidBodyDriver::rigidBodyDriver
(
    const Time& runTime,
    const dictionary& coeffs,
    const word& name,
    const bool externalForces
)
:
    rigidBodyDriver
    (
        runTime,
        coeffs,
        restartState(runTime, coeffs),
        name,
        externalForces
    )
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyDriver::~rigidBodyDriver()
{
    unregisterForExit(this);
    end();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyDriver::commitState(const bool row, const bool flush)
{
    // The row's restraint forces are those of the step's end, evaluated
    // before the commit; its restraint columns show the committed states.
    // A row that is not finite fails the step, whose start is still state0
    if (row)
    {
        tables_.restraintForces(motion_);
    }
    motion_.commitRestraints();
    if (row)
    {
        tables_.fill(motion_, residual_, fx_);
        if (Pstream::master())
        {
            check(failure_.rows(tables_));
        }
    }

    motion_.newTime();

    if (row)
    {
        tables_.write(flush);
    }
}


void Foam::RBD::rigidBodyDriver::commitStep()
{
    reportCoupling();

    // On disk at least at every write time, and at every row where a fluid
    // acts: a CFD step costs far more than a flush, and a flow solver that
    // dies of its own FatalError or signal leaves the rows up to it
    commitState
    (
        tableEveryStep_ || step_.atWriteTime(),
        step_.atWriteTime() || externalForces_
    );

    step_.commit();
}


void Foam::RBD::rigidBodyDriver::beginCorrector()
{
    const label timeIndex = time_.timeIndex();

    if (step_.now() == coupledStep::stage::ended)
    {
        FatalErrorInFunction
            << "The rigid-body motion (" << name_ << ") was solved at t = "
            << time_.value() << " s, after the run's end" << nl
            << exit(FatalError);
    }

    if (step_.open() && timeIndex != step_.timeIndex())
    {
        // The front-end did not say which corrector ended the step before:
        // it ends where the next begins
        if (!unsaidFinal_)
        {
            WarningInFunction
                << "The rigid-body motion (" << name_ << "): time step "
                << step_.timeIndex() << " had no final corrector. Its last"
                << " solve is committed as the next step begins; the front"
                << " end should say which corrector is final." << endl;
            unsaidFinal_ = true;
        }
        commitStep();
    }
    else if
    (
        step_.now() == coupledStep::stage::committed
     && timeIndex == step_.timeIndex()
    )
    {
        FatalErrorInFunction
            << "The rigid-body motion (" << name_ << ") was solved again at"
            << " t = " << time_.value() << " s, after the final corrector of"
            << " its time step: a step ends once. The front-end must solve"
            << " the bodies in each outer corrector up to the final one, and"
            << " not after it." << nl
            << exit(FatalError);
    }

    if (!step_.open())
    {
        // After a failed step (a FatalError thrown, as in a test), the
        // state is back at that step's start: committed again there
        if (step_.now() == coupledStep::stage::failed)
        {
            motion_.newTime();
        }
        step_.begin(timeIndex, time_.writeTime());
    }

    step_.corrector();
}


void Foam::RBD::rigidBodyDriver::solve
(
    const Field<spatialVector>& fx,
    const bool finalCorrector
)
{
    beginCorrector();

    fx_ = fx;
    check(failure_.externalForces(model(), fx_));

    if (Pstream::master())
    {
        floatingPointTraps traps;
        motion_.solve(time_.value(), time_.deltaTValue(), tau_, fx_);

        if (externalForces_)
        {
            residual_.measure
            (
                motion_.coupling().distance(),
                motion_.state().qDdot(),
                motion_.constraints()
            );
        }

        if (debug)
        {
            Info<< "rigidBodyMotion: solve " << motion_.nSolves()
                << ", coupling distance " << motion_.coupling().distance()
                << ", residual " << residual_.residual()
                << ", qDdot " << motion_.state().qDdot() << endl;
        }
    }
    Pstream::scatter(motion_.state());
    step_.solved(motion_.nIter());

    // Every processor has the state: all stop together if it is not finite
    check(failure_.state(motion_));

    if (externalForces_)
    {
        // Every processor holds the master's residual (a PIMPLE loop ended
        // on it ends on all of them at the same corrector)
        floatingPointTraps traps;
        Pstream::scatter(residual_.residual());
        residual_.solved();
        step_.measured(residual_.maxResidual());
    }

    if (finalCorrector)
    {
        floatingPointTraps traps;
        commitStep();
    }
}


void Foam::RBD::rigidBodyDriver::end()
{
    if (step_.now() == coupledStep::stage::ended)
    {
        return;
    }

    floatingPointTraps traps;

    // A step whose final corrector was not said
    if (step_.open())
    {
        commitStep();
    }

    atExit();
}


void Foam::RBD::rigidBodyDriver::atExit()
{
    if (step_.now() == coupledStep::stage::ended)
    {
        return;
    }

    reportSummary();
    tables_.flush();
    step_.end();
}


void Foam::RBD::rigidBodyDriver::check(const string& failure)
{
    if (failure.empty())
    {
        return;
    }

    floatingPointTraps traps;

    // Back to the start of the step, the last state that was finite, with
    // no row or coupling report of the failed step due (where FatalError
    // throws, as in a test, the driver can go on from there)
    motion_.state() = motion_.state0();
    step_.fail();
    failure_.stop(motion_, tables_, failure);
}


bool Foam::RBD::rigidBodyDriver::read(const dictionary& coeffs)
{
    report_ = coeffs.getOrDefault<Switch>("report", false);
    failure_.read(coeffs);
    residual_.read(coeffs);
    return motion_.read(motionDict(time_, coeffs, externalForces_));
}
