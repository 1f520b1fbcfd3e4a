#!/usr/bin/env python3
"""Compare every number that two runs of the same cases wrote.

    compare.py A B [--tol 1e-12] [--label A-vs-B]

A and B are two run trees written by bench/vectorisation/run, one per build:
each holds <group>/<case>/ directories (rigidBodySim or interFoam cases) and
tests/<name>.log files (the output of a test).  The cases are paired by
their path; in a case, these files are compared:
- every log.* file (the status blocks, solver residuals, time steps),
- everything under postProcessing/ (the bodies' tables),
- everything under a time directory after the start (a directory whose name
  is a number > 0: uniform/rigidBodyMotionState, uniform/time, the fields
  and the moved mesh points),
and each tests/<name>.log as a whole.

Before comparing, lines that change from one run to the next whatever the
build are dropped (OpenFOAM's banner: date, time, PID, host, case path;
ExecutionTime and ClockTime; rigidBodySim's progress and wall/CPU-time
summary), the CPU time in cylinderAddedMass's log.result is replaced by a
placeholder, and the paths of the two trees, of mktemp directories and of the
builds' bin and lib directories (in a crash's stack trace) are replaced by
placeholders.  Each remaining line is split into its text, with
every number replaced by '#', and its numbers.  The text must be the same
line for line; the numbers are paired in order and compared by

    rel = |a - b| / max(|a|, |b|, 1e-300)

(pure relative difference; the absolute difference is printed too).

Prints one row per case: files and numbers compared, files identical byte
for byte (after the filtering), largest relative and absolute difference
and where, and the verdict: "identical" (every number equal), "within TOL"
(largest rel <= TOL) or "DIFFERS".  Exit status 0 if no case differs, 1 if
one does, 2 on a usage error.
"""

import argparse
import os
import re
import sys

NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")

# Lines that differ between two runs of the same build
DROP = re.compile(
    r"^\s*(Build|Arch|Exec|Date|Time|PID|I/O|Case|nProcs|Host|trapFpe|"
    r"fileModificationChecking|allowSystemOperations)\s*:"
    r"|ExecutionTime\s*="
    r"|ClockTime\s*="
    r"|steps/s"
    r"|s of wall time"
    r"|s of CPU time"
    r"|^\s*\(\d+ s\)\s*$"
)
MKTEMP = re.compile(r"/tmp/tmp\.[A-Za-z0-9]+")
# A build's bin or lib directory (in a crash's stack trace):
# platforms/$WM_OPTIONS/bin of the normal build, .../novec/platforms/bin
BUILD = re.compile(r"\S*/platforms/(?:[A-Za-z0-9]+/)?(bin|lib)/")
# CPU time in cylinderAddedMass's log.result
CPU = re.compile(r"\bcpu [0-9.eE+-]+ s\b")


def isTimeName(name):
    try:
        return float(name) > 0
    except ValueError:
        return False


def wanted(rel):
    """Whether a file of a case (path relative to the case) is compared"""
    parts = rel.split(os.sep)
    if parts[-1].startswith("log."):
        return True
    if "postProcessing" in parts:
        return True
    return any(isTimeName(p) for p in parts[:-1])


def caseFiles(caseDir):
    files = []
    for root, dirs, names in os.walk(caseDir):
        dirs.sort()
        for n in sorted(names):
            rel = os.path.relpath(os.path.join(root, n), caseDir)
            if wanted(rel):
                files.append(rel)
    return files


def cases(tree):
    """{case name: (directory or file, is a single file)}"""
    found = {}
    for group in sorted(os.listdir(tree)):
        g = os.path.join(tree, group)
        if not os.path.isdir(g) or group == "ld":
            continue
        for name in sorted(os.listdir(g)):
            p = os.path.join(g, name)
            found[group + "/" + name] = (p, os.path.isfile(p))
    return found


def lines(path, tree):
    out = []
    with open(path, errors="replace") as f:
        for n, line in enumerate(f, 1):
            if DROP.search(line):
                continue
            if "/" in line:
                line = line.replace(tree, "<run>")
                if "/tmp/tmp." in line:
                    line = MKTEMP.sub("<tmp>", line)
                if "/platforms/" in line:
                    line = BUILD.sub(r"<build>/\1/", line)
            if "cpu " in line:
                line = CPU.sub("cpu <time> s", line)
            out.append((n, line.rstrip("\n")))
    return out


