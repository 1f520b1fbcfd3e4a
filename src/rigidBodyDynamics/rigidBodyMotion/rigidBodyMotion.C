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

#include "rigidBodyMotion.H"
#include "denseLinearAlgebra.H"
#include "rigidBodyEntries.H"
#include "unitConversion.H"
#include "OStringStream.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

addRigidBodyCommonKeywords
(
    coefficients, Motion, "restraints", "solver", "nIter", "ramp", "rampCoeffs"
);


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyMotion::readCoeffs(const dictionary& dict)
{
    nIter_ = dict.getOrDefault<label>("nIter", 1);

    if (nIter_ < 1)
    {
        FatalIOErrorInFunction(dict.lookup("nIter"))
            << "Entry nIter " << nIter_ << " must be at least 1" << nl
            << exit(FatalIOError);
    }

    coupling_ = couplingScheme::New(dict, model_);
    solver_ = rigidBodySolver::New(model_, dict.subDict("solver"));
    checkSolverCoupling(dict);

    ramp_.clear();
    if (dict.found("ramp"))
    {
        ramp_ = readFunction1<scalar>(dict, "ramp");
    }
}


void Foam::RBD::rigidBodyMotion::checkSolverCoupling
(
    const dictionary& dict
) const
{
    if (!solver_->multiStage() || !coupling_->learnsFromHistory())
    {
        return;
    }

    // The schemes that do not learn from their history, as each is with
    // its default entries
    const wordList schemes
    (
        couplingScheme::dictionaryConstructorTablePtr_->sortedToc()
    );
    std::string valid;
    for (const word& scheme : schemes)
    {
        dictionary schemeDict;
        schemeDict.add("accelerationRelaxationType", scheme);
        if (!couplingScheme::New(schemeDict, model_)->learnsFromHistory())
        {
            valid += ' ' + scheme;
        }
    }

    OStringStream given;
    given.incrIndent();
    coupling_->write(given);

    FatalIOErrorInFunction(dict)
        << "The solver " << solver_->type() << " evaluates the"
        << " accelerations at several stages a step, each relaxed against"
        << " that stage's previous evaluation, but the coupling scheme "
        << coupling_->type() << " learns from the history of its calls,"
        << " which would mix the stages'." << nl
        << "The coupling entries read (given or defaulted):" << nl
        << given.str().c_str()
        << "Valid coupling schemes (accelerationRelaxationType) with the "
        << solver_->type() << " solver, each with its default entries:"
        << valid.c_str() << nl
        << exit(FatalIOError);
}


void Foam::RBD::rigidBodyMotion::readRestraints(const dictionary& dict)
{
    const dictionary* restraintsDict = dict.findDict("restraints");

    if (!restraintsDict)
    {
        return;
    }

    for (const entry& e : *restraintsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*restraintsDict)
                << "Entry " << e.keyword() << " of restraints is not a"
                << " dictionary" << nl
                << exit(FatalIOError);
        }

        restraints_.append(restraint::New(e.keyword(), e.dict(), model_));
    }

    // The prescriptions, as themselves and as the model's constraints,
    // then the other restraints' constraints (a PTO's latch), and the
    // restraints with states of their own
    label nP = 0, nC = 0, nS = 0;
    for (restraint& r : restraints_)
    {
        nP += isA<prescription>(r) ? 1 : 0;
        nC += r.constraint() ? 1 : 0;
        nS += isA<statefulRestraint>(r) ? 1 : 0;
    }
    prescribing_.setSize(nP);
    prescriptions_.setSize(nC);
    stateful_.setSize(nS);
    label nOthers = nP;
    nP = 0;
    nS = 0;
    for (restraint& r : restraints_)
    {
        prescription* p = dynamic_cast<prescription*>(&r);
        if (p)
        {
            prescribing_.set(nP, p);
            prescriptions_.set(nP++, p);
        }
        else if (r.constraint())
        {
            prescriptions_.set(nOthers++, r.constraint());
        }
        statefulRestraint* sr = dynamic_cast<statefulRestraint*>(&r);
        if (sr)
        {
            stateful_.set(nS++, sr);
        }
    }
    ws_.setConstraints(model_, nC);
}


