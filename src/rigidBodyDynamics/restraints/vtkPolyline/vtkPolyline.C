/*---------------------------------------------------------------------------*\
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
