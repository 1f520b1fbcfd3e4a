#include "Pz.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Pz, 0);
    addToRunTimeSelectionTable(joint, Pz, dictionary);
    addRigidBodyKeywords(joint, Pz);
}
}
}


Foam::RBD::joints::Pz::Pz()
:
    Pa(vector(0, 0, 1))
{}


Foam::RBD::joints::Pz::Pz(const dictionary&)
:
    Pa(vector(0, 0, 1))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Pz::clone() const
{
    return autoPtr<joint>(new Pz(*this));
}


void Foam::RBD::joints::Pz::write(Ostream& os) const
{
    joint::write(os);
}
