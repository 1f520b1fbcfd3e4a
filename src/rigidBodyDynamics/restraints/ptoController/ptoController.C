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

#include "ptoController.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(ptoController, 0);
    defineRunTimeSelectionTable(ptoController, dictionary);
}
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::RBD::ptoController> Foam::RBD::ptoController::New
(
    const dictionary& dict
)
{
    const word type(dict.get<word>("type"));

    // No table at all until a library registers a controller
    if
    (
        !dictionaryConstructorTablePtr_
     || !dictionaryConstructorTablePtr_->found(type)
    )
    {
        FatalIOErrorInFunction(dict)
            << "Unknown ptoController type " << type << "; the types loaded: "
            << (
                   dictionaryConstructorTablePtr_
                 ? dictionaryConstructorTablePtr_->sortedToc()
                 : wordList()
               ) << nl
            << "A controller is a class of the user's own library: load it"
            << " with libs (\"libNAME.so\") in system/controlDict" << nl
            << exit(FatalIOError);
    }

    return dictionaryConstructorTablePtr_->cfind(type)()(dict);
}


// ************************************************************************* //
