#include "subBody.H"

Foam::RBD::subBody::subBody
(
    autoPtr<rigidBody> body,
    const word& masterName,
    const label masterID,
    const spatialTransform& masterXT
)
:
    body_(std::move(body)),
    masterName_(masterName),
    masterID_(masterID),
    masterXT_(masterXT)
{}


Foam::RBD::subBody::subBody(const subBody& sb)
:
    body_(sb.body_->clone()),
    masterName_(sb.masterName_),
    masterID_(sb.masterID_),
    masterXT_(sb.masterXT_)
{}
