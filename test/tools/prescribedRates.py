#!/usr/bin/env python3
"""Check bodies' angular velocities in a status log against prescribed rates.

    prescribedRates.py LOG --rate BODY AXIS EXPR [--rate ...] --tol FRACTION

For each --rate: the component AXIS (x, y or z, global axes) of the
"Angular velocity" of BODY in the last status block of each time of LOG
(the time step's last outer corrector, as compareStatus.py pairs them),
against EXPR, a Python expression of t with math's functions (sin, pi,
min ...).  The deviation allowed is FRACTION times the largest |EXPR| over
the times of the log.

Prints one line per rate, e.g.

    propeller omega x vs 16*min(t, 1): worst deviation 0.0123 rad/s at
    t = 0.0046 (0.0614 against 0.0737), allowed 0.0016 (1% of 0.16)

Exit status 0 if every rate is within its allowance, 1 if not, 2 if the
log cannot be read or a body has no blocks.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compareStatus import parse  # noqa: E402

AXES = {"x": 0, "y": 1, "z": 2}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log")
    parser.add_argument("--rate", nargs=3, action="append", required=True,
                        metavar=("BODY", "AXIS", "EXPR"))
    parser.add_argument("--tol", type=float, required=True)
    args = parser.parse_args()

    blocks = parse(args.log)
    ok = True
    for body, axis, expr in args.rate:
        if axis not in AXES:
            print("prescribedRates: axis %s is not x, y or z" % axis,
                  file=sys.stderr)
            return 2
        target = eval("lambda t: " + expr, vars(math))
        rows = sorted((t, b["angular"][AXES[axis]])
                      for (t, name), b in blocks.items()
                      if name == body and "angular" in b)
        if not rows:
            print("prescribedRates: no status of body %s in %s"
                  % (body, args.log), file=sys.stderr)
            return 2
        scale = max(abs(target(t)) for t, _ in rows)
        allowed = args.tol*scale
        dev, t, w = max((abs(w - target(t)), t, w) for t, w in rows)
        within = dev <= allowed
        ok = ok and within
        print("%s omega %s vs %s over %d steps to t = %g: worst deviation "
              "%.3g rad/s at t = %g (%.6g against %.6g), allowed %.3g "
              "(%g%% of %.4g)%s"
              % (body, axis, expr, len(rows), rows[-1][0], dev, t, w,
                 target(t), allowed, 100*args.tol, scale,
                 "" if within else ": OUTSIDE"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
