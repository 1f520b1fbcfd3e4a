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

#include "sixDoFConverter.H"
#include "rigidBodyEntries.H"
#include "rigidBodyModel.H"
#include "keywordTable.H"
#include "spatialTransform.H"
#include "IOstream.H"

// * * * * * * * * * * * * * * * * Keywords  * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    // The sixDoFRigidBodyMotion keywords, in the library's keyword table
    // (keywordTable.H), each list once: of the coefficients, those mapped,
    // those copied as they are, those kept for the mesh motion (at the top
    // level and in the body's entry), those read and not used, and the
    // dynamicMeshDict's own (the coefficients at its top level); each
    // constraint's, each restraint's (sixDoFConverterRestraints.C) and each
    // solver's
    addRigidBodyKeywords
    (
        sixDoF, mapped,
        "mass", "momentOfInertia", "centreOfMass", "initialCentreOfMass",
        "orientation", "initialOrientation", "centreOfRotation", "velocity",
        "angularMomentum", "solver", "restraints", "constraints"
    );
    addRigidBodyKeywords
    (
        sixDoF, copied,
        "accelerationRelaxation", "accelerationDamping", "report", "g"
    );
    addRigidBodyKeywords(sixDoF, kept, "rho", "rhoInf", "test");
    addRigidBodyKeywords
    (
        sixDoF, body, "patches", "innerDistance", "outerDistance"
    );
    addRigidBodyKeywords
    (
        sixDoF, notUsed,
        "CofGvelocity", "cellZone", "cellSet", "acceleration", "torque"
    );
    addRigidBodyKeywords
    (
        sixDoF, meshDict,
        "dynamicFvMesh", "dynamicFvMeshLibs", "motionSolver",
        "motionSolverLibs", "updateControl", "updateInterval",
        "sixDoFRigidBodyMotionCoeffs", "rigidBodyMotionCoeffs"
    );

    addRigidBodyCommonKeywords
    (
        sixDoFConstraint, Constraint, "sixDoFRigidBodyMotionConstraint"
    );
    addRigidBodyKeywords(sixDoFConstraint, axis, "axis");
    addRigidBodyKeywords
    (
        sixDoFConstraint, line, "direction", "centreOfRotation"
    );
    addRigidBodyKeywords(sixDoFConstraint, plane, "normal", "centreOfRotation");
    addRigidBodyKeywords(sixDoFConstraint, point, "centreOfRotation");
    addRigidBodyKeywords
    (
        sixDoFConstraint, orientation, "sixDoFRigidBodyMotionConstraint"
    );

    addRigidBodyCommonKeywords(sixDoFSolver, Solver, "type");
    addRigidBodyKeywords(sixDoFSolver, Newmark, "gamma", "beta");
    addRigidBodyKeywords(sixDoFSolver, CrankNicolson, "aoc", "voc");
    addRigidBodyKeywords(sixDoFSolver, symplectic, "type");
}
}

const Foam::word Foam::RBD::sixDoFConverter::bodyName("body");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// The keywords that the converter registers as type of family sixDoF
wordList sixDoFKeywords(const char* type)
{
    return RBD::keywordTable::keywords("sixDoF", type);
}

