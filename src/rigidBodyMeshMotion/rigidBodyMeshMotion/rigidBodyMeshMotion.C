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

#include "rigidBodyMeshMotion.H"
#include "rigidBodyEntries.H"
#include "keywordTable.H"
#include "addToRunTimeSelectionTable.H"
#include "polyMesh.H"
#include "pointMesh.H"
#include "pointPatchDist.H"
#include "pointConstraints.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
#include "volFields.H"
#include "unitConversion.H"
#include "OStringStream.H"
#include "pimpleControl.H"

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

// What the mesh motion reads from the motion's dictionaries, beside the
// library's own keywords.  With the coefficients at the dynamicMeshDict's
// top level (no rigidBodyMotionCoeffs), that level's entries are
// OpenFOAM's.  rigidBodySim, which dry-runs a dynamicMeshDict without this
// library, registers the same lists (test/keywords compares them)
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::rigidBodyMeshMotion::bodyMesh Foam::rigidBodyMeshMotion::readBodyMesh
(
    const entry& e,
    const RBD::rigidBodyModelWorkspace& ws00
)
{
    const polyBoundaryMesh& pbm = mesh().boundaryMesh();
    const RBD::rigidBodyModel& model = driver_.model();
    const dictionary& bd = e.dict();

    bodyMesh b;
    b.name = e.keyword();
    b.bodyID = model.bodyID(b.name);
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

    b.innerDistance = RBD::readNonNegative(bd, "innerDistance");
    b.outerDistance = RBD::readPositive(bd, "outerDistance");

    if (b.innerDistance >= b.outerDistance)
    {
        FatalIOErrorInFunction(bd)
            << "Body " << b.name << ": innerDistance " << b.innerDistance
            << " must be less than outerDistance " << b.outerDistance
            << nl << exit(FatalIOError);
    }

    // The further band of the translation along one direction
    b.translationDirection = Zero;
    b.translationOuterDistance = 0;
    const bool hasDirection = bd.found("translationDirection");
    const bool hasDistance = bd.found("translationOuterDistance");
    if (hasDirection != hasDistance)
    {
        FatalIOErrorInFunction(bd)
            << "Body " << b.name << ": translationDirection and"
            << " translationOuterDistance go together: give both or"
            << " neither" << nl << exit(FatalIOError);
    }
    if (hasDistance)
    {
        b.translationDirection = RBD::readAxis(bd, "translationDirection");
        b.translationOuterDistance =
            RBD::readPositive(bd, "translationOuterDistance");

        if (b.translationOuterDistance <= b.outerDistance)
        {
            FatalIOErrorInFunction(bd)
                << "Body " << b.name << ": translationOuterDistance "
                << b.translationOuterDistance << " must be more than"
                << " outerDistance " << b.outerDistance << nl
                << exit(FatalIOError);
        }
    }

    b.X00 = model.X0(b.bodyID, ws00);
    b.X = driver_.motion().X0(b.bodyID);

    return b;
}


void Foam::rigidBodyMeshMotion::readBodyMeshes()
{
    const dictionary& bodiesDict = coeffDict().subDict("bodies");
    const RBD::rigidBodyModel& model = driver_.model();

    // Body transforms of the dictionary's initial state, which points0
    // belong to
    const RBD::rigidBodyModelState state00(model.nDoF(), coeffDict());
    RBD::rigidBodyModelWorkspace ws00(model);
    model.kinematics(state00, ws00);

    DynamicList<bodyMesh> bodies;
    for (const entry& e : bodiesDict)
    {
        if (e.isDict() && e.dict().found("patches"))
        {
            bodies.append(readBodyMesh(e, ws00));
        }
    }

    if (bodies.empty())
    {
        FatalIOErrorInFunction(coeffDict())
            << "No body has patches: give the bodies that move the mesh"
            << " their patches, innerDistance and outerDistance" << nl
            << "Bodies: " << model.bodyNames() << nl
            << exit(FatalIOError);
    }

    bodyMeshes_.transfer(bodies);

    computeWeights();
    findBandCells();
}


