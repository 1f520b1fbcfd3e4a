/*---------------------------------------------------------------------------*\
    Rigid-body dynamics for OpenFOAM v1912
    Copyright (C) the authors of this project (its git history names them)
-------------------------------------------------------------------------------
License
    This file is part of the rigid-body dynamics for OpenFOAM v1912.

    It is free software: you can redistribute it and/or modify it under the
    terms of the GNU General Public License as published by the Free
    Software Foundation, either version 3 of the License, or (at your
    option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT ANY
    WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License along
    with it (the file LICENSE at the top of the project).  If not, see
    <https://www.gnu.org/licenses/>.
\*---------------------------------------------------------------------------*/

#include "rigidBodyInertia.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyInertia::rigidBodyInertia()
:
    m_(0),
    c_(Zero),
    Ic_(Zero)
{}


Foam::RBD::rigidBodyInertia::rigidBodyInertia
(
    const scalar m,
    const vector& c,
    const symmTensor& Ic
)
:
    m_(m),
    c_(c),
    Ic_(Ic)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::RBD::crossMatrix(const vector& v)
{
    return tensor
    (
        0,    -v.z(),  v.y(),
        v.z(),  0,    -v.x(),
       -v.y(),  v.x(),  0
    );
}


Foam::symmTensor Foam::RBD::rigidBodyInertia::Io() const
{
    // Parallel-axis theorem
    return Ic_ + m_*(magSqr(c_)*symmTensor::I - sqr(c_));
}


Foam::spatialTensor Foam::RBD::rigidBodyInertia::spatial() const
{
    const tensor mcx(m_*crossMatrix(c_));

    return spatialTensor
    (
        tensor(Io()), mcx,
        -mcx,         m_*tensor::I
    );
}


Foam::spatialVector Foam::RBD::rigidBodyInertia::operator&
(
    const spatialVector& v
) const
{
    // Linear momentum of the centre of mass, then moment about the origin
    const vector p(m_*(v.l() + (v.w() ^ c_)));

    return spatialVector((Ic_ & v.w()) + (c_ ^ p), p);
}


Foam::scalar Foam::RBD::rigidBodyInertia::kineticEnergy
(
    const spatialVector& v
) const
{
    return 0.5*(v && (*this & v));
}


void Foam::RBD::rigidBodyInertia::add
(
    const rigidBodyInertia& other,
    const spatialTransform& X
)
{
    // The other body's centre of mass and inertia in this body's frame
    const vector c2((X.E().T() & other.c_) + X.r());
    const symmTensor Ic2(transform(X.E().T(), other.Ic_));

    const scalar m = m_ + other.m_;

    if (m < VSMALL)
    {
        return;
    }

    const vector c((m_*c_ + other.m_*c2)/m);
    const vector d1(c_ - c);
    const vector d2(c2 - c);

    Ic_ +=
        m_*(magSqr(d1)*symmTensor::I - sqr(d1))
      + Ic2 + other.m_*(magSqr(d2)*symmTensor::I - sqr(d2));
    m_ = m;
    c_ = c;
}


void Foam::RBD::rigidBodyInertia::check(const dictionary& dict) const
{
    if (!(m_ > 0) || !std::isfinite(m_))
    {
        FatalIOErrorInFunction(dict.lookup("mass"))
            << "Body " << dict.dictName() << ": mass " << m_
            << " must be positive" << nl
            << exit(FatalIOError);
    }

    // The inertia about the body's origin, Ic + m(|c|^2 I - c c), must be
    // a number
    if (!std::isfinite(m_*magSqr(c_)))
    {
        OSstream& os =
            dict.found("centreOfMass")
          ? FatalIOErrorInFunction(dict.lookup("centreOfMass"))
          : FatalIOErrorInFunction(dict);
        os  << "Body " << dict.dictName() << ": centre of mass " << c_
            << " is so far from the body's origin that its inertia about"
            << " the origin (mass times the distance squared) overflows"
            << nl << exit(FatalIOError);
    }

    // Positive definite: leading principal minors positive (scaled by the
    // trace, so the test does not depend on units)
    const scalar trI = tr(Ic_);
    if (!(trI > 0) || !std::isfinite(trI))
    {
        FatalIOErrorInFunction(dict.lookup("inertia"))
            << "Body " << dict.dictName() << ": inertia " << Ic_
            << " about the centre of mass is not positive definite" << nl
            << exit(FatalIOError);
    }

    const symmTensor I(Ic_/trI);
    const scalar eps = 1e-10;

    if
    (
        !(
            I.xx() > eps
         && I.xx()*I.yy() - sqr(I.xy()) > eps
         && det(I) > eps
        )
    )
    {
        FatalIOErrorInFunction(dict.lookup("inertia"))
            << "Body " << dict.dictName() << ": inertia " << Ic_
            << " about the centre of mass is not positive definite" << nl
            << exit(FatalIOError);
    }

    // A real body's second moment J = tr(I)/2 - I is positive semi-definite
    // (the principal moments meet the triangle inequality): all principal
    // minors of J non-negative
    const symmTensor J(0.5*symmTensor::I - I);
    const bool semiDefinite =
        J.xx() >= -eps && J.yy() >= -eps && J.zz() >= -eps
     && J.xx()*J.yy() - sqr(J.xy()) >= -eps
     && J.yy()*J.zz() - sqr(J.yz()) >= -eps
     && J.xx()*J.zz() - sqr(J.xz()) >= -eps
     && det(J) >= -eps;

    if (!semiDefinite)
    {
        FatalIOErrorInFunction(dict.lookup("inertia"))
            << "Body " << dict.dictName() << ": inertia " << Ic_
            << " about the centre of mass has principal moments that break"
            << " the triangle inequality (no real body has them)" << nl
            << exit(FatalIOError);
    }
}