class Result:
    def __init__(self):
        self.nFiles = 0
        self.nSame = 0
        self.nNumbers = 0
        self.nUnequal = 0
        self.rel = 0.0
        self.relAt = ""
        self.abs = 0.0
        self.absAt = ""
        self.problems = []

    def add(self, a, b, where):
        self.nNumbers += 1
        if a == b:
            return
        self.nUnequal += 1
        d = abs(a - b)
        r = d/max(abs(a), abs(b), 1e-300)
        if r > self.rel:
            self.rel, self.relAt = r, where
        if d > self.abs:
            self.abs, self.absAt = d, where


def compareFile(pa, pb, treeA, treeB, label, res):
    res.nFiles += 1
    la = lines(pa, treeA)
    lb = lines(pb, treeB)
    textA = [l for _, l in la]
    if textA == [l for _, l in lb]:
        # The same text: the same numbers, only counted
        res.nSame += 1
        res.nNumbers += len(NUMBER.findall("\n".join(textA)))
        return
    if len(la) != len(lb):
        res.problems.append(
            "%s: %d lines against %d" % (label, len(la), len(lb)))
    for (na, a), (nb, b) in zip(la, lb):
        ta, tb = NUMBER.sub("#", a), NUMBER.sub("#", b)
        if ta != tb:
            res.problems.append(
                "%s:%d: text differs:\n    %s\n    %s" % (label, na, a, b))
            return
        for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
            res.add(float(x), float(y), "%s:%d" % (label, na))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--tol", type=float, default=1e-12)
    p.add_argument("--label", default="")
    args = p.parse_args()

    treeA = os.path.realpath(args.a)
    treeB = os.path.realpath(args.b)
    if not (os.path.isdir(treeA) and os.path.isdir(treeB)):
        print("compare.py: %s and %s must be run trees" % (args.a, args.b),
              file=sys.stderr)
        return 2
    ca, cb = cases(treeA), cases(treeB)
    if not ca:
        print("compare.py: no cases in %s" % args.a, file=sys.stderr)
        return 2

    rows = []
    worst = "identical"
    totalNumbers = 0
    for name in sorted(set(ca) | set(cb)):
        res = Result()
        if name not in ca or name not in cb:
            res.problems.append("only in %s" % (args.a if name in ca else args.b))
        else:
            (pa, fa), (pb, fb) = ca[name], cb[name]
            if fa:
                compareFile(pa, pb, treeA, treeB, name, res)
            else:
                filesA, filesB = caseFiles(pa), caseFiles(pb)
                for rel in sorted(set(filesA) ^ set(filesB)):
                    res.problems.append("%s/%s: in one run only" % (name, rel))
                for rel in [f for f in filesA if f in set(filesB)]:
                    compareFile(os.path.join(pa, rel), os.path.join(pb, rel),
                                treeA, treeB, name + "/" + rel, res)
            if res.nFiles == 0:
                res.problems.append("no file to compare")
        if res.problems:
            verdict = "DIFFERS"
        elif res.nUnequal == 0:
            verdict = "identical"
        elif res.rel <= args.tol:
            verdict = "within %g" % args.tol
        else:
            verdict = "DIFFERS"
        if verdict == "DIFFERS":
            worst = "DIFFERS"
        elif verdict != "identical" and worst == "identical":
            worst = verdict
        totalNumbers += res.nNumbers
        rows.append((name, res, verdict))

    title = args.label or "%s vs %s" % (args.a, args.b)
    print("## %s" % title)
    print()
    print("| case | files | identical files | numbers | unequal numbers "
          "| max rel diff | max abs diff | verdict |")
    print("|---|---|---|---|---|---|---|---|")
    for name, res, verdict in rows:
        print("| %s | %d | %d | %d | %d | %.3g | %.3g | %s |" % (
            name, res.nFiles, res.nSame, res.nNumbers, res.nUnequal,
            res.rel, res.abs, verdict))
    print()
    for name, res, verdict in rows:
        if res.nUnequal:
            print("%s: largest rel diff %.3g at %s; largest abs diff %.3g "
                  "at %s" % (name, res.rel, res.relAt, res.abs, res.absAt))
        for prob in res.problems[:5]:
            print("%s: %s" % (name, prob))
    print("%s: %d cases, %d numbers compared: %s" % (
        title, len(rows), totalNumbers, worst))
    return 1 if worst == "DIFFERS" else 0


if __name__ == "__main__":
    sys.exit(main())
