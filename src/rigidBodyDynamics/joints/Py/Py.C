#include "Py.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Py, 0);
    addToRunTimeSelectionTable(joint, Py, dictionary);
    addRigidBodyKeywords(joint, Py);
}
}
}


Foam::RBD::joints::Py::Py()
:
    Pa(vector(0, 1, 0))
{}


Foam::RBD::joints::Py::Py(const dictionary&)
:
    Pa(vector(0, 1, 0))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Py::clone() const
{
    return autoPtr<joint>(new Py(*this));
}


void Foam::RBD::joints::Py::write(Ostream& os) const
{
    joint::write(os);
}
