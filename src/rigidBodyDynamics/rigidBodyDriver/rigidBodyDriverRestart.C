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
#include "OSspecific.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::RBD::rigidBodyDriver::restartState
(
    const Time& runTime,
    const dictionary& coeffs,
    const dictionary& startState
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

    // Another solver's state, converted (its front-end says so)
    if (startState.size())
    {
        return startState;
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

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
