#!/usr/bin/env python3
"""Compare an interFoam log of a case with that of its Froude-scaled copy.

    compareFroude.py LOG1 LOG2 LAMBDA --motion TOL

LOG2's case is LOG1's at LAMBDA times the size (test/froudeScaling).  Each
step's line "rigidBodyMotion: coupling of the step to t = T: N solves, ..."
and its "coupling not converged" lines are read from both logs.  Prints one
"PASS:" or "FAIL:" line for each check:
- the same number of steps, at times T2 = T1 sqrt(LAMBDA) (1e-9 relative);
- the same solves (outer correctors) in every step;
- the same flagged steps;
- the same scaled motion: the orientation less the identity alike, the centre of
  rotation over LAMBDA and the angular velocity times sqrt(LAMBDA), each
  within TOL of the largest value of its quantity in LOG1.
"""

import argparse
import math
import re

STEP = re.compile(r"^rigidBodyMotion: coupling of the step to t = (\S+): "
                  r"(\d+) solves")
FLAG = re.compile(r"^rigidBodyMotion: coupling not converged at t = (\S+):")
BODY = re.compile(r"^Rigid-body motion of the (\S+)\s*$")
ENTRY = re.compile(r"^\s+(Centre of rotation|Orientation|Angular velocity):"
                   r" \(([^)]*)\)\s*$")
POWER = {"Centre of rotation": -1.0, "Orientation": 0.0,
         "Angular velocity": 0.5}


def parse(path):
    """Steps [(t, solves)], flagged times, and the status after each step:
    [{quantity: [values]}] (the last block before each step's line)"""
    steps, flagged, states = [], [], []
    block = {}
    with open(path) as f:
        for line in f:
            m = STEP.match(line)
            if m:
                steps.append((float(m.group(1)), int(m.group(2))))
                states.append(dict(block))
                continue
            m = FLAG.match(line)
            if m:
                flagged.append(float(m.group(1)))
                continue
            m = ENTRY.match(line)
            if m:
                v = [float(x) for x in m.group(2).split()]
                if m.group(1) == "Orientation":
                    # Its turn from the identity, on the scale of the angle
                    v = [x - (1.0 if k in (0, 4, 8) else 0.0)
                         for k, x in enumerate(v)]
                block[m.group(1)] = v
    return steps, flagged, states


def check(what, ok, why=""):
    print(("PASS: " if ok else "FAIL: ") + what + ("" if ok else ": " + why))
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("log1")
    ap.add_argument("log2")
    ap.add_argument("lam", type=float)
    ap.add_argument("--motion", type=float, required=True)
    ap.add_argument("--what", default="")
    a = ap.parse_args()
    lam, root = a.lam, math.sqrt(a.lam)
    w = a.what + ": " if a.what else ""

    s1, f1, st1 = parse(a.log1)
    s2, f2, st2 = parse(a.log2)

    n = min(len(s1), len(s2))
    check(w + "the same number of steps (%d)" % len(s1),
          len(s1) == len(s2) and n > 0, "%d and %d" % (len(s1), len(s2)))
    bad = [i for i in range(n)
           if abs(s2[i][0] - s1[i][0]*root) > 1e-9*max(1.0, s2[i][0])]
    check(w + "step times scaled by sqrt(lambda)", not bad,
          "step %d: %g and %g" % (bad[0], s1[bad[0]][0], s2[bad[0]][0])
          if bad else "")
    diff = [i for i in range(n) if s1[i][1] != s2[i][1]]
    total = sum(s for _, s in s1[:n])
    check(w + "the same outer correctors in every step (%d in all, "
          "%.2f a step)" % (total, total/max(n, 1)), not diff,
          "%d steps differ, the first at t = %g: %d and %d" % (
              len(diff), s1[diff[0]][0], s1[diff[0]][1], s2[diff[0]][1])
          if diff else "")
    same = len(f1) == len(f2) and all(
        abs(x*root - y) <= 1e-9*max(1.0, y) for x, y in zip(f1, f2))
    check(w + "the same flagged steps (%d)" % len(f1), same,
          "%d and %d flagged" % (len(f1), len(f2)))

    for q, p in POWER.items():
        ref = max((max(abs(v) for v in s[q]) for s in st1[:n] if q in s),
                  default=0)
        err = 0.0
        for x, y in zip(st1[:n], st2[:n]):
            if q in x and q in y:
                for u, v in zip(x[q], y[q]):
                    err = max(err, abs(u - v*lam**p))
        check(w + "%s scaled alike (largest difference %.2g of its largest"
              " value %.3g, tolerance %g)" % (q.lower(), err/max(ref, 1e-300),
                                              ref, a.motion),
              ref > 0 and err <= a.motion*ref, "")


if __name__ == "__main__":
    main()
