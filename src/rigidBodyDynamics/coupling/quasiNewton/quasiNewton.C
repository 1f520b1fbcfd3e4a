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

#include "quasiNewton.H"
#include "denseLinearAlgebra.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(quasiNewton, 0);
    addToRunTimeSelectionTable(couplingScheme, quasiNewton, dictionary);
    addRigidBodyKeywords(coupling, quasiNewton);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::quasiNewton::quasiNewton
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model),
    Jinv_(model.nDoF(), Zero),
    aGivenPrev_(model.nDoF(), Zero),
    rPrev_(model.nDoF(), Zero),
    da_(model.nDoF(), Zero),
    dr_(model.nDoF(), Zero),
    JinvDr_(model.nDoF(), Zero)
{
    resetJacobian();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::couplingSchemes::quasiNewton::resetJacobian()
{
    Jinv_ = Zero;
    for (label i = 0; i < Jinv_.m(); ++i)
    {
        Jinv_(i, i) = -relaxation_;
    }
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::quasiNewton::correct
(
    const rigidBodyModelState&,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    const label n = Jinv_.m();

    // The residual, and the changes since the previous solve; the norm
    // weighs rotations by their lengths squared, as translations, so that
    // Broyden's update is the same at any Froude scale
    scalar dr2 = 0;
    forAll(a, i)
    {
        const scalar r = a[i] - aGiven[i];
        da_[i] = aGiven[i] - aGivenPrev_[i];
        dr_[i] = r - rPrev_[i];
        dr2 += weight_[i]*sqr(dr_[i]);
        aGivenPrev_[i] = aGiven[i];
        rPrev_[i] = r;
    }

    // Broyden's inverse update from the previous solve of the step
    if (!firstSolve && dr2 > VSMALL)
    {
        matrixVector(Jinv_, dr_, JinvDr_);

        bool valid = true;
        for (label i = 0; i < n; ++i)
        {
            const scalar c = (da_[i] - JinvDr_[i])/dr2;
            for (label j = 0; j < n; ++j)
            {
                Jinv_(i, j) += c*weight_[j]*dr_[j];
            }
            // Each degree of freedom is relaxed by a factor in (0, 2)
            valid = valid && -Jinv_(i, i) > 0.005 && -Jinv_(i, i) < 2;
        }

        if (!valid)
        {
            resetJacobian();
        }
    }

    // a = aGiven - Jinv r, JinvDr_ the scratch for Jinv r
    matrixVector(Jinv_, rPrev_, JinvDr_);
    forAll(a, i)
    {
        a[i] = aGiven[i] - JinvDr_[i];
    }
}
