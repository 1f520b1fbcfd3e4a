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

#include "secantAcceleration.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::scalar dotFields(const Foam::scalarField& a, const Foam::scalarField& b)
{
    Foam::scalar s = 0;
    forAll(a, i)
    {
        s += a[i]*b[i];
    }
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::secantAcceleration::secantAcceleration
(
    const scalarField& length,
    const label reuse
)
:
    length_(length),
    reuse_(reuse),
    V_(8*length.size() + 8, scalarField(length.size(), Zero)),
    W_(V_.size(), scalarField(length.size(), Zero)),
    stepOf_(V_.size(), -1),
    next_(0),
    nColumns_(0),
    step_(-1),
    nSolves_(0),
    rPrev_(length.size(), Zero),
    tPrev_(length.size(), Zero),
    Q_(length.size(), scalarField(length.size(), Zero)),
    R_(length.size(), Zero),
    kept_(length.size(), -1),
    r_(length.size(), Zero),
    c_(length.size(), Zero),
    q_(length.size(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::secantAcceleration::accelerate
(
    const scalarField& aGiven,
    const scalarField& t,
    scalarField& x,
    const bool firstSolve
)
{
    const label n = length_.size();
    const label capacity = V_.size();

    if (firstSolve)
    {
        ++step_;
        nSolves_ = 0;
    }

    forAll(r_, i)
    {
        r_[i] = length_[i]*(t[i] - aGiven[i]);
    }
    x = t;

    if (firstSolve)
    {
        return;
    }

    // The secant of this solve and the previous one of the step
    if (nSolves_ > 0)
    {
        forAll(r_, i)
        {
            V_[next_][i] = r_[i] - rPrev_[i];
            W_[next_][i] = t[i] - tPrev_[i];
        }
        stepOf_[next_] = step_;
        next_ = (next_ + 1) % capacity;
        nColumns_ = min(nColumns_ + 1, capacity);
    }
    rPrev_ = r_;
    tPrev_ = t;
    ++nSolves_;

    // Modified Gram-Schmidt, newest column first, over the columns of this
    // step and the reuse steps before
    label m = 0;
    for (label j = 0; j < nColumns_ && m < n; ++j)
    {
        const label col = (next_ - 1 - j + capacity) % capacity;
        if (stepOf_[col] < step_ - reuse_)
        {
            break;
        }

        q_ = V_[col];
        const scalar norm0 = sqrt(dotFields(q_, q_));
        if (norm0 <= VSMALL)
        {
            continue;
        }
        for (label p = 0; p < m; ++p)
        {
            R_(p, m) = dotFields(Q_[p], q_);
            forAll(q_, i)
            {
                q_[i] -= R_(p, m)*Q_[p][i];
            }
        }
        const scalar norm = sqrt(dotFields(q_, q_));
        if (norm < 0.01*norm0)
        {
            continue;
        }
        R_(m, m) = norm;
        forAll(q_, i)
        {
            Q_[m][i] = q_[i]/norm;
        }
        kept_[m] = col;
        ++m;
    }

    if (m == 0)
    {
        return;
    }

    // R c = -Q^T r
    for (label p = m - 1; p >= 0; --p)
    {
        scalar s = -dotFields(Q_[p], r_);
        for (label k = p + 1; k < m; ++k)
        {
            s -= R_(p, k)*c_[k];
        }
        c_[p] = s/R_(p, p);
    }

    // W c, at most twice the scheme's own step
    q_ = Zero;
    for (label p = 0; p < m; ++p)
    {
        forAll(q_, i)
        {
            q_[i] += c_[p]*W_[kept_[p]][i];
        }
    }
    scalar dx2 = 0;
    forAll(q_, i)
    {
        dx2 += sqr(length_[i]*q_[i]);
    }
    const scalar limit = 2*sqrt(dotFields(r_, r_));
    const scalar f = dx2 > sqr(limit) ? limit/sqrt(dx2) : 1;
    forAll(x, i)
    {
        x[i] = t[i] + f*q_[i];
    }
}


// ************************************************************************* //
