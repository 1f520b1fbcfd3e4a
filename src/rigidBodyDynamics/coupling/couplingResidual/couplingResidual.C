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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Whether each degree of freedom of the model turns its body: its motion
//  subspace column has an angular part (at q = 0)
Foam::boolList rotations(const Foam::RBD::rigidBodyModel& model)
{
    using namespace Foam;

    boolList rotation(model.nDoF(), false);
    const scalarField q(model.nDoF(), Zero);
    const scalarField qDot(model.nDoF(), Zero);

    for (const RBD::joint& J : model.joints())
    {
        if (J.nDoF() == 0)
        {
            continue;
        }
        RBD::joint::XSvc xsvc;
        J.jcalc(xsvc, q, qDot);
        for (label k = 0; k < J.nDoF(); ++k)
        {
            rotation[J.qIndex() + k] = mag(xsvc.S[k].w()) > SMALL;
        }
    }

    return rotation;
}

//- A non-negative entry, def if absent
Foam::scalar readOrDefault
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar def
)
{
    return dict.found(key) ? Foam::RBD::readNonNegative(dict, key) : def;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::couplingResidual::couplingResidual
(
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    tolerance_(0.1),
    floor_(0.1),
    floorRotation_(0.1),
    rotation_(rotations(model)),
    peak_(model.nDoF(), Zero),
    peakPrev_(model.nDoF(), Zero),
    sign_(model.nDoF(), Zero),
    residual_(model.nDoF(), Zero),
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
    floor_ = readOrDefault(dict, "couplingFloor", 0.1);
    floorRotation_ = readOrDefault(dict, "couplingFloorRotation", 0.1);
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
            max(mag(a[i]), rotation_[i] ? floorRotation_ : floor_)
        );
        residual_[i] = mag(d[i])/max(scale, VSMALL);
    }
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
