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

#include "addedMass.H"
#include "denseLinearAlgebra.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(addedMass, 0);
    addToRunTimeSelectionTable(couplingScheme, addedMass, dictionary);
    addRigidBodyKeywords
    (
        coupling, addedMass, "addedMassRelaxation", "addedMass"
    );
}
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The mass of the bodies of the model's tree (merged ones included)
Foam::scalar totalMass(const Foam::RBD::rigidBodyModel& model)
{
    Foam::scalar m = 0;
    for (Foam::label i = 1; i < model.nBodies(); ++i)
    {
        m += model.bodies()[i].m();
    }
    return m;
}

//- Entry addedMass: fluid (true) or learnt (false)
bool readAddedMassSource(const Foam::dictionary& dict)
{
    const Foam::wordList choices({"fluid", "learnt"});
    const Foam::word source =
        dict.getOrDefault<Foam::word>("addedMass", choices[0]);

    if (!choices.found(source))
    {
        FatalIOErrorInFunction(dict)
            << "Entry addedMass " << source << ": unknown; valid choices: "
            << choices << " (fluid: computed by the mesh motion from the"
            << " fluid each time step; learnt: from the solves' answers)"
            << Foam::nl << Foam::exit(Foam::FatalIOError);
    }

    return source == choices[0];
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::addedMass::addedMass
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model),
    A_(model.nDoF(), Zero),
    K_(model.nDoF(), Zero),
    kState_(jacobian::none),
    P_(model.nDoF(), Zero),
    Q_(model.nDoF(), Zero),
    forgetting_(0.9),
    aSource_(source::none),
    useFluid_(readAddedMassSource(dict)),
    nSolves_(0),
    aGivenPrev_(model.nDoF(), Zero),
    aNewPrev_(model.nDoF(), Zero),
    H_(model.nDoF(), Zero),
    M_(model.nDoF(), Zero),
    L_(model.nDoF(), Zero),
    Aold_(model.nDoF(), Zero),
    r_(model.nDoF(), Zero),
    s_(model.nDoF(), Zero),
    y_(model.nDoF(), Zero),
    b_(model.nDoF(), Zero),
    x_(model.nDoF(), Zero),
    ws_(model),
    gravityScale_(mag(model.g())*sqrt(totalMass(model))),
    omega_(readFactor(dict, "addedMassRelaxation")),
    aTrial_(model.nDoF(), Zero)
{
    if (relaxation_ != 1)
    {
        Info<< "rigidBodyMotion: coupling addedMass, addedMassRelaxation "
            << omega_ << ": accelerationRelaxation " << relaxation_
            << " is the constant scheme's and is not used (docs/coupling.md)"
            << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::couplingSchemes::addedMass::massMatrix
(
    const rigidBodyModelState& state
)
{
    model_.massMatrix(state, ws_, H_);
}


Foam::scalar Foam::RBD::couplingSchemes::addedMass::normH
(
    const scalarField& x
) const
{
    return sqrt(max(quadraticForm(H_, x), scalar(0)));
}


bool Foam::RBD::couplingSchemes::addedMass::newtonStep
(
    const scalarField& aGiven,
    scalarField& a,
    const bool withK,
    const scalar aScale
)
{
    const label n = H_.m();

    // H + aScale A (+ K), and H (a - aGiven)
    for (label i = 0; i < n; ++i)
    {
        r_[i] = a[i] - aGiven[i];
    }
    matrixVector(H_, r_, b_);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            M_(i, j) =
                H_(i, j) + aScale*A_(i, j) + (withK ? K_(i, j) : 0);
        }
    }

    if (!choleskyDecompose(M_, L_))
    {
        return false;
    }
    choleskySolve(L_, b_, x_);

    for (label i = 0; i < n; ++i)
    {
        a[i] = aGiven[i] + x_[i];
    }

    return true;
}


