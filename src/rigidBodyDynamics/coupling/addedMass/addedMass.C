#include "addedMass.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace couplingSchemes
{
    defineTypeNameAndDebug(addedMass, 0);
    addToRunTimeSelectionTable(couplingScheme, addedMass, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingSchemes::addedMass::addedMass
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    couplingScheme(dict, model),
    A_(model.nDoF(), Zero),
    learnt_(false),
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
    rest_(model.nDoF()),
    ws_(model),
    tauG_(model.nDoF(), Zero),
    noForces_(model.nBodies(), Zero)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::couplingSchemes::addedMass::massMatrix
(
    const rigidBodyModelState& state
)
{
    model_.massMatrix(state, ws_, H_);
}


bool Foam::RBD::couplingSchemes::addedMass::cholesky()
{
    const label n = M_.m();

    for (label j = 0; j < n; ++j)
    {
        scalar d = M_(j, j);
        for (label k = 0; k < j; ++k)
        {
            d -= sqr(L_(j, k));
        }
        if (!(d > 0))
        {
            return false;
        }
        L_(j, j) = sqrt(d);

        for (label i = j + 1; i < n; ++i)
        {
            scalar v = M_(i, j);
            for (label k = 0; k < j; ++k)
            {
                v -= L_(i, k)*L_(j, k);
            }
            L_(i, j) = v/L_(j, j);
        }
    }

    return true;
}


void Foam::RBD::couplingSchemes::addedMass::choleskySolve
(
    const scalarField& b,
    scalarField& x
) const
{
    const label n = L_.m();

    for (label i = 0; i < n; ++i)
    {
        scalar v = b[i];
        for (label k = 0; k < i; ++k)
        {
            v -= L_(i, k)*x[k];
        }
        x[i] = v/L_(i, i);
    }
    for (label i = n - 1; i >= 0; --i)
    {
        scalar v = x[i];
        for (label k = i + 1; k < n; ++k)
        {
            v -= L_(k, i)*x[k];
        }
        x[i] = v/L_(i, i);
    }
}


Foam::scalar Foam::RBD::couplingSchemes::addedMass::normH
(
    const scalarField& x
) const
{
    const label n = H_.m();

    scalar xHx = 0;
    for (label i = 0; i < n; ++i)
    {
        scalar Hx = 0;
        for (label j = 0; j < n; ++j)
        {
            Hx += H_(i, j)*x[j];
        }
        xHx += x[i]*Hx;
    }

    return sqrt(max(xHx, scalar(0)));
}


Foam::scalar Foam::RBD::couplingSchemes::addedMass::gravityScale
(
    const rigidBodyModelState& state
)
{
    rest_.q() = state.q();
    rest_.qDot() = Zero;
    rest_.qDdot() = Zero;

    // The joint forces that hold the state against gravity: tauG = H aG
    model_.inverseDynamics(rest_, ws_, noForces_, tauG_);

    M_ = H_;
    if (!cholesky())
    {
        return 0;
    }
    choleskySolve(tauG_, x_);

    scalar tauAG = 0;
    forAll(tauG_, i)
    {
        tauAG += tauG_[i]*x_[i];
    }

    return sqrt(max(tauAG, scalar(0)));
}


bool Foam::RBD::couplingSchemes::addedMass::newtonStep
(
    const scalarField& aGiven,
    scalarField& a
)
{
    const label n = H_.m();

    // H + A, and H (a - aGiven)
    for (label i = 0; i < n; ++i)
    {
        r_[i] = a[i] - aGiven[i];
    }
    for (label i = 0; i < n; ++i)
    {
        b_[i] = 0;
        for (label j = 0; j < n; ++j)
        {
            b_[i] += H_(i, j)*r_[j];
            M_(i, j) = H_(i, j) + A_(i, j);
        }
    }

    if (!cholesky())
    {
        return false;
    }
    choleskySolve(b_, x_);

    for (label i = 0; i < n; ++i)
    {
        a[i] = aGiven[i] + x_[i];
    }

    return true;
}


void Foam::RBD::couplingSchemes::addedMass::update()
{
    const label n = A_.m();

    // Powell-symmetric-Broyden, e = y - A s:
    //     A += (e s^T + s e^T)/(s.s) - (e.s) s s^T/(s.s)^2
    scalar ss = 0;
    for (label i = 0; i < n; ++i)
    {
        scalar As = 0;
        for (label j = 0; j < n; ++j)
        {
            As += A_(i, j)*s_[j];
        }
        b_[i] = y_[i] - As;
        ss += sqr(s_[i]);
    }
    scalar es = 0;
    for (label i = 0; i < n; ++i)
    {
        es += b_[i]*s_[i];
    }

    Aold_ = A_;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            A_(i, j) +=
                (b_[i]*s_[j] + s_[i]*b_[j])/ss - es*s_[i]*s_[j]/sqr(ss);
        }
    }
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            M_(i, j) = A_(i, j) + 0.1*H_(i, j);
        }
    }

    // Refused unless A > -H/10: added mass is not negative, and a secant
    // spoilt by noise must not leave H + A near losing definiteness
    const bool accepted = cholesky();
    if (accepted)
    {
        learnt_ = true;
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


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::RBD::couplingSchemes::addedMass::correct
(
    const rigidBodyModelState& state,
    const scalarField& aGiven,
    scalarField& a,
    const bool firstSolve
)
{
    const label n = A_.m();

    massMatrix(state);

    // Learn from the previous solve of the step, where the accelerations
    // given changed enough to tell the forces' answer from their noise
    // (not from the first solve of all: the fluid at rest it was given had
    // answered no acceleration)
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
            for (label i = 0; i < n; ++i)
            {
                y_[i] = 0;
                for (label j = 0; j < n; ++j)
                {
                    y_[i] -= H_(i, j)*r_[j];
                }
            }
            update();
        }
    }

    aGivenPrev_ = aGiven;
    aNewPrev_ = a;
    ++nSolves_;

    if (learnt_ && newtonStep(aGiven, a))
    {
        return;
    }

    // Not learnt yet: relaxed, the change capped at gravity's size
    for (label i = 0; i < n; ++i)
    {
        r_[i] = a[i] - aGiven[i];
    }

    scalar omega = relaxation_;
    const scalar rH = normH(r_);
    const scalar gH = gravityScale(state);
    if (gH > VSMALL && omega*rH > gH)
    {
        omega = gH/rH;
    }

    for (label i = 0; i < n; ++i)
    {
        a[i] = aGiven[i] + omega*r_[i];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::couplingSchemes::addedMass::relaxStart
(
    const rigidBodyModelState& state0,
    const scalarField&,
    const scalarField& aExternal,
    scalarField& a
)
{
    massMatrix(state0);

    // The share of the fluid's forces, capped at gravity's size
    const scalar eH = normH(aExternal);
    const scalar gH = gravityScale(state0);

    if (gH > VSMALL && eH > gH)
    {
        const scalar cut = 1 - gH/eH;
        forAll(a, i)
        {
            a[i] -= cut*aExternal[i];
        }
    }
}
