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

#include "denseLinearAlgebra.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::RBD::matrixVector
(
    const scalarSquareMatrix& A,
    const UList<scalar>& x,
    UList<scalar>& Ax
)
{
    const label n = A.m();
    for (label i = 0; i < n; ++i)
    {
        scalar s = 0;
        for (label j = 0; j < n; ++j)
        {
            s += A(i, j)*x[j];
        }
        Ax[i] = s;
    }
}


void Foam::RBD::matrixMatrix
(
    const scalarSquareMatrix& A,
    const scalarSquareMatrix& B,
    scalarSquareMatrix& AB
)
{
    const label n = A.m();
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            scalar s = 0;
            for (label k = 0; k < n; ++k)
            {
                s += A(i, k)*B(k, j);
            }
            AB(i, j) = s;
        }
    }
}


Foam::scalar Foam::RBD::quadraticForm
(
    const scalarSquareMatrix& A,
    const UList<scalar>& x
)
{
    const label n = A.m();
    scalar xAx = 0;
    for (label i = 0; i < n; ++i)
    {
        scalar Ax = 0;
        for (label j = 0; j < n; ++j)
        {
            Ax += A(i, j)*x[j];
        }
        xAx += x[i]*Ax;
    }
    return xAx;
}


bool Foam::RBD::choleskyDecompose
(
    const scalarSquareMatrix& M,
    scalarSquareMatrix& L
)
{
    const label n = M.m();

    for (label j = 0; j < n; ++j)
    {
        scalar d = M(j, j);
        for (label k = 0; k < j; ++k)
        {
            d -= sqr(L(j, k));
        }
        if (!(d > 0))
        {
            return false;
        }
        L(j, j) = sqrt(d);

        for (label i = j + 1; i < n; ++i)
        {
            scalar v = M(i, j);
            for (label k = 0; k < j; ++k)
            {
                v -= L(i, k)*L(j, k);
            }
            L(i, j) = v/L(j, j);
        }
    }

    return true;
}


void Foam::RBD::choleskySolve
(
    const scalarSquareMatrix& L,
    const UList<scalar>& b,
    UList<scalar>& x
)
{
    const label n = L.m();

    // L y = b, then L^T x = y
    for (label i = 0; i < n; ++i)
    {
        scalar v = b[i];
        for (label k = 0; k < i; ++k)
        {
            v -= L(i, k)*x[k];
        }
        x[i] = v/L(i, i);
    }
    for (label i = n - 1; i >= 0; --i)
    {
        scalar v = x[i];
        for (label k = i + 1; k < n; ++k)
        {
            v -= L(k, i)*x[k];
        }
        x[i] = v/L(i, i);
    }
}


// ************************************************************************* //
