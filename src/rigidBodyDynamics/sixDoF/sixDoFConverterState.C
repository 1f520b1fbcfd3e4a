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

// The state: a sixDoF state's q and qDot, and what the front-ends print

#include "sixDoFConverter.H"
#include "rigidBodyModel.H"
#include "quaternion.H"
#include "transform.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalarField Foam::RBD::sixDoFConverter::q
(
    const dictionary& stateDict,
    const point& CofR,
    const tensor& Q
) const
{
    // The state is read as written, to the precision of its digits
    // (writePrecision, often 6): what is across the joint's freedom by less
    // than that is round-off
    const scalar tol = 1e-5;
    scalarField q(P_.size() + R_.size(), Zero);

    // The translation, along the joint's directions from the initial centre
    // of rotation
    vector d(CofR - CofR_);
    forAll(P_, i)
    {
        q[i] = d & P_[i];
        d -= q[i]*P_[i];
    }
    if (mag(d) > tol*max(scalar(1), max(mag(CofR_), mag(CofR))))
    {
        FatalIOErrorInFunction(stateDict)
            << "Entry centreOfRotation " << CofR << " of the state is "
            << CofR - CofR_ << " from the initial centre of rotation "
            << CofR_ << ", " << d << " of it along directions the"
            << " constraints fix: not a state of this body's joint" << nl
            << exit(FatalIOError);
    }

    // The rotation since the start (global, active), R Q0 = Q
    const tensor Rg(Q & Q0_.T());
    const label n = P_.size();
    tensor made(tensor::I);
    if (R_.size() == 3)
    {
        // Rs: the unit quaternion's vector part, its scalar part positive
        quaternion qt(Rg);
        qt.normalize();
        if (qt.w() < 0)
        {
            qt = -qt;
        }
        for (direction i = 0; i < 3; ++i)
        {
            q[n + i] = qt.v()[i];
        }
        made = qt.R();
    }
    else if (R_.size() == 1)
    {
        // Rx, Ry, Rz, Ra: the angle about the axis, in (-pi, pi] (sixDoF
        // keeps no turns, only the orientation)
        const vector& a = R_[0];
        const vector sinAxis
        (
            0.5*(Rg.zy() - Rg.yz()),
            0.5*(Rg.xz() - Rg.zx()),
            0.5*(Rg.yx() - Rg.xy())
        );
        q[n] = atan2(a & sinAxis, 0.5*(tr(Rg) - 1));
        made = Ra(a, q[n]).T();
    }

    if (mag(Rg - made) > tol)
    {
        FatalIOErrorInFunction(stateDict)
            << "Entry orientation " << Q << " of the state is turned from"
            << " the initial orientation " << Q0_ << " by " << Rg;
        if (R_.size() == 1)
        {
            FatalIOError << ", not only about the axis " << R_[0];
        }
        FatalIOError
            << ", which the constraints do not free: not a state of this"
            << " body's joint" << nl << exit(FatalIOError);
    }

    return q;
}


