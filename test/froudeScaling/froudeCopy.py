#!/usr/bin/env python3
"""Make a Froude-scaled copy of a meshed hingedFlap case.

    froudeCopy.py SOURCE COPY LAMBDA

SOURCE is a copy of tutorials/interDyMFoam/hingedFlap already meshed (its
blockMesh, topoSet, subsetMesh and setFields run).  COPY becomes the same
case at LAMBDA times the size, as Froude similarity scales it (g and the
densities the same):

    lengths x lambda        times x lambda^0.5
    masses x lambda^3       inertias x lambda^5
    kinematic viscosity x lambda^1.5     surface tension x lambda^2
    a rotational spring [N m/rad] x lambda^4, its damper [N m s/rad] x
    lambda^4.5
    an angular velocity x lambda^-0.5

It scales only the entries the hingedFlap case holds, and stops with an
error on a body or restraint type it does not know how to scale, so that it
never makes a copy that is silently not similar.
"""

import os
import re
import shutil
import subprocess
import sys


def run(*args):
    return subprocess.run(args, check=True, capture_output=True,
                          text=True).stdout


def value(path, entry):
    return run("foamDictionary", path, "-entry", entry, "-value").strip()


def set_entry(path, entry, text):
    run("foamDictionary", path, "-entry", entry, "-set", text)


def numbers(text):
    return [float(x) for x in re.findall(
        r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", text)]


def fmt(x):
    return repr(float(x))


def scaled(path, entry, power, lam):
    """Multiply every number of the entry by lam**power"""
    text = value(path, entry)
    vals = [v * lam**power for v in numbers(text)]
    if text.startswith("("):
        set_entry(path, entry, "(" + " ".join(fmt(v) for v in vals) + ")")
    else:
        (v,) = vals
        set_entry(path, entry, fmt(v))


def main():
    source, copy, lam = sys.argv[1], sys.argv[2], float(sys.argv[3])
    shutil.copytree(source, copy, symlinks=True)
    os.chdir(copy)
    os.environ["PWD"] = os.getcwd()   # OpenFOAM checks it against cwd

    # The mesh (and the 0 fields, which hold no lengths here)
    s = fmt(lam)
    run("transformPoints", "-scale", "(%s %s %s)" % (s, s, s))

    control = "system/controlDict"
    for e in ("deltaT", "endTime", "writeInterval", "maxDeltaT"):
        scaled(control, e, 0.5, lam)

    tp = "constant/transportProperties"
    for phase in numbers_free(value(tp, "phases")):
        scaled(tp, phase + "/nu", 1.5, lam)
    scaled(tp, "sigma", 2, lam)

    scaled("constant/hRef", "value", 1, lam)

    # The body model: its #eval and $ expanded first, so that derived
    # entries are set from their values
    dmd = "constant/dynamicMeshDict"
    expanded = run("foamDictionary", dmd, "-expand")
    with open(dmd, "w") as f:
        f.write(expanded)
    coeffs = "rigidBodyMotionCoeffs"

    names = run("foamDictionary", dmd, "-entry", coeffs + "/bodies",
                "-keywords").split()
    for b in names:
        p = coeffs + "/bodies/" + b
        kind = value(dmd, p + "/type")
        if kind != "cuboid":
            sys.exit("froudeCopy: body type %s is not scaled here" % kind)
        if value(dmd, p + "/joint/type") not in ("Rx", "Ry", "Rz"):
            sys.exit("froudeCopy: only a revolute joint is scaled here")
        scaled(dmd, p + "/mass", 3, lam)
        for e in ("L", "centreOfMass", "innerDistance", "outerDistance",
                  "Lx", "Ly", "Lz"):
            scaled(dmd, p + "/" + e, 1, lam)
        t = numbers(value(dmd, p + "/transform"))
        t[9:12] = [x * lam for x in t[9:12]]
        set_entry(dmd, p + "/transform", "(%s) (%s)" % (
            " ".join(fmt(x) for x in t[:9]),
            " ".join(fmt(x) for x in t[9:12])))

    # Angular velocities of the revolute joints
    scaled(dmd, coeffs + "/qDot", -0.5, lam)

    names = run("foamDictionary", dmd, "-entry", coeffs + "/restraints",
                "-keywords").split()
    for r in names:
        p = coeffs + "/restraints/" + r
        kind = value(dmd, p + "/type")
        if kind != "linearAxialAngularSpring":
            sys.exit("froudeCopy: restraint type %s is not scaled here"
                     % kind)
        scaled(dmd, p + "/stiffness", 4, lam)
        scaled(dmd, p + "/damping", 4.5, lam)


def numbers_free(text):
    """The words of a list such as (water air)"""
    return text.strip("()").split()


if __name__ == "__main__":
    main()
