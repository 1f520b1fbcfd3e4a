#include "rigidBodyDriver.H"
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(rigidBodyDriver, 0);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::RBD::rigidBodyDriver::motionDict
(
    const Time& runTime,
    const dictionary& coeffs,
    const bool externalForces
)
{
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


Foam::label Foam::RBD::rigidBodyDriver::nColumns(const label bi) const
{
    // t, CofR, orientation, v, omega; q and qDot; external force and moment;
    // restraint force and moment; kinetic and potential energy
    return
        1 + 3 + 9 + 3 + 3
      + 2*dofs_[bi].size()
      + (externalForces_ ? 6 : 0)
      + 6
      + 2;
}


void Foam::RBD::rigidBodyDriver::fillRows()
{
    const rigidBodyModel& model = motion_.model();
    const rigidBodyModelWorkspace& ws = motion_.workspace();
    const rigidBodyModelState& state = motion_.state();

    tauR_ = Zero;
    fxR_ = Zero;
    motion_.restraintForces(tauR_, fxR_);

    forAll(bodyIDs_, bi)
    {
        const label id = bodyIDs_[bi];
        const label master = model.masterID(id);
        const rigidBody& body = model.bodies()[master];
        const spatialTransform X(model.X0(id, ws));
        const spatialVector v(model.v(id, Zero, ws));

        scalarField& row = rows_[bi];
        label k = 0;
        row[k++] = state.t();
        for (const scalar s : X.r()) row[k++] = s;
        for (const scalar s : X.E()) row[k++] = s;
        for (const scalar s : v.l()) row[k++] = s;
        for (const scalar s : v.w()) row[k++] = s;
        for (const label i : dofs_[bi]) row[k++] = state.q()[i];
        for (const label i : dofs_[bi]) row[k++] = state.qDot()[i];
        if (externalForces_)
        {
            for (const scalar s : fx_[master].l()) row[k++] = s;
            for (const scalar s : fx_[master].w()) row[k++] = s;
        }
        for (const scalar s : fxR_[master].l()) row[k++] = s;
        for (const scalar s : fxR_[master].w()) row[k++] = s;
        row[k++] = body.kineticEnergy(ws.v[master]);
        row[k++] =
            -body.m()*(model.g() & model.globalPoint(master, body.c(), ws));
    }
}


void Foam::RBD::rigidBodyDriver::writeRows()
{
    if (!Pstream::master() || !rowsPending_)
    {
        return;
    }

    fillRows();

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
                << " in global axes, moments about the global origin" << nl
                << "# t CofR(x y z) Orientation(xx xy xz yx yy yz zx zy zz)"
                << " v(x y z) omega(x y z)";
            for (const label i : dofs_[bi]) os << " q" << i;
            for (const label i : dofs_[bi]) os << " qDot" << i;
            if (externalForces_)
            {
                os << " fluidForce(x y z) fluidMoment(x y z)";
            }
            os  << " restraintForce(x y z) restraintMoment(x y z)"
                << " kineticEnergy potentialEnergy" << nl;
        }
    }

    forAll(rows_, bi)
    {
        OFstream& os = tables_[bi];
        const scalarField& row = rows_[bi];
        forAll(row, k)
        {
            os  << (k ? " " : "") << row[k];
        }
        os  << nl;

        // On disk at least at every write time (the row's, written at the
        // start of the next step)
        if (rowsAtWriteTime_)
        {
            os.flush();
        }
    }

    rowsPending_ = false;
}


void Foam::RBD::rigidBodyDriver::reportCoupling() const
{
    if (!externalForces_ || curTimeIndex_ < 0)
    {
        return;
    }

    const scalar r = motion_.coupling().residual();

    Info<< "rigidBodyMotion: coupling of the step to t = "
        << motion_.state().t() << ": " << motion_.nSolves() << " solves, "
        << motion_.coupling().type() << ", residual " << r;

    if (r > couplingTolerance_)
    {
        Info<< ": NOT CONVERGED (couplingTolerance " << couplingTolerance_
            << "; more outer correctors, or another"
            << " accelerationRelaxationType, may converge it)";
    }
    Info<< endl;
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
    motion_(motionDict(runTime, coeffs, externalForces), stateDict),
    report_(coeffs.getOrDefault<Switch>("report", false)),
    externalForces_(externalForces),
    tableEveryStep_(true),
    curTimeIndex_(-1),
    couplingTolerance_
    (
        coeffs.getOrDefault<scalar>("couplingTolerance", 0.05)
    ),
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
    fxR_(motion_.model().nBodies(), Zero)
{
    forAll(names_, bi)
    {
        bodyIDs_[bi] = model().bodyID(names_[bi]);
        dofs_[bi] = model().bodyDoFs(bodyIDs_[bi]);
        rows_[bi].setSize(nColumns(bi), Zero);
    }

    // A state that does not say when it is starts at the case's start time
    if (!coeffs.found("t") && !stateDict.found("t"))
    {
        motion_.state().t() = runTime.value();
        motion_.newTime();
    }

    // A row for the start, where its forces are known (no external forces:
    // a fluid's are known only once the first solve has computed them)
    rowsPending_ = !externalForces_;
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
    reportCoupling();
    writeRows();
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
    }

    fx_ = fx;

    if (Pstream::master())
    {
        motion_.solve(time_.value(), time_.deltaTValue(), tau_, fx_);

        if (debug)
        {
            Info<< "rigidBodyMotion: solve " << motion_.nSolves()
                << ", coupling residual " << motion_.coupling().residual()
                << ", qDdot " << motion_.state().qDdot() << endl;
        }
    }
    Pstream::scatter(motion_.state());

    // The row of the step is made from its last solve, when it is written
    rowsPending_ = tableEveryStep_ || time_.writeTime();
    rowsAtWriteTime_ = time_.writeTime();
}


void Foam::RBD::rigidBodyDriver::status(const label bodyID)
{
    const spatialTransform CofR(motion_.X0(bodyID));
    const spatialVector vCofR(motion_.v(bodyID, Zero));

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
    IOobject::writeEndDivider(os);

    return os.good();
}


bool Foam::RBD::rigidBodyDriver::read(const dictionary& coeffs)
{
    report_ = coeffs.getOrDefault<Switch>("report", false);
    return motion_.read(motionDict(time_, coeffs, externalForces_));
}
