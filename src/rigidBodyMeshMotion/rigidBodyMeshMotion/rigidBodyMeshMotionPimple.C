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

// The coupling's plumbing into PIMPLE: residualControl's entry, the
// residual PIMPLE sees and the corrector that ends a step

#include "rigidBodyMeshMotion.H"
#include "rigidBodyEntries.H"
#include "volFields.H"
#include "pimpleControl.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rigidBodyMeshMotion::useResidualControl
(
    const entry& e,
    const dictionary& controls,
    const dictionary& pimpleDict
)
{
    const fvMesh& fvm = refCast<const fvMesh>(mesh());

    if (!e.isDict())
    {
        FatalIOErrorInFunction(controls)
            << "PIMPLE residualControl entry " << e.keyword()
            << " must be a dictionary: " << e.keyword()
            << " { tolerance 0.1; relTol 0; }" << nl
            << exit(FatalIOError);
    }
    const dictionary& d = e.dict();
    const scalar tol = RBD::readPositive(d, "tolerance");
    const scalar relTol = d.getOrDefault<scalar>("relTol", 0);
    if (relTol != 0)
    {
        FatalIOErrorInFunction(d)
            << "PIMPLE residualControl entry " << e.keyword()
            << ": relTol " << relTol << " must be 0. The coupling's"
            << " residual is already relative (to the motion's"
            << " amplitude), and the first corrector of a step has none"
            << " of its own, so a relative drop means nothing." << nl
            << exit(FatalIOError);
    }

    if
    (
        coeffs_.found("couplingTolerance")
     && coeffs_.get<scalar>("couplingTolerance") != tol
    )
    {
        FatalIOErrorInFunction(coeffs_)
            << "couplingTolerance "
            << coeffs_.get<scalar>("couplingTolerance")
            << " differs from the tolerance " << tol << " of PIMPLE"
            << " residualControl entry " << e.keyword() << " in "
            << fvm.solutionDict().name() << ": they are one tolerance."
            << " Give it once (residualControl's sets both)." << nl
            << exit(FatalIOError);
    }

    if (!pimpleDict.getOrDefault<bool>("moveMeshOuterCorrectors", false))
    {
        WarningInFunction
            << "PIMPLE residualControl entry " << e.keyword()
            << ": the mesh moves only in the first outer corrector"
            << " (moveMeshOuterCorrectors no), so the bodies are solved"
            << " once a step and the correctors cannot converge their"
            << " coupling; the loop will run all nOuterCorrectors."
            << endl;
    }

    driver_.setCouplingTolerance(tol);
    Info<< "rigidBodyMotion: outer correctors on demand: PIMPLE ends"
        << " them once the coupling's residual is below " << tol
        << " (residualControl " << e.keyword() << ")" << endl;
}


void Foam::rigidBodyMeshMotion::readResidualControl()
{
    const fvMesh& fvm = refCast<const fvMesh>(mesh());
    const word name(typeName);

    residualField_.reset
    (
        new volScalarField
        (
            IOobject
            (
                name,
                fvm.time().timeName(),
                fvm,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            fvm,
            dimensionedScalar(dimless, Zero)
        )
    );

    const dictionary& pimpleDict =
        fvm.solutionDict().subOrEmptyDict("PIMPLE");
    const dictionary& controls = pimpleDict.subOrEmptyDict("residualControl");

    for (const entry& e : controls)
    {
        const wordRe key(e.keyword());

        // An entry no field matches is counted converged by PIMPLE
        bool matched = false;
        for (const word& field : fvm.names())
        {
            matched = matched || key.match(field);
        }
        if (!matched)
        {
            WarningInFunction
                << "PIMPLE residualControl entry " << e.keyword()
                << " matches no field of the mesh: OpenFOAM counts it"
                << " converged without checking it. Fields: "
                << fvm.sortedNames<volScalarField>() << " (the rigid"
                << " bodies' coupling: " << name << ")" << endl;
        }

        if (!key.match(name))
        {
            continue;
        }

        useResidualControl(e, controls, pimpleDict);
    }
}


bool Foam::rigidBodyMeshMotion::finalCorrector() const
{
    // With no PIMPLE loop, or one that moves the mesh only in its first
    // corrector, every solve is its step's last
    const fvMesh& fvm = refCast<const fvMesh>(mesh());
    const HashTable<const pimpleControl*> pimples
    (
        fvm.lookupClass<pimpleControl>()
    );
    if (pimples.empty())
    {
        return true;
    }
    const bool moveMeshOuterCorrectors =
        fvm.solutionDict().subOrEmptyDict("PIMPLE")
       .getOrDefault<bool>("moveMeshOuterCorrectors", false);

    return !moveMeshOuterCorrectors || (*pimples.cbegin())->finalIter();
}


Foam::scalar Foam::rigidBodyMeshMotion::pimpleResidual() const
{
    // PIMPLE's residualControl ends the correctors, from the 2nd on, at the
    // first check that passes, and then runs one more.  The step's 1st
    // solve has the previous step's forces: never converged.  Its 2nd has
    // those of the fluid's 1st corrector, whose own fields have not
    // converged, so the next corrector can still move the forces by more
    // than the residual says: its residual counts twice, a margin that
    // keeps PIMPLE from stopping on a residual that only looks small.  So
    // a step takes 3 correctors at least
    const RBD::coupledStep& step = driver_.step();
    if (step.nCorrectors() <= 1)
    {
        return GREAT;
    }
    if (step.nCorrectors() == 2)
    {
        return 2*step.residual();
    }
    return step.residual();
}


void Foam::rigidBodyMeshMotion::setSolverPerformance()
{
    const scalar r = pimpleResidual();

    refCast<const fvMesh>(mesh()).setSolverPerformance
    (
        typeName,
        SolverPerformance<scalar>
        (
            typeName,
            typeName,
            r,
            r,
            driver_.step().nSolves()
        )
    );
}
