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

#include "fluidAddedMass.H"
#include "fvm.H"
#include "fvc.H"
#include "fixedGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidAddedMass::fluidAddedMass
(
    const fvMesh& mesh,
    const word& rhoName,
    const scalar rhoInf,
    const RBD::rigidBodyModel& model,
    const RBD::rigidBodyModelState& s,
    const labelList& bodyIDs,
    const List<labelHashSet>& patches
)
:
    mesh_(mesh),
    rhoName_(rhoName),
    rhoInf_(rhoInf),
    bodyIDs_(bodyIDs),
    patches_(patches),
    p_(model.nDoF()),
    state_(s),
    ws_(model),
    J_(bodyIDs.size(), List<spatialVector>(model.nDoF(), Zero)),
    fb_(bodyIDs.size(), Zero),
    A_(model.nDoF(), Zero),
    Aprev_(model.nDoF(), Zero),
    length_(RBD::dofLengths(model)),
    interval_(1),
    countdown_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::fluidAddedMass::constraint(const label patchi) const
{
    return polyPatch::constraintType(mesh_.boundaryMesh()[patchi].type());
}


Foam::wordList Foam::fluidAddedMass::patchTypes() const
{
    // The case's pressure tells where it is fixed (an atmosphere)
    const volScalarField* pCase = nullptr;
    for (const word& name : {"p_rgh", "p"})
    {
        if (!pCase)
        {
            pCase = mesh_.findObject<volScalarField>(name);
        }
    }

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    wordList types(pbm.size(), zeroGradientFvPatchScalarField::typeName);

    forAll(pbm, patchi)
    {
        bool body = false;
        for (const labelHashSet& ps : patches_)
        {
            body = body || ps.found(patchi);
        }

        if (polyPatch::constraintType(pbm[patchi].type()))
        {
            types[patchi] = pbm[patchi].type();
        }
        else if (body)
        {
            types[patchi] = fixedGradientFvPatchScalarField::typeName;
        }
        else if (pCase && pCase->boundaryField()[patchi].fixesValue())
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
    }

    return types;
}


