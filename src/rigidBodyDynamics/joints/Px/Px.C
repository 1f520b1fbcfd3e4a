#include "Px.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Px, 0);
    addToRunTimeSelectionTable(joint, Px, dictionary);
    addRigidBodyKeywords(joint, Px);
}
}
}


Foam::RBD::joints::Px::Px()
:
    Pa(vector(1, 0, 0))
{}


Foam::RBD::joints::Px::Px(const dictionary&)
:
    Pa(vector(1, 0, 0))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Px::clone() const
{
    return autoPtr<joint>(new Px(*this));
}


void Foam::RBD::joints::Px::write(Ostream& os) const
{
    joint::write(os);
}
