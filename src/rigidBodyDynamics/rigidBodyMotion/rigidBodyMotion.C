#include "rigidBodyMotion.H"
#include "rigidBodySolver.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyMotion::readCoeffs(const dictionary& dict)
{
    aRelax_ = dict.getOrDefault<scalar>("accelerationRelaxation", 1);
    aDamp_ = dict.getOrDefault<scalar>("accelerationDamping", 1);
    nIter_ = dict.getOrDefault<label>("nIter", 1);

    const word relaxType
    (
        dict.getOrDefault<word>("accelerationRelaxationType", "constant")
    );
    if (relaxType == "constant")
    {
        relaxType_ = relaxation::constant;
    }
    else if (relaxType == "Aitken")
    {
        relaxType_ = relaxation::Aitken;
    }
    else if (relaxType == "quasiNewton")
    {
        relaxType_ = relaxation::quasiNewton;
    }
    else
    {
        FatalIOErrorInFunction(dict.lookup("accelerationRelaxationType"))
            << "Unknown accelerationRelaxationType " << relaxType << nl
            << "Valid types: 3(constant Aitken quasiNewton)" << nl
            << exit(FatalIOError);
    }
    omega_ = aRelax_;
    resetJacobian();
    report_ = dict.getOrDefault<Switch>("report", false);

    if (!(aRelax_ > 0 && aRelax_ <= 1))
    {
        FatalIOErrorInFunction(dict.lookup("accelerationRelaxation"))
            << "Entry accelerationRelaxation " << aRelax_
            << " must be in (0, 1]" << nl << exit(FatalIOError);
    }
    if (!(aDamp_ > 0 && aDamp_ <= 1))
    {
        FatalIOErrorInFunction(dict.lookup("accelerationDamping"))
            << "Entry accelerationDamping " << aDamp_
            << " must be in (0, 1]" << nl << exit(FatalIOError);
    }
    if (nIter_ < 1)
    {
        FatalIOErrorInFunction(dict.lookup("nIter"))
            << "Entry nIter " << nIter_ << " must be at least 1" << nl
            << exit(FatalIOError);
    }

    solver_ = rigidBodySolver::New(*this, dict.subDict("solver"));
}


