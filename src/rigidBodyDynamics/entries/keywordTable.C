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

#include "keywordTable.H"
#include "IOstreams.H"
#include "DynamicList.H"
#include "HashSet.H"
#include <algorithm>
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::HashTable<Foam::HashTable<Foam::wordList>>&
Foam::RBD::keywordTable::table()
{
    // Built on first use: registrations run at static initialisation, in
    // any order of the translation units
    static HashTable<HashTable<wordList>> t;
    return t;
}


Foam::RBD::keywordTable::add::add
(
    const char* family,
    const char* type,
    std::initializer_list<const char*> keywords
)
{
    wordList& list = table()(family)(type);
    for (const char* k : keywords)
    {
        list.append(word(k));
    }
}


bool Foam::RBD::keywordTable::found(const word& family, const word& type)
{
    const auto f = table().cfind(family);
    return f.found() && f().found(type);
}


Foam::wordList Foam::RBD::keywordTable::keywords
(
    const word& family,
    const word& type
)
{
    wordList list;
    const auto f = table().cfind(family);
    if (f.found())
    {
        for (const word& t : {word::null, type})
        {
            const auto k = f().cfind(t);
            if (k.found())
            {
                list.append(k());
            }
        }
    }
    return list;
}


Foam::wordList Foam::RBD::keywordTable::keywords(const word& family)
{
    wordList list;
    const auto f = table().cfind(family);
    if (f.found())
    {
        forAllConstIters(f(), iter)
        {
            list.append(iter.val());
        }
    }
    return list;
}


Foam::wordList Foam::RBD::keywordTable::types(const word& family)
{
    wordList list;
    const auto f = table().cfind(family);
    if (f.found())
    {
        for (const word& t : f().sortedToc())
        {
            if (!t.empty())
            {
                list.append(t);
            }
        }
    }
    return list;
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::RBD::editDistance
(
    const std::string& a,
    const std::string& b
)
{
    const size_t n = a.size(), m = b.size();
    std::vector<std::vector<label>> d(n + 1, std::vector<label>(m + 1, 0));
    for (size_t i = 0; i <= n; ++i)
    {
        d[i][0] = label(i);
    }
    for (size_t j = 0; j <= m; ++j)
    {
        d[0][j] = label(j);
    }
    for (size_t i = 1; i <= n; ++i)
    {
        for (size_t j = 1; j <= m; ++j)
        {
            const label cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min
            (
                {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost}
            );
            if
            (
                i > 1 && j > 1
             && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]
            )
            {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}


Foam::word Foam::RBD::nearKeyword
(
    const word& key,
    const wordList& candidates
)
{
    word best;
    label bestD = labelMax;
    for (const word& c : candidates)
    {
        if (c == key || c.size() < 4 || key.size() < 4)
        {
            continue;
        }

        // The keyword switched off by digits after it (bodies0)
        if
        (
            key.size() > c.size() && key.compare(0, c.size(), c) == 0
         && std::all_of
            (
                key.begin() + c.size(), key.end(),
                [](const char ch){ return std::isdigit(ch); }
            )
        )
        {
            continue;
        }

        const label allowed = std::min(c.size(), key.size()) >= 8 ? 2 : 1;
        const label d = editDistance(key, c);
        if (d <= allowed && d < bestD)
        {
            best = c;
            bestD = d;
        }
    }
    return best;
}


void Foam::RBD::checkEntries
(
    const dictionary& dict,
    const wordList& read,
    const wordList& candidates,
    const std::string& where
)
{
    DynamicList<word> unread;
    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();
        if (key.isPattern() || read.found(key) || key == "FoamFile")
        {
            continue;
        }

        const word near(nearKeyword(key, candidates));
        if (near.size())
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                e.isDict() ? e.dict().name() : dict.name(),
                e.startLineNumber(), e.endLineNumber()
            )   << "Entry " << key << " in " << where.c_str() << ": did you"
                << " mean " << near << "?" << nl
                << "    An entry that is not read is ignored: misspelt, its"
                << " default would be used without a word." << nl
                << "    The entries read here:";
            for (const word& k : wordHashSet(read).sortedToc())
            {
                FatalIOError<< ' ' << k;
            }
            FatalIOError<< nl << exit(FatalIOError);
        }

        unread.append(key);
    }

    if (unread.size())
    {
        Info<< "rigidBodyMotion: entries not read in " << where.c_str()
            << " (" << dict.name() << "):";
        for (const word& k : unread)
        {
            Info<< ' ' << k;
        }
        Info<< endl;
    }
}


