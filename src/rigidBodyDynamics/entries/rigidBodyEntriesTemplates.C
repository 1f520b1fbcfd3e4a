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

#include "rigidBodyEntries.H"
#include "fileOperation.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::RBD::checkTable
(
    const dictionary& dict,
    const word& key,
    const List<Tuple2<scalar, Type>>& table
)
{
    if (table.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " in " << dict.dictName()
            << ": Table for entry " << key << " is invalid (empty)" << nl << nl
            << exit(FatalIOError);
    }

    for (label i = 1; i < table.size(); ++i)
    {
        if (table[i].first() <= table[i - 1].first())
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << key << " in " << dict.dictName()
                << ": out-of-order value: " << table[i].first()
                << " at index " << i << nl << nl
                << exit(FatalIOError);
        }
    }
}


template<class Type>
Foam::autoPtr<Foam::Function1<Type>> Foam::RBD::readFunction1
(
    const dictionary& dict,
    const word& key
)
{
    const entry& e = function1Entry(dict, key);
    const word type(function1Type(e));
    const auto& types = *Function1<Type>::dictionaryConstructorTablePtr_;

    if (type.size() && !types.found(type))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " in " << dict.dictName()
            << ": Unknown Function1 type " << type << " for " << key
            << nl << nl << "Valid Function1 types :" << nl
            << types.sortedToc() << nl << nl
            << exit(FatalIOError);
    }

    if (type == "table")
    {
        // The entry's own stream: the type, then the points
        ITstream& is = (e.isDict() ? e.dict() : dict).lookup(key);
        const word tableType(is);
        checkTable(dict, key, List<Tuple2<scalar, Type>>(is));
    }
    else if (type == "tableFile")
    {
        const fileName file
        (
            function1Coeffs(dict, e).get<fileName>("file").expand()
        );
        autoPtr<ISstream> isPtr(fileHandler().NewIFstream(file));
        if (!isPtr->good())
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << key << " in " << dict.dictName()
                << ": Cannot open file." << nl
                << exit(FatalIOError);
        }
        checkTable(dict, key, List<Tuple2<scalar, Type>>(isPtr()));
    }

    return Function1<Type>::New(key, dict);
}


// ************************************************************************* //