Foam::scalarField Foam::RBD::sixDoFConverter::rates
(
    const dictionary& stateDict,
    const word& linearKey,
    const word& angularKey,
    const bool warn
) const
{
    const vector v(stateDict.getOrDefault<vector>(linearKey, Zero));
    const vector pi(stateDict.getOrDefault<vector>(angularKey, Zero));

    // sixDoF's inertia about the centre of rotation: the parallel axes
    // theorem's diagonal added to the principal moments, as it reports
    // omega (sixDoFRigidBodyMotion.C of OpenFOAM v1912)
    diagTensor JR(J_);
    const vector r(CofM_ - CofR_);
    if (magSqr(r) > VSMALL)
    {
        JR += mass_*diag(tensor::I*magSqr(r) - sqr(r));
    }

    // The angular rate in the body's frame (parallel to the global one at
    // the start): sixDoF's Q & (inv(J_R) & pi) turned back by the rotation
    // since the start, Q0 Q^T, which is Q0 & (inv(J_R) & pi)
    const vector omega
    (
        Q0_ & vector(pi.x()/JR.xx(), pi.y()/JR.yy(), pi.z()/JR.zz())
    );

    scalarField rates(P_.size() + R_.size(), Zero);
    vector vLeft(v);
    vector omegaLeft(omega);
    forAll(P_, i)
    {
        rates[i] = v & P_[i];
        vLeft -= rates[i]*P_[i];
    }
    forAll(R_, i)
    {
        rates[P_.size() + i] = omega & R_[i];
        omegaLeft -= rates[P_.size() + i]*R_[i];
    }

    if (warn && mag(vLeft) > 1e-12*max(mag(v), SMALL))
    {
        WarningInFunction
            << linearKey << ' ' << v << " has " << vLeft << " along"
            << " directions the constraints fix: dropped, as sixDoF's"
            << " constraints drop it in the first step" << endl;
    }
    if (warn && mag(omegaLeft) > 1e-12*max(mag(omega), SMALL))
    {
        WarningInFunction
            << angularKey << ' ' << pi << " gives an angular velocity "
            << omega << " (in the body's initial axes) with " << omegaLeft
            << " about axes the constraints fix: dropped, as sixDoF's"
            << " constraints drop it in the first step" << endl;
    }
    return rates;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dictionary Foam::RBD::sixDoFConverter::state
(
    const dictionary& stateDict
) const
{
    // As sixDoF reads its state (sixDoFRigidBodyMotionState.C and
    // sixDoFRigidBodyMotion.C of OpenFOAM v1912): the centre of rotation,
    // else the centre of mass; the initial centre of rotation if a
    // constraint put it off the centre of mass and the state gives none
    point CofR
    (
        stateDict.getOrDefault<point>
        (
            "centreOfRotation",
            stateDict.getOrDefault<point>("centreOfMass", Zero)
        )
    );
    if (magSqr(CofM_ - CofR_) > VSMALL && !stateDict.found("centreOfRotation"))
    {
        CofR = CofR_;
    }
    const tensor Q
    (
        checkRotation
        (
            stateDict,
            "orientation",
            stateDict.getOrDefault<tensor>("orientation", tensor::I)
        )
    );

    const fullPrecision precision;
    dictionary s(stateDict.name());
    s.add("q", q(stateDict, CofR, Q));
    s.add("qDot", rates(stateDict, "velocity", "angularMomentum", true));

    // The acceleration (sixDoF's of the centre of rotation, not
    // constrained) and the torque (body frame, about the centre of
    // rotation, not constrained): the rates of the velocity and angular
    // momentum that sixDoF's Newmark and CrankNicolson start the next step
    // from; along the joint's directions
    if (stateDict.found("acceleration") || stateDict.found("torque"))
    {
        s.add("qDdot", rates(stateDict, "acceleration", "torque", false));
    }
    return s;
}


Foam::dictionary Foam::RBD::sixDoFConverter::restartState
(
    const Time& runTime
) const
{
    // The project's own state (rigidBodyDriver's), and sixDoF's
    auto stateIO = [&runTime](const word& name)
    {
        return IOobject
        (
            name,
            runTime.timeName(),
            "uniform",
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
    };
    IOobject own(stateIO("rigidBodyMotionState"));
    IOobject io(stateIO("sixDoFRigidBodyMotionState"));
    if
    (
        own.typeHeaderOk<IOdictionary>(true)
     || !io.typeHeaderOk<IOdictionary>(true)
    )
    {
        return dictionary();
    }

    const dictionary s(state(IOdictionary(io)));
    Info<< "Restarting from " << io.objectPath() << ", the state"
        << " sixDoFRigidBodyMotion wrote (this time has no"
        << " rigidBodyMotionState): q " << s.get<scalarField>("q")
        << ", qDot " << s.get<scalarField>("qDot");
    if (s.found("qDdot"))
    {
        Info<< ", qDdot " << s.get<scalarField>("qDdot");
    }
    Info<< nl << endl;
    return s;
}


void Foam::RBD::sixDoFConverter::useConstantG()
{
    constantG_ = true;
    coeffs_.remove("g");
}


void Foam::RBD::sixDoFConverter::summary(Ostream& os) const
{
    const dictionary& body = coeffs_.subDict("bodies").subDict(bodyName);
    os  << "sixDoFRigidBodyMotion: run as the rigid-body model it maps to,"
        << " one body on a " << body.subDict("joint").get<word>("type")
        << " joint with " << coeffs_.subDict("restraints").size()
        << " restraints" << nl;
    if (constantG_ && dict_.found("g"))
    {
        os  << "    g: constant/g, as sixDoFRigidBodyMotion takes it when"
            << " it exists (the entry g is not used)" << nl;
    }
    if (notUsed_.size())
    {
        os  << "    entries read and not used:";
        for (const word& key : notUsed_)
        {
            os  << ' ' << key;
        }
        os  << nl;
    }
}


// ************************************************************************* //
