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
    stockRigidBodySim

Group
    grpRigidBodyDynamicsTests

Description
    Runs a rigid-body model from its dictionary with the STOCK OpenFOAM v1912
    librigidBodyDynamics (/usr/lib), so that tests can compare the project's
    own rigidBodySim against it, each in its own process.  It is built
    against the stock headers and linked to the stock library only.

    Same command line and output as rigidBodySim: the coefficients come from
    the rigidBodyMotionCoeffs sub-dictionary of constant/dynamicMeshDict, or
    else from the top level of constant/rigidBodyMotionDict; gravity is their
    g entry, or else constant/g; system/controlDict gives deltaT and endTime.
    Prints "Time = t" and the stock status block of every body named in
    bodies, first for the initial state and then after every step (with
    -endOnly, after the last step only).

    Ends, as rigidBodySim does, with a summary of the time loop:
        stockRigidBodySim: N steps, M solves, W s of wall time, X us per step,
            C s of CPU time
    (the wall and CPU time, std::clock, of the loop, from its start to
    after the last step's output, the way rigidBodySim's summary counts
    them).  The status is
    printed with controlDict's writePrecision digits, as rigidBodySim does.

    Prints first "stock library: <path>", the real path of the shared object
    that holds the stock model's code, found with dladdr(), so that a test
    can prove which library was loaded; stops if that is the project's own.
    Run it through runStock, which keeps the project's library directory off
    LD_LIBRARY_PATH.

Usage
    test/stockDriver/runStock [-case DIR]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "rigidBodyMotion.H"
#include "rigidBodySimInput.H"

#include "clockTime.H"

#include <ctime>

#include <dlfcn.h>
#include <climits>
#include <cstdlib>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

//- The real path of a file, or the path itself if it cannot be resolved
fileName resolved(const fileName& path)
{
    char buf[PATH_MAX];

    if (::realpath(path.c_str(), buf))
    {
        return fileName(buf);
    }

    return path;
}


//- The shared object that holds the stock library's rigidBodyModel::typeName
fileName stockLibrary()
{
    Dl_info info;
    const void* addr = &RBD::rigidBodyModel::typeName;

    if (!::dladdr(addr, &info) || !info.dli_fname)
    {
        FatalErrorInFunction
            << "dladdr found no shared object holding "
            << "Foam::RBD::rigidBodyModel::typeName" << nl
            << exit(FatalError);
    }

    const fileName lib(resolved(info.dli_fname));

    const fileName userLibBin(getEnv("FOAM_USER_LIBBIN"));
    if (!userLibBin.empty() && lib.path() == resolved(userLibBin))
    {
        FatalErrorInFunction
            << "Loaded " << lib << ", the project's library, not the stock"
            << " one: run through test/stockDriver/runStock" << nl
            << exit(FatalError);
    }

    return lib;
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Runs a rigid-body model from its dictionary with the stock"
        " librigidBodyDynamics, for comparison"
    );
    argList::noParallel();
    argList::addBoolOption
    (
        "endOnly",
        "print the status at the start and the end only (for timing)"
    );

    #include "setRootCase.H"

    const bool endOnly = args.found("endOnly");

    const fileName lib(stockLibrary());
    Info<< "stock library: " << lib.c_str() << nl << endl;

    #include "createTime.H"

    // The status with writePrecision digits, as rigidBodySim prints it
    Sout.precision(IOstream::defaultPrecision());

    const dictionary coeffs(rigidBodySimCoeffs(runTime));

    // The stock constructor reads g from coeffs but not constant/g: gravity
    // as the project's rigidBodyDriver takes it, coeffs' g, else constant/g
    RBD::rigidBodyMotion motion(runTime, coeffs);
    if (!coeffs.found("g"))
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
            motion.g() = uniformDimensionedVectorField(gIO).value();
        }
    }

    const label nIter = coeffs.getOrDefault<label>("nIter", 1);

    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);

    // Bodies to report, in the order of the dictionary
    const wordList names(coeffs.subDict("bodies").toc());
    labelList bodyIDs(names.size());
    forAll(names, bi)
    {
        bodyIDs[bi] = motion.bodyID(names[bi]);
    }

    auto report = [&]()
    {
        Info<< "Time = " << runTime.timeName() << endl;

        for (const label id : bodyIDs)
        {
            motion.status(id);
        }
    };

    report();

    label nSteps = 0;
    label nSolves = 0;
    clockTime clock;
    const std::clock_t cpu0 = std::clock();

    while (runTime.run())
    {
        ++runTime;

        motion.newTime();
        for (label iter = 0; iter < nIter; ++iter)
        {
            motion.solve(runTime.value(), runTime.deltaTValue(), tau, fx);
            ++nSolves;
        }
        ++nSteps;

        const bool last =
            runTime.value()
          > runTime.endTime().value() - 0.5*runTime.deltaTValue();
        if (!endOnly || last)
        {
            report();
        }
    }

    const scalar wall = clock.elapsedTime();
    Info<< "stockRigidBodySim: " << nSteps << " steps, " << nSolves
        << " solves, " << 1e-3*label(1e3*wall + 0.5) << " s of wall time, "
        << 1e-3*label(1e9*wall/max(nSteps, 1) + 0.5) << " us per step, "
        << scalar(std::clock() - cpu0)/CLOCKS_PER_SEC << " s of CPU time"
        << nl;

    Info<< "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
