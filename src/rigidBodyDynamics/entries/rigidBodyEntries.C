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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Read a scalar entry; FatalIOError unless finite and above zero (or at
//  least zero)
Foam::scalar readBounded
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const bool zeroAllowed
)
{
    using namespace Foam;

    const scalar v = dict.get<scalar>(key);

    if (!std::isfinite(v) || v < 0 || (!zeroAllowed && v == 0))
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << ' ' << v << " in " << dict.dictName()
            << " must be " << (zeroAllowed ? "non-negative" : "positive")
            << nl << exit(FatalIOError);
    }

    return v;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::RBD::readPositive(const dictionary& dict, const word& key)
{
    return readBounded(dict, key, false);
}


Foam::scalar Foam::RBD::readNonNegative
(
    const dictionary& dict,
    const word& key
)
{
    return readBounded(dict, key, true);
}


Foam::vector Foam::RBD::readAxis(const dictionary& dict, const word& key)
{
    const vector a(dict.get<vector>(key));
    const scalar magA = mag(a);

    if (!(magA > VSMALL) || !std::isfinite(magA))
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << ' ' << a << " in " << dict.dictName()
            << " must be a non-zero vector" << nl
            << exit(FatalIOError);
    }

    return a/magA;
}


const Foam::entry& Foam::RBD::function1Entry
(
    const dictionary& dict,
    const word& key
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " in " << dict.dictName()
            << ": No Function1 dictionary entry: " << key << nl << nl << nl
            << exit(FatalIOError);
    }
    return *e;
}


Foam::word Foam::RBD::function1Type(const entry& e)
{
    if (e.isDict())
    {
        return e.dict().getOrDefault<word>("type", word::null);
    }

    ITstream& is = e.stream();
    const token first(is);
    is.rewind();
    return first.isWord() ? first.wordToken() : word::null;
}


const Foam::dictionary& Foam::RBD::function1Coeffs
(
    const dictionary& dict,
    const entry& e
)
{
    return
        e.isDict()
      ? e.dict()
      : dict.optionalSubDict(word(e.keyword() + "Coeffs"));
}
