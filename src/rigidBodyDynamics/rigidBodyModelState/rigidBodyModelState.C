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

#include "rigidBodyModelState.H"
#include "IOstreams.H"
#include "keywordTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

addRigidBodyCommonKeywords
(
    coefficients, State, "q", "qDot", "qDdot", "t", "deltaT"
);

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodyModelState::readField
(
    const dictionary& dict,
    const word& key,
    const label nDoF,
    scalarField& f
)
{
    scalarField values;
    if (!dict.readIfPresent(key, values))
    {
        return;
    }

    if (values.size() != nDoF)
    {
        FatalIOErrorInFunction(dict.lookup(key))
            << "Entry " << key << " has " << values.size()
            << " values; the model has " << nDoF << " degrees of freedom"
            << nl << exit(FatalIOError);
    }

    forAll(values, i)
    {
        if (!std::isfinite(values[i]))
        {
            FatalIOErrorInFunction(dict.lookup(key))
                << "Entry " << key << " holds " << values[i]
                << " at index " << i << nl
                << exit(FatalIOError);
        }
    }

    f = values;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodyModelState::rigidBodyModelState(const label nDoF)
:
    q_(nDoF, Zero),
    qDot_(nDoF, Zero),
    qDdot_(nDoF, Zero),
    t_(0),
    deltaT_(0),
    qDdotValid_(false)
{}


Foam::RBD::rigidBodyModelState::rigidBodyModelState
(
    const label nDoF,
    const dictionary& dict
)
:
    rigidBodyModelState(nDoF)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodyModelState::read(const dictionary& dict)
{
    const label nDoF = this->nDoF();

    readField(dict, "q", nDoF, q_);
    readField(dict, "qDot", nDoF, qDot_);
    if (dict.found("qDdot"))
    {
        readField(dict, "qDdot", nDoF, qDdot_);
        qDdotValid_ = true;
    }
    dict.readIfPresent("t", t_);
    dict.readIfPresent("deltaT", deltaT_);
}


void Foam::RBD::rigidBodyModelState::write(dictionary& dict) const
{
    dict.add("q", q_, true);
    dict.add("qDot", qDot_, true);
    dict.add("qDdot", qDdot_, true);
    dict.add("t", t_, true);
    dict.add("deltaT", deltaT_, true);
}


void Foam::RBD::rigidBodyModelState::write(Ostream& os) const
{
    const unsigned int precision = os.precision(17);

    os.writeEntry("q", q_);
    os.writeEntry("qDot", qDot_);
    os.writeEntry("qDdot", qDdot_);
    os.writeEntry("t", t_);
    os.writeEntry("deltaT", deltaT_);

    os.precision(precision);
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Istream& Foam::RBD::operator>>(Istream& is, rigidBodyModelState& s)
{
    is  >> s.q_ >> s.qDot_ >> s.qDdot_ >> s.t_ >> s.deltaT_;
    s.qDdotValid_ = true;

    is.check(FUNCTION_NAME);
    return is;
}


Foam::Ostream& Foam::RBD::operator<<(Ostream& os, const rigidBodyModelState& s)
{
    os  << s.q_ << token::SPACE << s.qDot_ << token::SPACE << s.qDdot_
        << token::SPACE << s.t_ << token::SPACE << s.deltaT_;

    os.check(FUNCTION_NAME);
    return os;
}
