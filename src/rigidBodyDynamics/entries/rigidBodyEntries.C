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