namespace
{

//- The keywords of type in family, with the mesh motion's of meshType if
//  given; the candidates: every type's
void levelKeywords
(
    const Foam::word& family,
    const Foam::word& type,
    const Foam::word& meshType,
    Foam::wordList& read,
    Foam::wordList& candidates
)
{
    using namespace Foam::RBD;
    read = keywordTable::keywords(family, type);
    candidates = keywordTable::keywords(family);
    if (meshType.size())
    {
        read.append(keywordTable::keywords("meshMotion", meshType));
        candidates.append(keywordTable::keywords("meshMotion", meshType));
    }
}


//- Check a dictionary of family whose type is its entry type
void checkTyped
(
    const Foam::dictionary& dict,
    const Foam::word& family,
    const Foam::word& meshType,
    const std::string& where
)
{
    using namespace Foam;
    const word type(dict.getOrDefault<word>("type", word::null));
    wordList read, candidates;
    levelKeywords(family, type, meshType, read, candidates);
    RBD::checkEntries(dict, read, candidates, where);
}


//- Check a joint dictionary and, for a composite, each of its joints
void checkJoint(const Foam::dictionary& dict, const std::string& where)
{
    using namespace Foam;
    checkTyped(dict, "joint", word::null, where);

    if (dict.getOrDefault<word>("type", word::null) == "composite")
    {
        const List<dictionary> joints
        (
            dict.getOrDefault<List<dictionary>>("joints", List<dictionary>())
        );
        forAll(joints, i)
        {
            checkJoint
            (
                joints[i],
                where + ", its joint " + std::to_string(i)
            );
        }
    }
}

} // End anonymous namespace


void Foam::RBD::checkHasBodies(const dictionary& dict)
{
    if (dict.found("bodies"))
    {
        return;
    }

    if (dict.found("sixDoFRigidBodyMotionCoeffs"))
    {
        FatalIOErrorInFunction(dict.subDict("sixDoFRigidBodyMotionCoeffs"))
            << "This case gives sixDoFRigidBodyMotionCoeffs: the entries of"
            << " OpenFOAM's sixDoFRigidBodyMotion solver (one body, its"
            << " constraints and restraints)." << nl
            << "    The rigidBodyMotion solver reads rigidBodyMotionCoeffs"
            << " instead: bodies with joints, restraints and a solver."
            << nl << "    To run the sixDoF dictionary as the model it maps"
            << " to, give motionSolver sixDoFRigidBodyMotion; rigidBodySim"
            << " -report prints that model's rigidBodyMotionCoeffs." << nl
            << "    How to move a sixDoFRigidBodyMotion case across,"
            << " entry by entry: docs/coming-from-stock.md of the"
            << " rigid-body dynamics project" << nl
            << exit(FatalIOError);
    }

    const wordList names({"bodies", "rigidBodyMotionCoeffs"});
    for (const entry& e : dict)
    {
        const word near(nearKeyword(e.keyword(), names));
        if (near.size())
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, dict.name(),
                e.startLineNumber(), e.endLineNumber()
            )   << "Entry " << e.keyword() << " in " << dict.name()
                << ": did you mean " << near << "?" << nl
                << "    The rigid-body model's bodies are read from"
                << " rigidBodyMotionCoeffs { bodies {...} }, or from bodies"
                << " at the top level" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::RBD::checkMotionEntries(const dictionary& coeffs)
{
    {
        wordList read, candidates;
        levelKeywords
        (
            "coefficients", word::null, "coefficients", read, candidates
        );
        const word coupling
        (
            coeffs.getOrDefault<word>("accelerationRelaxationType", "constant")
        );
        read.append(keywordTable::keywords("coupling", coupling));
        candidates.append(keywordTable::keywords("coupling"));
        checkEntries(coeffs, read, candidates, "the motion's coefficients");
    }

    const dictionary* bodies = coeffs.findDict("bodies");
    if (bodies)
    {
        for (const entry& e : *bodies)
        {
            if (!e.isDict())
            {
                continue;
            }
            const std::string where("body " + e.keyword());
            checkTyped(e.dict(), "body", "body", where);

            const dictionary* joint = e.dict().findDict("joint");
            if (joint)
            {
                checkJoint(*joint, "the joint of " + where);
            }
        }
    }

    const dictionary* restraints = coeffs.findDict("restraints");
    if (restraints)
    {
        for (const entry& e : *restraints)
        {
            if (e.isDict())
            {
                checkTyped
                (
                    e.dict(), "restraint", word::null,
                    "restraint " + e.keyword()
                );
            }
        }
    }

    const dictionary* solver = coeffs.findDict("solver");
    if (solver)
    {
        checkTyped(*solver, "solver", word::null, "the solver");
    }
}


// ************************************************************************* //