void Foam::RBD::couplingSchemes::addedMass::choleskySolveRows
(
    const scalarSquareMatrix& B,
    scalarSquareMatrix& X
)
{
    const label n = B.m();

    for (label row = 0; row < n; ++row)
    {
        for (label k = 0; k < n; ++k)
        {
            b_[k] = B(row, k);
        }
        choleskySolve(L_, b_, x_);
        for (label k = 0; k < n; ++k)
        {
            X(row, k) = x_[k];
        }
    }
}


void Foam::RBD::couplingSchemes::addedMass::update()
{
    const label n = A_.m();

    // The sums, older pairs forgotten a little; the trace weighs
    // rotations by their lengths squared, as translations
    scalar trQ = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            P_(i, j) = forgetting_*P_(i, j) + y_[i]*s_[j];
            Q_(i, j) = forgetting_*Q_(i, j) + s_[i]*s_[j];
        }
        trQ += weight_[i]*Q_(i, i);
    }

    // A^T = Q^-1 P^T, Q regularised where no pair has moved the
    // accelerations yet
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            M_(i, j) =
                Q_(i, j) + (i == j ? 1e-9*trQ/weight_[i] + VSMALL : 0);
        }
    }

    Aold_ = A_;
    if (choleskyDecompose(M_, L_))
    {
        choleskySolveRows(P_, A_);

        // A = (A + A^T)/2
        for (label i = 0; i < n; ++i)
        {
            for (label j = i + 1; j < n; ++j)
            {
                const scalar a = 0.5*(A_(i, j) + A_(j, i));
                A_(i, j) = a;
                A_(j, i) = a;
            }
        }
    }

    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            M_(i, j) = A_(i, j) + 0.1*H_(i, j);
        }
    }

    // Refused unless A > -H/10: added mass is not negative, and a fit
    // spoilt by noise must not leave H + A near losing definiteness
    const bool accepted = choleskyDecompose(M_, L_);
    if (accepted && aSource_ == source::none)
    {
        aSource_ = source::learnt;
    }
    else
    {
        A_ = Aold_;
    }

    if (debug)
    {
        Info<< "addedMass: secant s " << s_ << " y " << y_
            << (accepted ? "" : " refused") << ", A " << A_ << endl;
    }
}


