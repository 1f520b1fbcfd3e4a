#include "jointBody.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(jointBody, 0);
    addToRunTimeSelectionTable(rigidBody, jointBody, dictionary);
    addRigidBodyKeywords(body, jointBody);
}
}


Foam::RBD::jointBody::jointBody(const word& name)
:
    masslessBody(name)
{}


Foam::RBD::jointBody::jointBody(const word& name, const dictionary& dict)
:
    masslessBody(name, dict)
{}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::jointBody::clone() const
{
    return autoPtr<rigidBody>(new jointBody(*this));
}
