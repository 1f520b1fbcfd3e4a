#include "jointBody.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(jointBody, 0);
}
}


Foam::RBD::jointBody::jointBody(const word& name)
:
    masslessBody(name)
{}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::jointBody::clone() const
{
    return autoPtr<rigidBody>(new jointBody(*this));
}
