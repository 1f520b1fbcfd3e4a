#!/usr/bin/python3
"""sceneSlicesDraw.py: the drawing half of bin/tools/sceneSlices.

Reads, for each time, the cutting plane's cells (slice.vtk: polygons with
the cell values of the field) and each body's patch (body_<name>.vtk: the
patch's faces on the mesh of that time) that OpenFOAM's surfaces function
object wrote in legacy ascii VTK, cuts the patch faces with the same plane
into the body's outline, and draws a PNG per time with gnuplot: the cells
filled by the field's value, their edges thin, the outline thick, and the
centre of rotation from the body's table as a cross, and the mooring
lines the motion wrote at that time (TABLEDIR/<time>/<line>.vtk, VTK
polylines: catenaryLine, lumpedMassLine) projected on the plane.  Prints,
per time and
body, the table's centre and the outline's extent in the plane, for a check
by eye or by script.  Standard library only (Debian's /usr/bin/python3).

    sceneSlicesDraw.py CASENAME POINT NORMAL FIELD MARGIN SAMPLEDIR TABLEDIR \
        BODY=PATCH... -- TIME...

POINT and NORMAL: "x y z"; MARGIN: the window's margin about the bodies'
outlines [m] (the bodies' largest outerDistance when the caller gives none);
SAMPLEDIR: postProcessing/<function> with a directory per time; TABLEDIR:
postProcessing/rigidBodyMotion (tables <start>/<body>.dat).
"""

import glob
import math
import os
import subprocess
import sys


# ---------------------------------------------------------------------------
# Small vector helpers (3-tuples)

def dot(a, b):
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]


def cross(a, b):
    return (a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2],
            a[0]*b[1] - a[1]*b[0])


