#!/usr/bin/env python3
"""Compare two rigidBodyMotionState files: q, qDot, qDdot and t.

    compareState.py A B --tol TOL

Exit 0 if every value agrees within TOL*(1 + |value|) (absolute for small
values, relative for large), 1 if not (the worst entry is printed), 2 if a
file cannot be read or the entries differ in length."""

import argparse
import re
import sys


def read(path):
    text = open(path).read()
    values = {}
    for key in ("q", "qDot", "qDdot"):
        m = re.search(r"^%s\s+\d*\s*\(([^)]*)\)\s*;" % key, text, re.M)
        if not m:
            raise ValueError("%s: no entry %s" % (path, key))
        values[key] = [float(x) for x in m.group(1).split()]
    m = re.search(r"^t\s+(\S+)\s*;", text, re.M)
    if not m:
        raise ValueError("%s: no entry t" % path)
    values["t"] = [float(m.group(1))]
    return values


def main():
    p = argparse.ArgumentParser()
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--tol", type=float, required=True)
    args = p.parse_args()
    try:
        a, b = read(args.a), read(args.b)
    except (OSError, ValueError) as e:
        print(e)
        return 2
    worst = (0.0, "")
    for key in a:
        if len(a[key]) != len(b[key]):
            print("%s: %d values against %d" % (key, len(a[key]), len(b[key])))
            return 2
        for i, (x, y) in enumerate(zip(a[key], b[key])):
            err = abs(x - y)/(1 + max(abs(x), abs(y)))
            if err > worst[0]:
                worst = (err, "%s[%d] %.17g vs %.17g" % (key, i, x, y))
    print("largest scaled difference %.3g %s" % worst)
    return 0 if worst[0] <= args.tol else 1


if __name__ == "__main__":
    sys.exit(main())
