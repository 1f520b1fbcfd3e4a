#include "Rzyx.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Rzyx, 0);
    addToRunTimeSelectionTable(joint, Rzyx, dictionary);
    addRigidBodyKeywords(joint, Rzyx);
}
}
}


Foam::RBD::joints::Rzyx::Rzyx()
:
    euler(2, 1, 0)
{}


Foam::RBD::joints::Rzyx::Rzyx(const dictionary&)
:
    euler(2, 1, 0)
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Rzyx::clone() const
{
    return autoPtr<joint>(new Rzyx(*this));
}
