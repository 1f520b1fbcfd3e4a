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

#include "couplingScales.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::boolList Foam::RBD::rotationDoFs(const rigidBodyModel& model)
{
    boolList turns(model.nDoF(), false);
    const scalarField q(model.nDoF(), Zero);
    const scalarField qDot(model.nDoF(), Zero);

    for (const joint& J : model.joints())
    {
        if (J.nDoF() == 0)
        {
            continue;
        }
        joint::XSvc xsvc;
        J.jcalc(xsvc, q, qDot);
        for (label k = 0; k < J.nDoF(); ++k)
        {
            turns[J.qIndex() + k] = mag(xsvc.S[k].w()) > SMALL;
        }
    }

    return turns;
}


Foam::scalarField Foam::RBD::dofLengths(const rigidBodyModel& model)
{
    const label nb = model.nBodies();
    const boolList turns(rotationDoFs(model));

    // Mass carried by each body's joint: its own and its descendants'
    scalarField carried(nb, Zero);
    for (label i = nb - 1; i > 0; --i)
    {
        carried[i] += model.bodies()[i].m();
        if (model.lambda()[i] > 0)
        {
            carried[model.lambda()[i]] += carried[i];
        }
    }

    rigidBodyModelState atRest(model.nDoF());
    rigidBodyModelWorkspace restWorkspace(model);
    scalarSquareMatrix M(model.nDoF(), Zero);
    model.massMatrix(atRest, restWorkspace, M);

    scalarField length(model.nDoF(), 1.0);
    for (label i = 1; i < nb; ++i)
    {
        const joint& J = model.joints()[i];
        for (label k = 0; k < J.nDoF(); ++k)
        {
            const label dof = J.qIndex() + k;
            if (turns[dof] && carried[i] > 0 && M(dof, dof) > 0)
            {
                length[dof] = Foam::sqrt(M(dof, dof)/carried[i]);
            }
        }
    }

    return length;
}