def scale(s, a):
    return (s*a[0], s*a[1], s*a[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def unit(a):
    m = math.sqrt(dot(a, a))
    if m == 0:
        raise ValueError("zero vector")
    return scale(1.0/m, a)


# ---------------------------------------------------------------------------
# The plane's own axes: v is "up" (z, or y for a plane normal to z) as seen
# in the plane, u = the other, signed so that its largest component is
# positive (x to the right for a plane normal to y or z, y for one normal
# to x)

AXES = "xyz"


def planeAxes(normal):
    n = unit(normal)
    up = (0.0, 0.0, 1.0) if abs(n[2]) < 0.9 else (0.0, 1.0, 0.0)
    v = unit(sub(up, scale(dot(up, n), n)))
    u = cross(n, v)
    big = max(range(3), key=lambda i: abs(u[i]))
    if u[big] < 0:
        u = scale(-1.0, u)
    return n, u, v


def axisLabel(a):
    for i in range(3):
        if abs(abs(a[i]) - 1) < 1e-9:
            return ("-" if a[i] < 0 else "") + AXES[i] + " [m]"
    return "(%.3g %.3g %.3g) [m]" % a


# ---------------------------------------------------------------------------
# Legacy ascii VTK polydata, as OpenFOAM's vtk surface writer writes it:
# POINTS, POLYGONS and CELL_DATA with FIELD arrays

def readVtk(path):
    with open(path) as f:
        lines = f.read().split("\n")
    # The header: three lines (version, title, ASCII), then DATASET
    tokens = " ".join(lines[3:]).split()
    points, polys, cellData = [], [], {}
    i, n = 0, len(tokens)
    section = None
    while i < n:
        t = tokens[i]
        if t == "POINTS":
            nPoints = int(tokens[i + 1])
            i += 3
            vals = tokens[i:i + 3*nPoints]
            points = [(float(vals[3*k]), float(vals[3*k + 1]),
                       float(vals[3*k + 2])) for k in range(nPoints)]
            i += 3*nPoints
        elif t == "POLYGONS":
            nPolys = int(tokens[i + 1])
            i += 3
            for _ in range(nPolys):
                m = int(tokens[i])
                polys.append([int(x) for x in tokens[i + 1:i + 1 + m]])
                i += 1 + m
        elif t in ("CELL_DATA", "POINT_DATA"):
            section = t
            i += 2
        elif t == "FIELD":
            nArrays = int(tokens[i + 2])
            i += 3
            for _ in range(nArrays):
                name, nComp, nTuples = tokens[i], int(tokens[i + 1]), \
                    int(tokens[i + 2])
                i += 4
                vals = [float(x) for x in tokens[i:i + nComp*nTuples]]
                i += nComp*nTuples
                if section == "CELL_DATA" and nComp == 1:
                    cellData[name] = vals
        else:
            i += 1
    return points, polys, cellData


# ---------------------------------------------------------------------------
# A patch cut by the plane: a segment per face the plane crosses

def cutFaces(points, polys, p0, n):
    d = [dot(sub(p, p0), n) for p in points]
    segments = []
    for face in polys:
        crossings = []
        m = len(face)
        for k in range(m):
            a, b = face[k], face[(k + 1) % m]
            # A point on the plane counts as above it: each crossing once
            if (d[a] >= 0) != (d[b] >= 0):
                s = d[a]/(d[a] - d[b])
                crossings.append(
                    tuple(points[a][j] + s*(points[b][j] - points[a][j])
                          for j in range(3)))
        if len(crossings) < 2:
            continue
        if len(crossings) > 2:
            # A face that is not convex: pair the crossings in their order
            # along the line they lie on
            direction = sub(crossings[-1], crossings[0])
            crossings.sort(key=lambda c: dot(c, direction))
        for k in range(0, len(crossings) - 1, 2):
            segments.append((crossings[k], crossings[k + 1]))
    return segments


# ---------------------------------------------------------------------------
# A body's table: the row nearest a time, found by the header's names

def readPolyline(path):
    """The points of a legacy ascii VTK polyline (a mooring line's
    shape), in order."""
    words = open(path).read().split()
    i = words.index("POINTS")
    n = int(words[i + 1])
    x = [float(w) for w in words[i + 3:i + 3 + 3*n]]
    return [tuple(x[3*k:3*k + 3]) for k in range(n)]


def readTable(tableDir, body):
    rows = []
    cofr, orient = 1, 4
    for path in sorted(glob.glob(os.path.join(tableDir, "*", body + ".dat"))):
        with open(path) as f:
            for line in f:
                if line.startswith("# t "):
                    names = line[1:].split()
                    for k, name in enumerate(names):
                        if name.startswith("CofR("):
                            cofr = k
                        elif name.startswith("Orientation("):
                            orient = k
                    continue
                if line.startswith("#") or not line.strip():
                    continue
                rows.append([float(x) for x in line.split()])
    rows.sort(key=lambda r: r[0])
    return rows, cofr, orient


def nearestRow(table, t):
    rows, cofr, orient = table
    if not rows:
        return None
    r = min(rows, key=lambda r: abs(r[0] - t))
    c = tuple(r[cofr:cofr + 3])
    q = r[orient:orient + 9]
    return r[0], c, q


def turnInView(q, n, u, v):
    """The body's rotation about the plane's normal, as seen in the
    picture (degrees, anticlockwise positive): the orientation Q maps
    global to body coordinates, so the body turns global vectors by Q^T."""
    # Q^T u: column-major use of the row-major Q
    ru = tuple(q[0 + j]*u[0] + q[3 + j]*u[1] + q[6 + j]*u[2]
               for j in range(3))
    return math.degrees(math.atan2(dot(ru, v), dot(ru, u)))


# ---------------------------------------------------------------------------

def fmt(x, digits=5):
    s = "%.*g" % (digits, x)
    return "0" if s in ("-0", "0") else s


def main(argv):
    try:
        sep = argv.index("--")
    except ValueError:
        sys.exit(__doc__)
    head, times = argv[:sep], argv[sep + 1:]
    if len(head) < 7 or not times:
        sys.exit(__doc__)
    caseName = head[0]
    p0 = tuple(float(x) for x in head[1].split())
    n, u, v = planeAxes(tuple(float(x) for x in head[2].split()))
    field = head[3]
    margin = float(head[4])
    sampleDir, tableDir = head[5], head[6]
    bodies = list(head[7:])

    # In the plane, a point's coordinates are its components along u and
    # v: global coordinates for an axis-aligned plane
    def toPlane(p):
        return (dot(p, u), dot(p, v))

    scenes = []
    for t in times:
        d = os.path.join(sampleDir, t)
        if not os.path.isfile(os.path.join(d, "slice.vtk")):
            sys.exit("sceneSlices: no slice at t = %s: does the plane cut "
                     "the mesh? (log.sceneSlices)" % t)
        points, polys, data = readVtk(os.path.join(d, "slice.vtk"))
        if field not in data:
            sys.exit("sceneSlices: no %s in %s" % (field, d))
        cells = [([toPlane(points[k]) for k in poly], val)
                 for poly, val in zip(polys, data[field])]
        outlines = {}
        for body in bodies:
            name = body.split("=")[0]
            f = os.path.join(d, "body_" + name + ".vtk")
            if not os.path.isfile(f):
                outlines[name] = []
                continue
            bp, bf, _ = readVtk(f)
            outlines[name] = [(toPlane(a), toPlane(b))
                              for a, b in cutFaces(bp, bf, p0, n)]
        lines = [[toPlane(p) for p in readPolyline(f)]
                 for f in sorted(glob.glob(os.path.join(tableDir, t,
                                                        "*.vtk")))]
        scenes.append((t, cells, outlines, lines))

    # The window: the outlines of all times, and the margin about them,
    # within the cut's extent; the same for every time
    allCells = [p for c, _ in scenes[0][1] for p in c]
    if not allCells:
        sys.exit("sceneSlices: the plane cuts no cell")
    du = (min(p[0] for p in allCells), max(p[0] for p in allCells))
    dv = (min(p[1] for p in allCells), max(p[1] for p in allCells))
    ends = [p for _, _, outl, _ in scenes for segs in outl.values()
            for s in segs for p in s]
    if ends:
        wu = [min(p[0] for p in ends) - margin,
              max(p[0] for p in ends) + margin]
        wv = [min(p[1] for p in ends) - margin,
              max(p[1] for p in ends) + margin]
    else:
        print("sceneSlices: the plane cuts no body patch: the whole cut shown")
        wu, wv = list(du), list(dv)
    # Not too flat or too tall a picture: widen the short side about its
    # middle, then keep within the cut
    lu, lv = wu[1] - wu[0], wv[1] - wv[0]
    if lv < 0.45*lu:
        mid, lv = 0.5*(wv[0] + wv[1]), 0.45*lu
        wv = [mid - lv/2, mid + lv/2]
    elif lu < lv/1.2:
        mid, lu = 0.5*(wu[0] + wu[1]), lv/1.2
        wu = [mid - lu/2, mid + lu/2]
    wu = [max(wu[0], du[0]), min(wu[1], du[1])]
    wv = [max(wv[0], dv[0]), min(wv[1], dv[1])]
    aspect = (wv[1] - wv[0])/(wu[1] - wu[0])

    tables = {b.split("=")[0]: readTable(tableDir, b.split("=")[0])
              for b in bodies}

    width = 1000
    height = int(min(max(800*aspect + 190, 420), 1400))

    for t, cells, outlines, lines in scenes:
        tv = float(t)
        titleBodies, centres = [], []
        for name in tables:
            row = nearestRow(tables[name], tv)
            segs = outlines[name]
            if segs:
                pu = [p[0] for s in segs for p in s]
                pv = [p[1] for s in segs for p in s]
                extent = "outline u %s to %s, v %s to %s" % (
                    fmt(min(pu), 6), fmt(max(pu), 6), fmt(min(pv), 6),
                    fmt(max(pv), 6))
            else:
                extent = "no outline in the plane"
            if row is None:
                print("t = %s: %s: no table row; %s" % (t, name, extent))
                continue
            rt, c, q = row
            turn = turnInView(q, n, u, v)
            when = "" if abs(rt - tv) <= 1e-9*max(1.0, abs(tv)) \
                else " (table at t = %s)" % fmt(rt)
            cu, cv = toPlane(c)
            print("t = %s: %s: centre of rotation (%s %s %s)%s, in the "
                  "plane (%s, %s), turned %.4f deg; %s"
                  % (t, name, fmt(c[0], 6), fmt(c[1], 6), fmt(c[2], 6),
                     when, fmt(cu, 6), fmt(cv, 6), turn, extent))
            titleBodies.append("%s: centre of rotation (%s, %s, %s), "
                               "turned %+.2f deg%s"
                               % (name, fmt(c[0]), fmt(c[1]), fmt(c[2]),
                                  turn, when))
            centres.append((cu, cv))

        pad = 0.02*max(wu[1] - wu[0], wv[1] - wv[0])
        inside = lambda poly: not (
            max(p[0] for p in poly) < wu[0] - pad
            or min(p[0] for p in poly) > wu[1] + pad
            or max(p[1] for p in poly) < wv[0] - pad
            or min(p[1] for p in poly) > wv[1] + pad)

        out = []
        out.append("$cells << EOD")
        for poly, val in cells:
            if not inside(poly):
                continue
            for p in poly + [poly[0]]:
                out.append("%.7g %.7g %.6g" % (p[0], p[1], val))
            out.append("")
        out.append("EOD")
        out.append("$outline << EOD")
        for segs in outlines.values():
            for a, b in segs:
                out.append("%.7g %.7g\n%.7g %.7g\n" % (a + b))
        out.append("EOD")
        out.append("$mooring << EOD")
        for line in lines:
            for p in line:
                out.append("%.7g %.7g" % p)
            out.append("")
        out.append("EOD")
        out.append("$centres << EOD")
        for c in centres:
            out.append("%.7g %.7g" % c)
        out.append("EOD")

        png = "%s-scene-%s.png" % (caseName, t)
        plane = "plane through (%s %s %s), normal (%s %s %s)" % (
            tuple(fmt(x) for x in p0) + tuple(fmt(x) for x in n))
        title = "%s, t = %s s; %s; turns anticlockwise as drawn " \
            "positive\\n%s" % (
            caseName, t, plane, "\\n".join(titleBodies))
        out.append("""
set terminal pngcairo size %d,%d font ',11'
set output '%s'
set title "%s" noenhanced
set size ratio -1
set xrange [%.7g:%.7g]
set yrange [%.7g:%.7g]
set xlabel '%s' noenhanced
set ylabel '%s' noenhanced
set palette defined (0 '#ffffff', 1 '#3a78c8')
set cbrange [0:1]
set cblabel '%s' noenhanced
set object 1 rectangle from graph 0,0 to graph 1,1 behind \\
    fillcolor rgb '#a0a0a0' fillstyle solid noborder
set key outside bottom center horizontal noenhanced
set tics out
""" % (width, height, png, title, wu[0], wu[1], wv[0], wv[1],
       axisLabel(u), axisLabel(v), field))
        # (an empty datablock makes gnuplot warn: only those with data)
        plots = [
            "$cells using 1:2:3 with filledcurves closed"
            " fillcolor palette notitle",
            "$cells using 1:2 with lines lc rgb '#40404040' lw 0.6"
            " title 'cells cut by the plane'"]
        if any(outlines.values()):
            plots.append("$outline using 1:2 with lines lc rgb 'black' lw 3"
                         " title 'body patch cut by the plane'")
        if lines:
            plots.append("$mooring using 1:2 with lines lc rgb '#8b4513'"
                         " lw 2 title 'mooring lines (projected)'")
        if centres:
            plots.append("$centres using 1:2 with points pt 1 ps 3 lw 2"
                         " lc rgb '#d00000'"
                         " title 'centre of rotation (body table)'")
        plots.append("keyentry with boxes fillcolor rgb '#a0a0a0'"
                     " fillstyle solid title 'no cells (the body)'")
        out.append("plot " + ", \\\n     ".join(plots) + "\n")
        script = os.path.join(sampleDir, t, "scene.gp")
        with open(script, "w") as f:
            f.write("\n".join(out))
        subprocess.run(["gnuplot", script], check=True)
        print("Written %s" % png)


if __name__ == "__main__":
    main(sys.argv[1:])
