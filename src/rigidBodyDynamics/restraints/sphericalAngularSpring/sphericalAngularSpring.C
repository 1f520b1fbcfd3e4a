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

#include "sphericalAngularSpring.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(sphericalAngularSpring, 0);
    addToRunTimeSelectionTable(restraint, sphericalAngularSpring, dictionary);
    addRigidBodyKeywords
    (
        restraint, sphericalAngularSpring, "referenceOrientation", "axes",
        "stiffness", "damping"
    );
}
}
}


Foam::RBD::restraints::sphericalAngularSpring::sphericalAngularSpring
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    restraint(name, dict, model)
{
    read(dict);
}


void Foam::RBD::restraints::sphericalAngularSpring::restrain
(
    scalarField&,
    Field<spatialVector>& fx,
    const rigidBodyModelState&,
    const rigidBodyModelWorkspace& ws
) const
{
    // The spring's axes at rest and now (columns, global), and the turn
    // from the one to the other in the axes at rest
    const tensor A(refQ_.T() & axes_);
    const tensor B(model_.X0(bodyID_, ws).E().T() & axes_);
    const tensor C(A.T() & B);

    addMoment
    (
        fx,
        -stiffness_*(A & vector(C.zy(), C.xz(), C.yx()))
      - damping_*model_.v(bodyID_, Zero, ws).w()
    );
}


bool Foam::RBD::restraints::sphericalAngularSpring::read
(
    const dictionary& dict
)
{
    restraint::read(dict);

    refQ_ = checkRotation
    (
        dict,
        "referenceOrientation",
        dict.getOrDefault<tensor>("referenceOrientation", tensor::I)
    );
    axes_ = checkRotation
    (
        dict,
        "axes",
        dict.getOrDefault<tensor>("axes", tensor::I)
    );
    stiffness_ = readNonNegative(dict, "stiffness");
    damping_ = readNonNegative(dict, "damping");

    return true;
}


void Foam::RBD::restraints::sphericalAngularSpring::write(Ostream& os) const
{
    restraint::write(os);
    os.writeEntry("referenceOrientation", refQ_);
    os.writeEntry("axes", axes_);
    os.writeEntry("stiffness", stiffness_);
    os.writeEntry("damping", damping_);
}