void Foam::RBD::rigidBodyMotion::checkPrescriptions(const dictionary& dict)
{
    if (prescribing_.empty())
    {
        return;
    }

    // Each motor's response: the change of its rate per unit force
    prescribe(state_);
    model_.motorResponses(state_, ws_, prescriptions_);
    wsValid_ = true;

    const dictionary& restraintsDict = dict.subDict("restraints");
    forAll(prescribing_, s)
    {
        const prescription& ps = prescribing_[s];
        ps.checkMotor
        (
            ws_,
            ws_.constraintMatrix(s, s),
            restraintsDict.subDict(ps.name())
        );

        // One rate prescribed twice
        for (label r = 0; r < s; ++r)
        {
            if (ps.sameRate(prescribing_[r]))
            {
                OSstream& os = FatalIOErrorInFunction(restraintsDict);
                os  << "Restraints " << prescribing_[r].name() << " and "
                    << ps.name() << " both prescribe ";
                ps.writeWhat(os);
                os  << ": give it one prescription." << nl
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::RBD::rigidBodyMotion::checkPrescribedStart()
{
    if (prescribing_.empty())
    {
        return;
    }
    prescribe(state_);
    model_.motorResponses(state_, ws_, prescriptions_);
    wsValid_ = true;

    forAll(prescribing_, s)
    {
        const prescription& ps = prescribing_[s];

        // A start off the prescribed rate jumps onto it in the first step
        scalar rate0 = 0;
        forAll(ps.row, i)
        {
            rate0 += ps.row[i]*state_.qDot()[i];
        }
        if
        (
            mag(rate0 - ps.rate)
          > 1e-6*max(mag(ps.rate), mag(rate0)) + VSMALL
        )
        {
            WarningInFunction
                << "Restraint " << ps.name() << " (" << ps.type()
                << ") prescribes the rate " << ps.rate << " at t = "
                << state_.t() << ", but the state starts at " << rate0
                << " (the motion's qDot): the motion jumps to the"
                << " prescribed rate in the first step.  Give qDot so"
                << " that the start is at the prescribed rate" << endl;
        }
    }
}


void Foam::RBD::rigidBodyMotion::prescribe(const rigidBodyModelState& state)
{
    forAll(prescribing_, s)
    {
        prescribing_[s].prescribe(state, deltaT_);
    }
}


void Foam::RBD::rigidBodyMotion::startRestraints
(
    const rigidBodyModelState& state,
    const rigidBodyModelWorkspace& ws
)
{
    if (!restraintsStarted_)
    {
        forAll(stateful_, si)
        {
            stateful_[si].start(state, ws);
        }
        restraintsStarted_ = true;
    }
}


void Foam::RBD::rigidBodyMotion::evaluate
(
    rigidBodyModelState& state,
    scalarField& qDdot
)
{
    model_.kinematics(state, ws_);
    wsValid_ = (&state == &state_);
    startRestraints(state, ws_);
    prescribe(state);

    forAll(tauTotal_, i)
    {
        tauTotal_[i] = tauGiven_[i];
    }
    forAll(fxTotal_, i)
    {
        fxTotal_[i] = fxGiven_[i];
    }

    forAll(restraints_, ri)
    {
        restraints_[ri].restrain(tauTotal_, fxTotal_, state, ws_);
    }

    // The ramp's share of the weight, ramp(t) m g in all, at each body's
    // centre of mass (the model applies m g)
    if (ramp_.valid())
    {
        const scalar extra = ramp_->value(state.t()) - 1;
        for (label i = 1; i < model_.nBodies(); ++i)
        {
            const rigidBody& body = model_.bodies()[i];
            const vector F(extra*body.m()*model_.g());
            const vector p(model_.globalPoint(i, body.c(), ws_));
            fxTotal_[i] += spatialVector(p ^ F, F);
        }
    }

    model_.constrainedDynamics(tauTotal_, fxTotal_, prescriptions_, ws_, qDdot);
}


void Foam::RBD::rigidBodyMotion::solveJacobian
(
    const rigidBodyModelState& state,
    const bool firstSolve
)
{
    scalar wq = 0, wqDot = 0;
    solver_->accelerationWeights(state.deltaT(), firstSolve, wq, wqDot);

    solveJacobian_ = Zero;
    if (wq <= 0 && wqDot <= 0)
    {
        return;
    }

    // A change h of an acceleration moves q by wq h and qDot by wqDot h:
    // h such that q moves by 1e-7 (m or rad), or qDot by 1e-7 where q
    // does not move
    const scalar h = 1e-7/(wq > 0 ? wq : wqDot);

    // H (a + h e_j) - H a for each j, then -H (da_j)/h: the mass matrix
    // of the state, from the model
    const label n = model_.nDoF();
    for (label j = 0; j < n; ++j)
    {
        stateFD_ = state;
        dqFD_ = Zero;
        dqFD_[j] = wq*h;
        model_.integrate(stateFD_.q(), state.q(), dqFD_);
        stateFD_.qDot()[j] += wqDot*h;

        evaluate(stateFD_);

        for (label i = 0; i < n; ++i)
        {
            solveJacobian_(i, j) =
                (stateFD_.qDdot()[i] - state.qDdot()[i])/h;
        }
    }

    // The accelerations' Jacobian J, made -H J
    model_.massMatrix(state, ws_, massMatrix_);
    wsValid_ = false;
    matrixMatrix(massMatrix_, solveJacobian_, HJ_);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            solveJacobian_(i, j) = -HJ_(i, j);
        }
    }
}


void Foam::RBD::rigidBodyMotion::accelerations
(
    rigidBodyModelState& state,
    const bool firstSolve
)
{
    // The accelerations given (those the forces were computed with)
    forAll(qDdotGiven_, i)
    {
        qDdotGiven_[i] = state.qDdot()[i];
    }

    evaluate(state);

    if (coupling_->usesSolveJacobian())
    {
        solveJacobian(state, firstSolve);
        coupling_->setSolveJacobian(solveJacobian_);
    }

    coupling_->relax(state, qDdotGiven_, state.qDdot(), firstSolve);
}


void Foam::RBD::rigidBodyMotion::initialAcceleration()
{
    if (!state0_.qDdotValid())
    {
        // The accelerations the forces give, and the share of the external
        // forces in them (the algorithm is linear in the forces)
        forAll(qDdotGiven_, i)
        {
            qDdotGiven_[i] = state0_.qDdot()[i];
        }
        evaluate(state0_);

        forAll(fxTotal_, i)
        {
            fxTotal_[i] -= fxGiven_[i];
        }
        model_.constrainedDynamics
        (
            tauTotal_,
            fxTotal_,
            prescriptions_,
            ws_,
            qDdotExternal_
        );
        forAll(qDdotExternal_, i)
        {
            qDdotExternal_[i] = state0_.qDdot()[i] - qDdotExternal_[i];
        }

        coupling_->relaxStart
        (
            state0_,
            qDdotGiven_,
            qDdotExternal_,
            state0_.qDdot()
        );

        state0_.setQDdotValid(true);
        state_.qDdot() = state0_.qDdot();
        state_.setQDdotValid(true);
        provisionalStart_ = true;
    }
    else if (provisionalStart_)
    {
        if (externalForces_ && coupling_->relaxesStart())
        {
            state0_.qDdot() = state_.qDdot();
        }
        else
        {
            evaluate(state0_);
        }
    }
}


void Foam::RBD::rigidBodyMotion::checkSingularities() const
{
    for (label i = 1; i < model_.nBodies(); ++i)
    {
        const joint& J = model_.joints()[i];

        if (J.nearSingularity(state_.q()))
        {
            FatalErrorInFunction
                << "Body " << model_.bodies()[i].name() << ": its "
                << J.type() << " joint (Euler angles; the rotation of a"
                << " floating joint is one) reached its singularity at"
                << " t = " << state_.t() << " s: the middle angle is "
                << radToDeg(state_.q()[J.qIndex() + 1])
                << " degrees, within 1 degree of +-90, where its angles"
                << " cannot represent the body's turning." << nl
                << "Give the body a joint without the singularity, e.g."
                << " for a free body" << nl
                << "    joint { type composite; joints ({ type Pxyz; }"
                << " { type Rs; }); }" << nl
                << "(Rs: a quaternion, any orientation)"
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyMotion::rigidBodyMotion
(
    const dictionary& dict,
    const dictionary& stateDict
)
:
    model_(dict),
    restraintsStarted_(false),
    momentsValid_(false),
    deltaT_(0),
    state_(model_.nDoF(), dict),
    state0_(state_),
    ws_(model_),
    wsValid_(false),
    nIter_(1),
    nSolves_(0),
    restraintsCommitted_(false),
    provisionalStart_(false),
    tauGiven_(model_.nDoF(), Zero),
    fxGiven_(model_.nBodies(), Zero),
    externalForces_(false),
    tauTotal_(model_.nDoF(), Zero),
    fxTotal_(model_.nBodies(), Zero),
    qDdotGiven_(model_.nDoF(), Zero),
    qDdotExternal_(model_.nDoF(), Zero),
    stateFD_(state_),
    dqFD_(model_.nDoF(), Zero),
    solveJacobian_(model_.nDoF(), Zero),
    massMatrix_(model_.nDoF(), Zero),
    HJ_(model_.nDoF(), Zero)
{
    readRestraints(dict);
    model_.checkState(state_.q(), dict);
    readCoeffs(dict);

    if (stateDict.size())
    {
        state_.read(stateDict);
        model_.checkState(state_.q(), stateDict);
        state0_ = state_;

        // The restraints' own states (a lumpedMassLine's nodes)
        const dictionary* rs = stateDict.findDict("restraintStates");
        forAll(stateful_, si)
        {
            const word& name = stateful_[si].name();
            if (rs && rs->found(name))
            {
                stateful_[si].readState(rs->subDict(name));
            }
        }
    }

    deltaT_ = state_.deltaT();
    checkPrescriptions(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::RBD::rigidBodyModelWorkspace&
Foam::RBD::rigidBodyMotion::workspace() const
{
    if (!wsValid_)
    {
        model_.kinematics(state_, ws_);
        wsValid_ = true;
    }
    return ws_;
}


void Foam::RBD::rigidBodyMotion::commitRestraints()
{
    if (stateful_.size())
    {
        // The motors' forces at the state (a latch's, for its work)
        prescriptions();

        const rigidBodyModelWorkspace& ws = workspace();
        startRestraints(state_, ws);
        forAll(stateful_, si)
        {
            stateful_[si].commit(state_, ws);
        }
    }
    restraintsCommitted_ = true;
}


void Foam::RBD::rigidBodyMotion::newTime()
{
    // The restraints with states of their own start their step here
    if (!restraintsCommitted_)
    {
        commitRestraints();
    }

    state0_ = state_;
    nSolves_ = 0;
    provisionalStart_ = false;
}


void Foam::RBD::rigidBodyMotion::solve
(
    const scalar t,
    const scalar deltaT,
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    forAll(tauGiven_, i)
    {
        tauGiven_[i] = tau[i];
    }
    externalForces_ = false;
    forAll(fxGiven_, i)
    {
        fxGiven_[i] = fx[i];
        externalForces_ = externalForces_ || (mag(fx[i]) > 0);
    }

    deltaT_ = deltaT;
    momentsValid_ = false;
    restraintsCommitted_ = false;

    initialAcceleration();

    state_.t() = t;
    state_.deltaT() = deltaT;

    for (label iter = 0; iter < nIter_; ++iter)
    {
        solver_->solve(state0_, state_, *this, nSolves_ == 0);
        ++nSolves_;

        // The prescribed rates met at the end of the solve, whatever the
        // relaxation and the scheme left
        if (prescriptions_.size())
        {
            prescribe(state_);
            model_.constrainState(state_, ws_, prescriptions_);
        }
    }

    // The solver's last evaluation was at an intermediate state
    wsValid_ = false;

    checkSingularities();
}


const Foam::UPtrList<Foam::RBD::prescription>&
Foam::RBD::rigidBodyMotion::prescriptions()
{
    if (!momentsValid_ && prescriptions_.size())
    {
        evaluate(state_, ws_.qDdotScratch);
        momentsValid_ = true;
    }
    return prescribing_;
}


void Foam::RBD::rigidBodyMotion::restraintForces
(
    scalarField& tau,
    Field<spatialVector>& fx
)
{
    // The motors' forces (a moment on its body and the reaction)
    const UPtrList<prescription>& P = prescriptions();
    forAll(P, s)
    {
        P[s].addMotorForce(tau, fx);
    }

    const rigidBodyModelWorkspace& ws = workspace();
    startRestraints(state_, ws);

    forAll(restraints_, ri)
    {
        restraints_[ri].restrain(tau, fx, state_, ws);
    }
}


Foam::spatialTransform Foam::RBD::rigidBodyMotion::X0
(
    const label bodyID
) const
{
    return model_.X0(bodyID, workspace());
}


Foam::spatialVector Foam::RBD::rigidBodyMotion::v
(
    const label bodyID,
    const vector& p
) const
{
    return model_.v(bodyID, p, workspace());
}


bool Foam::RBD::rigidBodyMotion::read(const dictionary& dict)
{
    readCoeffs(dict);
    return true;
}


void Foam::RBD::rigidBodyMotion::write(Ostream& os) const
{
    model_.write(os);

    if (restraints_.size())
    {
        os.beginBlock("restraints");
        forAll(restraints_, ri)
        {
            os.beginBlock(restraints_[ri].name());
            restraints_[ri].write(os);
            os.endBlock();
        }
        os.endBlock();
    }

    coupling_->write(os);
    os.writeEntry("nIter", nIter_);
    state_.write(os);
    writeRestraintStates(os);
}


void Foam::RBD::rigidBodyMotion::writeRestraintStates(Ostream& os) const
{
    bool any = false;
    forAll(stateful_, si)
    {
        OStringStream entries;
        if (stateful_[si].writeState(entries))
        {
            if (!any)
            {
                os.beginBlock("restraintStates");
                any = true;
            }
            os.beginBlock(stateful_[si].name());
            os.writeQuoted(entries.str(), false);
            os.endBlock();
        }
    }
    if (any)
    {
        os.endBlock();
    }
}
