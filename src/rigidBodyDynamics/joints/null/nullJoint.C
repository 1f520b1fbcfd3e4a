#include "nullJoint.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(null, 0);
    addToRunTimeSelectionTable(joint, null, dictionary);
    addRigidBodyKeywords(joint, null);
}
}
}


Foam::RBD::joints::null::null()
:
    joint(0)
{}


Foam::RBD::joints::null::null(const dictionary&)
:
    joint(0)
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::null::clone() const
{
    return autoPtr<joint>(new null(*this));
}


void Foam::RBD::joints::null::jcalc
(
    XSvc& J,
    const scalarField&,
    const scalarField&
) const
{
    J.X = spatialTransform();
    J.v = Zero;
    J.c = Zero;
}
