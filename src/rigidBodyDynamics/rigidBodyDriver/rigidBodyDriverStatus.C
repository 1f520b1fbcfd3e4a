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

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyDriver::status(const label bodyID)
{
    floatingPointTraps traps;
    const spatialTransform CofR(motion_.X0(bodyID));
    const spatialVector vCofR(motion_.v(bodyID, Zero));

    check(failure_.status(motion_, bodyID, CofR, vCofR));

    Info<< "Rigid-body motion of the " << model().name(bodyID) << nl
        << "    Centre of rotation: " << CofR.r() << nl
        << "    Orientation: " << CofR.E() << nl
        << "    Linear velocity: " << vCofR.l() << nl
        << "    Angular velocity: " << vCofR.w()
        << endl;

    // The body's prescriptions: a line each
    forAll(motion_.prescribing(), s)
    {
        if (motion_.prescribing()[s].bodyID() == bodyID)
        {
            motion_.prescriptions()[s].writeStatus(motion_.state(), vCofR);
        }
    }
}
