#include "Rx.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Rx, 0);
    addToRunTimeSelectionTable(joint, Rx, dictionary);
    addRigidBodyKeywords(joint, Rx);
}
}
}


Foam::RBD::joints::Rx::Rx()
:
    Ra(vector(1, 0, 0))
{}


Foam::RBD::joints::Rx::Rx(const dictionary&)
:
    Ra(vector(1, 0, 0))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Rx::clone() const
{
    return autoPtr<joint>(new Rx(*this));
}


void Foam::RBD::joints::Rx::write(Ostream& os) const
{
    joint::write(os);
}
