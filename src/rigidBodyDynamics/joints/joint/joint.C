#include "joint.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(joint, 0);
    defineRunTimeSelectionTable(joint, dictionary);
}
}


Foam::RBD::joint::joint(const label nDoF)
:
    nDoF_(nDoF),
    qIndex_(0)
{}


Foam::autoPtr<Foam::RBD::joint> Foam::RBD::joint::New(const dictionary& dict)
{
    const word jointType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(jointType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "joint",
            jointType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


void Foam::RBD::joint::expand(PtrList<joint>& joints) const
{
    joints.append(clone().ptr());
}


void Foam::RBD::joint::integrate
(
    scalarField& q,
    const scalarField& q0,
    const scalarField& dq
) const
{
    for (label i = qIndex_; i < qIndex_ + nDoF_; ++i)
    {
        q[i] = q0[i] + dq[i];
    }
}


void Foam::RBD::joint::write(Ostream& os) const
{
    os.writeEntry("type", type());
}
