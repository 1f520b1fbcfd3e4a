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

#include "joint.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(joint, 0);
    defineRunTimeSelectionTable(joint, dictionary);
    addRigidBodyCommonKeywords(joint, Joint, "type");
}
}


Foam::RBD::joint::joint(const label nDoF)
:
    nDoF_(nDoF),
    qIndex_(0),
    unitColumn_(-1)
{}


Foam::label Foam::RBD::joint::coordinateAxis(const vector& axis)
{
    for (direction k = 0; k < 3; ++k)
    {
        if
        (
            axis[k] == 1
         && axis[(k + 1) % 3] == 0
         && axis[(k + 2) % 3] == 0
        )
        {
            return k;
        }
    }
    return -1;
}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joint::New(const dictionary& dict)
{
    const word jointType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(jointType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "joint",
            jointType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


void Foam::RBD::joint::expand(PtrList<joint>& joints) const
{
    joints.append(clone().ptr());
}


void Foam::RBD::joint::integrate
(
    scalarField& q,
    const scalarField& q0,
    const scalarField& dq
) const
{
    for (label i = qIndex_; i < qIndex_ + nDoF_; ++i)
    {
        q[i] = q0[i] + dq[i];
    }
}


void Foam::RBD::joint::write(Ostream& os) const
{
    os.writeEntry("type", type());
}
