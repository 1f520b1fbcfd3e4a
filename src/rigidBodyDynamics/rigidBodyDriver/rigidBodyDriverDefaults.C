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
#include "uniformDimensionedFields.H"
#include "keywordTable.H"

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
