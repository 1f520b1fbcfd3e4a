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

// The mesh's morphing: each body's points, their weights between
// innerDistance and outerDistance, their displacement and the check of the
// cells they bound

#include "rigidBodyMeshMotion.H"
#include "rigidBodyEntries.H"
#include "pointMesh.H"
#include "pointPatchDist.H"
#include "pointConstraints.H"
#include "unitConversion.H"
#include "OStringStream.H"

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
    const dictionary& bodiesDict = coeffs_.subDict("bodies");
    const RBD::rigidBodyModel& model = driver_.model();

    // Body transforms of the dictionary's initial state, which points0
    // belong to
    const RBD::rigidBodyModelState state00(model.nDoF(), coeffs_);
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
        FatalIOErrorInFunction(coeffs_)
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
