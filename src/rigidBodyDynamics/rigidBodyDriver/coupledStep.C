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

#include "coupledStep.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::coupledStep::coupledStep()
:
    stage_(stage::initial),
    timeIndex_(-1),
    nCorrectors_(0),
    nSolves_(0),
    atWriteTime_(false),
    residual_(GREAT)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::coupledStep::begin(const label timeIndex, const bool writeTime)
{
    stage_ = stage::solving;
    timeIndex_ = timeIndex;
    nCorrectors_ = 0;
    nSolves_ = 0;
    atWriteTime_ = writeTime;
    residual_ = GREAT;
}


void Foam::RBD::coupledStep::corrector()
{
    ++nCorrectors_;
}


void Foam::RBD::coupledStep::solved(const label n)
{
    nSolves_ += n;
}


void Foam::RBD::coupledStep::measured(const scalar residual)
{
    residual_ = residual;
}


void Foam::RBD::coupledStep::commit()
{
    stage_ = stage::committed;
}


void Foam::RBD::coupledStep::fail()
{
    stage_ = stage::failed;
}


void Foam::RBD::coupledStep::end()
{
    stage_ = stage::ended;
}