void Foam::RBD::rigidBodyMotion::accelerations
(
    rigidBodyModelState& state,
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    kinematics(state, ws_);
    wsValid_ = (&state == &motionState_);

    forAll(rtau_, i)
    {
        rtau_[i] = tau[i];
    }
    forAll(rfx_, i)
    {
        rfx_[i] = fx[i];
    }
    applyRestraints(state, ws_, rtau_, rfx_);

    articulatedBodyDynamics(rtau_, rfx_, ws_, state.qDdot());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyMotion::rigidBodyMotion(const dictionary& dict)
:
    rigidBodyModel(dict),
    motionState_(*this, dict),
    motionState0_(motionState_),
    ws_(*this),
    wsValid_(false),
    aRelax_(1),
    aDamp_(1),
    relaxType_(relaxation::constant),
    omega_(1),
    a0_(nDoF(), Zero),
    r0_(nDoF(), Zero),
    Jinv_(nDoF(), Zero),
    da_(nDoF(), Zero),
    dr_(nDoF(), Zero),
    JinvDr_(nDoF(), Zero),
    nIter_(1),
    report_(false),
    iteration_(0),
    provisionalQDdot0_(false),
    rtau_(nDoF(), Zero),
    rfx_(nBodies(), Zero),
    qDdotPrev_(nDoF(), Zero)
{
    readCoeffs(dict);
}


Foam::RBD::rigidBodyMotion::rigidBodyMotion
(
    const dictionary& dict,
    const dictionary& stateDict
)
:
    rigidBodyMotion(dict)
{
    motionState_.read(*this, stateDict);
    motionState0_ = motionState_;
}


Foam::RBD::rigidBodyMotion::~rigidBodyMotion()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::RBD::rigidBodyModelWorkspace&
Foam::RBD::rigidBodyMotion::workspace()
{
    if (!wsValid_)
    {
        kinematics(motionState_, ws_);
        wsValid_ = true;
    }
    return ws_;
}


void Foam::RBD::rigidBodyMotion::newTime()
{
    motionState0_ = motionState_;
    iteration_ = 0;
    provisionalQDdot0_ = false;
}


void Foam::RBD::rigidBodyMotion::resetJacobian()
{
    Jinv_ = Zero;
    for (label i = 0; i < Jinv_.m(); ++i)
    {
        Jinv_(i, i) = -aRelax_;
    }
}


void Foam::RBD::rigidBodyMotion::forwardDynamics
(
    rigidBodyModelState& state,
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    // The accelerations given (those the forces were computed with)
    qDdotPrev_ = state.qDdot();

    accelerations(state, tau, fx);

    scalarField& qDdot = state.qDdot();

    // Only the state now is iterated; any other state is relaxed plainly
    const bool iterated = (&state == &motionState_);
    const bool pair = iterated && iteration_ >= 1;

    if (iterated && relaxType_ == relaxation::quasiNewton)
    {
        // Residual, and Broyden's inverse update from the previous solve:
        // Jinv += (da - Jinv dr) dr^T/(dr . dr)
        scalar dr2 = 0;
        forAll(qDdot, i)
        {
            const scalar r = qDdot[i] - qDdotPrev_[i];
            da_[i] = qDdotPrev_[i] - a0_[i];
            dr_[i] = r - r0_[i];
            dr2 += sqr(dr_[i]);
            a0_[i] = qDdotPrev_[i];
            r0_[i] = r;
        }

        if (pair && dr2 > VSMALL)
        {
            const label n = Jinv_.m();
            bool valid = true;
            for (label i = 0; i < n; ++i)
            {
                JinvDr_[i] = 0;
                for (label j = 0; j < n; ++j)
                {
                    JinvDr_[i] += Jinv_(i, j)*dr_[j];
                }
            }
            for (label i = 0; i < n; ++i)
            {
                const scalar c = (da_[i] - JinvDr_[i])/dr2;
                for (label j = 0; j < n; ++j)
                {
                    Jinv_(i, j) += c*dr_[j];
                }
                // Each degree of freedom is relaxed by a factor in (0, 2)
                valid = valid && -Jinv_(i, i) > 0.005 && -Jinv_(i, i) < 2;
            }
            if (!valid)
            {
                resetJacobian();
            }
        }

        // a = a0 - Jinv r
        forAll(qDdot, i)
        {
            scalar Jr = 0;
            forAll(qDdot, j)
            {
                Jr += Jinv_(i, j)*r0_[j];
            }
            qDdot[i] = aDamp_*(qDdotPrev_[i] - Jr);
        }
        return;
    }

    scalar omega = aRelax_;

    if (iterated && relaxType_ == relaxation::Aitken)
    {
        scalar rdr = 0, dr2 = 0;
        forAll(qDdot, i)
        {
            const scalar r = qDdot[i] - qDdotPrev_[i];
            const scalar dr = r - r0_[i];
            rdr += r0_[i]*dr;
            dr2 += sqr(dr);
            r0_[i] = r;
        }

        if (pair && dr2 > VSMALL)
        {
            omega = min(max(-omega_*rdr/dr2, scalar(0.01)), scalar(1));
        }
        else
        {
            // The first solve of a step: the factor the previous step
            // ended with, if smaller
            omega = min(omega_, aRelax_);
        }
        omega_ = omega;
    }

    forAll(qDdot, i)
    {
        qDdot[i] = aDamp_*(omega*qDdot[i] + (1 - omega)*qDdotPrev_[i]);
    }
}


void Foam::RBD::rigidBodyMotion::initialAcceleration
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    if (!motionState0_.qDdotValid())
    {
        accelerations(motionState0_, tau, fx);
        motionState0_.setQDdotValid(true);
        motionState_.qDdot() = motionState0_.qDdot();
        motionState_.setQDdotValid(true);
        provisionalQDdot0_ = true;
    }
    else if (provisionalQDdot0_)
    {
        accelerations(motionState0_, tau, fx);
    }
}


void Foam::RBD::rigidBodyMotion::solve
(
    const scalar t,
    const scalar deltaT,
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    initialAcceleration(tau, fx);

    motionState_.t() = t;
    motionState_.deltaT() = deltaT;

    solver_->solve(tau, fx);
    ++iteration_;

    // The solver's last evaluation was at an intermediate state
    wsValid_ = false;
}


Foam::spatialTransform Foam::RBD::rigidBodyMotion::X0(const label bodyID)
{
    return rigidBodyModel::X0(bodyID, workspace());
}


Foam::spatialVector Foam::RBD::rigidBodyMotion::v
(
    const label bodyID,
    const vector& p
)
{
    return rigidBodyModel::v(bodyID, p, workspace());
}


void Foam::RBD::rigidBodyMotion::status(const label bodyID)
{
    const spatialTransform CofR(X0(bodyID));
    const spatialVector vCofR(v(bodyID, Zero));

    Info<< "Rigid-body motion of the " << name(bodyID) << nl
        << "    Centre of rotation: " << CofR.r() << nl
        << "    Orientation: " << CofR.E() << nl
        << "    Linear velocity: " << vCofR.l() << nl
        << "    Angular velocity: " << vCofR.w()
        << endl;
}


bool Foam::RBD::rigidBodyMotion::read(const dictionary& dict)
{
    readCoeffs(dict);
    return true;
}


void Foam::RBD::rigidBodyMotion::write(Ostream& os) const
{
    rigidBodyModel::write(os);

    os.writeEntry("accelerationRelaxation", aRelax_);
    os.writeEntry("accelerationDamping", aDamp_);
    os.writeEntry("nIter", nIter_);
    os.writeEntry("report", report_);
    motionState_.write(os);
}
