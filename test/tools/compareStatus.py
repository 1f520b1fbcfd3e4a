#!/usr/bin/env python3
"""Compare the rigid-body status blocks of two logs.

Each log holds "Time = t" lines, each followed by status blocks

    Rigid-body motion of the NAME
        Centre of rotation: (x y z)
        Orientation: (xx xy xz yx yy yz zx zy zz)
        Linear velocity: (x y z)
        Angular velocity: (x y z)

as printed by rigidBodySim, test/stockDriver/runStock or a solver with
"report on".  Blocks are paired by (time, body); where a log holds several
blocks of one body at one time (outer correctors), the last one counts.
Prints the largest absolute and relative difference of each quantity.

Exit status: 0 if every compared value has |a - b| <= abs + rel*max(|a|,|b|),
1 if not (the worst offender is printed), 2 if the logs cannot be compared:
unreadable, no blocks in common, different sets of times or bodies, or an
incomplete block.

    compareStatus.py A.log B.log --abs TOL --rel TOL
        [--quantities centre,orientation,linear,angular] [--until T]
"""

import argparse
import math
import re
import sys

QUANTITIES = {
    "centre": ("Centre of rotation", 3),
    "orientation": ("Orientation", 9),
    "linear": ("Linear velocity", 3),
    "angular": ("Angular velocity", 3),
}
LABELS = {label: q for q, (label, n) in QUANTITIES.items()}
TIME = re.compile(r"^Time = (\S+)\s*$")
BODY = re.compile(r"^Rigid-body motion of the (\S+)\s*$")
ENTRY = re.compile(r"^\s+(" + "|".join(LABELS) + r"): \(([^)]*)\)\s*$")


def fail(message):
    print("compareStatus: " + message, file=sys.stderr)
    sys.exit(2)


def parse(path):
    """The blocks of a log: {(time, body): {quantity: [values]}}"""
    blocks = {}
    time = block = None
    try:
        lines = open(path).read().splitlines()
    except OSError as err:
        fail("cannot read %s: %s" % (path, err))
    for n, line in enumerate(lines, 1):
        m = TIME.match(line)
        if m:
            time, block = float(m.group(1)), None
            continue
        m = BODY.match(line)
        if m:
            if time is None:
                fail("%s:%d: status block before any 'Time =' line"
                     % (path, n))
            block = blocks[(time, m.group(1))] = {}
            continue
        m = ENTRY.match(line)
        if m and block is not None:
            q = LABELS[m.group(1)]
            values = [float(v) for v in m.group(2).split()]
            if len(values) != QUANTITIES[q][1]:
                fail("%s:%d: %d values for %s" % (path, n, len(values), q))
            block[q] = values
    return blocks


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("a", help="first log")
    parser.add_argument("b", help="second log")
    parser.add_argument("--abs", type=float, default=0.0, dest="atol")
    parser.add_argument("--rel", type=float, default=0.0, dest="rtol")
    parser.add_argument("--quantities", default=",".join(QUANTITIES))
    parser.add_argument("--until", type=float, default=math.inf,
                        help="compare only times <= UNTIL")
    args = parser.parse_args()

    quantities = [q for q in args.quantities.split(",") if q]
    unknown = [q for q in quantities if q not in QUANTITIES]
    if unknown or not quantities:
        fail("unknown quantities %s: choose from %s"
             % (unknown, ",".join(QUANTITIES)))

    logs = []
    for path in (args.a, args.b):
        blocks = parse(path)
        logs.append({k: v for k, v in blocks.items()
                     if k[0] <= args.until*(1 + 1e-12) + 1e-300})
    A, B = logs
    common = sorted(set(A) & set(B))
    if not common:
        fail("no status blocks in common")
    timesA, timesB = {k[0] for k in A}, {k[0] for k in B}
    if timesA != timesB:
        only = sorted(timesA ^ timesB)
        fail("different sets of times: %d in A, %d in B; first unmatched %g"
             % (len(timesA), len(timesB), only[0]))
    if set(A) != set(B):
        t, body = sorted(set(A) ^ set(B))[0]
        fail("body %s at time %g is in one log only" % (body, t))

    maxAbs = {q: 0.0 for q in quantities}
    maxRel = {q: 0.0 for q in quantities}
    worst, worstRatio, failed = None, -1.0, False
    for key in common:
        for q in quantities:
            if q not in A[key] or q not in B[key]:
                fail("incomplete block: body %s at time %g has no %s"
                     % (key[1], key[0], q))
            for i, (a, b) in enumerate(zip(A[key][q], B[key][q])):
                scale = max(abs(a), abs(b))
                diff = abs(a - b)
                tol = args.atol + args.rtol*scale
                ok = diff <= tol
                if math.isnan(diff):
                    diff, ratio, ok = math.inf, math.inf, False
                else:
                    ratio = diff/tol if tol > 0 else diff
                rel = diff/scale if scale > 0 else (diff and math.inf)
                maxAbs[q] = max(maxAbs[q], diff)
                maxRel[q] = max(maxRel[q], rel)
                failed = failed or not ok
                if ratio > worstRatio:
                    worst, worstRatio = (key, q, i, a, b), ratio

    print("%d blocks compared at %d times from %g to %g"
          % (len(common), len(timesA), common[0][0], common[-1][0]))
    print("%-12s %14s %14s" % ("quantity", "max abs diff", "max rel diff"))
    for q in quantities:
        print("%-12s %14.6e %14.6e" % (q, maxAbs[q], maxRel[q]))
    (t, body), q, i, a, b = worst
    print("%s: worst at time %g, body %s, %s[%d]: %.15g vs %.15g"
          " (|a-b| = %.3e, abs %g, rel %g)"
          % ("FAIL" if failed else "PASS", t, body, q, i, a, b,
             abs(a - b), args.atol, args.rtol))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
