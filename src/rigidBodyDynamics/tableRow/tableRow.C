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

#include "tableRow.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::tableRow::tableRow()
:
    groups_(),
    components_(),
    values_(),
    k_(0),
    fixed_(false)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::tableRow::add
(
    const word& group,
    const word& component,
    const scalar v
)
{
    if (!fixed_)
    {
        groups_.append(group);
        components_.append(component);
        values_.append(v);
    }
    else if
    (
        k_ >= values_.size()
     || groups_[k_] != group
     || components_[k_] != component
    )
    {
        FatalErrorInFunction
            << "Column " << k_ + 1 << " of the table row is "
            << (component.empty() ? group : word(group + "." + component))
            << ", but the table's header has "
            << (k_ < values_.size() ? name(k_) : word("no such column"))
            << " there: the columns of every row must be those of the"
            << " first" << nl << abort(FatalError);
    }
    else
    {
        values_[k_] = v;
    }
    ++k_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::tableRow::start()
{
    k_ = 0;
}


void Foam::RBD::tableRow::add(const word& name, const scalar v)
{
    add(name, word::null, v);
}


void Foam::RBD::tableRow::add(const word& name, const vector& v)
{
    for (direction c = 0; c < vector::nComponents; ++c)
    {
        add(name, word(vector::componentNames[c]), v[c]);
    }
}


void Foam::RBD::tableRow::add(const word& name, const tensor& t)
{
    for (direction c = 0; c < tensor::nComponents; ++c)
    {
        add(name, word(tensor::componentNames[c]), t[c]);
    }
}


void Foam::RBD::tableRow::end()
{
    if (fixed_ && k_ != values_.size())
    {
        FatalErrorInFunction
            << "The table row has " << k_ << " columns, but the table's"
            << " header has " << values_.size() << ": the columns of every"
            << " row must be those of the first" << nl << abort(FatalError);
    }
    fixed_ = true;
}


Foam::word Foam::RBD::tableRow::name(const label k) const
{
    return
        components_[k].empty()
      ? groups_[k]
      : word(groups_[k] + "." + components_[k]);
}


Foam::wordList Foam::RBD::tableRow::names() const
{
    wordList n(values_.size());
    forAll(n, k)
    {
        n[k] = name(k);
    }
    return n;
}


void Foam::RBD::tableRow::writeHeader(Ostream& os) const
{
    os  << '#';
    forAll(groups_, k)
    {
        const bool first = (k == 0 || groups_[k - 1] != groups_[k]);
        const bool last =
            (k == groups_.size() - 1 || groups_[k + 1] != groups_[k]);
        if (components_[k].empty())
        {
            os  << ' ' << groups_[k];
        }
        else
        {
            os  << ' ';
            if (first)
            {
                os  << groups_[k] << '(';
            }
            os  << components_[k];
            if (last)
            {
                os  << ')';
            }
        }
    }
    os  << nl;
}


void Foam::RBD::tableRow::write(Ostream& os) const
{
    forAll(values_, k)
    {
        os  << (k ? " " : "") << values_[k];
    }
    os  << nl;
}


// ************************************************************************* //
