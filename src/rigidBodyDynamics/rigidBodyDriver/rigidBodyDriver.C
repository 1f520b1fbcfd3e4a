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
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
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

// What the mesh motion (rigidBodyMeshMotion) reads from the same
// dictionaries; rigidBodySim, which dry-runs a dynamicMeshDict, knows them
// too.  With the coefficients at the dynamicMeshDict's top level (no
// rigidBodyMotionCoeffs), that level's entries are OpenFOAM's
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


// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Whether every component is finite (not magSqr: a finite 1e200 squared
//  is not)
template<class Type>
bool allFinite(const Type& v)
{
    for (Foam::direction c = 0; c < Foam::pTraits<Type>::nComponents; ++c)
    {
        if (!std::isfinite(Foam::component(v, c)))
        {
            return false;
        }
    }
    return true;
}

template<class Type>
bool allFinite(const Foam::Field<Type>& f)
{
    for (const Type& v : f)
    {
        if (!allFinite(v))
        {
            return false;
        }
    }
    return true;
}

//- Append to os every entry of dict (at any depth, its keywords joined by
//  '/') that holds a number beyond 1e100 or, not zero, below 1e-100 in
//  magnitude: the likely cause of an overflow
void extremeEntries
(
    const Foam::dictionary& dict,
    const Foam::string& path,
    Foam::OStringStream& os
)
{
    for (const Foam::entry& e : dict)
    {
        const Foam::string key
        (
            path.empty() ? Foam::string(e.keyword()) : path + "/" + e.keyword()
        );
        if (e.isDict())
        {
            extremeEntries(e.dict(), key, os);
            continue;
        }
        for (const Foam::token& t : e.stream())
        {
            const Foam::scalar x =
                t.isNumber() ? Foam::mag(t.number()) : Foam::scalar(0);
            if (x > 1e100 || (x > 0 && x < 1e-100))
            {
                os  << "    entry " << key.c_str() << ": " << t.number()
                    << Foam::nl;
                break;
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::RBD::rigidBodyDriver::motionDict
(
    const Time& runTime,
    const dictionary& coeffs,
    const bool externalForces
)
{
    // OpenFOAM's sixDoFRigidBodyMotion's coefficients, or a misspelling
    checkHasBodies(coeffs);

    dictionary dict(coeffs);

    // A fluid's added mass makes the stock scheme diverge for light bodies
    if (externalForces && !dict.found("accelerationRelaxationType"))
    {
        dict.add("accelerationRelaxationType", "addedMass");
    }

    if (!dict.found("g"))
    {
        IOobject gIO
        (
            "g",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );

        if (gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
        {
            dict.add("g", uniformDimensionedVectorField(gIO).value());
        }
    }

    // A misspelt entry stops the run; other entries not read are listed
    checkMotionEntries(dict);

    return dict;
}


Foam::dictionary Foam::RBD::rigidBodyDriver::restartState
(
    const Time& runTime,
    const dictionary& coeffs
)
{
    IOobject io
    (
        "rigidBodyMotionState",
        runTime.timeName(),
        "uniform",
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );

    if (io.typeHeaderOk<IOdictionary>(true))
    {
        Info<< "Restarting from " << io.objectPath() << nl << endl;
        return IOdictionary(io);
    }

    // A time a run has written (OpenFOAM's uniform/time) without the
    // bodies' state: starting from the dictionary would silently put the
    // bodies back where they started
    const fileName timeDict(runTime.timePath()/"uniform"/"time");
    if
    (
        isFile(timeDict)
     && !coeffs.getOrDefault<Switch>("startFromDictionary", false)
    )
    {
        FatalErrorInFunction
            << "Restart from t = " << runTime.timeName() << ": the bodies'"
            << " state " << io.objectPath() << " is missing or unreadable,"
            << " but a run wrote this time (" << timeDict << " exists)."
            << nl << "Starting from the dictionary's initial state would"
            << " put the bodies back where they started." << nl
            << "Restore the file, start from another written time, or, to"
            << " start the bodies over from the dictionary on purpose, set"
            << nl << "    startFromDictionary yes;" << nl
            << "in the motion's coefficients." << nl
            << exit(FatalError);
    }

    return dictionary();
}


Foam::string Foam::RBD::rigidBodyDriver::modelSignature() const
{
    const rigidBodyModel& m = model();
    string signature;
    for (label bodyID = 1; bodyID < m.nBodies(); ++bodyID)
    {
        signature +=
            (bodyID > 1 ? " " : "") + m.name(bodyID) + ":"
          + m.joints()[bodyID].type();
    }
    return signature;
}


void Foam::RBD::rigidBodyDriver::fillRow(const label bi, tableRow& row)
{
    const rigidBodyModel& model = motion_.model();
    const rigidBodyModelWorkspace& ws = motion_.workspace();
    const rigidBodyModelState& state = motion_.state();

    const label id = bodyIDs_[bi];
    const label master = model.masterID(id);
    const rigidBody& body = model.bodies()[master];
    const spatialTransform X(model.X0(id, ws));
    const spatialVector v(model.v(id, Zero, ws));

    row.start();
    row.add("t", state.t());
    row.add("CofR", X.r());
    row.add("Orientation", X.E());
    row.add("v", v.l());
    row.add("omega", v.w());
    for (const label i : dofs_[bi])
    {
        row.add("q" + Foam::name(i), state.q()[i]);
    }
    for (const label i : dofs_[bi])
    {
        row.add("qDot" + Foam::name(i), state.qDot()[i]);
    }
    if (externalForces_)
    {
        row.add("fluidForce", fx_[master].l());
        row.add("fluidMoment", fx_[master].w());
    }
    row.add("restraintForce", fxR_[master].l());
    row.add("restraintMoment", fxR_[master].w());
    row.add("kineticEnergy", body.kineticEnergy(ws.v[master]));
    row.add
    (
        "potentialEnergy",
        -body.m()*(model.g() & model.globalPoint(master, body.c(), ws))
    );
    if (externalForces_)
    {
        label dof = -1;
        row.add("couplingResidual", bodyResidual(bi, dof));
    }
    for (const restraint& r : motion_.restraints())
    {
        if (r.bodyID() == id)
        {
            r.addColumns(row);
        }
    }

    // A prescribed joint's driving force: in a forced oscillation, what the
    // fluid and the body's own inertia take
    const labelList& prescribing = motion_.prescribing();
    forAll(prescribing, s)
    {
        const restraint& r = motion_.restraints()[prescribing[s]];
        const rateConstraint& c = motion_.prescriptions()[s];
        if (c.dof >= 0 && r.bodyID() == id)
        {
            row.add(r.name() + ".force", c.moment);
        }
    }
    row.end();
}


void Foam::RBD::rigidBodyDriver::writeRows()
{
    if (!Pstream::master() || !rowsPending_)
    {
        return;
    }

    floatingPointTraps traps;

    // The restraints' forces at the state now, the step's end; then their
    // own states committed there, which the rows show (the coupling's
    // trial evaluations never reach the table)
    tauR_ = Zero;
    fxR_ = Zero;
    motion_.restraintForces(tauR_, fxR_);
    motion_.commitRestraints();

    forAll(rows_, bi)
    {
        tableRow& row = rows_[bi];
        fillRow(bi, row);
        for (label k = 0; k < row.size(); ++k)
        {
            if (!allFinite(row[k]))
            {
                stepFailed
                (
                    "The " + row.name(k) + " of body " + names_[bi]
                  + " at t = " + Foam::name(row[0]) + " (column "
                  + Foam::name(k + 1) + " of its table) is "
                  + Foam::name(row[k])
                );
            }
        }
    }

    if (tables_.empty())
    {
        const fileName dir
        (
            time_.globalPath()/"postProcessing"/name_/startTimeName_
        );
        mkDir(dir);

        tables_.setSize(names_.size());
        forAll(names_, bi)
        {
            tables_.set(bi, new OFstream(dir/names_[bi] + ".dat"));
            OFstream& os = tables_[bi];
            os.precision(IOstream::defaultPrecision());
            os  << "# Motion of body " << names_[bi] << ": SI units; forces"
                << " in global axes, moments about the global origin" << nl;
            rows_[bi].writeHeader(os);
        }
    }

    forAll(rows_, bi)
    {
        OFstream& os = tables_[bi];
        rows_[bi].write(os);

        // On disk at least at every write time (the row's, written at the
        // start of the next step), and at every row where a fluid acts: a
        // CFD step costs far more than a flush, and a flow solver that
        // dies of its own FatalError or signal leaves the rows up to it
        if (rowsAtWriteTime_ || externalForces_)
        {
            os.flush();
        }
    }

    rowsPending_ = false;
}


Foam::scalar Foam::RBD::rigidBodyDriver::bodyResidual
(
    const label bi,
    label& dof
) const
{
    scalar r = 0;
    dof = -1;
    for (const label i : dofs_[bi])
    {
        if (residual_.residual()[i] > r || dof < 0)
        {
            r = residual_.residual()[i];
            dof = i;
        }
    }
    return r;
}


void Foam::RBD::rigidBodyDriver::reportCoupling()
{
    if (!externalForces_ || curTimeIndex_ < 0)
    {
        return;
    }

    const scalar t = motion_.state().t();
    if (!residual_.endStep(motion_.state().qDdot(), t))
    {
        return;
    }

    Info<< "rigidBodyMotion: coupling of the step to t = " << t << ": "
        << motion_.nSolves() << " solves, " << motion_.coupling().type()
        << ", residual";
    forAll(names_, bi)
    {
        label dof = -1;
        const scalar r = bodyResidual(bi, dof);
        if (dof >= 0)
        {
            Info<< ' ' << names_[bi] << ' ' << r;
        }
    }
    Info<< endl;

    forAll(names_, bi)
    {
        label dof = -1;
        const scalar r = bodyResidual(bi, dof);
        if (dof >= 0 && r > residual_.tolerance())
        {
            Info<< "rigidBodyMotion: coupling not converged at t = " << t
                << ": body " << names_[bi] << ", " << dofName(dof).c_str()
                << (residual_.rotation(dof) ? ", rotation" : ", translation")
                << ": residual " << r << " > couplingTolerance "
                << residual_.tolerance() << endl;
        }
    }
}


void Foam::RBD::rigidBodyDriver::reportFloors() const
{
    if (!externalForces_)
    {
        return;
    }

    Info<< "rigidBodyMotion: coupling residual's floors (below them a body"
        << " counts as at rest):" << nl;
    forAll(names_, bi)
    {
        for (const label i : dofs_[bi])
        {
            Info<< "    " << dofName(i).c_str() << ' '
                << residual_.floors()[i];
            if (residual_.rotation(i))
            {
                Info<< " rad/s^2 (radius of gyration "
                    << residual_.gyrations()[i] << " m)";
            }
            else
            {
                Info<< " m/s^2";
            }
            Info<< nl;
        }
    }
    Info<< endl;
}


Foam::string Foam::RBD::rigidBodyDriver::dofName(const label i) const
{
    // The body (not a jointBody of its composite joint) that the degree of
    // freedom moves relative to its parent
    const rigidBodyModel& m = model();
    for (const word& name : m.bodyNames())
    {
        const label bodyID = m.bodyID(name);
        if (m.isMerged(bodyID) || !m.bodyDoFs(bodyID).found(i))
        {
            continue;
        }
        const joint& J = m.joints()[bodyID];
        const bool composite = m.bodyDoFs(bodyID).size() > J.nDoF();
        return
            "degree of freedom " + Foam::name(i) + ", of the joint of body "
          + name + " (" + (composite ? word("composite") : J.type()) + ")";
    }
    return "degree of freedom " + Foam::name(i);
}


void Foam::RBD::rigidBodyDriver::checkExternalForces
(
    const Field<spatialVector>& fx
)
{
    forAll(fx, bodyID)
    {
        if (!allFinite(fx[bodyID]))
        {
            stepFailed
            (
                "The external (fluid) force on body " + model().name(bodyID)
              + " for the step to t = " + Foam::name(time_.value())
              + " is not finite: moment " + Foam::name(fx[bodyID].w())
              + ", force " + Foam::name(fx[bodyID].l()) + " (global axes,"
              + " about the global origin).\nThe flow has failed before"
              + " the bodies moved: look at the flow solution of this step"
              + " (Courant number, pressure solver)"
            );
        }
    }
}


void Foam::RBD::rigidBodyDriver::checkState()
{
    const rigidBodyModelState& state = motion_.state();
    const scalarField* fields[3] = {&state.q(), &state.qDot(), &state.qDdot()};
    const char* names[3] = {"q", "qDot", "qDdot"};

    for (label f = 0; f < 3; ++f)
    {
        const scalarField& values = *fields[f];
        forAll(values, i)
        {
            if (!allFinite(values[i]))
            {
                stepFailed
                (
                    "The step from t = " + Foam::name(motion_.state0().t())
                  + " to " + Foam::name(time_.value()) + " gave "
                  + names[f] + " = " + Foam::name(values[i]) + " at "
                  + dofName(i)
                );
            }
        }
    }
}


void Foam::RBD::rigidBodyDriver::restraintCauses(OStringStream& causes)
{
    const rigidBodyModelState& state = motion_.state();
    const scalar deltaT = time_.deltaTValue();

    // Restraints whose force is not finite at the state, and the three
    // largest of the others
    const PtrList<restraint>& restraints = motion_.restraints();
    const rigidBodyModelWorkspace& ws = motion_.workspace();
    scalarField tau(model().nDoF());
    Field<spatialVector> fx(model().nBodies());
    List<spatialVector> fr(restraints.size(), Zero);
    scalarList size(restraints.size(), Zero);
    forAll(restraints, ri)
    {
        const restraint& r = restraints[ri];
        tau = Zero;
        fx = Zero;
        r.restrain(tau, fx, state, ws);
        fr[ri] = fx[model().masterID(r.bodyID())];
        if (!allFinite(tau) || !allFinite(fx))
        {
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model().name(r.bodyID()) << "): its force"
                << " is not finite at t = " << state.t() << ": look at its"
                << " coefficients" << nl;
        }
        else
        {
            size[ri] = mag(fr[ri].l()) + mag(fr[ri].w()) + sum(mag(tau));
        }
    }
    labelList order;
    sortedOrder(size, order);
    for (label k = order.size() - 1; k >= max(order.size() - 3, 0); --k)
    {
        const label ri = order[k];
        if (size[ri] > 0)
        {
            const restraint& r = restraints[ri];
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model().name(r.bodyID()) << "): force "
                << fr[ri].l() << " N, moment " << fr[ri].w() << " N m at t = "
                << state.t() << nl;
        }
    }

    // Restraints faster than the step resolves
    for (const restraint& r : motion_.restraints())
    {
        const scalar T = r.naturalPeriod();
        if (T > 0 && T < 10*deltaT)
        {
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model().name(r.bodyID()) << "): natural"
                << " period " << T << " s, " << T/deltaT << " steps of"
                << " deltaT " << deltaT << ": give it 10 steps or more"
                << " (deltaT below " << T/10 << " s; rigidBodySim -report"
                << " lists every period)" << nl;
        }
    }
}


void Foam::RBD::rigidBodyDriver::stepFailed(const string& what)
{
    floatingPointTraps traps;

    // Back to the start of the step, the last state that was finite, with
    // no row or coupling report of the failed step due (where FatalError
    // throws, as in a test, the driver can go on from there)
    motion_.state() = motion_.state0();
    rowsPending_ = false;
    curTimeIndex_ = -1;
    const rigidBodyModelState& state = motion_.state();

    OStringStream causes;
    restraintCauses(causes);

    // Numbers of extreme magnitude in the coefficients
    extremeEntries(coeffs_, string::null, causes);

    // The last good state, to inspect or start from
    const fileName dir
    (
        time_.globalPath()/"postProcessing"/name_/startTimeName_
    );
    const fileName lastGood(dir/"rigidBodyMotionState.lastGood");
    if (Pstream::master())
    {
        mkDir(dir);
        OFstream os(lastGood);
        os.precision(IOstream::defaultPrecision());
        state.write(os);

        forAll(tables_, bi)
        {
            tables_[bi].flush();
        }
    }

    FatalErrorInFunction
        << "The rigid-body motion (" << name_ << ") has failed." << nl
        << what.c_str() << nl;

    if (!causes.str().empty())
    {
        FatalError
            << "What may have caused it:" << nl
            << causes.str().c_str();
    }

    FatalError
        << "The last good state, at t = " << state.t() << ", is written to"
        << nl << "    " << lastGood << nl
        << "(to start from it, copy it to <time>/uniform/"
        << "rigidBodyMotionState)" << nl
        << exit(FatalError);
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
    curTimeIndex_(-1),
    residual_(coeffs, motion_.model(), externalForces),
    nCalls_(0),
    names_(coeffs.subDict("bodies").toc()),
    bodyIDs_(names_.size()),
    dofs_(names_.size()),
    startTimeName_(runTime.timeName()),
    rows_(names_.size()),
    rowsPending_(false),
    rowsAtWriteTime_(false),
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

    // A state written by another model (one with the same number of
    // degrees of freedom: another number is refused as it is read)
    string written;
    if
    (
        stateDict.readIfPresent("model", written)
     && written != modelSignature()
    )
    {
        FatalIOErrorInFunction(stateDict)
            << "The state " << stateDict.name() << " was written by another"
            << " model:" << nl << "    " << written.c_str() << nl
            << "This model's bodies and joints:" << nl << "    "
            << modelSignature().c_str() << nl
            << "Start from a state this model wrote, or remove the file and"
            << " set startFromDictionary yes; to start the bodies from the"
            << " dictionary" << nl
            << exit(FatalIOError);
    }

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
    rowsPending_ = !externalForces_;

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
    floatingPointTraps traps;
    reportCoupling();
    writeRows();

    if (!externalForces_ || residual_.nSteps() == 0)
    {
        return;
    }

    Info<< "rigidBodyMotion: coupling summary: " << residual_.nFlagged()
        << " of " << residual_.nSteps() << " steps not converged"
        << " (couplingTolerance " << residual_.tolerance() << ")";
    if (residual_.worstDoF() >= 0)
    {
        Info<< "; the largest residual " << residual_.worst() << " at t = "
            << residual_.worstTime() << ", "
            << dofName(residual_.worstDoF()).c_str();
    }
    Info<< endl;
    if (residual_.nFlagged())
    {
        Info<< "rigidBodyMotion: the motion of the flagged steps is not the"
            << " coupled answer: give more outer correctors, or let PIMPLE's"
            << " residualControl run them on demand (rigidBodyMotion entry)"
            << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyDriver::solve(const Field<spatialVector>& fx)
{
    // The start of a new time step
    if (curTimeIndex_ != time_.timeIndex())
    {
        reportCoupling();
        writeRows();
        motion_.newTime();
        curTimeIndex_ = time_.timeIndex();
        nCalls_ = 0;
    }
    ++nCalls_;

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
    }

    // The row of the step is made from its last solve, when it is written
    rowsPending_ = tableEveryStep_ || time_.writeTime();
    rowsAtWriteTime_ = time_.writeTime();
}


void Foam::RBD::rigidBodyDriver::status(const label bodyID)
{
    floatingPointTraps traps;
    const spatialTransform CofR(motion_.X0(bodyID));
    const spatialVector vCofR(motion_.v(bodyID, Zero));

    if (!allFinite(CofR.r()) || !allFinite(CofR.E()) || !allFinite(vCofR))
    {
        stepFailed
        (
            "The status of body " + model().name(bodyID) + " at t = "
          + Foam::name(motion_.state().t()) + " is not finite: centre of"
          + " rotation " + Foam::name(CofR.r()) + ", velocity "
          + Foam::name(vCofR)
        );
    }

    Info<< "Rigid-body motion of the " << model().name(bodyID) << nl
        << "    Centre of rotation: " << CofR.r() << nl
        << "    Orientation: " << CofR.E() << nl
        << "    Linear velocity: " << vCofR.l() << nl
        << "    Angular velocity: " << vCofR.w()
        << endl;

    // The body's prescribed rotations: rate, prescription, motor moment
    const labelList& prescribing = motion_.prescribing();
    forAll(prescribing, s)
    {
        const RBD::restraint& r = motion_.restraints()[prescribing[s]];
        if (r.bodyID() == bodyID)
        {
            const rateConstraint& c = motion_.prescriptions()[s];
            if (c.dof >= 0)
            {
                Info<< "    Prescribed motion " << r.name() << ": q "
                    << motion_.state().q()[c.dof] << " (prescribed "
                    << c.position << "), qDot "
                    << motion_.state().qDot()[c.dof] << " (prescribed "
                    << c.rate << "), driving force " << c.moment << endl;
                continue;
            }
            Info<< "    Prescribed rotation " << r.name() << ": omega "
                << (c.axis & vCofR.w()) << " rad/s about " << c.axis
                << " (prescribed " << c.rate << "), motor moment "
                << c.moment << " N m" << endl;
        }
    }
}


bool Foam::RBD::rigidBodyDriver::writeState() const
{
    const fileName dir(time_.timePath()/"uniform");
    mkDir(dir);

    OFstream os(dir/"rigidBodyMotionState");
    IOobject io("rigidBodyMotionState", time_.timeName(), "uniform", time_);
    io.writeHeader(os, IOdictionary::typeName);
    motion_.state().write(os);
    motion_.writeRestraintStates(os);
    os.writeEntry("model", modelSignature());
    if (externalForces_)
    {
        residual_.writeAmplitudes(os);
    }
    IOobject::writeEndDivider(os);

    // The restraints' own output (a catenaryLine's shape)
    if (Pstream::master())
    {
        const fileName outDir
        (
            time_.globalPath()/"postProcessing"/name_/time_.timeName()
        );
        for (const restraint& r : motion_.restraints())
        {
            r.writeOutput(outDir, time_.value());
        }
    }

    return os.good();
}


bool Foam::RBD::rigidBodyDriver::read(const dictionary& coeffs)
{
    report_ = coeffs.getOrDefault<Switch>("report", false);
    coeffs_ = coeffs;
    residual_.read(coeffs);
    return motion_.read(motionDict(time_, coeffs, externalForces_));
}
