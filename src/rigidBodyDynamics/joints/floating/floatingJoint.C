#include "floatingJoint.H"
#include "Pxyz.H"
#include "Rzyx.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(floating, 0);
    addToRunTimeSelectionTable(joint, floating, dictionary);
    addRigidBodyKeywords(joint, floating);
}
}
}


namespace
{
    Foam::PtrList<Foam::RBD::joint> PxyzRzyx()
    {
        Foam::PtrList<Foam::RBD::joint> joints(2);
        joints.set(0, new Foam::RBD::joints::Pxyz());
        joints.set(1, new Foam::RBD::joints::Rzyx());
        return joints;
    }
}


Foam::RBD::joints::floating::floating(const dictionary&)
:
    composite(PxyzRzyx())
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::floating::clone() const
{
    return autoPtr<joint>(new floating(*this));
}


void Foam::RBD::joints::floating::write(Ostream& os) const
{
    joint::write(os);
}
