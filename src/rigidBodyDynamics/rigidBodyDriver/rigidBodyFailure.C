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

#include "rigidBodyFailure.H"
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyFailure::rigidBodyFailure
(
    const Time& runTime,
    const word& name,
    const fileName& dir,
    const dictionary& coeffs
)
:
    time_(runTime),
    name_(name),
    dir_(dir),
    coeffs_(coeffs)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyFailure::restraintCauses
(
    const rigidBodyMotion& motion,
    OStringStream& causes
) const
{
    const rigidBodyModel& model = motion.model();
    const rigidBodyModelState& state = motion.state();
    const scalar deltaT = time_.deltaTValue();

    // Restraints whose force is not finite at the state, and the three
    // largest of the others
    const PtrList<restraint>& restraints = motion.restraints();
    const rigidBodyModelWorkspace& ws = motion.workspace();
    scalarField tau(model.nDoF());
    Field<spatialVector> fx(model.nBodies());
    List<spatialVector> fr(restraints.size(), Zero);
    scalarList size(restraints.size(), Zero);
    forAll(restraints, ri)
    {
        const restraint& r = restraints[ri];
        tau = Zero;
        fx = Zero;
        r.restrain(tau, fx, state, ws);
        fr[ri] = fx[model.masterID(r.bodyID())];
        if (!allFinite(tau) || !allFinite(fx))
        {
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model.name(r.bodyID()) << "): its force"
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
                << " on body " << model.name(r.bodyID()) << "): force "
                << fr[ri].l() << " N, moment " << fr[ri].w() << " N m at t = "
                << state.t() << nl;
        }
    }

    // Restraints faster than the step resolves
    for (const restraint& r : motion.restraints())
    {
        restraintReport rr;
        r.describe(ws, rr);
        const scalar T = rr.period("natural");
        if (T > 0 && T < 10*deltaT)
        {
            causes
                << "    restraint " << r.name() << " (" << r.type()
                << " on body " << model.name(r.bodyID()) << "): natural"
                << " period " << T << " s, " << T/deltaT << " steps of"
                << " deltaT " << deltaT << ": give it 10 steps or more"
                << " (deltaT below " << T/10 << " s; rigidBodySim -report"
                << " lists every period)" << nl;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::RBD::rigidBodyFailure::externalForces
(
    const rigidBodyModel& model,
    const Field<spatialVector>& fx
) const
{
    forAll(fx, bodyID)
    {
        if (!allFinite(fx[bodyID]))
        {
            return
                "The external (fluid) force on body " + model.name(bodyID)
              + " for the step to t = " + Foam::name(time_.value())
              + " is not finite: moment " + Foam::name(fx[bodyID].w())
              + ", force " + Foam::name(fx[bodyID].l()) + " (global axes,"
              + " about the global origin).\nThe flow has failed before"
              + " the bodies moved: look at the flow solution of this step"
              + " (Courant number, pressure solver)";
        }
    }
    return string::null;
}


Foam::string Foam::RBD::rigidBodyFailure::state
(
    const rigidBodyMotion& motion
) const
{
    const rigidBodyModelState& state = motion.state();
    const scalarField* fields[3] = {&state.q(), &state.qDot(), &state.qDdot()};
    const char* names[3] = {"q", "qDot", "qDdot"};

    for (label f = 0; f < 3; ++f)
    {
        const scalarField& values = *fields[f];
        forAll(values, i)
        {
            if (!allFinite(values[i]))
            {
                return
                    "The step from t = " + Foam::name(motion.state0().t())
                  + " to " + Foam::name(time_.value()) + " gave "
                  + names[f] + " = " + Foam::name(values[i]) + " at "
                  + motion.model().dofDescription(i);
            }
        }
    }
    return string::null;
}


Foam::string Foam::RBD::rigidBodyFailure::rows
(
    const rigidBodyTables& tables
) const
{
    const List<tableRow>& rows = tables.rows();
    forAll(rows, bi)
    {
        const tableRow& row = rows[bi];
        for (label k = 0; k < row.size(); ++k)
        {
            if (!allFinite(row[k]))
            {
                return
                    "The " + row.name(k) + " of body " + tables.names()[bi]
                  + " at t = " + Foam::name(row[0]) + " (column "
                  + Foam::name(k + 1) + " of its table) is "
                  + Foam::name(row[k]);
            }
        }
    }
    return string::null;
}


Foam::string Foam::RBD::rigidBodyFailure::status
(
    const rigidBodyMotion& motion,
    const label bodyID,
    const spatialTransform& CofR,
    const spatialVector& vCofR
) const
{
    if (!allFinite(CofR.r()) || !allFinite(CofR.E()) || !allFinite(vCofR))
    {
        return
            "The status of body " + motion.model().name(bodyID) + " at t = "
          + Foam::name(motion.state().t()) + " is not finite: centre of"
          + " rotation " + Foam::name(CofR.r()) + ", velocity "
          + Foam::name(vCofR);
    }
    return string::null;
}


void Foam::RBD::rigidBodyFailure::stop
(
    const rigidBodyMotion& motion,
    rigidBodyTables& tables,
    const string& what
) const
{
    const rigidBodyModelState& state = motion.state();

    OStringStream causes;
    restraintCauses(motion, causes);

    // Numbers of extreme magnitude in the coefficients
    extremeEntries(coeffs_, string::null, causes);

    // The last good state, to inspect or start from
    const fileName lastGood(dir_/"rigidBodyMotionState.lastGood");
    if (Pstream::master())
    {
        mkDir(dir_);
        OFstream os(lastGood);
        os.precision(IOstream::defaultPrecision());
        state.write(os);

        tables.flush();
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
