#include "Pxyz.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
namespace joints
{
    defineTypeNameAndDebug(Pxyz, 0);
    addToRunTimeSelectionTable(joint, Pxyz, dictionary);
    addRigidBodyKeywords(joint, Pxyz);
}
}
}


Foam::RBD::joints::Pxyz::Pxyz()
:
    joint(3)
{
    unitColumn_ = 3;
}


Foam::RBD::joints::Pxyz::Pxyz(const dictionary&)
:
    joint(3)
{
    unitColumn_ = 3;
}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joints::Pxyz::clone() const
{
    return autoPtr<joint>(new Pxyz(*this));
}


void Foam::RBD::joints::Pxyz::jcalc
(
    XSvc& J,
    const scalarField& q,
    const scalarField& qDot
) const
{
    const label i = qIndex_;

    J.X = spatialTransform(tensor::I, vector(q[i], q[i + 1], q[i + 2]));
    J.S[0] = spatialVector(0, 0, 0, 1, 0, 0);
    J.S[1] = spatialVector(0, 0, 0, 0, 1, 0);
    J.S[2] = spatialVector(0, 0, 0, 0, 0, 1);
    J.v = spatialVector(Zero, vector(qDot[i], qDot[i + 1], qDot[i + 2]));
    J.c = Zero;
}
