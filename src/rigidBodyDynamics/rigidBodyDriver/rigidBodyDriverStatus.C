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

    // The body's prescribed rotations: rate, prescription, motor moment
    const labelList& prescribing = motion_.prescribing();
    forAll(prescribing, s)
    {
        const RBD::restraint& r = motion_.restraints()[prescribing[s]];
        if (r.bodyID() == bodyID)
        {
            const rateConstraint& c = motion_.prescriptions()[s];
            if (c.dof >= 0)
            {
                Info<< "    Prescribed motion " << r.name() << ": q "
                    << motion_.state().q()[c.dof] << " (prescribed "
                    << c.position << "), qDot "
                    << motion_.state().qDot()[c.dof] << " (prescribed "
                    << c.rate << "), driving force " << c.moment << endl;
                continue;
            }
            Info<< "    Prescribed rotation " << r.name() << ": omega "
                << (c.axis & vCofR.w()) << " rad/s about " << c.axis
                << " (prescribed " << c.rate << "), motor moment "
                << c.moment << " N m" << endl;
        }
    }
}
