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

// The fluid's forces on the bodies, and its added mass for the coupling
// schemes that use it

#include "rigidBodyMeshMotion.H"
#include "volFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidBodyMeshMotion::fluidForces()
{
    fx_ = Zero;

    if (test_)
    {
        return;
    }

    if (forces_.empty())
    {
        if
        (
            rhoName_ != "rhoInf"
         && !mesh().foundObject<volScalarField>(rhoName_)
        )
        {
            FatalIOErrorInFunction(coeffs_.lookup("rho"))
                << "Entry rho " << rhoName_ << ": no such density field;"
                << " give the name of one or, for a fluid of constant"
                << " density, rho rhoInf with rhoInf" << nl
                << "Fields: "
                << mesh().sortedNames<volScalarField>() << nl
                << exit(FatalIOError);
        }

        forces_.setSize(bodyMeshes_.size());
        forAll(bodyMeshes_, bi)
        {
            dictionary forcesDict;
            forcesDict.add("type", functionObjects::forces::typeName);
            forcesDict.add("patches", bodyMeshes_[bi].patches);
            forcesDict.add("rho", rhoName_);
            forcesDict.add("rhoInf", rhoInf_);
            forcesDict.add("CofR", vector::zero);
            forcesDict.add("log", false);

            forces_.set
            (
                bi,
                new functionObjects::forces
                (
                    "rigidBodyMotion:" + bodyMeshes_[bi].name,
                    mesh(),
                    forcesDict
                )
            );
        }
    }

    // Scaled as gravity is, by the ramp
    const scalar ramp = driver_.motion().ramp(mesh().time().value());

    forAll(bodyMeshes_, bi)
    {
        functionObjects::forces& f = forces_[bi];
        f.calcForcesMoment();
        fx_[driver_.model().masterID(bodyMeshes_[bi].bodyID)] +=
            ramp*spatialVector(f.momentEff(), f.forceEff());
    }
}


void Foam::rigidBodyMeshMotion::giveAddedMass()
{
    // At the first solve of a step (and at the first after read())
    if
    (
        test_
     || !driver_.motion().coupling().usesFluidAddedMass()
     || (
            addedMass_.valid()
         && !driver_.beginsStep()
        )
    )
    {
        return;
    }

    if (!addedMass_.valid())
    {
        labelList bodyIDs(bodyMeshes_.size());
        List<labelHashSet> patches(bodyMeshes_.size());
        forAll(bodyMeshes_, bi)
        {
            bodyIDs[bi] = bodyMeshes_[bi].bodyID;
            patches[bi] = bodyMeshes_[bi].patchSet;
        }

        addedMass_.reset
        (
            new Foam::fluidAddedMass
            (
                refCast<const fvMesh>(mesh()),
                rhoName_,
                rhoInf_,
                driver_.model(),
                driver_.motion().state(),
                bodyIDs,
                patches
            )
        );
    }

    // Given again when recomputed, or when the ramp has changed it
    const scalar ramp = driver_.motion().ramp(mesh().time().value());
    if
    (
        !addedMass_->update(driver_.model(), driver_.motion().state())
     && ramp == addedMassRamp_
    )
    {
        return;
    }
    addedMassRamp_ = ramp;

    // Scaled as the fluid's forces are, by the ramp
    scalarSquareMatrix A(addedMass_->A());
    A *= ramp;

    if (driver_.report())
    {
        Info<< "rigidBodyMotion: the fluid's added mass in joint space "
            << A << endl;
    }

    driver_.motion().setFluidAddedMass(A);
}
