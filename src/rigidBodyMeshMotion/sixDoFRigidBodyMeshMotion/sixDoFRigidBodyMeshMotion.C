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

#include "sixDoFRigidBodyMeshMotion.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(sixDoFRigidBodyMeshMotion, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        sixDoFRigidBodyMeshMotion,
        dictionary
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::RBD::sixDoFConverter Foam::sixDoFRigidBodyMeshMotion::converter
(
    const polyMesh& mesh,
    const dictionary& dict
)
{
    Info<< "sixDoFRigidBodyMotion: the rigid-body dynamics project's"
        << " librigidBodyMeshMotion (not OpenFOAM's libsixDoFRigidBodyMotion)"
        << endl;

    RBD::sixDoFConverter c(dict);
    if (isFile(mesh.time().constantPath()/"g"))
    {
        c.useConstantG();
    }
    c.summary(Info);
    Info<< endl;
    return c;
}


Foam::dictionary Foam::sixDoFRigidBodyMeshMotion::rigidBodyCoeffs() const
{
    return converter(mesh(), *this).coeffs();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sixDoFRigidBodyMeshMotion::sixDoFRigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const RBD::sixDoFConverter& converter
)
:
    rigidBodyMeshMotion
    (
        mesh,
        dict,
        typeName,
        converter.coeffs(),
        converter.restartState(mesh.time())
    )
{}


Foam::sixDoFRigidBodyMeshMotion::sixDoFRigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    sixDoFRigidBodyMeshMotion(mesh, dict, converter(mesh, dict))
{}


// ************************************************************************* //
