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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidBodyMeshMotion::rigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const word& type,
    const dictionary& coeffs,
    const dictionary& startState
)
:
    displacementMotionSolver(mesh, dict, type),
    coeffs_(coeffs),
    driver_
    (
        mesh.time(),
        coeffs_,
        typeName,
        !coeffs_.getOrDefault<Switch>("test", false),
        startState
    ),
    test_(coeffs_.getOrDefault<Switch>("test", false)),
    rhoName_(coeffs_.getOrDefault<word>("rho", "rho")),
    rhoInf_(1),
    addedMassRamp_(-1),
    fx_(driver_.model().nBodies(), Zero)
{
    Info<< "rigidBodyMotion: the rigid-body dynamics project's"
        << " librigidBodyMeshMotion (not OpenFOAM's stock library)" << endl;

    if (rhoName_ == "rhoInf")
    {
        rhoInf_ = RBD::readPositive(coeffs_, "rhoInf");
    }

    readBodyMeshes();
}


Foam::rigidBodyMeshMotion::rigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    rigidBodyMeshMotion
    (
        mesh,
        dict,
        typeName,
        dict.optionalSubDict(typeName + "Coeffs"),
        dictionary::null
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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

    driver_.solve(fx_, finalCorrector());

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


Foam::dictionary Foam::rigidBodyMeshMotion::rigidBodyCoeffs() const
{
    return coeffDict();
}


bool Foam::rigidBodyMeshMotion::read()
{
    if (displacementMotionSolver::read())
    {
        // A new coupling scheme: give it the added mass at the next step
        addedMass_.clear();
        addedMassRamp_ = -1;
        residualField_.clear();
        coeffs_ = rigidBodyCoeffs();
        return driver_.read(coeffs_);
    }

    return false;
}
