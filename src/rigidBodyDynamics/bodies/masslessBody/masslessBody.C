#include "masslessBody.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(masslessBody, 0);
    addToRunTimeSelectionTable(rigidBody, masslessBody, dictionary);
    addRigidBodyKeywords(body, masslessBody);
}
}


Foam::RBD::masslessBody::masslessBody(const word& name)
:
    rigidBody(name, rigidBodyInertia())
{}


Foam::RBD::masslessBody::masslessBody(const word& name, const dictionary&)
:
    rigidBody(name, rigidBodyInertia())
{}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::masslessBody::clone() const
{
    return autoPtr<rigidBody>(new masslessBody(*this));
}


void Foam::RBD::masslessBody::write(Ostream& os) const
{
    os.writeEntry("type", type());
}
