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

#include "constant.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(couplingScheme, constant, dictionary);
    addRigidBodyKeywords(coupling, constant);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::constant::constant
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::constant::correct
(
    const rigidBodyModelState&,
    const scalarField& aGiven,
    scalarField& a,
    const bool
)
{
    const scalar omega = relaxation_;

    forAll(a, i)
    {
        a[i] = omega*a[i] + (1 - omega)*aGiven[i];
    }
}
