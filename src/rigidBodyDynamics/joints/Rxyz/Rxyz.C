#include "Rxyz.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Rxyz, 0);
    addToRunTimeSelectionTable(joint, Rxyz, dictionary);
    addRigidBodyKeywords(joint, Rxyz);
}
}
}


Foam::RBD::joints::Rxyz::Rxyz()
:
    euler(0, 1, 2)
{}


Foam::RBD::joints::Rxyz::Rxyz(const dictionary&)
:
    euler(0, 1, 2)
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Rxyz::clone() const
{
    return autoPtr<joint>(new Rxyz(*this));
}
