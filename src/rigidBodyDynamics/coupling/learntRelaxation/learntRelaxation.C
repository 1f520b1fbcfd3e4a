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

#include "learntRelaxation.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::learntRelaxation::learntRelaxation(const label n)
:
    forgetting_(0.95),
    Sxd_(n, Zero),
    Sxx_(n, Zero),
    weight_(0),
    nSolves_(0),
    xPrev_(n, Zero),
    dPrev_(n, Zero),
    omega_(n, 1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::learntRelaxation::relax
(
    const scalarField& aGiven,
    const scalarField& d,
    scalarField& x,
    const bool firstSolve
)
{
    if (firstSolve)
    {
        nSolves_ = 0;
    }
    ++nSolves_;

    // The pair of this solve and the previous one, from the third on
    if (nSolves_ >= 4)
    {
        forAll(d, i)
        {
            const scalar dx = aGiven[i] - xPrev_[i];
            Sxd_[i] = forgetting_*Sxd_[i] + dx*(d[i] - dPrev_[i]);
            Sxx_[i] = forgetting_*Sxx_[i] + dx*dx;
        }
        weight_ = forgetting_*weight_ + 1;

        if (weight_ >= 3)
        {
            forAll(omega_, i)
            {
                if (Sxx_[i] > VSMALL && Sxd_[i] < 0)
                {
                    omega_[i] = min(max(-Sxx_[i]/Sxd_[i], 0.25), 2.5);
                }
                else
                {
                    omega_[i] = 1;
                }
            }
        }
    }
    xPrev_ = aGiven;
    dPrev_ = d;

    forAll(x, i)
    {
        x[i] = aGiven[i] + (nSolves_ >= 3 ? omega_[i] : 1)*d[i];
    }
}


// ************************************************************************* //
