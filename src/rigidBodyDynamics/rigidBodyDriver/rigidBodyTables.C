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

#include "rigidBodyTables.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyTables::rigidBodyTables
(
    const fileName& dir,
    const dictionary& coeffs,
    const rigidBodyModel& model,
    const bool externalForces
)
:
    dir_(dir),
    externalForces_(externalForces),
    names_(coeffs.subDict("bodies").toc()),
    bodyIDs_(names_.size()),
    dofs_(names_.size()),
    rows_(names_.size()),
    tauR_(model.nDoF(), Zero),
    fxR_(model.nBodies(), Zero)
{
    forAll(names_, bi)
    {
        bodyIDs_[bi] = model.bodyID(names_[bi]);
        dofs_[bi] = model.bodyDoFs(bodyIDs_[bi]);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyTables::fillRow
(
    const label bi,
    rigidBodyMotion& motion,
    const couplingResidual& residual,
    const Field<spatialVector>& fx,
    tableRow& row
) const
{
    const rigidBodyModel& model = motion.model();
    const rigidBodyModelWorkspace& ws = motion.workspace();
    const rigidBodyModelState& state = motion.state();

    const label id = bodyIDs_[bi];
    const label master = model.masterID(id);
    const rigidBody& body = model.bodies()[master];
    const spatialTransform X(model.X0(id, ws));
    const spatialVector v(model.v(id, Zero, ws));

    row.start();
    row.add("t", state.t());
    row.add("CofR", X.r());
    row.add("Orientation", X.E());
    row.add("v", v.l());
    row.add("omega", v.w());
    for (const label i : dofs_[bi])
    {
        row.add("q" + Foam::name(i), state.q()[i]);
    }
    for (const label i : dofs_[bi])
    {
        row.add("qDot" + Foam::name(i), state.qDot()[i]);
    }
    if (externalForces_)
    {
        row.add("fluidForce", fx[master].l());
        row.add("fluidMoment", fx[master].w());
    }
    row.add("restraintForce", fxR_[master].l());
    row.add("restraintMoment", fxR_[master].w());
    for (const label i : dofs_[bi])
    {
        row.add("restraintJointForce" + Foam::name(i), tauR_[i]);
    }
    row.add("kineticEnergy", body.kineticEnergy(ws.v[master]));
    row.add
    (
        "potentialEnergy",
        -body.m()*(model.g() & model.globalPoint(master, body.c(), ws))
    );
    if (externalForces_)
    {
        label dof = -1;
        row.add("couplingResidual", residual.largest(dofs_[bi], dof));
    }
    for (const restraint& r : motion.restraints())
    {
        if (r.bodyID() == id)
        {
            r.addColumns(row);
        }
    }

    // The prescriptions' own columns (a prescribed joint's driving force)
    const UPtrList<prescription>& prescriptions = motion.prescriptions();
    forAll(prescriptions, s)
    {
        if (prescriptions[s].bodyID() == id)
        {
            prescriptions[s].addMotorColumns(row);
        }
    }
    row.end();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyTables::restraintForces(rigidBodyMotion& motion)
{
    if (!Pstream::master())
    {
        return;
    }
    tauR_ = Zero;
    fxR_ = Zero;
    motion.restraintForces(tauR_, fxR_);
}


void Foam::RBD::rigidBodyTables::fill
(
    rigidBodyMotion& motion,
    const couplingResidual& residual,
    const Field<spatialVector>& fx
)
{
    if (!Pstream::master())
    {
        return;
    }
    forAll(rows_, bi)
    {
        fillRow(bi, motion, residual, fx, rows_[bi]);
    }
}


void Foam::RBD::rigidBodyTables::write(const bool flush)
{
    if (!Pstream::master())
    {
        return;
    }

    if (tables_.empty())
    {
        mkDir(dir_);

        tables_.setSize(names_.size());
        forAll(names_, bi)
        {
            tables_.set(bi, new OFstream(dir_/names_[bi] + ".dat"));
            OFstream& os = tables_[bi];
            os.precision(IOstream::defaultPrecision());
            os  << "# Motion of body " << names_[bi] << ": SI units; forces"
                << " in global axes, moments about the global origin" << nl;
            rows_[bi].writeHeader(os);
        }
    }

    forAll(rows_, bi)
    {
        OFstream& os = tables_[bi];
        rows_[bi].write(os);
        if (flush)
        {
            os.flush();
        }
    }
}


void Foam::RBD::rigidBodyTables::flush()
{
    forAll(tables_, bi)
    {
        tables_[bi].flush();
    }
}