Foam::IOobject Foam::fluidAddedMass::scratch(const word& name) const
{
    return IOobject
    (
        "rigidBodyAddedMass:" + name,
        mesh_.time().timeName(),
        mesh_,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
}


Foam::tmp<Foam::volScalarField> Foam::fluidAddedMass::rho() const
{
    if (rhoName_ == "rhoInf")
    {
        return tmp<volScalarField>::New
        (
            scratch("rho"),
            mesh_,
            dimensionedScalar("rhoInf", dimDensity, rhoInf_)
        );
    }

    return mesh_.lookupObject<volScalarField>(rhoName_);
}


void Foam::fluidAddedMass::jacobian
(
    const RBD::rigidBodyModel& model,
    const RBD::rigidBodyModelState& s
)
{
    state_.q() = s.q();

    for (label j = 0; j < model.nDoF(); ++j)
    {
        state_.qDot() = Zero;
        state_.qDot()[j] = 1;
        model.kinematics(state_, ws_);

        forAll(bodyIDs_, bi)
        {
            // The body's origin r moves at v0; the point of the body at
            // the global origin at v0 - omega x r
            const spatialVector v0(model.v(bodyIDs_[bi], Zero, ws_));
            const vector r(model.globalPoint(bodyIDs_[bi], Zero, ws_));

            J_[bi][j] = spatialVector(v0.w(), v0.l() - (v0.w() ^ r));
        }
    }
}


Foam::dictionary Foam::fluidAddedMass::solverControls() const
{
    // The case's own for its pressure, converged fully
    dictionary controls;
    const dictionary& solvers = mesh_.solutionDict().subDict("solvers");
    for (const word& name : {"p_rghFinal", "p_rgh", "pFinal", "p"})
    {
        if (controls.empty() && solvers.found(name))
        {
            controls = mesh_.solverDict(name);
        }
    }
    if (controls.empty())
    {
        controls.add("solver", "PCG");
        controls.add("preconditioner", "DIC");
    }
    controls.set("tolerance", 1e-5);
    controls.set("relTol", 0);
    return controls;
}


void Foam::fluidAddedMass::setGradients
(
    const label j,
    const volScalarField& rho,
    volScalarField& p
) const
{
    // dp/dn = -rho (a . n) on the bodies' faces, n out of the fluid
    forAll(bodyIDs_, bi)
    {
        const spatialVector& Jb = J_[bi][j];

        for (const label patchi : patches_[bi])
        {
            if (constraint(patchi))
            {
                continue;
            }
            fixedGradientFvPatchScalarField& pp =
                refCast<fixedGradientFvPatchScalarField>
                (
                    p.boundaryFieldRef()[patchi]
                );
            const vectorField& Cf = mesh_.Cf().boundaryField()[patchi];
            const vectorField nf(mesh_.Sf().boundaryField()[patchi]
                /mesh_.magSf().boundaryField()[patchi]);
            const scalarField& rhob = rho.boundaryField()[patchi];

            forAll(pp, facei)
            {
                const vector a(Jb.l() + (Jb.w() ^ Cf[facei]));
                pp.gradient()[facei] = -rhob[facei]*(a & nf[facei]);
            }
        }
    }
}


void Foam::fluidAddedMass::bodyForces(const volScalarField& p)
{
    forAll(bodyIDs_, bi)
    {
        fb_[bi] = Zero;
        for (const label patchi : patches_[bi])
        {
            if (constraint(patchi))
            {
                continue;
            }
            const vectorField& Cf = mesh_.Cf().boundaryField()[patchi];
            const vectorField& Sf = mesh_.Sf().boundaryField()[patchi];
            const scalarField& pb = p.boundaryField()[patchi];
            forAll(pb, facei)
            {
                const vector f(pb[facei]*Sf[facei]);
                fb_[bi] += spatialVector(Cf[facei] ^ f, f);
            }
        }
        reduce(fb_[bi], sumOp<spatialVector>());
    }
}


void Foam::fluidAddedMass::compute
(
    const RBD::rigidBodyModel& model,
    const RBD::rigidBodyModelState& s
)
{
    const label nDoF = model.nDoF();

    jacobian(model, s);

    const tmp<volScalarField> trho(rho());
    const volScalarField& rho = trho();

    // The fluid solver's pressure equation weighs the faces by the
    // interpolate of 1/rho
    const surfaceScalarField rAf
    (
        "rigidBodyAddedMass:rAf",
        fvc::interpolate(1/rho)
    );

    const dictionary controls(solverControls());

    const wordList types(patchTypes());

    for (label j = 0; j < nDoF; ++j)
    {
        if (!p_.set(j))
        {
            p_.set
            (
                j,
                new volScalarField
                (
                    scratch("p" + Foam::name(j)),
                    mesh_,
                    dimensionedScalar(dimPressure, Zero),
                    types
                )
            );
        }
        volScalarField& p = p_[j];

        setGradients(j, rho, p);

        fvScalarMatrix pEqn(fvm::laplacian(rAf, p));
        pEqn.setReference
        (
            Pstream::master() && mesh_.nCells() ? 0 : -1,
            0
        );
        pEqn.solve(controls);

        // The pressure's force and moment (about the origin) on each
        // body, and its joint forces Q_i: A_ij = -Q_i
        bodyForces(p);

        for (label i = 0; i < nDoF; ++i)
        {
            scalar Q = 0;
            forAll(bodyIDs_, bi)
            {
                Q += (J_[bi][i].w() & fb_[bi].w()) + (J_[bi][i].l() & fb_[bi].l());
            }
            A_(i, j) = -Q;
        }
    }

    // Symmetric in theory: made so
    for (label i = 0; i < nDoF; ++i)
    {
        for (label j = i + 1; j < nDoF; ++j)
        {
            const scalar a = 0.5*(A_(i, j) + A_(j, i));
            A_(i, j) = a;
            A_(j, i) = a;
        }
    }

}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fluidAddedMass::update
(
    const RBD::rigidBodyModel& model,
    const RBD::rigidBodyModelState& s
)
{
    if (countdown_ > 0)
    {
        --countdown_;
        return false;
    }

    Aprev_ = A_;
    compute(model, s);

    // Its relative change since the last computation sets the interval;
    // each entry over its degrees of freedom's lengths is a mass (kg), so
    // that the change weighs the entries alike at any Froude scale
    scalar d2 = 0, a2 = 0;
    for (label i = 0; i < A_.m(); ++i)
    {
        for (label j = 0; j < A_.n(); ++j)
        {
            const scalar l2 = sqr(length_[i]*length_[j]);
            d2 += sqr(A_(i, j) - Aprev_(i, j))/l2;
            a2 += sqr(A_(i, j))/l2;
        }
    }
    const scalar change = sqrt(d2/max(a2, VSMALL));

    if (change < 0.02)
    {
        interval_ = min(2*interval_, 32);
    }
    else if (change > 0.08)
    {
        interval_ = max(interval_/2, 1);
    }
    countdown_ = interval_ - 1;

    return true;
}
