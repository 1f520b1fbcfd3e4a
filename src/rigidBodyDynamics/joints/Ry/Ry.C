#include "Ry.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Ry, 0);
    addToRunTimeSelectionTable(joint, Ry, dictionary);
    addRigidBodyKeywords(joint, Ry);
}
}
}


Foam::RBD::joints::Ry::Ry()
:
    Ra(vector(0, 1, 0))
{}


Foam::RBD::joints::Ry::Ry(const dictionary&)
:
    Ra(vector(0, 1, 0))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Ry::clone() const
{
    return autoPtr<joint>(new Ry(*this));
}


void Foam::RBD::joints::Ry::write(Ostream& os) const
{
    joint::write(os);
}