void Foam::rigidBodyMeshMotion::computeWeights()
{
    // Weights from the distance of the initial points to each body's
    // patches: 1 within innerDistance, 0 beyond outerDistance, a smooth
    // step between; the translation's further band the same step out to
    // translationOuterDistance, less the weight of the whole motion.
    // Scaled where bodies' bands overlap, for each point by the sum over
    // the bodies of the larger of its two weights, when that exceeds 1
    const pointMesh& pMesh = pointMesh::New(mesh());
    scalarField total(points0().size(), Zero);
    List<scalarField> allWeights(bodyMeshes_.size());
    List<scalarField> allTranslationWeights(bodyMeshes_.size());

    // 1 within inner, 0 beyond outer, smooth between
    auto step = [](const scalar d, const scalar inner, const scalar outer)
    {
        const scalar s = min(max((d - inner)/(outer - inner), 0), 1);
        return 1 - sqr(s)*(3 - 2*s);
    };

    forAll(bodyMeshes_, bi)
    {
        bodyMesh& b = bodyMeshes_[bi];

        const pointPatchDist dist(pMesh, b.patchSet, points0());
        const scalarField& d = dist.primitiveField();

        scalarField& w = allWeights[bi];
        scalarField& wt = allTranslationWeights[bi];
        w.setSize(d.size());
        wt.setSize(d.size(), Zero);

        forAll(d, pi)
        {
            w[pi] = step(d[pi], b.innerDistance, b.outerDistance);

            if (b.translationOuterDistance > 0)
            {
                wt[pi] = max
                (
                    step
                    (
                        d[pi],
                        b.innerDistance,
                        b.translationOuterDistance
                    )
                  - w[pi],
                    0
                );
            }

            total[pi] += w[pi] + wt[pi];
        }
    }

    forAll(bodyMeshes_, bi)
    {
        bodyMesh& b = bodyMeshes_[bi];
        const scalarField& w = allWeights[bi];
        const scalarField& wt = allTranslationWeights[bi];
        const bool hasTranslationBand = b.translationOuterDistance > 0;

        DynamicList<label> ids;
        DynamicList<scalar> ws;
        DynamicList<scalar> wts;
        forAll(w, pi)
        {
            if (w[pi] > 0 || wt[pi] > 0)
            {
                const scalar scale = 1/max(total[pi], scalar(1));
                ids.append(pi);
                ws.append(w[pi]*scale);
                if (hasTranslationBand)
                {
                    wts.append(wt[pi]*scale);
                }
            }
        }
        b.pointIDs.transfer(ids);
        b.weights.transfer(ws);
        b.translationWeights.transfer(wts);

        Info<< "rigidBodyMotion: body " << b.name << " moves "
            << returnReduce(b.pointIDs.size(), sumOp<label>())
            << " points (patches " << b.patches << ", innerDistance "
            << b.innerDistance << ", outerDistance " << b.outerDistance;
        if (b.translationOuterDistance > 0)
        {
            Info<< ", its translation along " << b.translationDirection
                << " out to " << b.translationOuterDistance;
        }
        Info<< ")" << endl;
    }
}


void Foam::rigidBodyMeshMotion::findBandCells()
{
    // The cells that use a moved point, and their volumes now
    boolList inBand(mesh().nCells(), false);
    forAll(bodyMeshes_, bi)
    {
        for (const label pi : bodyMeshes_[bi].pointIDs)
        {
            for (const label celli : mesh().pointCells()[pi])
            {
                inBand[celli] = true;
            }
        }
    }
    bandCells_ = findIndices(inBand, true);
    bandVolumes0_.setSize(bandCells_.size());
    forAll(bandCells_, i)
    {
        bandVolumes0_[i] = mesh().cellVolumes()[bandCells_[i]];
    }
}


Foam::scalar Foam::rigidBodyMeshMotion::displacedVolume
(
    const label celli
) const
{
    // Divergence theorem: V = sum over faces of (centre & area vector)/3,
    // area vectors out of the cell, from the displaced points
    const pointField& p0 = points0();
    const pointField& d = pointDisplacement_.primitiveField();
    const faceList& faces = mesh().faces();
    const labelList& owner = mesh().faceOwner();

    scalar V = 0;
    for (const label facei : mesh().cells()[celli])
    {
        const face& f = faces[facei];

        // The face's centre and area vector from triangles about its
        // points' average
        vector centre(Zero);
        forAll(f, k)
        {
            centre += p0[f[k]] + d[f[k]];
        }
        centre /= f.size();

        vector Sf(Zero);
        forAll(f, k)
        {
            const point a(p0[f[k]] + d[f[k]]);
            const point b(p0[f.nextLabel(k)] + d[f.nextLabel(k)]);
            Sf += 0.5*((a - centre) ^ (b - centre));
        }

        V += (owner[facei] == celli ? 1 : -1)*(centre & Sf)/3;
    }

    return V;
}


