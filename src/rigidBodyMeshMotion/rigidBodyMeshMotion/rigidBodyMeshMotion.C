#include "rigidBodyMeshMotion.H"
#include "addToRunTimeSelectionTable.H"
#include "polyMesh.H"
#include "pointMesh.H"
#include "pointPatchDist.H"
#include "pointConstraints.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
#include "volFields.H"

namespace Foam
{
    defineTypeNameAndDebug(rigidBodyMeshMotion, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        rigidBodyMeshMotion,
        dictionary
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::rigidBodyMeshMotion::stateDict
(
    const polyMesh& mesh,
    const dictionary&
)
{
    IOobject io
    (
        "rigidBodyMotionState",
        mesh.time().timeName(),
        "uniform",
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );

    if (io.typeHeaderOk<IOdictionary>(true))
    {
        Info<< "rigidBodyMotion: restarting from " << io.objectPath() << endl;
        return IOdictionary(io);
    }

    return dictionary();
}


void Foam::rigidBodyMeshMotion::readBodyMeshes()
{
    const polyBoundaryMesh& pbm = mesh().boundaryMesh();
    const dictionary& bodiesDict = coeffDict().subDict("bodies");

    // Body transforms of the initial state, which points0 belong to
    RBD::rigidBodyModelState state00(model_, coeffDict());
    RBD::rigidBodyModelWorkspace ws00(model_);
    model_.kinematics(state00, ws00);

    DynamicList<bodyMesh> bodies;

    for (const entry& e : bodiesDict)
    {
        if (!e.isDict() || !e.dict().found("patches"))
        {
            continue;
        }

        const dictionary& bd = e.dict();

        bodyMesh b;
        b.name = e.keyword();
        b.bodyID = model_.bodyID(b.name);
        b.patches = bd.get<wordRes>("patches");

        if (b.patches.empty())
        {
            FatalIOErrorInFunction(bd)
                << "Body " << b.name << ": entry patches is empty" << nl
                << "Patches of the mesh: " << pbm.names() << nl
                << exit(FatalIOError);
        }

        for (const wordRe& p : b.patches)
        {
            const labelHashSet ids(pbm.patchSet(wordRes(1, p), false));
            if (ids.empty())
            {
                FatalIOErrorInFunction(bd)
                    << "Body " << b.name << ": patches entry " << p
                    << " matches no patch of the mesh" << nl
                    << "Patches of the mesh: " << pbm.names() << nl
                    << exit(FatalIOError);
            }
            b.patchSet += ids;
        }

        b.di = RBD::readPositive(bd, "innerDistance", true);
        b.dOuter = RBD::readPositive(bd, "outerDistance");

        if (b.di >= b.dOuter)
        {
            FatalIOErrorInFunction(bd)
                << "Body " << b.name << ": innerDistance " << b.di
                << " must be less than outerDistance " << b.dOuter << nl
                << exit(FatalIOError);
        }

        b.X00 = model_.X0(b.bodyID, ws00);
        b.X = model_.X0(b.bodyID);

        bodies.append(b);
    }

    if (bodies.empty())
    {
        FatalIOErrorInFunction(coeffDict())
            << "No body has patches: give the bodies that move the mesh"
            << " their patches, innerDistance and outerDistance" << nl
            << "Bodies: " << model_.bodyNames() << nl
            << exit(FatalIOError);
    }

    bodyMeshes_.transfer(bodies);

    // Weights from the distance of the initial points to each body's
    // patches: 1 within innerDistance, 0 beyond outerDistance, a smooth
    // step between; scaled where bodies' bands overlap to sum to 1
    const pointMesh& pMesh = pointMesh::New(mesh());
    scalarField total(points0().size(), Zero);
    List<scalarField> allWeights(bodyMeshes_.size());

    forAll(bodyMeshes_, bi)
    {
        bodyMesh& b = bodyMeshes_[bi];

        const pointPatchDist dist(pMesh, b.patchSet, points0());
        const scalarField& d = dist.primitiveField();

        scalarField& w = allWeights[bi];
        w.setSize(d.size());

        forAll(d, pi)
        {
            const scalar s = min(max((d[pi] - b.di)/(b.dOuter - b.di), 0), 1);
            w[pi] = 1 - sqr(s)*(3 - 2*s);
            total[pi] += w[pi];
        }
    }

    forAll(bodyMeshes_, bi)
    {
        bodyMesh& b = bodyMeshes_[bi];
        const scalarField& w = allWeights[bi];

        DynamicList<label> ids;
        DynamicList<scalar> ws;
        forAll(w, pi)
        {
            if (w[pi] > 0)
            {
                ids.append(pi);
                ws.append(w[pi]/max(total[pi], scalar(1)));
            }
        }
        b.pointIDs.transfer(ids);
        b.weights.transfer(ws);

        Info<< "rigidBodyMotion: body " << b.name << " moves "
            << returnReduce(b.pointIDs.size(), sumOp<label>())
            << " points (patches " << b.patches << ", innerDistance "
            << b.di << ", outerDistance " << b.dOuter << ")" << endl;
    }
}


void Foam::rigidBodyMeshMotion::storeRows()
{
    if (!Pstream::master())
    {
        return;
    }

    const RBD::rigidBodyModelWorkspace& ws = model_.workspace();

    // Restraint forces on the state now
    tauR_ = Zero;
    fxR_ = Zero;
    model_.applyRestraints(model_.state(), ws, tauR_, fxR_);

    rows_.setSize(bodyMeshes_.size());

    forAll(bodyMeshes_, bi)
    {
        const label id = bodyMeshes_[bi].bodyID;
        const label master = model_.masterID(id);
        const spatialTransform X(model_.X0(id, ws));
        const spatialVector v(model_.v(id, Zero, ws));
        const spatialVector& ff = fx_[master];
        const spatialVector& fr = fxR_[master];

        scalarField& row = rows_[bi];
        row.setSize(31);
        label k = 0;
        row[k++] = mesh().time().value();
        for (const scalar s : X.r()) row[k++] = s;
        for (const scalar s : X.E()) row[k++] = s;
        for (const scalar s : v.l()) row[k++] = s;
        for (const scalar s : v.w()) row[k++] = s;
        for (const scalar s : ff.l()) row[k++] = s;
        for (const scalar s : ff.w()) row[k++] = s;
        for (const scalar s : fr.l()) row[k++] = s;
        for (const scalar s : fr.w()) row[k++] = s;
    }
}


void Foam::rigidBodyMeshMotion::writeRows()
{
    if (!Pstream::master() || rows_.empty())
    {
        return;
    }

    if (tables_.empty())
    {
        const fileName dir
        (
            mesh().time().globalPath()
           /"postProcessing"/"rigidBodyMotion"/startTimeName_
        );
        mkDir(dir);

        tables_.setSize(bodyMeshes_.size());
        forAll(bodyMeshes_, bi)
        {
            tables_.set(bi, new OFstream(dir/bodyMeshes_[bi].name + ".dat"));
            tables_[bi].precision(IOstream::defaultPrecision());
            tables_[bi]
                << "# Motion of body " << bodyMeshes_[bi].name << nl
                << "# t CofR(x y z) Orientation(xx xy xz yx yy yz zx zy zz)"
                << " v(x y z) omega(x y z) fluidForce(x y z)"
                << " fluidMoment(x y z) restraintForce(x y z)"
                << " restraintMoment(x y z); moments about the origin"
                << nl;
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
        os  << endl;
    }

    rows_.clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidBodyMeshMotion::rigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    displacementMotionSolver(mesh, dict, typeName),
    model_(coeffDict(), stateDict(mesh, coeffDict())),
    test_(coeffDict().getOrDefault<Switch>("test", false)),
    rhoName_(coeffDict().getOrDefault<word>("rho", "rho")),
    rhoInf_(1),
    curTimeIndex_(-1),
    startTimeName_(mesh.time().timeName()),
    tau_(model_.nDoF(), Zero),
    fx_(model_.nBodies(), Zero),
    tauR_(model_.nDoF(), Zero),
    fxR_(model_.nBodies(), Zero)
{
    Info<< "rigidBodyMotion: the rigid-body dynamics project's"
        << " librigidBodyMeshMotion (not OpenFOAM's stock library)" << endl;

    if (rhoName_ == "rhoInf")
    {
        rhoInf_ = RBD::readPositive(coeffDict(), "rhoInf");
    }

    if (coeffDict().found("ramp"))
    {
        ramp_ = Function1<scalar>::New("ramp", coeffDict());
    }

    if (!coeffDict().found("t"))
    {
        const dictionary sd(stateDict(mesh, coeffDict()));
        if (!sd.found("t"))
        {
            model_.state().t() = mesh.time().value();
            model_.newTime();
        }
    }

    readBodyMeshes();
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::rigidBodyMeshMotion::~rigidBodyMeshMotion()
{
    writeRows();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::pointField> Foam::rigidBodyMeshMotion::curPoints() const
{
    tmp<pointField> tnewPoints
    (
        new pointField(points0() + pointDisplacement_.primitiveField())
    );

    twoDCorrectPoints(tnewPoints.ref());

    return tnewPoints;
}


void Foam::rigidBodyMeshMotion::displace()
{
    pointField& disp = pointDisplacement_.primitiveFieldRef();
    const pointField& p0 = points0();

    // Only the points within the bodies' outerDistance move
    forAll(bodyMeshes_, bi)
    {
        for (const label pi : bodyMeshes_[bi].pointIDs)
        {
            disp[pi] = Zero;
        }
    }

    forAll(bodyMeshes_, bi)
    {
        const bodyMesh& b = bodyMeshes_[bi];

        // The body's motion since points0: p -> E^T E00 (p - r00) + r
        const tensor R(b.X.E().T() & b.X00.E());
        const vector& r00 = b.X00.r();
        const vector& r = b.X.r();

        forAll(b.pointIDs, i)
        {
            const label pi = b.pointIDs[i];
            disp[pi] += b.weights[i]*((R & (p0[pi] - r00)) + r - p0[pi]);
        }
    }

    // Boundary conditions of pointDisplacement: walls stay, slips slide
    pointConstraints::New(pointMesh::New(mesh())).constrainDisplacement
    (
        pointDisplacement_
    );
}


void Foam::rigidBodyMeshMotion::solve()
{
    const Time& t = mesh().time();

    if (mesh().nPoints() != points0().size())
    {
        FatalErrorInFunction
            << "The mesh has " << mesh().nPoints() << " points, its"
            << " initial points0 " << points0().size()
            << ": topology changes are not supported" << nl
            << exit(FatalError);
    }

    // The start of a new time step
    if (curTimeIndex_ != t.timeIndex())
    {
        writeRows();
        model_.newTime();
        curTimeIndex_ = t.timeIndex();
    }

    const scalar ramp = ramp_.valid() ? ramp_->value(t.value()) : 1;

    if (t.foundObject<uniformDimensionedVectorField>("g"))
    {
        model_.setG
        (
            ramp*t.lookupObject<uniformDimensionedVectorField>("g").value()
        );
    }

    // Fluid forces and moments about the origin, summed over processors
    fx_ = Zero;
    if (!test_)
    {
        if (forces_.empty())
        {
            if
            (
                rhoName_ != "rhoInf"
             && !mesh().foundObject<volScalarField>(rhoName_)
            )
            {
                FatalIOErrorInFunction(coeffDict().lookup("rho"))
                    << "Entry rho " << rhoName_ << ": no such density field;"
                    << " give the name of one or, for a fluid of constant"
                    << " density, rho rhoInf with rhoInf" << nl
                    << "Fields: "
                    << mesh().sortedNames<volScalarField>() << nl
                    << exit(FatalIOError);
            }

            forces_.setSize(bodyMeshes_.size());
            forAll(bodyMeshes_, bi)
            {
                dictionary forcesDict;
                forcesDict.add("type", functionObjects::forces::typeName);
                forcesDict.add("patches", bodyMeshes_[bi].patches);
                forcesDict.add("rho", rhoName_);
                forcesDict.add("rhoInf", rhoInf_);
                forcesDict.add("CofR", vector::zero);
                forcesDict.add("log", false);

                forces_.set
                (
                    bi,
                    new functionObjects::forces
                    (
                        "rigidBodyMotion:" + bodyMeshes_[bi].name,
                        mesh(),
                        forcesDict
                    )
                );
            }
        }

        forAll(bodyMeshes_, bi)
        {
            functionObjects::forces& f = forces_[bi];
            f.calcForcesMoment();
            fx_[model_.masterID(bodyMeshes_[bi].bodyID)] +=
                ramp*spatialVector(f.momentEff(), f.forceEff());
        }
    }

    // Solve on the master, broadcast the state
    if (Pstream::master())
    {
        for (label iter = 0; iter < model_.nIter(); ++iter)
        {
            model_.solve(t.value(), t.deltaTValue(), tau_, fx_);
        }
    }
    Pstream::scatter(model_.state());

    forAll(bodyMeshes_, bi)
    {
        bodyMeshes_[bi].X = model_.X0(bodyMeshes_[bi].bodyID);
    }

    displace();

    if (model_.report())
    {
        forAll(bodyMeshes_, bi)
        {
            model_.status(bodyMeshes_[bi].bodyID);
        }
    }

    storeRows();
}


bool Foam::rigidBodyMeshMotion::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    const Time& t = mesh().time();

    const fileName dir(t.timePath()/"uniform");
    mkDir(dir);

    OFstream os(dir/"rigidBodyMotionState");
    IOobject io("rigidBodyMotionState", t.timeName(), "uniform", mesh());
    io.writeHeader(os, IOdictionary::typeName);
    model_.state().write(os);
    IOobject::writeEndDivider(os);

    return os.good();
}


bool Foam::rigidBodyMeshMotion::read()
{
    if (displacementMotionSolver::read())
    {
        model_.read(coeffDict());
        return true;
    }

    return false;
}
