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

#include "Aitken.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(Aitken, 0);
    addToRunTimeSelectionTable(couplingScheme, Aitken, dictionary);
    addRigidBodyKeywords(coupling, Aitken);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::Aitken::Aitken
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model),
    omega_(relaxation_),
    rPrev_(model.nDoF(), Zero)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::Aitken::correct
(
    const rigidBodyModelState&,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    // The products weigh rotations by their lengths squared, as
    // translations: the factor is the same at any Froude scale
    scalar rdr = 0, dr2 = 0;
    forAll(a, i)
    {
        const scalar r = a[i] - aGiven[i];
        const scalar dr = r - rPrev_[i];
        rdr += weight_[i]*rPrev_[i]*dr;
        dr2 += weight_[i]*sqr(dr);
        rPrev_[i] = r;
    }

    if (!firstSolve && dr2 > VSMALL)
    {
        omega_ = min(max(-omega_*rdr/dr2, scalar(0.01)), scalar(1));
    }
    else
    {
        omega_ = min(omega_, relaxation_);
    }

    forAll(a, i)
    {
        a[i] = omega_*a[i] + (1 - omega_)*aGiven[i];
    }
}
