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

#include "couplingScheme.H"
#include "keywordTable.H"
#include "couplingScales.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(couplingScheme, 0);
    defineRunTimeSelectionTable(couplingScheme, dictionary);
    addRigidBodyCommonKeywords
    (
        coupling, Coupling, "accelerationRelaxationType", "accelerationRelaxation",
        "accelerationDamping"
    );
}
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::RBD::couplingScheme::readFactor
(
    const dictionary& dict,
    const word& key
)
{
    const scalar f = dict.getOrDefault<scalar>(key, 1);

    if (!(f > 0 && f <= 1))
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << ' ' << f << " must be in (0, 1]" << nl
            << exit(FatalIOError);
    }

    return f;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingScheme::couplingScheme
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    model_(model),
    relaxation_(readFactor(dict, "accelerationRelaxation")),
    damping_(readFactor(dict, "accelerationDamping")),
    length_(dofLengths(model)),
    weight_(sqr(length_)),
    distance_(model.nDoF(), Zero)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::RBD::couplingScheme> Foam::RBD::couplingScheme::New
(
    const dictionary& dict,
    const rigidBodyModel& model
)
{
    const word schemeType
    (
        dict.getOrDefault<word>("accelerationRelaxationType", "constant")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(schemeType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "accelerationRelaxationType",
            schemeType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, model);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::couplingScheme::relax
(
    const rigidBodyModelState& state,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    forAll(a, i)
    {
        distance_[i] = a[i] - aGiven[i];
    }

    if (debug)
    {
        Info<< type() << ": given " << aGiven << " new " << a << endl;
    }

    correct(state, aGiven, a, firstSolve);

    forAll(a, i)
    {
        a[i] *= damping_;
    }
}


void Foam::RBD::couplingScheme::write(Ostream& os) const
{
    os.writeEntry("accelerationRelaxationType", type());
    os.writeEntry("accelerationRelaxation", relaxation_);
    os.writeEntry("accelerationDamping", damping_);
}
