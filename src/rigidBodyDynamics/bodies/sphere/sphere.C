#include "sphere.H"
#include "rigidBodyEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

namespace Foam
{
namespace RBD
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(rigidBody, sphere, dictionary);
    addRigidBodyKeywords(body, sphere, "radius", "mass", "centreOfMass");
}
}



Foam::RBD::sphere::sphere(const word& name, const dictionary& dict)
:
    rigidBody(name, rigidBodyInertia()),
    r_(readPositive(dict, "radius"))
{
    const scalar m = readPositive(dict, "mass");
    setInertia
    (
        rigidBodyInertia
        (
            m,
            dict.get<vector>("centreOfMass"),
            (2.0/5.0)*m*sqr(r_)*symmTensor::I
        )
    );
}


Foam::autoPtr<Foam::RBD::rigidBody> Foam::RBD::sphere::clone() const
{
    return autoPtr<rigidBody>(new sphere(*this));
}


void Foam::RBD::sphere::write(Ostream& os) const
{
    os.writeEntry("type", type());
    os.writeEntry("mass", m());
    os.writeEntry("radius", r_);
    os.writeEntry("centreOfMass", c());
}
