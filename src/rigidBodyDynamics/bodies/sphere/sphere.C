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

#include "sphere.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(rigidBody, sphere, dictionary);
    addRigidBodyKeywords(body, sphere, "radius", "mass", "centreOfMass");
}
}



Foam::RBD::sphere::sphere(const word& name, const dictionary& dict)
:
    rigidBody(name, rigidBodyInertia()),
    r_(readPositive(dict, "radius"))
{
    const scalar m = readPositive(dict, "mass");
    setInertia
    (
        rigidBodyInertia
        (
            m,
            dict.get<vector>("centreOfMass"),
            (2.0/5.0)*m*sqr(r_)*symmTensor::I
        )
    );
}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::sphere::clone() const
{
    return autoPtr<rigidBody>(new sphere(*this));
}


void Foam::RBD::sphere::write(Ostream& os) const
{
    os.writeEntry("type", type());
    os.writeEntry("mass", m());
    os.writeEntry("radius", r_);
    os.writeEntry("centreOfMass", c());
}