void Foam::RBD::couplingSchemes::addedMass::learn
(
    const scalarField& aGiven,
    const scalarField& a,
    const bool firstSolve
)
{
    const label n = A_.m();

    // From the previous solve of the step, where the accelerations given
    // changed enough to tell the forces' answer from their noise (not from
    // the first solve of all: the fluid at rest it was given had answered
    // no acceleration)
    if (!firstSolve && nSolves_ >= 2)
    {
        for (label i = 0; i < n; ++i)
        {
            s_[i] = aGiven[i] - aGivenPrev_[i];
            r_[i] = a[i] - aNewPrev_[i];
        }

        const scalar sH = normH(s_);
        if (sH > 1e-6*max(normH(aGiven), normH(a)) && sH > VSMALL)
        {
            // y less the part the solve's own Jacobian explains: -(H r +
            // K s), x_ the scratch for K s
            matrixVector(H_, r_, y_);
            matrixVector(K_, s_, x_);
            for (label i = 0; i < n; ++i)
            {
                y_[i] = -(y_[i] + x_[i]);
            }
            update();
        }
    }

    aGivenPrev_ = aGiven;
    aNewPrev_ = a;
    ++nSolves_;
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::addedMass::judgeJacobian()
{
    if (kState_ != jacobian::pending)
    {
        return;
    }

    // K counts where it is more than the round-off of its finite
    // differences against the mass matrix: an entry against the entries
    // of its row and column's diagonal, of the same units at any scale
    kState_ = jacobian::none;
    for (label i = 0; i < K_.m(); ++i)
    {
        for (label j = 0; j < K_.m(); ++j)
        {
            if (mag(K_(i, j)) > 1e-6*Foam::sqrt(mag(H_(i, i)*H_(j, j))))
            {
                kState_ = jacobian::significant;
                return;
            }
        }
    }
}


void Foam::RBD::couplingSchemes::addedMass::correctWithFluid
(
    const scalarField& aGiven,
    scalarField& a
)
{
    const bool hasK = kState_ == jacobian::significant;

    // Newton's step with the fluid's added mass (if a mesh motion gave
    // it) and the solve's Jacobian: the distance of aGiven from the
    // coupled answer, and the whole step; with addedMassRelaxation
    // below 1, A/omega on the left, a damped step
    aTrial_ = a;
    if
    (
        (aSource_ == source::fluid || hasK)
     && (
            newtonStep(aGiven, aTrial_, hasK, 1)
         || newtonStep(aGiven, aTrial_, false, 1)
        )
    )
    {
        distance_ = x_;
        if (omega_ == 1)
        {
            a = aTrial_;
        }
        else if
        (
            !newtonStep(aGiven, a, hasK, 1/omega_)
         && !newtonStep(aGiven, a, false, 1/omega_)
        )
        {
            a = aTrial_;
        }
        return;
    }

    // Nothing known: the stock scheme at addedMassRelaxation
    forAll(a, i)
    {
        a[i] = aGiven[i] + omega_*(a[i] - aGiven[i]);
    }
}


void Foam::RBD::couplingSchemes::addedMass::correct
(
    const rigidBodyModelState& state,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    massMatrix(state);
    judgeJacobian();

    if (useFluid_)
    {
        correctWithFluid(aGiven, a);
        return;
    }

    learn(aGiven, a, firstSolve);

    const bool hasK = kState_ == jacobian::significant;
    const bool learnt = aSource_ != source::none;

    // The fraction addedMassRelaxation of Newton's step with the learnt
    // added mass (noisy, which the whole step would follow): the stock
    // scheme where the added mass is small, and where it is not an error
    // that shrinks by (1 - omega) per solve whatever the density
    if
    (
        (learnt || hasK)
     && (
            newtonStep(aGiven, a, hasK, 1)
         || (learnt && newtonStep(aGiven, a, false, 1))
        )
    )
    {
        distance_ = x_;
        forAll(a, i)
        {
            a[i] = aGiven[i] + omega_*(a[i] - aGiven[i]);
        }
        return;
    }

    // Not learnt yet: relaxed, the change capped at gravity's size
    forAll(a, i)
    {
        r_[i] = a[i] - aGiven[i];
    }

    scalar omega = omega_;
    const scalar rH = normH(r_);
    if (gravityScale_ > 0 && omega*rH > gravityScale_)
    {
        omega = gravityScale_/rH;
    }

    forAll(a, i)
    {
        a[i] = aGiven[i] + omega*r_[i];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::couplingSchemes::addedMass::setFluidAddedMass
(
    const scalarSquareMatrix& A
)
{
    A_ = A;
    aSource_ = source::fluid;

    if (debug)
    {
        Info<< "addedMass: the fluid's added mass " << A_ << endl;
    }
}


void Foam::RBD::couplingSchemes::addedMass::setSolveJacobian
(
    const scalarSquareMatrix& K
)
{
    const label n = K_.m();

    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            K_(i, j) = 0.5*(K(i, j) + K(j, i));
        }
    }
    kState_ = jacobian::pending;
}


void Foam::RBD::couplingSchemes::addedMass::relaxStart
(
    const rigidBodyModelState& state0,
    const scalarField&,
    const scalarField& aExternal,
    scalarField& a
)
{
    massMatrix(state0);

    // The fluid at rest has answered no acceleration yet: with its added
    // mass on both sides, (H + A) a = H a
    if (aSource_ == source::fluid)
    {
        s_ = Zero;
        if (newtonStep(s_, a, false, 1))
        {
            return;
        }
    }

    // The share of the fluid's forces, capped at gravity's size
    const scalar eH = normH(aExternal);

    if (gravityScale_ > 0 && eH > gravityScale_)
    {
        const scalar cut = 1 - gravityScale_/eH;
        forAll(a, i)
        {
            a[i] -= cut*aExternal[i];
        }
    }
}


void Foam::RBD::couplingSchemes::addedMass::write(Ostream& os) const
{
    couplingScheme::write(os);
    os.writeEntry("addedMassRelaxation", omega_);
    os.writeEntry("addedMass", word(useFluid_ ? "fluid" : "learnt"));
}
