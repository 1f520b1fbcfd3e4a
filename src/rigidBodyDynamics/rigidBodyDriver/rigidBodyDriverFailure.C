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

#include "rigidBodyDriver.H"
#include "allFinite.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Append to os every entry of dict (at any depth, its keywords joined by
//  '/') that holds a number beyond 1e100 or, not zero, below 1e-100 in
//  magnitude: the likely cause of an overflow
void extremeEntries
(
    const Foam::dictionary& dict,
    const Foam::string& path,
    Foam::OStringStream& os
)
{
    for (const Foam::entry& e : dict)
    {
        const Foam::string key
        (
            path.empty() ? Foam::string(e.keyword()) : path + "/" + e.keyword()
        );
        if (e.isDict())
        {
            extremeEntries(e.dict(), key, os);
            continue;
        }
        for (const Foam::token& t : e.stream())
        {
            const Foam::scalar x =
                t.isNumber() ? Foam::mag(t.number()) : Foam::scalar(0);
            if (x > 1e100 || (x > 0 && x < 1e-100))
            {
                os  << "    entry " << key.c_str() << ": " << t.number()
                    << Foam::nl;
                break;
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::RBD::rigidBodyDriver::dofName(const label i) const
{
    // The body (not a jointBody of its composite joint) that the degree of
    // freedom moves relative to its parent
    const rigidBodyModel& m = model();
    for (const word& name : m.bodyNames())
    {
        const label bodyID = m.bodyID(name);
        if (m.isMerged(bodyID) || !m.bodyDoFs(bodyID).found(i))
        {
            continue;
        }
        const joint& J = m.joints()[bodyID];
        const bool composite = m.bodyDoFs(bodyID).size() > J.nDoF();
        return
            "degree of freedom " + Foam::name(i) + ", of the joint of body "
          + name + " (" + (composite ? word("composite") : J.type()) + ")";
    }
    return "degree of freedom " + Foam::name(i);
}


void Foam::RBD::rigidBodyDriver::checkExternalForces
(
    const Field<spatialVector>& fx
)
{
    forAll(fx, bodyID)
    {
        if (!allFinite(fx[bodyID]))
        {
            stepFailed
            (
                "The external (fluid) force on body " + model().name(bodyID)
              + " for the step to t = " + Foam::name(time_.value())
              + " is not finite: moment " + Foam::name(fx[bodyID].w())
              + ", force " + Foam::name(fx[bodyID].l()) + " (global axes,"
              + " about the global origin).\nThe flow has failed before"
              + " the bodies moved: look at the flow solution of this step"
              + " (Courant number, pressure solver)"
            );
        }
    }
}


void Foam::RBD::rigidBodyDriver::checkState()
{
    const rigidBodyModelState& state = motion_.state();
    const scalarField* fields[3] = {&state.q(), &state.qDot(), &state.qDdot()};
    const char* names[3] = {"q", "qDot", "qDdot"};

    for (label f = 0; f < 3; ++f)
    {
        const scalarField& values = *fields[f];
        forAll(values, i)
        {
            if (!allFinite(values[i]))
            {
                stepFailed
                (
                    "The step from t = " + Foam::name(motion_.state0().t())
                  + " to " + Foam::name(time_.value()) + " gave "
                  + names[f] + " = " + Foam::name(values[i]) + " at "
                  + dofName(i)
                );
            }
        }
    }
}


void Foam::RBD::rigidBodyDriver::checkRows()
{
    forAll(rows_, bi)
    {
        const tableRow& row = rows_[bi];
        for (label k = 0; k < row.size(); ++k)
        {
            if (!allFinite(row[k]))
            {
                stepFailed
                (
                    "The " + row.name(k) + " of body " + names_[bi]
                  + " at t = " + Foam::name(row[0]) + " (column "
                  + Foam::name(k + 1) + " of its table) is "
                  + Foam::name(row[k])
                );
            }
        }
    }
}


void Foam::RBD::rigidBodyDriver::restraintCauses(OStringStream& causes)
{
    const rigidBodyModelState& state = motion_.state();
    const scalar deltaT = time_.deltaTValue();

    // Restraints whose force is not finite at the state, and the three
    // largest of the others
    const PtrList<restraint>& restraints = motion_.restraints();
    const rigidBodyModelWorkspace& ws = motion_.workspace();
    scalarField tau(model().nDoF());
    Field<spatialVector> fx(model().nBodies());
    List<spatialVector> fr(restraints.size(), Zero);
    scalarList size(restraints.size(), Zero);
    forAll(restraints, ri)
    {
        const restraint& r = restraints[ri];
        tau = Zero;
        fx = Zero;
        r.restrain(tau, fx, state, ws);
        fr[ri] = fx[model().masterID(r.bodyID())];
        if (!allFinite(tau) || !allFinite(fx))
        {
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model().name(r.bodyID()) << "): its force"
                << " is not finite at t = " << state.t() << ": look at its"
                << " coefficients" << nl;
        }
        else
        {
            size[ri] = mag(fr[ri].l()) + mag(fr[ri].w()) + sum(mag(tau));
        }
    }
    labelList order;
    sortedOrder(size, order);
    for (label k = order.size() - 1; k >= max(order.size() - 3, 0); --k)
    {
        const label ri = order[k];
        if (size[ri] > 0)
        {
            const restraint& r = restraints[ri];
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model().name(r.bodyID()) << "): force "
                << fr[ri].l() << " N, moment " << fr[ri].w() << " N m at t = "
                << state.t() << nl;
        }
    }

    // Restraints faster than the step resolves
    for (const restraint& r : motion_.restraints())
    {
        const scalar T = r.naturalPeriod();
        if (T > 0 && T < 10*deltaT)
        {
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model().name(r.bodyID()) << "): natural"
                << " period " << T << " s, " << T/deltaT << " steps of"
                << " deltaT " << deltaT << ": give it 10 steps or more"
                << " (deltaT below " << T/10 << " s; rigidBodySim -report"
                << " lists every period)" << nl;
        }
    }
}


void Foam::RBD::rigidBodyDriver::stepFailed(const string& what)
{
    floatingPointTraps traps;

    // Back to the start of the step, the last state that was finite, with
    // no row or coupling report of the failed step due (where FatalError
    // throws, as in a test, the driver can go on from there)
    motion_.state() = motion_.state0();
    motion_.step().fail();
    const rigidBodyModelState& state = motion_.state();

    OStringStream causes;
    restraintCauses(causes);

    // Numbers of extreme magnitude in the coefficients
    extremeEntries(coeffs_, string::null, causes);

    // The last good state, to inspect or start from
    const fileName dir
    (
        time_.globalPath()/"postProcessing"/name_/startTimeName_
    );
    const fileName lastGood(dir/"rigidBodyMotionState.lastGood");
    if (Pstream::master())
    {
        mkDir(dir);
        OFstream os(lastGood);
        os.precision(IOstream::defaultPrecision());
        state.write(os);

        forAll(tables_, bi)
        {
            tables_[bi].flush();
        }
    }

    FatalErrorInFunction
        << "The rigid-body motion (" << name_ << ") has failed." << nl
        << what.c_str() << nl;

    if (!causes.str().empty())
    {
        FatalError
            << "What may have caused it:" << nl
            << causes.str().c_str();
    }

    FatalError
        << "The last good state, at t = " << state.t() << ", is written to"
        << nl << "    " << lastGood << nl
        << "(to start from it, copy it to <time>/uniform/"
        << "rigidBodyMotionState)" << nl
        << exit(FatalError);
}