Foam::string Foam::rigidBodyMeshMotion::crushedCell
(
    const label i,
    const scalar ratio
) const
{
    OStringStream what;
    const point c(mesh().cellCentres()[bandCells_[i]]);
    label bi = 0;
    scalar nearest = GREAT;
    forAll(bodyMeshes_, b)
    {
        const scalar dist = mag(c - bodyMeshes_[b].X.r());
        if (dist < nearest)
        {
            nearest = dist;
            bi = b;
        }
    }
    const bodyMesh& b = bodyMeshes_[bi];
    const scalar moved = mag(b.X.r() - b.X00.r());
    const scalar turned =
        radToDeg
        (
            acos
            (
                min
                (
                    max
                    (
                        0.5*(tr(b.X.E().T() & b.X00.E()) - 1),
                        scalar(-1)
                    ),
                    scalar(1)
                )
            )
        );
    what<< "Body " << b.name << " at t = " << mesh().time().value()
        << " s has moved " << moved << " m and turned " << turned
        << " degrees from where the mesh was made; a cell at " << c
        << " in its band (innerDistance " << b.innerDistance
        << ", outerDistance " << b.outerDistance;
    if (b.translationOuterDistance > 0)
    {
        what<< ", translationOuterDistance "
            << b.translationOuterDistance;
    }
    what<< ") would be"
        << " crushed to " << ratio << " of its volume.";
    return what.str();
}


