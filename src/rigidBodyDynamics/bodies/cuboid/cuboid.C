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

#include "cuboid.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(cuboid, 0);
    addToRunTimeSelectionTable(rigidBody, cuboid, dictionary);
    addRigidBodyKeywords(body, cuboid, "L", "mass", "centreOfMass");
}
}


Foam::RBD::cuboid::cuboid(const word& name, const dictionary& dict)
:
    rigidBody(name, rigidBodyInertia()),
    L_(dict.get<vector>("L"))
{
    if (!(cmptMin(L_) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << name << ": edge lengths L " << L_
            << " must all be positive" << nl
            << exit(FatalIOError);
    }

    const scalar m = readPositive(dict, "mass");
    const vector L2(cmptMultiply(L_, L_));

    setInertia
    (
        rigidBodyInertia
        (
            m,
            dict.get<vector>("centreOfMass"),
            (m/12.0)
           *symmTensor
            (
                L2.y() + L2.z(), 0, 0,
                L2.x() + L2.z(), 0,
                L2.x() + L2.y()
            )
        )
    );
}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::cuboid::clone() const
{
    return autoPtr<rigidBody>(new cuboid(*this));
}


void Foam::RBD::cuboid::write(Ostream& os) const
{
    os.writeEntry("type", type());
    os.writeEntry("mass", m());
    os.writeEntry("L", L_);
    os.writeEntry("centreOfMass", c());
}
