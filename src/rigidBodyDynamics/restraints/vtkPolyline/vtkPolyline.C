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
-------------------------------------------------------------------------------
    writeVtkPolyline: a polyline as a legacy VTK file (vtkPolyline.H)
\*---------------------------------------------------------------------------*/

#include "vtkPolyline.H"
#include "OFstream.H"
#include "OSspecific.H"

void Foam::RBD::writeVtkPolyline
(
    const fileName& file,
    const string& title,
    const vectorField& points,
    const word& name,
    const scalarField& values
)
{
    mkDir(file.path());
    OFstream os(file);
    os.precision(IOstream::defaultPrecision());
    const label n = points.size();

    os  << "# vtk DataFile Version 2.0" << nl
        << title.c_str() << nl
        << "ASCII" << nl
        << "DATASET POLYDATA" << nl
        << "POINTS " << n << " double" << nl;
    for (const vector& p : points)
    {
        os  << p.x() << ' ' << p.y() << ' ' << p.z() << nl;
    }
    os  << "LINES 1 " << n + 1 << nl << n;
    for (label i = 0; i < n; ++i)
    {
        os  << ' ' << i;
    }
    os  << nl << "POINT_DATA " << n << nl
        << "SCALARS " << name << " double 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (const scalar v : values)
    {
        os  << v << nl;
    }
}

// ************************************************************************* //