void Foam::rigidBodyMeshMotion::checkCells() const
{
    label worst = -1;
    scalar worstRatio = GREAT;
    forAll(bandCells_, i)
    {
        // A volume that overflowed (a body thrown far) counts as crushed
        const scalar r = displacedVolume(bandCells_[i])/bandVolumes0_[i];
        const scalar ratio = std::isfinite(r) ? r : -GREAT;
        if (ratio < worstRatio)
        {
            worstRatio = ratio;
            worst = i;
        }
    }

    if (returnReduce(worstRatio, minOp<scalar>()) >= 0.01)
    {
        return;
    }

    // The body whose band holds the crushed cell (on the processor that
    // has it), and how far it has moved from where points0 put it
    string what;
    if (worst >= 0 && worstRatio < 0.01)
    {
        what = crushedCell(worst, worstRatio);
    }

    // The processor that has the cell says it
    List<string> messages(Pstream::nProcs());
    messages[Pstream::myProcNo()] = what;
    Pstream::gatherList(messages);

    if (Pstream::master())
    {
        string message;
        for (const string& m : messages)
        {
            if (m.size())
            {
                message = m;
                break;
            }
        }

        FatalErrorInFunction
            << message.c_str() << nl
            << "The body has moved further than its band can absorb (about"
            << " (outerDistance - innerDistance)/1.5, and along a"
            << " translationDirection (translationOuterDistance -"
            << " innerDistance)/1.5), or into a wall:"
            << " the mesh would tangle.  Widen the band, give the body room"
            << " (its joint's range, a restraint), or remesh." << nl
            << exit(FatalError);
    }
    else
    {
        FatalErrorInFunction << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidBodyMeshMotion::rigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    displacementMotionSolver(mesh, dict, typeName),
    driver_
    (
        mesh.time(),
        coeffDict(),
        typeName,
        !coeffDict().getOrDefault<Switch>("test", false)
    ),
    test_(coeffDict().getOrDefault<Switch>("test", false)),
    rhoName_(coeffDict().getOrDefault<word>("rho", "rho")),
    rhoInf_(1),
    addedMassRamp_(-1),
    fx_(driver_.model().nBodies(), Zero)
{
    Info<< "rigidBodyMotion: the rigid-body dynamics project's"
        << " librigidBodyMeshMotion (not OpenFOAM's stock library)" << endl;

    if (rhoName_ == "rhoInf")
    {
        rhoInf_ = RBD::readPositive(coeffDict(), "rhoInf");
    }

    readBodyMeshes();
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


void Foam::rigidBodyMeshMotion::fluidForces()
{
    fx_ = Zero;

    if (test_)
    {
        return;
    }

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

    // Scaled as gravity is, by the ramp
    const scalar ramp = driver_.motion().ramp(mesh().time().value());

    forAll(bodyMeshes_, bi)
    {
        functionObjects::forces& f = forces_[bi];
        f.calcForcesMoment();
        fx_[driver_.model().masterID(bodyMeshes_[bi].bodyID)] +=
            ramp*spatialVector(f.momentEff(), f.forceEff());
    }
}


void Foam::rigidBodyMeshMotion::giveAddedMass()
{
    // At the first solve of a step (and at the first after read())
    if
    (
        test_
     || !driver_.motion().coupling().usesFluidAddedMass()
     || (
            addedMass_.valid()
         && !driver_.step().isNew(mesh().time().timeIndex())
        )
    )
    {
        return;
    }

    if (!addedMass_.valid())
    {
        labelList bodyIDs(bodyMeshes_.size());
        List<labelHashSet> patches(bodyMeshes_.size());
        forAll(bodyMeshes_, bi)
        {
            bodyIDs[bi] = bodyMeshes_[bi].bodyID;
            patches[bi] = bodyMeshes_[bi].patchSet;
        }

        addedMass_.reset
        (
            new Foam::fluidAddedMass
            (
                refCast<const fvMesh>(mesh()),
                rhoName_,
                rhoInf_,
                driver_.model(),
                driver_.motion().state(),
                bodyIDs,
                patches
            )
        );
    }

    // Given again when recomputed, or when the ramp has changed it
    const scalar ramp = driver_.motion().ramp(mesh().time().value());
    if
    (
        !addedMass_->update(driver_.model(), driver_.motion().state())
     && ramp == addedMassRamp_
    )
    {
        return;
    }
    addedMassRamp_ = ramp;

    // Scaled as the fluid's forces are, by the ramp
    scalarSquareMatrix A(addedMass_->A());
    A *= ramp;

    if (driver_.report())
    {
        Info<< "rigidBodyMotion: the fluid's added mass in joint space "
            << A << endl;
    }

    driver_.motion().setFluidAddedMass(A);
}


void Foam::rigidBodyMeshMotion::useResidualControl
(
    const entry& e,
    const dictionary& controls,
    const dictionary& pimpleDict
)
{
    const fvMesh& fvm = refCast<const fvMesh>(mesh());

    if (!e.isDict())
    {
        FatalIOErrorInFunction(controls)
            << "PIMPLE residualControl entry " << e.keyword()
            << " must be a dictionary: " << e.keyword()
            << " { tolerance 0.1; relTol 0; }" << nl
            << exit(FatalIOError);
    }
    const dictionary& d = e.dict();
    const scalar tol = RBD::readPositive(d, "tolerance");
    const scalar relTol = d.getOrDefault<scalar>("relTol", 0);
    if (relTol != 0)
    {
        FatalIOErrorInFunction(d)
            << "PIMPLE residualControl entry " << e.keyword()
            << ": relTol " << relTol << " must be 0. The coupling's"
            << " residual is already relative (to the motion's"
            << " amplitude), and the first corrector of a step has none"
            << " of its own, so a relative drop means nothing." << nl
            << exit(FatalIOError);
    }

    if
    (
        coeffDict().found("couplingTolerance")
     && coeffDict().get<scalar>("couplingTolerance") != tol
    )
    {
        FatalIOErrorInFunction(coeffDict())
            << "couplingTolerance "
            << coeffDict().get<scalar>("couplingTolerance")
            << " differs from the tolerance " << tol << " of PIMPLE"
            << " residualControl entry " << e.keyword() << " in "
            << fvm.solutionDict().name() << ": they are one tolerance."
            << " Give it once (residualControl's sets both)." << nl
            << exit(FatalIOError);
    }

    if (!pimpleDict.getOrDefault<bool>("moveMeshOuterCorrectors", false))
    {
        WarningInFunction
            << "PIMPLE residualControl entry " << e.keyword()
            << ": the mesh moves only in the first outer corrector"
            << " (moveMeshOuterCorrectors no), so the bodies are solved"
            << " once a step and the correctors cannot converge their"
            << " coupling; the loop will run all nOuterCorrectors."
            << endl;
    }

    driver_.setCouplingTolerance(tol);
    Info<< "rigidBodyMotion: outer correctors on demand: PIMPLE ends"
        << " them once the coupling's residual is below " << tol
        << " (residualControl " << e.keyword() << ")" << endl;
}


void Foam::rigidBodyMeshMotion::readResidualControl()
{
    const fvMesh& fvm = refCast<const fvMesh>(mesh());
    const word name(typeName);

    residualField_.reset
    (
        new volScalarField
        (
            IOobject
            (
                name,
                fvm.time().timeName(),
                fvm,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            fvm,
            dimensionedScalar(dimless, Zero)
        )
    );

    const dictionary& pimpleDict =
        fvm.solutionDict().subOrEmptyDict("PIMPLE");
    const dictionary& controls = pimpleDict.subOrEmptyDict("residualControl");

    for (const entry& e : controls)
    {
        const wordRe key(e.keyword());

        // An entry no field matches is counted converged by PIMPLE
        bool matched = false;
        for (const word& field : fvm.names())
        {
            matched = matched || key.match(field);
        }
        if (!matched)
        {
            WarningInFunction
                << "PIMPLE residualControl entry " << e.keyword()
                << " matches no field of the mesh: OpenFOAM counts it"
                << " converged without checking it. Fields: "
                << fvm.sortedNames<volScalarField>() << " (the rigid"
                << " bodies' coupling: " << name << ")" << endl;
        }

        if (!key.match(name))
        {
            continue;
        }

        useResidualControl(e, controls, pimpleDict);
    }
}


bool Foam::rigidBodyMeshMotion::lastSolve() const
{
    const Time& runTime = mesh().time();
    if
    (
        runTime.value()
      < runTime.endTime().value() - 0.5*runTime.deltaTValue()
    )
    {
        return false;
    }

    // Its last solve
    const fvMesh& fvm = refCast<const fvMesh>(mesh());
    const HashTable<const pimpleControl*> pimples
    (
        fvm.lookupClass<pimpleControl>()
    );
    if (pimples.empty())
    {
        return true;
    }
    const bool moveMeshOuterCorrectors =
        fvm.solutionDict().subOrEmptyDict("PIMPLE")
       .getOrDefault<bool>("moveMeshOuterCorrectors", false);

    return !moveMeshOuterCorrectors || (*pimples.cbegin())->finalIter();
}


void Foam::rigidBodyMeshMotion::setSolverPerformance()
{
    const scalar r = driver_.step().pimpleResidual();

    refCast<const fvMesh>(mesh()).setSolverPerformance
    (
        typeName,
        SolverPerformance<scalar>
        (
            typeName,
            typeName,
            r,
            r,
            driver_.motion().nSolves()
        )
    );
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

        if (b.translationWeights.empty())
        {
            forAll(b.pointIDs, i)
            {
                const label pi = b.pointIDs[i];
                disp[pi] += b.weights[i]*((R & (p0[pi] - r00)) + r - p0[pi]);
            }
        }
        else
        {
            // One pass with the translation's further band, along its
            // direction alone; most of its points, beyond outerDistance,
            // have no share of the whole motion
            const vector& e = b.translationDirection;
            const vector te(((r - r00) & e)*e);
            forAll(b.pointIDs, i)
            {
                const label pi = b.pointIDs[i];
                if (b.weights[i] > 0)
                {
                    disp[pi] +=
                        b.weights[i]*((R & (p0[pi] - r00)) + r - p0[pi]);
                }
                disp[pi] += b.translationWeights[i]*te;
            }
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
    if (mesh().nPoints() != points0().size())
    {
        FatalErrorInFunction
            << "The mesh has " << mesh().nPoints() << " points, its"
            << " initial points0 " << points0().size()
            << ": topology changes are not supported" << nl
            << exit(FatalError);
    }

    fluidForces();
    giveAddedMass();

    if (!test_ && !residualField_.valid())
    {
        readResidualControl();
    }

    driver_.solve(fx_);

    if (!test_)
    {
        setSolverPerformance();
    }

    forAll(bodyMeshes_, bi)
    {
        bodyMeshes_[bi].X = driver_.motion().X0(bodyMeshes_[bi].bodyID);
    }

    // The new points and their check with the traps off: a body thrown
    // far is refused by checkCells, not by a signal in its arithmetic
    {
        RBD::floatingPointTraps traps;
        displace();
        checkCells();
    }

    if (driver_.report())
    {
        forAll(bodyMeshes_, bi)
        {
            driver_.status(bodyMeshes_[bi].bodyID);
        }
    }

    // The run's end: its last step committed (not in a destructor, where a
    // FatalError would end in std::terminate)
    if (lastSolve())
    {
        driver_.end();
    }
}


bool Foam::rigidBodyMeshMotion::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    return driver_.writeState();
}


bool Foam::rigidBodyMeshMotion::read()
{
    if (displacementMotionSolver::read())
    {
        // A new coupling scheme: give it the added mass at the next step
        addedMass_.clear();
        addedMassRamp_ = -1;
        residualField_.clear();
        return driver_.read(coeffDict());
    }

    return false;
}