// A FatalIOError at dict if value, of its state entry key, is not initial
// (which names it): the coefficients' state is the initial one, where the
// mesh's points are; a restart's is read from its own file
template<class Type>
void checkInitial
(
    const dictionary& dict,
    const word& key,
    const Type& value,
    const Type& initial,
    const char* which
)
{
    if (mag(value - initial) > 1e-12*max(mag(initial), 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << ' ' << value << " (the state's) is not "
            << which << ' ' << initial << ": the coefficients give the"
            << " initial state, where the mesh's points are; a restart's"
            << " state is read from <time>/uniform/"
            << "sixDoFRigidBodyMotionState" << nl
            << exit(FatalIOError);
    }
}

// The joint along unit vector d: X (Px, Rx) along a global axis, else the
// general type (Pa, Ra) with d as its axis
dictionary axisJoint(const char prefix, const vector& d)
{
    dictionary j;
    const char* names = "xyz";
    for (direction i = 0; i < 3; ++i)
    {
        vector e(Zero);
        e[i] = 1;
        if (mag(d - e) < 1e-12)
        {
            j.add("type", word(std::string(1, prefix) + names[i]));
            return j;
        }
    }
    j.add("type", word(std::string(1, prefix) + 'a'));
    j.add("axis", d);
    return j;
}

// Two orthonormal vectors in the plane of unit normal n: the other two
// global axes, in order, if n is along one
void inPlane(const vector& n, vector& e1, vector& e2)
{
    for (direction a = 0; a < 3; ++a)
    {
        if (mag(n[a]) > 1 - 1e-12)
        {
            e1 = Zero;
            e2 = Zero;
            e1[a == 0 ? 1 : 0] = 1;
            e2[a == 2 ? 1 : 2] = 1;
            return;
        }
    }

    // Else across n and the global axis least along it
    direction k = 0;
    for (direction i = 1; i < 3; ++i)
    {
        if (mag(n[i]) < mag(n[k]))
        {
            k = i;
        }
    }
    vector ek(Zero);
    ek[k] = 1;
    e1 = n ^ ek;
    e1 /= mag(e1);
    e2 = n ^ e1;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::sixDoFConverter::unknownType
(
    const dictionary& dict,
    const char* what,
    const word& type,
    const word& family
)
{
    FatalIOErrorInFunction(dict)
        << "Unknown " << what << " type " << type << nl << nl
        << "Valid " << what << " types :" << nl
        << keywordTable::types(family) << nl
        << exit(FatalIOError);
}


void Foam::RBD::sixDoFConverter::readBody()
{
    mass_ = readPositive(dict_, "mass");

    J_ = dict_.get<diagTensor>("momentOfInertia");
    for (direction i = 0; i < 3; ++i)
    {
        const scalar Ji = J_[i];
        if (!(Ji > 0) || !std::isfinite(Ji))
        {
            FatalIOErrorInFunction(dict_.lookup("momentOfInertia"))
                << "Entry momentOfInertia " << J_ << ": the principal"
                << " moments of inertia about the centre of mass must be"
                << " finite and positive" << nl
                << exit(FatalIOError);
        }
    }

    const word cofmKey
    (
        dict_.found("initialCentreOfMass")
      ? "initialCentreOfMass" : "centreOfMass"
    );
    CofM_ = dict_.get<point>(cofmKey);

    const word qKey
    (
        dict_.found("initialOrientation") ? "initialOrientation" : "orientation"
    );
    Q0_ = checkRotation
    (
        dict_,
        qKey,
        dict_.getOrDefault<tensor>(qKey, tensor::I)
    );
}


void Foam::RBD::sixDoFConverter::readConstraints()
{
    CofR_ = CofM_;
    if (!dict_.found("constraints"))
    {
        return;
    }

    const dictionary& cs = dict_.subDict("constraints");
    for (const entry& e : cs)
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& c = e.dict();
        const word type(c.get<word>("sixDoFRigidBodyMotionConstraint"));

        const word family("sixDoFConstraint");
        if (!keywordTable::found(family, type))
        {
            unknownType(c, "constraint", type, family);
        }
        const wordList read(keywordTable::keywords(family, type));
        checkEntries(c, read, read, "constraint " + e.keyword());

        if (type == "axis")
        {
            rotation_.combine
            (
                pointConstraint(Tuple2<label, vector>(2, readAxis(c, "axis")))
            );
        }
        else if (type == "orientation")
        {
            rotation_.combine(pointConstraint(Tuple2<label, vector>(3, Zero)));
        }
        else
        {
            CofR_ = c.getOrDefault<point>("centreOfRotation", CofM_);
            if (type == "line")
            {
                translation_.combine
                (
                    pointConstraint
                    (
                        Tuple2<label, vector>(2, readAxis(c, "direction"))
                    )
                );
            }
            else if (type == "plane")
            {
                // As sixDoF: the normal as given (its length matters to
                // pointConstraint's test of parallel planes)
                const vector n(c.get<vector>("normal"));
                if (!(mag(n) > VSMALL))
                {
                    FatalIOErrorInFunction(c.lookup("normal"))
                        << "Entry normal " << n << " of plane constraint "
                        << e.keyword() << " has zero length" << nl
                        << exit(FatalIOError);
                }
                translation_.applyConstraint(n);
            }
            else
            {
                translation_.combine
                (
                    pointConstraint(Tuple2<label, vector>(3, Zero))
                );
            }
        }

    }
}


Foam::dictionary Foam::RBD::sixDoFConverter::joint()
{
    List<vector>& P = P_;
    List<vector>& R = R_;

    List<dictionary> parts;

    // Translation: free, in a plane, on a line, fixed
    if (translation_.first() == 0)
    {
        parts.append(dictionary());
        parts.last().add("type", "Pxyz");
        P = List<vector>({vector(1, 0, 0), vector(0, 1, 0), vector(0, 0, 1)});
    }
    else if (translation_.first() == 1)
    {
        vector e1, e2;
        inPlane(translation_.second()/mag(translation_.second()), e1, e2);
        parts.append(axisJoint('P', e1));
        parts.append(axisJoint('P', e2));
        P = List<vector>({e1, e2});
    }
    else if (translation_.first() == 2)
    {
        parts.append(axisJoint('P', translation_.second()));
        P = List<vector>({translation_.second()});
    }

    // Rotation: free, about an axis of the principal axes, fixed
    if (rotation_.first() == 0)
    {
        parts.append(dictionary());
        parts.last().add("type", "Rs");
        R = List<vector>({vector(1, 0, 0), vector(0, 1, 0), vector(0, 0, 1)});
    }
    else if (rotation_.first() == 2)
    {
        vector a(Q0_ & rotation_.second());
        a /= mag(a);
        parts.append(axisJoint('R', a));
        R = List<vector>({a});
    }
    else if (rotation_.first() != 3)
    {
        FatalErrorInFunction
            << "Rotational constraint of count " << rotation_.first()
            << ": axis and orientation constraints make 0, 2 or 3" << nl
            << abort(FatalError);
    }

    if (parts.empty())
    {
        dictionary j;
        j.add("type", "null");
        return j;
    }
    if (parts.size() == 1)
    {
        return parts.first();
    }
    dictionary j;
    j.add("type", "composite");
    j.add("joints", parts);
    return j;
}


Foam::dictionary Foam::RBD::sixDoFConverter::body
(
    const dictionary& jointDict
) const
{
    const tensor J
    (
        J_.xx(), 0, 0,
        0, J_.yy(), 0,
        0, 0, J_.zz()
    );

    dictionary b;
    b.add("type", "rigidBody");
    b.add("parent", "root");
    b.add("mass", mass_);
    b.add("centreOfMass", CofM_ - CofR_);
    b.add("inertia", symm(Q0_ & J & Q0_.T()));
    b.add("transform", spatialTransform(tensor::I, CofR_));
    b.add("joint", jointDict);
    for (const word& key : sixDoFKeywords("body"))
    {
        if (dict_.found(key))
        {
            b.add(dict_.lookupEntry(key, keyType::LITERAL));
        }
    }
    return b;
}


Foam::dictionary Foam::RBD::sixDoFConverter::solver() const
{
    const dictionary& s = dict_.subDict("solver");
    const word type(s.get<word>("type"));

    const word family("sixDoFSolver");
    if (!keywordTable::found(family, type))
    {
        unknownType(s, "sixDoF solver", type, family);
    }
    const wordList read(keywordTable::keywords(family, type));
    checkEntries(s, read, read, "solver");

    dictionary d(s);
    if (type == "Newmark")
    {
        // sixDoF raises beta to keep the scheme unconditionally stable
        const scalar gamma = s.getOrDefault<scalar>("gamma", 0.5);
        const scalar beta = s.getOrDefault<scalar>("beta", 0.25);
        const scalar betaMin = 0.25*sqr(gamma + 0.5);
        if (beta < betaMin)
        {
            Info<< "sixDoFRigidBodyMotion: Newmark beta " << beta
                << " raised to (gamma + 1/2)^2/4 = " << betaMin
                << ", as sixDoF raises it" << nl << endl;
            d.set("beta", betaMin);
        }
    }
    return d;
}


void Foam::RBD::sixDoFConverter::copyEntries()
{
    for (const char* type : {"copied", "kept"})
    {
        for (const word& key : sixDoFKeywords(type))
        {
            if (dict_.found(key))
            {
                coeffs_.add(dict_.lookupEntry(key, keyType::LITERAL));
            }
        }
    }
    for (const word& key : sixDoFKeywords("notUsed"))
    {
        if (dict_.found(key))
        {
            notUsed_.append(key);
        }
    }
}


void Foam::RBD::sixDoFConverter::checkInitialState() const
{
    // sixDoF's state: centreOfRotation (default centreOfMass), orientation
    // (default I) and centreOfMass (which it requires); its initial ones:
    // the constraints' centre of rotation, initialOrientation and
    // initialCentreOfMass (defaults orientation and centreOfMass).  Apart,
    // they are a restart's state
    if (dict_.found("centreOfRotation"))
    {
        checkInitial
        (
            dict_, "centreOfRotation", dict_.get<point>("centreOfRotation"),
            CofR_,
            "the initial centre of rotation (the last line, plane or point"
            " constraint's, else the centre of mass)"
        );
    }
    if (dict_.found("initialOrientation"))
    {
        // As given: Q0_ is the nearest rotation to it
        checkInitial
        (
            dict_, "orientation",
            dict_.getOrDefault<tensor>("orientation", tensor::I),
            dict_.get<tensor>("initialOrientation"),
            "initialOrientation"
        );
    }
    checkInitial
    (
        dict_, "centreOfMass", dict_.get<point>("centreOfMass"), CofM_,
        "initialCentreOfMass"
    );
}


void Foam::RBD::sixDoFConverter::checkUnread() const
{
    const wordList read(keywordTable::keywords("sixDoF"));
    checkEntries(dict_, read, read, "the sixDoFRigidBodyMotion coefficients");

    for (const char* key : {"constraints", "restraints"})
    {
        if (!dict_.found(key))
        {
            continue;
        }
        // Non-dictionary entries: sixDoF skips them
        const dictionary& d = dict_.subDict(key);
        wordList dicts;
        for (const entry& e : d)
        {
            if (e.isDict())
            {
                dicts.append(e.keyword());
            }
        }
        checkEntries(d, dicts, wordList(), key);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::sixDoFConverter::sixDoFConverter(const dictionary& meshDict)
:
    dict_(meshDict.optionalSubDict("sixDoFRigidBodyMotionCoeffs")),
    mass_(0),
    CofM_(Zero),
    J_(Zero),
    Q0_(tensor::I),
    CofR_(Zero),
    coeffs_(dict_.name()),
    constantG_(false)
{
    const fullPrecision precision;

    // A misspelt entry is named before a missing one is looked for
    checkUnread();
    readBody();
    readConstraints();
    checkInitialState();

    const dictionary jointDict(joint());

    dictionary bodies;
    bodies.add(bodyName, body(jointDict));
    coeffs_.add("bodies", bodies);
    coeffs_.add("restraints", restraints());
    coeffs_.add("solver", solver());
    coeffs_.add("q", scalarField(P_.size() + R_.size(), Zero));
    coeffs_.add
    (
        "qDot",
        rates(dict_, "velocity", "angularMomentum", true)
    );
    copyEntries();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::RBD::sixDoFConverter::isSixDoF(const dictionary& meshDict)
{
    const word sixDoF("sixDoFRigidBodyMotion");
    for (const char* key : {"motionSolver", "solver"})
    {
        const entry* e = meshDict.findEntry(key, keyType::LITERAL);
        if (e && e->isStream())
        {
            const ITstream& is = e->stream();
            return is.size() && is[0].isWord() && is[0].wordToken() == sixDoF;
        }
    }
    return
        meshDict.found("sixDoFRigidBodyMotionCoeffs")
     && !meshDict.found("rigidBodyMotionCoeffs")
     && !meshDict.found("bodies");
}
