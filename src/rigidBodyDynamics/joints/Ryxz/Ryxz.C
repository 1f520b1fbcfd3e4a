#include "Ryxz.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Ryxz, 0);
    addToRunTimeSelectionTable(joint, Ryxz, dictionary);
    addRigidBodyKeywords(joint, Ryxz);
}
}
}


Foam::RBD::joints::Ryxz::Ryxz()
:
    euler(1, 0, 2)
{}


Foam::RBD::joints::Ryxz::Ryxz(const dictionary&)
:
    euler(1, 0, 2)
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Ryxz::clone() const
{
    return autoPtr<joint>(new Ryxz(*this));
}
