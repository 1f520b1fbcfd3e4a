#include "Rz.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Rz, 0);
    addToRunTimeSelectionTable(joint, Rz, dictionary);
    addRigidBodyKeywords(joint, Rz);
}
}
}


Foam::RBD::joints::Rz::Rz()
:
    Ra(vector(0, 0, 1))
{}


Foam::RBD::joints::Rz::Rz(const dictionary&)
:
    Ra(vector(0, 0, 1))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Rz::clone() const
{
    return autoPtr<joint>(new Rz(*this));
}


void Foam::RBD::joints::Rz::write(Ostream& os) const
{
    joint::write(os);
}
