#!/usr/bin/env python3
"""Check the mesh motion of one body with a translation band.

    checkBand.py POINTS0 POINTS LOG --inner A --outer B --band C
        --direction X Y Z --origin X Y Z
        --box XMIN YMIN ZMIN XMAX YMAX ZMAX
        --domain XMIN YMIN ZMIN XMAX YMAX ZMAX

POINTS0 and POINTS are the mesh's points (OpenFOAM ascii) before and after
the motion; LOG is the solver's log, whose last "Rigid-body motion" block
gives the body's final centre of rotation r and orientation; --origin is
the centre of rotation r00 where the mesh was made (the body's transform,
the run starting from q = 0).  The body's patch is the surface of
the box; the domain's faces are walls that stay put.

Each point off the walls must move by

    w (R (p0 - r00) + r - p0) + wt ((r - r00) . e) e

with w = S(d; inner, outer) and w + wt = S(d; inner, band), S the smooth
step (1 within the first distance, 0 beyond the second, 1 - s^2 (3 - 2s)
between) and d the point's distance to the patch as the library measures
it (from point to point across the mesh, which may exceed the exact
distance to the box by up to a cell's diagonal).  The check:

1. the points of the box's surface move rigidly (w = 1, wt = 0) to 1e-9 m;
2. each moved point's displacement is that form with w and wt recovered
   from it: its part across e is w times the rigid one's, to 1e-9 m;
3. w + wt is the wider step at the same d as w is the narrower one, to
   1e-9, where 0 < w < 1;
4. d (recovered from w, or from w + wt beyond the narrower band) lies
   within --tolerance of the exact distance to the box, and no point
   moves whose exact distance to the box exceeds band + tolerance;
5. points beyond outer + tolerance move along e alone, and some do.

Exit status 0 if all hold, 1 if one fails (printed), 2 on unreadable
input.
"""

import argparse
import math
import re
import sys


def read_points(path):
    with open(path) as f:
        text = f.read()
    body = text[text.index("FoamFile"):]
    body = body[body.index("}") + 1:]
    triples = re.findall(r"^\(([^()]*)\)\s*$", body, re.M)
    return [tuple(float(v) for v in t.split()) for t in triples]


def last_state(path):
    centre = None
    orientation = None
    with open(path) as f:
        for line in f:
            m = re.match(r"\s*Centre of rotation: \((.*)\)", line)
            if m:
                centre = [float(v) for v in m.group(1).split()]
            m = re.match(r"\s*Orientation: \((.*)\)", line)
            if m:
                orientation = [float(v) for v in m.group(1).split()]
    if centre is None or orientation is None:
        raise ValueError("no Rigid-body motion block in " + path)
    Q = [orientation[0:3], orientation[3:6], orientation[6:9]]
    return centre, Q


def step(d, inner, outer):
    s = min(max((d - inner)/(outer - inner), 0.0), 1.0)
    return 1 - s*s*(3 - 2*s)


def invert_step(w, inner, outer):
    # w = 1 - s^2 (3 - 2s) on 0 < w < 1: bisection on s
    lo, hi = 0.0, 1.0
    for _ in range(100):
        mid = 0.5*(lo + hi)
        if step(inner + mid*(outer - inner), inner, outer) > w:
            lo = mid
        else:
            hi = mid
    return inner + 0.5*(lo + hi)*(outer - inner)


def box_distance(p, lo, hi):
    return math.sqrt(sum(max(lo[i] - p[i], 0.0, p[i] - hi[i])**2
                         for i in range(3)))


