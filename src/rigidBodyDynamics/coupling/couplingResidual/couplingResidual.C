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

#include "couplingResidual.H"
#include "rigidBodyEntries.H"
#include "couplingScales.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// The old absolute floors are read to say that they are no longer used
addRigidBodyCommonKeywords
(
    coefficients, Residual, "couplingTolerance", "couplingFloorFraction",
    "couplingFloorFractionRotation", "couplingFloorAcceleration",
    "couplingFloor", "couplingFloorRotation"
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingResidual::couplingResidual
(
    const dictionary& dict,
    const rigidBodyModel& model,
    const bool coupled
)
:
    tolerance_(0.1),
    rotation_(rotationDoFs(model)),
    floorFraction_(0.01),
    floorFractionRotation_(0.001),
    floorAcceleration_(0),
    gyration_(dofLengths(model)),
    floor_(model.nDoF(), Zero),
    g_(mag(model.g())),
    coupled_(coupled),
    peak_(model.nDoF(), Zero),
    peakPrev_(model.nDoF(), Zero),
    sign_(model.nDoF(), Zero),
    residual_(model.nDoF(), Zero),
    free_(model.nDoF(), Zero),
    nMeasured_(0),
    max_(0),
    nSteps_(0),
    nFlagged_(0),
    worst_(-1),
    worstTime_(0),
    worstDoF_(-1)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::couplingResidual::read(const dictionary& dict)
{
    tolerance_ = dict.found("couplingTolerance")
        ? readPositive(dict, "couplingTolerance")
        : 0.1;

    for (const word key : {"couplingFloor", "couplingFloorRotation"})
    {
        if (dict.found(key))
        {
            FatalIOErrorInFunction(dict.lookup(key))
                << "Entry " << key << " in " << dict.dictName()
                << " is no longer read: an absolute floor is right at one"
                << " scale only." << nl
                << "    The floors now come from the model:"
                << " couplingFloorFraction |g| (translations) and"
                << " couplingFloorFractionRotation |g|/r (rotations, r the"
                << " radius of gyration about the joint's axis)." << nl
                << "    Remove " << key << ", or give couplingFloorFraction"
                << " (default 0.01) or couplingFloorFractionRotation"
                << " (default 0.001); see docs/coupling.md" << nl
                << exit(FatalIOError);
        }
    }

    floorFraction_ = dict.found("couplingFloorFraction")
        ? readNonNegative(dict, "couplingFloorFraction")
        : 0.01;
    floorFractionRotation_ = dict.found("couplingFloorFractionRotation")
        ? readNonNegative(dict, "couplingFloorFractionRotation")
        : 0.001;

    // The translation floor: a fraction of g, or given if there is no g;
    // the rotations' a fraction of g over their lengths, or without g the
    // translation floor in the ratio of the two fractions
    scalar floor = floorFraction_*g_;
    scalar floorRotation = floorFractionRotation_*g_;
    if (g_ < VSMALL)
    {
        if (dict.found("couplingFloorAcceleration"))
        {
            floorAcceleration_ =
                readNonNegative(dict, "couplingFloorAcceleration");
            floor = floorAcceleration_;
            floorRotation =
                floorFraction_ > 0
              ? floor*floorFractionRotation_/floorFraction_
              : 0;
        }
        else if (coupled_)
        {
            FatalIOErrorInFunction(dict)
                << "g is zero, so the coupling residual's floor has no"
                << " scale: give couplingFloorAcceleration [m/s^2] in "
                << dict.dictName() << ", the amplitude of translational"
                << " acceleration below which a body counts as at rest"
                << " (with gravity it is couplingFloorFraction |g|)" << nl
                << exit(FatalIOError);
        }
    }

    forAll(floor_, i)
    {
        floor_[i] = rotation_[i] ? floorRotation/gyration_[i] : floor;
    }
}


void Foam::RBD::couplingResidual::measure
(
    const scalarField& d,
    const scalarField& a
)
{
    forAll(residual_, i)
    {
        const scalar scale = max
        (
            max(peak_[i], peakPrev_[i]),
            max(mag(a[i]), floor_[i])
        );
        residual_[i] = mag(d[i])/max(scale, VSMALL);
    }
}


void Foam::RBD::couplingResidual::measure
(
    const scalarField& d,
    const scalarField& a,
    const UPtrList<rateConstraint>& prescriptions
)
{
    // Each motor's share of d taken out in turn (a motor on one degree of
    // freedom takes all of it)
    free_ = d;
    forAll(prescriptions, s)
    {
        const scalarField& m = prescriptions[s].motor;
        scalar md = 0, mm = 0;
        forAll(m, i)
        {
            md += m[i]*free_[i];
            mm += m[i]*m[i];
        }
        if (mm > 0)
        {
            forAll(m, i)
            {
                free_[i] -= md/mm*m[i];
            }
        }
    }
    measure(free_, a);
}


void Foam::RBD::couplingResidual::solved()
{
    max_ = residual_.size() ? max(residual_) : 0;
    ++nMeasured_;
}


bool Foam::RBD::couplingResidual::endStep
(
    const scalarField& a,
    const scalar t
)
{
    const bool measured = nMeasured_ > 0;
    nMeasured_ = 0;

    if (measured)
    {
        ++nSteps_;
        label worstDoF = -1;
        scalar worst = -1;
        forAll(residual_, i)
        {
            if (residual_[i] > worst)
            {
                worst = residual_[i];
                worstDoF = i;
            }
        }
        if (worst > tolerance_)
        {
            ++nFlagged_;
        }
        if (worst > worst_)
        {
            worst_ = worst;
            worstTime_ = t;
            worstDoF_ = worstDoF;
        }
    }

    // The amplitudes: a half cycle ends where the acceleration changes
    // sign and reaches a quarter of the peak before (noise about zero does
    // not end one)
    forAll(a, i)
    {
        const scalar s = a[i] < 0 ? -1 : 1;
        if (s == sign_[i] || mag(a[i]) < 0.25*peak_[i])
        {
            peak_[i] = max(peak_[i], mag(a[i]));
        }
        else
        {
            peakPrev_[i] = peak_[i];
            peak_[i] = mag(a[i]);
            sign_[i] = s;
        }
    }

    return measured;
}


void Foam::RBD::couplingResidual::writeAmplitudes(Ostream& os) const
{
    os.writeEntry("couplingPeak", peak_);
    os.writeEntry("couplingPeakPrevious", peakPrev_);
    os.writeEntry("couplingPeakSign", sign_);
}


void Foam::RBD::couplingResidual::readAmplitudes(const dictionary& stateDict)
{
    scalarField peak, peakPrev, sign;
    if
    (
        stateDict.readIfPresent("couplingPeak", peak)
     && stateDict.readIfPresent("couplingPeakPrevious", peakPrev)
     && stateDict.readIfPresent("couplingPeakSign", sign)
     && peak.size() == peak_.size()
     && peakPrev.size() == peak_.size()
     && sign.size() == peak_.size()
    )
    {
        peak_ = peak;
        peakPrev_ = peakPrev;
        sign_ = sign;
    }
}


Foam::scalar Foam::RBD::couplingResidual::largest
(
    const labelList& dofs,
    label& dof
) const
{
    scalar r = 0;
    dof = -1;
    for (const label i : dofs)
    {
        if (residual_[i] > r || dof < 0)
        {
            r = residual_[i];
            dof = i;
        }
    }
    return r;
}
