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

#include "rigidBodyModel.H"
#include "keywordTable.H"
#include "masslessBody.H"
#include "jointBody.H"
#include "compositeBody.H"
#include "nullJoint.H"
#include "quaternion.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(rigidBodyModel, 0);
    addRigidBodyCommonKeywords(coefficients, Model, "bodies", "g");
    addRigidBodyCommonKeywords
    (
        body, Body, "type", "parent", "mergeWith", "transform", "joint"
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::RBD::rigidBodyModel::addBody
(
    const label parentID,
    const spatialTransform& XT,
    autoPtr<joint> jointPtr,
    autoPtr<rigidBody> bodyPtr
)
{
    const label bodyID = bodies_.size();

    jointPtr->setQIndex(nDoF_);
    nDoF_ += jointPtr->nDoF();
    unitQuaternions_ = unitQuaternions_ || jointPtr->unitQuaternion();

    if (!bodyIDs_.insert(bodyPtr->name(), bodyID))
    {
        FatalErrorInFunction
            << "Body name " << bodyPtr->name() << " is used twice (names"
            << " NAME_jointK are taken by the frames of NAME's composite"
            << " joint)" << nl
            << exit(FatalError);
    }
    I_.append(rigidInertia(*bodyPtr));
    givenJoints_.append(nullptr);
    givenParent_.append(parentID);
    givenXT_.append(XT);
    bodies_.append(bodyPtr.ptr());
    joints_.append(jointPtr.ptr());
    lambda_.append(parentID);
    XT_.append(XT);
    XTrotates_.append(XT.E() != tensor::I);
    X0rotates_.append
    (
        parentID >= 0
     && (X0rotates_[parentID] || XlambdaRotation(bodyID) != 3)
    );

    return bodyID;
}


bool Foam::RBD::rigidBodyModel::readBody
(
    const dictionary& bodiesDict,
    const word& name
)
{
    const dictionary& bodyDict = bodiesDict.subDict(name);

    if (hasBody(name))
    {
        FatalIOErrorInFunction(bodyDict)
            << "Body name " << name << " is already taken (names"
            << " NAME_jointK belong to the frames of NAME's"
            << " composite joint)" << nl
            << exit(FatalIOError);
    }

    // With both, the merge wins, as in the stock library (whose
    // own test dictionaries name the same body in both)
    const bool merged = bodyDict.found("mergeWith");
    if
    (
        merged
     && bodyDict.found("parent")
     && bodyDict.get<word>("parent")
     != bodyDict.get<word>("mergeWith")
    )
    {
        IOWarningInFunction(bodyDict)
            << "Body " << name << " has parent "
            << bodyDict.get<word>("parent") << " and mergeWith "
            << bodyDict.get<word>("mergeWith") << ": it is merged"
            << " with " << bodyDict.get<word>("mergeWith")
            << " and parent is ignored, as the stock library does"
            << endl;
    }

    const word parentKey(merged ? "mergeWith" : "parent");
    const word parentName(bodyDict.get<word>(parentKey));

    if (!hasBody(parentName))
    {
        return false;
    }

    spatialTransform XT
    (
        bodyDict.getOrDefault<spatialTransform>
        (
            "transform",
            spatialTransform()
        )
    );
    XT.E() = checkRotation(bodyDict, "transform", XT.E());

    autoPtr<rigidBody> body(rigidBody::New(name, bodyDict));

    if (merged)
    {
        if (bodyDict.found("joint"))
        {
            FatalIOErrorInFunction(bodyDict)
                << "Body " << name << " is merged with "
                << parentName << " and cannot have a joint" << nl
                << exit(FatalIOError);
        }
        if (parentName == "root")
        {
            IOWarningInFunction(bodyDict)
                << "Body " << name << " is merged with root: it"
                << " never moves" << endl;
        }
        merge(bodyID(parentName), XT, std::move(body));
    }
    else
    {
        join
        (
            bodyID(parentName),
            XT,
            joint::New(bodyDict.subDict("joint")),
            std::move(body)
        );
    }

    return true;
}


void Foam::RBD::rigidBodyModel::noParent
(
    const dictionary& bodiesDict,
    const wordList& waiting
) const
{
    const dictionary& bodyDict = bodiesDict.subDict(waiting[0]);
    const word parentKey
    (
        bodyDict.found("mergeWith") ? "mergeWith" : "parent"
    );

    const word parentName(bodyDict.get<word>(parentKey));

    FatalIOErrorInFunction(bodyDict.lookup(parentKey))
        << "Body " << waiting[0] << ": " << parentKey << ' '
        << parentName
        << (
               bodiesDict.found(parentName)
             ? " is a body that never reaches root: the parents"
               " of the waiting bodies form a cycle"
             : " is not a body of the model"
           ) << nl
        << "Bodies: " << bodyNames() << nl
        << "(bodies waiting for a parent: " << waiting << ")" << nl
        << exit(FatalIOError);
}


void Foam::RBD::rigidBodyModel::readModel(const dictionary& dict)
{
    dict.readIfPresent("g", g_);

    const dictionary& bodiesDict = dict.subDict("bodies");

    // Join or merge the bodies once their parent is known, so bodies may be
    // listed in any order
    DynamicList<word> pending(bodiesDict.toc());

    while (pending.size())
    {
        DynamicList<word> waiting;

        for (const word& name : pending)
        {
            if (!readBody(bodiesDict, name))
            {
                waiting.append(name);
            }
        }

        if (waiting.size() == pending.size())
        {
            noParent(bodiesDict, waiting);
        }

        pending.transfer(waiting);
    }

    checkMasses(bodiesDict);
}


void Foam::RBD::rigidBodyModel::checkMasses(const dictionary& dict) const
{
    // Mass of each subtree, leaves first
    scalarField subtreeMass(nBodies(), Zero);
    for (label i = nBodies() - 1; i > 0; --i)
    {
        subtreeMass[i] += bodies_[i].m();
        subtreeMass[lambda_[i]] += subtreeMass[i];
    }

    for (label i = 1; i < nBodies(); ++i)
    {
        if (joints_[i].nDoF() && !(subtreeMass[i] > 0))
        {
            const dictionary& bodyDict =
                dict.found(bodies_[i].name())
              ? dict.subDict(bodies_[i].name())
              : dict;

            FatalIOErrorInFunction(bodyDict)
                << "The " << joints_[i].type() << " joint of body "
                << bodies_[i].name() << " moves no mass: give the body,"
                << " or one carried by it, a mass" << nl
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::tensor Foam::RBD::checkRotation
(
    const dictionary& dict,
    const word& key,
    const tensor& E
)
{
    const scalar err = mag((E & E.T()) - tensor::I);

    if (!(err < 1e-3) || det(E) < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " in " << dict.dictName() << ": " << E
            << " is not a rotation tensor (|E E^T - I| = " << err
            << ", det " << det(E) << ")" << nl
            << exit(FatalIOError);
    }

    if (err > 1e-12)
    {
        // Nearest rotation, through the unit quaternion
        const tensor R(normalize(quaternion(E.T())).R().T());

        if (err > 1e-9)
        {
            IOWarningInFunction(dict)
                << "Entry " << key << " in " << dict.dictName() << ": "
                << E << " is a rotation only to " << err
                << "; using the nearest rotation " << R << endl;
        }
        return R;
    }

    return E;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyModel::rigidBodyModel()
:
    nDoF_(0),
    unitQuaternions_(false),
    g_(Zero)
{
    addBody
    (
        -1,
        spatialTransform(),
        autoPtr<joint>(new joints::null()),
        autoPtr<rigidBody>(new masslessBody("root"))
    );
    findFreeBodies();
}


Foam::RBD::rigidBodyModel::rigidBodyModel(const dictionary& dict)
:
    rigidBodyModel()
{
    readModel(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::RBD::rigidBodyModel::join
(
    const label parentID,
    const spatialTransform& XT,
    autoPtr<joint> jointPtr,
    autoPtr<rigidBody> bodyPtr
)
{
    // Joining to a merged body joins to the body that carries it
    label parent = parentID;
    spatialTransform X(XT);
    if (isMerged(parentID))
    {
        X = XT & mergedBody(parentID).masterXT();
        parent = mergedBody(parentID).masterID();
    }

    PtrList<joint> chain;
    jointPtr->expand(chain);

    if (chain.empty())
    {
        FatalErrorInFunction
            << "Joint " << jointPtr->type() << " of body " << bodyPtr->name()
            << " has no joints" << nl
            << exit(FatalError);
    }

    const word& name = bodyPtr->name();

    for (label k = 0; k < chain.size() - 1; ++k)
    {
        parent = addBody
        (
            parent,
            X,
            autoPtr<joint>(chain.set(k, nullptr)),
            autoPtr<rigidBody>
            (
                new jointBody(name + "_joint" + Foam::name(k))
            )
        );
        X = spatialTransform();
    }

    const label id = addBody
    (
        parent,
        X,
        autoPtr<joint>(chain.set(chain.size() - 1, nullptr)),
        std::move(bodyPtr)
    );

    givenJoints_.set(id, jointPtr.ptr());
    givenParent_[id] = parentID;
    givenXT_[id] = XT;

    findFreeBodies();

    return id;
}


Foam::label Foam::RBD::rigidBodyModel::merge
(
    const label parentID,
    const spatialTransform& XT,
    autoPtr<rigidBody> bodyPtr
)
{
    label master = parentID;
    spatialTransform X(XT);
    if (isMerged(parentID))
    {
        X = XT & mergedBody(parentID).masterXT();
        master = mergedBody(parentID).masterID();
    }

    // Replace the master by a composite body holding the body as read
    if (!isA<compositeBody>(bodies_[master]))
    {
        autoPtr<rigidBody> original(bodies_.set(master, nullptr));
        bodies_.set(master, new compositeBody(std::move(original)));
    }

    rigidBodyInertia I(bodies_[master]);
    I.add(*bodyPtr, X);
    bodies_[master].setInertia(I);
    I_[master] = rigidInertia(I);

    const label id = mergedBodyOffset + mergedBodies_.size();
    bodyIDs_.insert(bodyPtr->name(), id);
    mergedBodies_.append
    (
        new subBody(std::move(bodyPtr), bodies_[master].name(), master, X)
    );

    findFreeBodies();

    return id;
}


bool Foam::RBD::rigidBodyModel::positiveDefinite(const rigidInertia& I)
{
    if (!(I.m() > 0))
    {
        return false;
    }

    // The inertia about the centre of mass (the Schur complement of the
    // mass block), by Sylvester's criterion
    const vector& h = I.h();
    const symmTensor Ic(I.Io() - (magSqr(h)*symmTensor::I - sqr(h))/I.m());
    return
        Ic.xx() > 0
     && Ic.xx()*Ic.yy() - sqr(Ic.xy()) > 0
     && det(Ic) > 0;
}


void Foam::RBD::rigidBodyModel::findFreeBodies()
{
    const label nb = nBodies();

    // Children of each body, counted
    labelList nChildren(nb, Zero);
    for (label i = 1; i < nb; ++i)
    {
        ++nChildren[lambda_[i]];
    }

    freeParent_.setSize(nb);
    freeChild_.setSize(nb);
    freeIinvValid_.setSize(nb);
    freeIinv_.setSize(nb);
    freeParent_ = -1;
    freeChild_ = -1;
    freeIinvValid_ = false;

    for (label i = 1; i < nb; ++i)
    {
        const label p = lambda_[i];
        const rigidInertia& Ip = I_[p];
        if
        (
            p > 0
         && lambda_[p] == 0
         && nChildren[p] == 1
         && joints_[i].rotational()
         && joints_[p].nDoF() == 3
         && joints_[p].unitColumn() == 3
         && Ip.m() == 0
         && Ip.h() == vector::zero
         && Ip.Io() == symmTensor::zero
        )
        {
            freeParent_[i] = p;
            freeChild_[p] = i;

            // With nothing on it, the body's articulated inertia is its own:
            // inverted here, once, if it can be.  While the model is built a
            // body may still be massless, before others are merged into it
            // (this runs again then); one that stays so is inverted at each
            // call, as a body with others on it is
            freeIinvValid_[i] = nChildren[i] == 0 && positiveDefinite(I_[i]);
            if (freeIinvValid_[i])
            {
                freeIinv_[i] = articulatedInertia(I_[i]).inverse();
            }
        }
    }
}


Foam::label Foam::RBD::rigidBodyModel::bodyID(const word& name) const
{
    const auto iter = bodyIDs_.cfind(name);

    if (!iter.found())
    {
        FatalErrorInFunction
            << "No body " << name << " in the model" << nl
            << "Bodies: " << bodyNames() << nl
            << exit(FatalError);
    }

    return *iter;
}


Foam::label Foam::RBD::rigidBodyModel::bodyID
(
    const dictionary& dict,
    const word& key
) const
{
    const word name(dict.get<word>(key));
    const auto iter = bodyIDs_.cfind(name);

    if (!iter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << ' ' << name << " in " << dict.dictName()
            << ": no such body" << nl
            << "Bodies: " << bodyNames() << nl
            << exit(FatalIOError);
    }

    return *iter;
}


Foam::label Foam::RBD::rigidBodyModel::jointAncestor
(
    const label bodyID
) const
{
    label i = lambda_[masterID(bodyID)];
    while (i > 0 && isA<jointBody>(bodies_[i]))
    {
        i = lambda_[i];
    }
    return i;
}


Foam::labelList Foam::RBD::rigidBodyModel::bodyDoFs(const label bodyID) const
{
    // From the body's own joint up through the jointBodies of its composite
    // joint, then reversed into the order of the state
    DynamicList<label> dofs;

    const label ancestor = jointAncestor(bodyID);
    for (label i = masterID(bodyID); i != ancestor; i = lambda_[i])
    {
        const joint& J = joints_[i];
        for (label k = J.nDoF() - 1; k >= 0; --k)
        {
            dofs.append(J.qIndex() + k);
        }
    }

    labelList result(dofs.size());
    forAll(dofs, k)
    {
        result[k] = dofs[dofs.size() - 1 - k];
    }
    return result;
}


Foam::string Foam::RBD::rigidBodyModel::dofDescription(const label i) const
{
    for (const word& name : bodyNames())
    {
        const label id = bodyID(name);
        if (isMerged(id) || !bodyDoFs(id).found(i))
        {
            continue;
        }
        const joint& J = joints()[id];
        const bool composite = bodyDoFs(id).size() > J.nDoF();
        return
            "degree of freedom " + Foam::name(i) + ", of the joint of body "
          + name + " (" + (composite ? word("composite") : J.type()) + ")";
    }
    return "degree of freedom " + Foam::name(i);
}


Foam::wordList Foam::RBD::rigidBodyModel::bodyNames() const
{
    DynamicList<word> names;
    forAll(bodies_, i)
    {
        if (!isA<jointBody>(bodies_[i]))
        {
            names.append(bodies_[i].name());
        }
    }
    forAll(mergedBodies_, i)
    {
        names.append(mergedBodies_[i].name());
    }
    return wordList(std::move(names));
}


const Foam::word& Foam::RBD::rigidBodyModel::name(const label bodyID) const
{
    return isMerged(bodyID) ? mergedBody(bodyID).name() : bodies_[bodyID].name();
}


const Foam::RBD::rigidBodyInertia& Foam::RBD::rigidBodyModel::inertia
(
    const label bodyID
) const
{
    return
        isMerged(bodyID)
      ? static_cast<const rigidBodyInertia&>(mergedBody(bodyID).body())
      : static_cast<const rigidBodyInertia&>(bodies_[bodyID]);
}


Foam::spatialTransform Foam::RBD::rigidBodyModel::X0
(
    const label bodyID,
    const rigidBodyModelWorkspace& ws
) const
{
    updateX0(ws);

    if (isMerged(bodyID))
    {
        const subBody& sb = mergedBody(bodyID);
        return sb.masterXT() & ws.X0[sb.masterID()];
    }
    return ws.X0[bodyID];
}


Foam::spatialVector Foam::RBD::rigidBodyModel::v
(
    const label bodyID,
    const vector& p,
    const rigidBodyModelWorkspace& ws
) const
{
    const label master = masterID(bodyID);
    const vector pm(inMaster(bodyID, p));
    const spatialVector& vb = ws.v[master];
    updateX0(ws);
    const tensor& E = ws.X0[master].E();

    // E^T u, as u E
    return spatialVector(vb.w() & E, (vb.l() + (vb.w() ^ pm)) & E);
}


Foam::vector Foam::RBD::rigidBodyModel::globalPoint
(
    const label bodyID,
    const vector& p,
    const rigidBodyModelWorkspace& ws
) const
{
    updateX0(ws);
    const spatialTransform& X = ws.X0[masterID(bodyID)];

    // E^T u as u E
    return (inMaster(bodyID, p) & X.E()) + X.r();
}


void Foam::RBD::rigidBodyModel::integrate
(
    scalarField& q,
    const scalarField& q0,
    const scalarField& dq
) const
{
    for (label i = 1; i < nBodies(); ++i)
    {
        joints_[i].integrate(q, q0, dq);
    }
}


void Foam::RBD::rigidBodyModel::checkState
(
    const scalarField& q,
    const dictionary& dict
) const
{
    for (label i = 1; i < nBodies(); ++i)
    {
        joints_[i].checkState(q, dict);
    }
}


Foam::scalar Foam::RBD::rigidBodyModel::kineticEnergy
(
    const rigidBodyModelWorkspace& ws
) const
{
    scalar T = 0;
    for (label i = 1; i < nBodies(); ++i)
    {
        T += bodies_[i].kineticEnergy(ws.v[i]);
    }
    return T;
}


Foam::scalar Foam::RBD::rigidBodyModel::potentialEnergy
(
    const rigidBodyModelWorkspace& ws
) const
{
    scalar V = 0;
    for (label i = 1; i < nBodies(); ++i)
    {
        V -= bodies_[i].m()*(g_ & globalPoint(i, bodies_[i].c(), ws));
    }
    return V;
}


void Foam::RBD::rigidBodyModel::write(Ostream& os) const
{
    os.writeEntry("g", g_);

    os.beginBlock("bodies");

    for (label i = 1; i < nBodies(); ++i)
    {
        if (!givenJoints_.set(i))
        {
            continue;
        }
        os.beginBlock(bodies_[i].name());
        bodies_[i].write(os);
        os.writeEntry("parent", name(givenParent_[i]));
        os.writeEntry("transform", givenXT_[i]);
        os.beginBlock("joint");
        givenJoints_[i].write(os);
        os.endBlock();
        os.endBlock();
    }

    forAll(mergedBodies_, i)
    {
        const subBody& sb = mergedBodies_[i];
        os.beginBlock(sb.name());
        sb.body().write(os);
        os.writeEntry("mergeWith", sb.masterName());
        os.writeEntry("transform", sb.masterXT());
        os.endBlock();
    }

    os.endBlock();

}
