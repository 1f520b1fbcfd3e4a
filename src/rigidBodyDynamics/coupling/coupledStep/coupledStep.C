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
    start_(startAccelerations::known),
    timeIndex_(-1),
    nCorrectors_(0),
    nSolves_(0),
    atWriteTime_(false),
    residual_(GREAT)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::RBD::coupledStep::isNew(const label timeIndex) const
{
    return
        timeIndex != timeIndex_
     || stage_ == stage::initial
     || stage_ == stage::failed;
}


Foam::scalar Foam::RBD::coupledStep::pimpleResidual() const
{
    // PIMPLE's residualControl ends the correctors, from the 2nd on, at the
    // first check that passes, and then runs one more.  The step's 1st
    // solve has the previous step's forces: never converged.  Its 2nd has
    // those of the fluid's 1st corrector, whose own fields have not
    // converged, so the next corrector can still move the forces by more
    // than the residual says: its residual counts twice, a margin that
    // keeps PIMPLE from stopping on a residual that only looks small.  So
    // a step takes 3 correctors at least
    if (nCorrectors_ <= 1)
    {
        return GREAT;
    }
    if (nCorrectors_ == 2)
    {
        return 2*residual_;
    }
    return residual_;
}


void Foam::RBD::coupledStep::begin(const label timeIndex)
{
    stage_ = stage::begun;
    start_ = startAccelerations::known;
    timeIndex_ = timeIndex;
    nCorrectors_ = 0;
    nSolves_ = 0;
    atWriteTime_ = false;
    residual_ = GREAT;
}


void Foam::RBD::coupledStep::corrector(const bool writeTime)
{
    ++nCorrectors_;
    atWriteTime_ = writeTime;

    // On every processor, where only the master solves
    stage_ = stage::solving;
}


void Foam::RBD::coupledStep::solved()
{
    ++nSolves_;
    stage_ = stage::solving;
}


void Foam::RBD::coupledStep::startProvisional()
{
    start_ = startAccelerations::provisional;
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
    timeIndex_ = -1;
}


void Foam::RBD::coupledStep::end()
{
    stage_ = stage::ended;
}
