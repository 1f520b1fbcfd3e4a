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

#include "rigidBodyDriver.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyDriver::reportCoupling()
{
    if (!externalForces_)
    {
        return;
    }

    const scalar t = motion_.state().t();
    if (!residual_.endStep(motion_.state().qDdot(), t))
    {
        return;
    }

    Info<< "rigidBodyMotion: coupling of the step to t = " << t << ": "
        << motion_.nSolves() << " solves, " << motion_.coupling().type()
        << ", residual";
    forAll(tables_.names(), bi)
    {
        label dof = -1;
        const scalar r = residual_.largest(tables_.dofs(bi), dof);
        if (dof >= 0)
        {
            Info<< ' ' << tables_.names()[bi] << ' ' << r;
        }
    }
    Info<< endl;

    forAll(tables_.names(), bi)
    {
        label dof = -1;
        const scalar r = residual_.largest(tables_.dofs(bi), dof);
        if (dof >= 0 && r > residual_.tolerance())
        {
            Info<< "rigidBodyMotion: coupling not converged at t = " << t
                << ": body " << tables_.names()[bi] << ", " << model().dofDescription(dof).c_str()
                << (residual_.rotation(dof) ? ", rotation" : ", translation")
                << ": residual " << r << " > couplingTolerance "
                << residual_.tolerance() << endl;
        }
    }
}


void Foam::RBD::rigidBodyDriver::reportFloors() const
{
    if (!externalForces_)
    {
        return;
    }

    Info<< "rigidBodyMotion: coupling residual's floors (below them a body"
        << " counts as at rest):" << nl;
    forAll(tables_.names(), bi)
    {
        for (const label i : tables_.dofs(bi))
        {
            Info<< "    " << model().dofDescription(i).c_str() << ' '
                << residual_.floors()[i];
            if (residual_.rotation(i))
            {
                Info<< " rad/s^2 (radius of gyration "
                    << residual_.gyrations()[i] << " m)";
            }
            else
            {
                Info<< " m/s^2";
            }
            Info<< nl;
        }
    }
    Info<< endl;
}


void Foam::RBD::rigidBodyDriver::reportSummary() const
{
    if (!externalForces_ || residual_.nSteps() == 0)
    {
        return;
    }

    Info<< "rigidBodyMotion: coupling summary: " << residual_.nFlagged()
        << " of " << residual_.nSteps() << " steps not converged"
        << " (couplingTolerance " << residual_.tolerance() << ")";
    if (residual_.worstDoF() >= 0)
    {
        Info<< "; the largest residual " << residual_.worst() << " at t = "
            << residual_.worstTime() << ", "
            << model().dofDescription(residual_.worstDoF()).c_str();
    }
    Info<< endl;
    if (residual_.nFlagged())
    {
        Info<< "rigidBodyMotion: the motion of the flagged steps is not the"
            << " coupled answer: give more outer correctors, or let PIMPLE's"
            << " residualControl run them on demand (rigidBodyMotion entry)"
            << endl;
    }
}
