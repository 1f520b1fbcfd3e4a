#include "rigidBodyModelWorkspace.H"
#include "rigidBodyModel.H"

Foam::RBD::rigidBodyModelWorkspace::rigidBodyModelWorkspace
(
    const rigidBodyModel& model
)
:
    X0valid(false)
{
    resize(model);
}


void Foam::RBD::rigidBodyModelWorkspace::resize(const rigidBodyModel& model)
{
    const label n = model.nBodies();

    J.setSize(n);
    Xlambda.setSize(n);
    X0.setSize(n);
    X0valid = false;
    v.setSize(n, Zero);
    a.setSize(n, Zero);
    c.setSize(n, Zero);
    IA.setSize(n);
    pA.setSize(n, Zero);
    U.setSize(n);
    Dinv.setSize(n, Zero);
    u.setSize(n, Zero);
}
