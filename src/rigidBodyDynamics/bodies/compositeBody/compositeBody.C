#include "compositeBody.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(compositeBody, 0);
}
}


Foam::RBD::compositeBody::compositeBody(autoPtr<rigidBody> body)
:
    rigidBody(body->name(), *body),
    body_(std::move(body))
{}


Foam::RBD::compositeBody::compositeBody(const compositeBody& cb)
:
    rigidBody(cb),
    body_(cb.body_->clone())
{}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::compositeBody::clone() const
{
    return autoPtr<rigidBody>(new compositeBody(*this));
}


void Foam::RBD::compositeBody::write(Ostream& os) const
{
    body_->write(os);
}
