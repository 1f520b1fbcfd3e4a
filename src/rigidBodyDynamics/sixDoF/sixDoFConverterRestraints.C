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

// * * * * * * * * * * * * * * * * Keywords  * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
    // Each mapped sixDoF restraint's keywords (keywordTable.H)
    addRigidBodyCommonKeywords
    (
        sixDoFRestraint, Restraint, "sixDoFRigidBodyMotionRestraint"
    );
    addRigidBodyKeywords
    (
        sixDoFRestraint, linearSpring,
        "anchor", "refAttachmentPt", "stiffness", "damping", "restLength"
    );
    addRigidBodyKeywords(sixDoFRestraint, linearDamper, "coeff");
    addRigidBodyKeywords(sixDoFRestraint, sphericalAngularDamper, "coeff");
    addRigidBodyKeywords
    (
        sixDoFRestraint, linearAxialAngularSpring,
        "axis", "stiffness", "damping", "referenceOrientation"
    );
    addRigidBodyKeywords
    (
        sixDoFRestraint, sphericalAngularSpring,
        "stiffness", "damping", "referenceOrientation"
    );
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
// The sixDoF restraints not mapped yet
const Foam::wordList notSupported
({
    "tabulatedAxialAngularSpring", "linearSpringDamper"
});

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::RBD::sixDoFConverter::restraint
(
    const word& name,
    const dictionary& r
) const
{
    const word type(r.get<word>("sixDoFRigidBodyMotionRestraint"));
    const word family("sixDoFRestraint");

    if (notSupported.found(type))
    {
        FatalIOErrorInFunction(r)
            << "Restraint " << name << ": sixDoFRigidBodyMotionRestraint "
            << type << " is not supported yet.  Supported: "
            << keywordTable::types(family) << nl
            << exit(FatalIOError);
    }
    if (!keywordTable::found(family, type))
    {
        unknownType(r, "restraint", type, family);
    }
    const wordList read(keywordTable::keywords(family, type));
    checkEntries(r, read, read, "restraint " + name);

    dictionary d;
    d.add("type", type);
    d.add("body", bodyName);

    if (type == "linearSpring")
    {
        d.add("anchor", r.get<point>("anchor"));
        d.add("refAttachmentPt", r.get<point>("refAttachmentPt") - CofR_);
        d.add("stiffness", readNonNegative(r, "stiffness"));
        d.add("damping", readNonNegative(r, "damping"));
        d.add("restLength", readNonNegative(r, "restLength"));
    }
    else if
    (
        type == "linearAxialAngularSpring" || type == "sphericalAngularSpring"
    )
    {
        const tensor refQ
        (
            checkRotation
            (
                r,
                "referenceOrientation",
                r.getOrDefault<tensor>("referenceOrientation", tensor::I)
            )
        );
        d.add("referenceOrientation", Q0_ & refQ.T());
        if (type == "linearAxialAngularSpring")
        {
            d.add("axis", readAxis(r, "axis"));
        }
        else
        {
            // sixDoF's spring turns the principal axes
            d.add("axes", Q0_);
        }
        d.add("stiffness", readNonNegative(r, "stiffness"));
        d.add("damping", readNonNegative(r, "damping"));
    }
    else
    {
        d.add("coeff", readNonNegative(r, "coeff"));
    }
    return d;
}


Foam::dictionary Foam::RBD::sixDoFConverter::restraints() const
{
    dictionary d;
    if (dict_.found("restraints"))
    {
        for (const entry& e : dict_.subDict("restraints"))
        {
            if (e.isDict())
            {
                d.add(e.keyword(), restraint(e.keyword(), e.dict()));
            }
        }
    }
    return d;
}
