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

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(rigidBodyDriver, 0);
}
}

addRigidBodyCommonKeywords(coefficients, Driver, "report", "startFromDictionary");

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
    names_(coeffs.subDict("bodies").toc()),
    bodyIDs_(names_.size()),
    dofs_(names_.size()),
    startTimeName_(runTime.timeName()),
    rows_(names_.size()),
    tau_(motion_.model().nDoF(), Zero),
    fx_(motion_.model().nBodies(), Zero),
    tauR_(motion_.model().nDoF(), Zero),
    fxR_(motion_.model().nBodies(), Zero),
    coeffs_(coeffs)
{
    forAll(names_, bi)
    {
        bodyIDs_[bi] = model().bodyID(names_[bi]);
        dofs_[bi] = model().bodyDoFs(bodyIDs_[bi]);
    }

    checkSignature(stateDict);

    // The motion's amplitudes for the coupling's residual, if written
    residual_.readAmplitudes(stateDict);
    reportFloors();

    // A state that does not say when it is starts at the case's start time
    if (!coeffs.found("t") && !stateDict.found("t"))
    {
        motion_.state().t() = runTime.value();
        motion_.newTime();
    }

    // A row for the start, where its forces are known (no external forces:
    // a fluid's are known only once the first solve has computed them)
    if (!externalForces_)
    {
        writeRows(false);
    }

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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyDriver::commitStep()
{
    coupledStep& step = motion_.step();
    if (!step.uncommitted())
    {
        return;
    }

    reportCoupling();

    // The row of the step is made from its last solve
    if (tableEveryStep_ || step.atWriteTime())
    {
        // On disk at least at every write time (the row's, written at the
        // start of the next step), and at every row where a fluid acts: a
        // CFD step costs far more than a flush, and a flow solver that
        // dies of its own FatalError or signal leaves the rows up to it
        writeRows(step.atWriteTime() || externalForces_);
    }

    step.commit();
}


void Foam::RBD::rigidBodyDriver::solve(const Field<spatialVector>& fx)
{
    // The start of a new time step: the step before committed first
    if (motion_.step().isNew(time_.timeIndex()))
    {
        commitStep();
        motion_.newTime(time_.timeIndex());
    }
    motion_.step().corrector(time_.writeTime());

    fx_ = fx;
    checkExternalForces(fx_);

    if (Pstream::master())
    {
        floatingPointTraps traps;
        motion_.solve(time_.value(), time_.deltaTValue(), tau_, fx_);

        if (externalForces_)
        {
            residual_.measure
            (
                motion_.coupling().distance(),
                motion_.state().qDdot()
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

    // Every processor has the state: all stop together if it is not finite
    checkState();

    if (externalForces_)
    {
        // Every processor holds the master's residual (a PIMPLE loop ended
        // on it ends on all of them at the same corrector)
        floatingPointTraps traps;
        Pstream::scatter(residual_.residual());
        residual_.solved();
        motion_.step().measured(residual_.maxResidual());
    }
}


void Foam::RBD::rigidBodyDriver::end()
{
    if (motion_.step().now() == coupledStep::stage::ended)
    {
        return;
    }

    floatingPointTraps traps;
    commitStep();
    reportSummary();

    forAll(tables_, bi)
    {
        tables_[bi].flush();
    }

    motion_.step().end();
}


bool Foam::RBD::rigidBodyDriver::read(const dictionary& coeffs)
{
    report_ = coeffs.getOrDefault<Switch>("report", false);
    coeffs_ = coeffs;
    residual_.read(coeffs);
    return motion_.read(motionDict(time_, coeffs, externalForces_));
}
