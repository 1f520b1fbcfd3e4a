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

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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


void Foam::RBD::rigidBodyDriver::checkSignature
(
    const dictionary& stateDict
) const
{
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
}
