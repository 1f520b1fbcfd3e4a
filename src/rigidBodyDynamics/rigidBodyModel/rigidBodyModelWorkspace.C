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

#include "rigidBodyModelWorkspace.H"
#include "rigidBodyModel.H"

Foam::RBD::rigidBodyModelWorkspace::rigidBodyModelWorkspace
(
    const rigidBodyModel& model
)
:
    X0valid(false)
{
    resize(model);
}


void Foam::RBD::rigidBodyModelWorkspace::resize(const rigidBodyModel& model)
{
    const label n = model.nBodies();

    J.setSize(n);
    Xlambda.setSize(n);
    X0.setSize(n);
    X0 = spatialTransform();    // the root's stays the identity
    X0valid = false;
    v.setSize(n, Zero);
    a.setSize(n, Zero);
    c.setSize(n, Zero);
    IA.setSize(n);
    pA.setSize(n, Zero);
    U.setSize(n);
    Dinv.setSize(n, Zero);
    u.setSize(n, Zero);
    setConstraints(model, nConstraints());
}


void Foam::RBD::rigidBodyModelWorkspace::setConstraints
(
    const rigidBodyModel& model,
    const label nConstraints
)
{
    // Nothing for a model with none
    const label n = nConstraints ? model.nBodies() : 0;
    const label nDoF = nConstraints ? model.nDoF() : 0;

    responseBias.setSize(n, Zero);
    responseJointBias.setSize(n, Zero);
    responseAcceleration.setSize(n, Zero);
    qDot.setSize(nDoF, Zero);
    responseQDdot.setSize(nConstraints);
    for (scalarField& r : responseQDdot)
    {
        r.setSize(nDoF, Zero);
    }
    constraintMatrix.setSize(nConstraints);
    constraintLU.setSize(nConstraints);
    constraintPivots.setSize(nConstraints, 0);
    motorMoments.setSize(nConstraints, Zero);
    tauZero.setSize(nDoF, Zero);
    fxZero.setSize(n, Zero);
    qDdotScratch.setSize(nDoF, Zero);
}
