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
-------------------------------------------------------------------------------
Description
    The joint-space mass matrix by the composite-rigid-body algorithm,
    after Featherstone, Rigid Body Dynamics Algorithms (2008), table 6.2.
\*---------------------------------------------------------------------------*/

#include "rigidBodyModel.H"
#include "spatialKernels.H"

using namespace Foam::RBD::spatialKernels;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyModel::massMatrix
(
    const rigidBodyModelState& state,
    rigidBodyModelWorkspace& ws,
    scalarSquareMatrix& H
) const
{
    kinematics(state, ws);

    const label nb = nBodies();

    H = Zero;

    // Composite inertias, leaves to root
    for (label i = 1; i < nb; ++i)
    {
        ws.IA[i] = I_[i];
    }
    for (label i = nb - 1; i > 0; --i)
    {
        const label p = lambda_[i];
        if (p)
        {
            ws.IA[i].transformAddTo
            (
                ws.Xlambda[i],
                ws.IA[p],
                XlambdaRotation(i)
            );
        }
    }

    for (label i = 1; i < nb; ++i)
    {
        const joint::XSvc& Ji = ws.J[i];
        const label qi = joints_[i].qIndex();

        for (label k = 0; k < joints_[i].nDoF(); ++k)
        {
            spatialVector F(ws.IA[i] & Ji.S[k]);

            for (label l = 0; l < joints_[i].nDoF(); ++l)
            {
                H(qi + l, qi + k) = Ji.S[l] && F;
            }

            label j = i;
            while (lambda_[j])
            {
                F = ws.Xlambda[j].T() & F;
                j = lambda_[j];

                const label qj = joints_[j].qIndex();
                for (label l = 0; l < joints_[j].nDoF(); ++l)
                {
                    H(qj + l, qi + k) = ws.J[j].S[l] && F;
                    H(qi + k, qj + l) = H(qj + l, qi + k);
                }
            }
        }
    }
}


// ************************************************************************* //
