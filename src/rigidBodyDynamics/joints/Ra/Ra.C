#include "Ra.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Ra, 0);
    addToRunTimeSelectionTable(joint, Ra, dictionary);
}
}
}


Foam::RBD::joints::Ra::Ra(const vector& axis)
:
    joint(1),
    axis_(axis/mag(axis))
{}


Foam::RBD::joints::Ra::Ra(const dictionary& dict)
:
    joint(1),
    axis_(readAxis(dict, "axis"))
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Ra::clone() const
{
    return autoPtr<joint>(new Ra(*this));
}


void Foam::RBD::joints::Ra::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    J.X = spatialTransform(Foam::Ra(axis_, q[qIndex_]), Zero);
    J.S[0] = spatialVector(axis_, Zero);
    J.v = qDot[qIndex_]*J.S[0];
    J.c = Zero;
}


void Foam::RBD::joints::Ra::write(Ostream& os) const
{
    joint::write(os);
    os.writeEntry("axis", axis_);
}