def on_box(p, lo, hi, eps=1e-9):
    inside = all(lo[i] - eps <= p[i] <= hi[i] + eps for i in range(3))
    face = any(abs(p[i] - lo[i]) < eps or abs(p[i] - hi[i]) < eps
               for i in range(3))
    return inside and face


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("points0")
    ap.add_argument("points")
    ap.add_argument("log")
    ap.add_argument("--inner", type=float, required=True)
    ap.add_argument("--outer", type=float, required=True)
    ap.add_argument("--band", type=float, required=True)
    ap.add_argument("--direction", type=float, nargs=3, required=True)
    ap.add_argument("--origin", type=float, nargs=3, required=True)
    ap.add_argument("--box", type=float, nargs=6, required=True)
    ap.add_argument("--domain", type=float, nargs=6, required=True)
    ap.add_argument("--tolerance", type=float, default=0.05)
    a = ap.parse_args()

    try:
        p0 = read_points(a.points0)
        p1 = read_points(a.points)
        r, Q = last_state(a.log)
    except (OSError, ValueError) as err:
        print("checkBand: " + str(err))
        return 2
    if len(p0) != len(p1) or not p0:
        print("checkBand: %d points before, %d after" % (len(p0), len(p1)))
        return 2

    n = math.sqrt(sum(v*v for v in a.direction))
    e = [v/n for v in a.direction]
    blo, bhi = a.box[0:3], a.box[3:6]
    dlo, dhi = a.domain[0:3], a.domain[3:6]
    r00 = a.origin
    te = sum((r[i] - r00[i])*e[i] for i in range(3))
    tol = 1e-9

    def rigid(p, R):
        q = [p[i] - r00[i] for i in range(3)]
        return [sum(R[i][j]*q[j] for j in range(3)) + r[i] - p[i]
                for i in range(3)]

    def across(v):
        ve = sum(v[i]*e[i] for i in range(3))
        return [v[i] - ve*e[i] for i in range(3)], ve

    # The orientation as printed or its transpose, whichever moves the
    # box's surface rigidly
    surface = [i for i, p in enumerate(p0) if on_box(p, blo, bhi)]
    if not surface:
        print("checkBand: no point on the box's surface")
        return 2
    best = None
    for R in (Q, [list(c) for c in zip(*Q)]):
        err = max(max(abs(p1[i][k] - p0[i][k] - rigid(p0[i], R)[k])
                      for k in range(3)) for i in surface)
        if best is None or err < best[0]:
            best = (err, R)
    err, R = best
    if err > tol:
        print("FAIL 1: the box's surface does not move rigidly: %g m" % err)
        return 1

    moved = beyond = 0
    worst_d = 0.0
    for p, q in zip(p0, p1):
        if any(abs(p[i] - dlo[i]) < tol or abs(p[i] - dhi[i]) < tol
               for i in range(3)):
            continue
        disp = [q[i] - p[i] for i in range(3)]
        if max(abs(v) for v in disp) < tol:
            if box_distance(p, blo, bhi) < a.band - a.tolerance:
                print("FAIL 4: a point %s %.4g m from the box, within the"
                      " band, does not move"
                      % (p, box_distance(p, blo, bhi)))
                return 1
            continue
        moved += 1
        g = box_distance(p, blo, bhi)
        rd = rigid(p, R)
        rc, re_ = across(rd)
        dc, de = across(disp)
        nrc = math.sqrt(sum(v*v for v in rc))
        if nrc > 1e-6:
            w = sum(dc[i]*rc[i] for i in range(3))/nrc**2
            if max(abs(dc[i] - w*rc[i]) for i in range(3)) > tol:
                print("FAIL 2: at %s the motion across the band's direction"
                      " is not a multiple of the rigid one" % (p,))
                return 1
        else:
            w = None
        if w is not None and not -tol <= w <= 1 + tol:
            print("FAIL 2: at %s the weight %g is outside [0, 1]" % (p, w))
            return 1
        if g > a.outer + a.tolerance:
            if w is not None and abs(w) > tol:
                print("FAIL 5: at %s, %.4g m from the box beyond outer,"
                      " the point moves across the band's direction"
                      % (p, g))
                return 1
            beyond += 1
        if w is None:
            continue
        wt = (de - w*re_)/te
        wide = w + wt
        if 0 < w < 1 - 1e-6:
            d = invert_step(w, a.inner, a.outer)
            if abs(wide - step(d, a.inner, a.band)) > 1e-6:
                print("FAIL 3: at %s, w = %.9g gives d = %.6g, where the"
                      " wider step is %.9g, not %.9g"
                      % (p, w, d, step(d, a.inner, a.band), wide))
                return 1
        elif w < tol and tol < wide < 1 - 1e-6:
            d = invert_step(wide, a.inner, a.band)
        else:
            continue
        worst_d = max(worst_d, d - g)
        if not -1e-6 <= d - g <= a.tolerance:
            print("FAIL 4: at %s the library's distance %.4g m is not"
                  " within %g of the exact %.4g m" % (p, d, a.tolerance, g))
            return 1
        if g > a.band + a.tolerance:
            print("FAIL 4: a point %.4g m from the box, beyond the band,"
                  " moves" % g)
            return 1

    if beyond == 0:
        print("FAIL 5: no point beyond outerDistance moves")
        return 1
    print("PASS: %d points move, %d of them beyond outerDistance along the"
          " band's direction alone; the box's surface rigidly to %.1e m;"
          " the library's distance at most %.3f m over the exact one"
          % (moved, beyond, err, worst_d))
    return 0


if __name__ == "__main__":
    sys.exit(main())
