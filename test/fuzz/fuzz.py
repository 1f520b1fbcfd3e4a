#!/usr/bin/env python3
"""Dictionary fuzzer for rigidBodySim (and, with --stock, the stock library).

    test/fuzz/fuzz.py [--cases N] [--seed S] [--jobs J] [--timeout T]
                      [--stock] [--keep DIR] [--replay I] [--summary FILE]

Makes N cases, each a valid seed case (the tests' and tutorials' rigid-body
dictionaries, and those of OpenFOAM v1912's source package) with one fault
put in by a mutation of one of its files (the body dictionary or
system/controlDict), and runs rigidBodySim on each with a time limit.  Case
i is a function of (S, i) alone: `--replay I --keep DIR` remakes case I in
DIR (and runs it) to look at it.

Mutations: delete an entry; a number replaced by 0, a negative, 1e300,
-1e300, 1e-300, 1e400, nan, inf, 1e8, 1e-8 or a word; a word (a type, a body
name) replaced by a wrong word or a number; a list one element shorter or
longer; a vector made zero or non-unit; a transform's tensor replaced by
nine random numbers; a body made its own parent; two bodies each other's
parent; a body entry written twice; the file truncated at a random place;
a keyword the library reads at that level (its registrations in src/:
addRigidBodyKeywords) misspelt by one edit (a letter dropped, two swapped,
a case changed).

Each outcome is one of
    error      a FOAM FATAL (IO) ERROR, no signal or stack trace, naming the
               entry: the message or its file/line names the mutated
               keyword, an enclosing keyword, the value put in, or the line
               of the mutation (for a truncated file: the file)
    reader     a FOAM FATAL IO ERROR of OpenFOAM's #eval expression parser,
               which expands and evaluates the dictionary before any code
               of the project sees it (e.g. an entry deleted that an #eval
               uses): it quotes the expression, not the entry
    vague      any other fatal error naming none of those
    completed  exit status 0, End, and every number in the log, the tables
               and the written states finite
    slow       a legal run still making progress at the time limit (its
               progress lines advance)
    signal     a signal (exit status >= 128) or a stack trace
    hang       killed at the time limit with no progress
    nonFinite  exit status 0 with nan or inf in the log or output
    other      any other exit (no FOAM FATAL message)
    unnoticed  a misspelt keyword whose run did not stop with "did you mean"
               and the keyword
The bad outcomes are signal, hang, nonFinite, other, vague and unnoticed:
each is
printed with its case number, seed case and mutation.  Prints the counts;
--summary writes them as a dictionary.  Exit status 0 always (the caller
judges the counts).
"""

import argparse
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

BAD = ("signal", "hang", "nonFinite", "other", "vague", "unnoticed")
OUTCOMES = ("error", "reader", "completed", "slow") + BAD

NUMBERS = ["0", "-1", "NEG", "1e300", "-1e300", "1e-300", "1e400", "nan",
           "inf", "-inf", "1e8", "1e-8", "oops"]

NUMBER_RE = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


# --------------------------------------------------------------- Seed cases

CONTROL_DICT = """FoamFile {{ version 2.0; format ascii; class dictionary; \
object controlDict; }}
application     rigidBodySim;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {end};
deltaT          {dt};
writeControl    runTime;
writeInterval   {write};
writeFormat     ascii;
writePrecision  12;
timeFormat      general;
timePrecision   8;
"""

G_FILE = """FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField;
location "constant"; object g; }
dimensions      [0 1 -2 0 0 0 0];
value           (0 0 -9.81);
"""


def seedCases(root):
    """Make the seed cases under root; return their directories.

    Each runs a few hundred steps at most, so that a case takes well under
    a second: the tests' base case, the rigidBodySim tutorials, the body
    dictionaries of the interDyMFoam tutorials (as dynamicMeshDict), and
    the rigidBodyDynamics test dictionaries and rigidBodyMotion tutorials
    of OpenFOAM v1912's source package."""
    seeds = []

    def add(name, files, end, dt):
        d = os.path.join(root, name)
        os.makedirs(os.path.join(d, "constant"))
        os.makedirs(os.path.join(d, "system"))
        for rel, src in files.items():
            dst = os.path.join(d, rel)
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            if isinstance(src, str) and os.path.isfile(src):
                shutil.copyfile(src, dst)
            else:
                with open(dst, "w") as f:
                    f.write(src[0])
        if "constant/g" not in files:
            with open(os.path.join(d, "constant", "g"), "w") as f:
                f.write(G_FILE)
        with open(os.path.join(d, "system", "controlDict"), "w") as f:
            f.write(CONTROL_DICT.format(end=end, dt=dt, write=end/2))
        seeds.append(d)

    base = os.path.join(TOP, "test", "badInput", "cases", "base")
    add("base", {"constant/rigidBodyMotionDict":
                 os.path.join(base, "constant", "rigidBodyMotionDict")},
        0.01, 0.001)

    for tut in ("pendulum", "springMass", "mooredSpar"):
        c = os.path.join(TOP, "tutorials", "rigidBodySim", tut, "constant")
        add(tut, {"constant/rigidBodyMotionDict":
                  os.path.join(c, "rigidBodyMotionDict")}, 0.1, 0.001)

    # The mooring lines: a buoy on a dynamic and a quasi-static line
    c = os.path.join(TOP, "test", "mooring", "mooredBuoy", "constant")
    add("mooredBuoy", {"constant/rigidBodyMotionDict":
                       os.path.join(c, "rigidBodyMotionDict")}, 0.1, 0.01)

    tutDir = os.path.join(TOP, "tutorials", "interDyMFoam")
    for tut in sorted(os.listdir(tutDir)):
        c = os.path.join(tutDir, tut, "constant")
        dmd = os.path.join(c, "dynamicMeshDict")
        if os.path.isfile(dmd) and "rigidBodyMotion" in open(dmd).read():
            files = {"constant/dynamicMeshDict": dmd}
            if os.path.isfile(os.path.join(c, "g")):
                files["constant/g"] = os.path.join(c, "g")
            # The files of parameters a tutorial's dictionaries include
            for name in ("caseParameters", "parameters"):
                params = os.path.join(tutDir, tut, "system", name)
                if os.path.isfile(params):
                    files["system/" + name] = params
            add(tut, files, 0.05, 0.001)

    src = os.path.join(TOP, "deps", "OpenFOAM")
    testDir = os.path.join(src, "applications", "test", "rigidBodyDynamics")
    if os.path.isdir(testDir):
        for name in sorted(os.listdir(testDir)):
            f = os.path.join(testDir, name, name)
            if os.path.isfile(f):
                add("stock-" + name, {"constant/rigidBodyMotionDict": f},
                    0.2, 0.01)
        tutRoot = os.path.join(src, "tutorials")
        for dirpath, _, files in sorted(os.walk(tutRoot)):
            if "dynamicMeshDict" in files and dirpath.endswith("constant"):
                dmd = os.path.join(dirpath, "dynamicMeshDict")
                text = open(dmd, errors="replace").read()
                if re.search(r"motionSolver\s+rigidBodyMotion", text):
                    caseName = os.path.basename(os.path.dirname(dirpath))
                    files = {"constant/dynamicMeshDict": dmd}
                    g = os.path.join(dirpath, "g")
                    if os.path.isfile(g):
                        files["constant/g"] = g
                    add("stock-" + caseName, files, 0.05, 0.001)
    return seeds


# ---------------------------------------------------- Dictionary structure

TOKEN_RE = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:[^"\\]|\\.)*"|[(){};\[\]]|[^\s(){};\[\]"]+',
    re.S)


class Entry:
    """An entry of a dictionary: its keyword, the keywords enclosing it,
    its span in the text, and its value's tokens (or sub-entries)."""

    def __init__(self, key, path, start):
        self.key = key
        self.path = path
        self.start = start
        self.end = start
        self.values = []      # (text, start, end) of the value's tokens
        self.children = None  # sub-entries of a sub-dictionary


def tokenize(text):
    return [(m.group(0), m.start(), m.end())
            for m in TOKEN_RE.finditer(text)
            if not m.group(0).startswith(("//", "/*"))]


def parse(text):
    """The entries of the dictionary text, all depths, in a flat list."""
    toks = tokenize(text)
    out = []

    def parseDict(i, path, closing):
        while i < len(toks):
            t, s, e = toks[i]
            if t == closing:
                return i + 1
            if t in "(){};[]":
                i += 1
                continue
            entry = Entry(t, path, s)
            i += 1
            if t.startswith("#"):
                # A directive: up to the end of its line's tokens
                while i < len(toks) and toks[i][0] not in ";}":
                    if text.count("\n", s, toks[i][1]):
                        break
                    i += 1
                continue
            if i < len(toks) and toks[i][0] == "{":
                entry.children = []
                j = parseDict(i + 1, path + [t], "}")
                entry.end = toks[j - 1][2] if j - 1 < len(toks) else len(text)
                out.append(entry)
                i = j
                continue
            depth = 0
            braces = 0    # inside the {...} of a directive (#eval {...})
            while i < len(toks):
                v, vs, ve = toks[i]
                if v == "{" and (braces or (entry.values and
                                 entry.values[-1][0].startswith("#"))):
                    braces += 1
                elif v == "}" and braces:
                    braces -= 1
                elif braces:
                    pass
                elif v in "([":
                    depth += 1
                elif v in ")]":
                    depth -= 1
                elif v == ";" and depth <= 0:
                    break
                elif v in "{}" and depth <= 0:
                    break
                entry.values.append((v, vs, ve))
                i += 1
            if i < len(toks) and toks[i][0] == ";":
                entry.end = toks[i][2]
                i += 1
            else:
                entry.end = entry.values[-1][2] if entry.values else s + len(t)
            out.append(entry)
        return i

    parseDict(0, [], None)
    return [e for e in out if "FoamFile" not in e.path + [e.key]]


def lists(entry):
    """The flat lists of numbers in the entry's value: (start, end, items)
    with items (text, start, end), the brackets' span from start to end."""
    found = []
    stack = []
    for v, s, e in entry.values:
        if v == "(":
            stack.append((s, []))
        elif v == ")" and stack:
            ls, items = stack.pop()
            if items and all(x[0] is not None and NUMBER_RE.match(x[0])
                             for x in items):
                found.append((ls, e, items))
            if stack:
                stack[-1][1].append((None, ls, e))
        elif stack:
            stack[-1][1].append((v, s, e))
    return found


def lineOf(text, pos):
    return text.count("\n", 0, pos) + 1


# --------------------------------------------------------------- Mutations

def registeredKeywords():
    """The keywords the library reads, by level: its registrations
    (addRigidBodyKeywords, addRigidBodyCommonKeywords in src/)."""
    reg = re.compile(r"addRigidBody(Common)?Keywords\s*\(\s*(\w+)\s*,"
                     r"\s*(\w*)\s*,?(.*?)\);", re.S)
    families = {}
    for d, _, files in os.walk(os.path.join(TOP, "src")):
        if "lnInclude" in d:
            continue
        for f in files:
            if f.endswith(".C"):
                with open(os.path.join(d, f)) as fh:
                    for m in reg.finditer(fh.read()):
                        family = m.group(2)
                        if family == "meshMotion":
                            family = m.group(3)
                        families.setdefault(family, set()).update(
                            re.findall(r'"(\w+)"', m.group(4)))
    return {
        "coefficients": families.get("coefficients", set())
        | families.get("coupling", set()),
        "body": families.get("body", set()),
        "joint": families.get("joint", set()),
        "restraint": families.get("restraint", set()),
        "solver": families.get("solver", set()),
    }


KEYWORDS = registeredKeywords()


def level(entry, hasCoeffs):
    """The level of the motion's dictionaries that holds the entry, or
    None (outside the motion's coefficients, or not a level checked)"""
    path = entry.path
    if hasCoeffs:
        if "rigidBodyMotionCoeffs" not in path:
            return None
        path = path[path.index("rigidBodyMotionCoeffs") + 1:]
    if not path:
        return "coefficients"
    if len(path) == 2 and path[0] == "bodies":
        return "body"
    if len(path) == 3 and path[0] == "bodies" and path[2] == "joint":
        return "joint"
    if len(path) == 2 and path[0] == "restraints":
        return "restraint"
    if path == ["solver"]:
        return "solver"
    return None


def misspelling(key, rng, known):
    """One edit of key (a letter dropped, two swapped, a case changed)
    that is no keyword of its level"""
    for _ in range(20):
        i = rng.randrange(len(key))
        kind = rng.choice(["drop", "swap", "case"])
        if kind == "drop":
            new = key[:i] + key[i + 1:]
        elif kind == "swap" and i + 1 < len(key) and key[i] != key[i + 1]:
            new = key[:i] + key[i + 1] + key[i] + key[i + 2:]
        elif kind == "case" and key[i].isalpha():
            new = key[:i] + key[i].swapcase() + key[i + 1:]
        else:
            continue
        if new not in known and len(new) >= 4:
            return new
    return None


def mutate(text, rng):
    """One mutation of the dictionary text: (new text, description, words
    that name it, line of the mutation).  None if nothing applies."""
    entries = parse(text)
    if not entries:
        return None

    leaves = [e for e in entries if e.children is None and e.values]
    numeric = [(e, v) for e in leaves for v in e.values
               if NUMBER_RE.match(v[0])]
    wordVals = [(e, v) for e in leaves for v in e.values
                if v[0] not in "(){}[];" and not NUMBER_RE.match(v[0])
                and not v[0].startswith("#")]
    vectors = [(e, l) for e in leaves for l in lists(e)]
    bodies = [e for e in entries if e.children is not None
              and e.path and e.path[-1] == "bodies"]

    def replaceValue(e, v, s, end, new):
        """The value v of entry e, at text[s:end], replaced by new"""
        return (text[:s] + new + text[end:],
                "%s: %s -> %s" % ("/".join(e.path + [e.key]), v, new),
                [e.key] + e.path + [new], lineOf(text, s))

    kinds = ["delete", "number", "number", "number", "word", "length",
             "vector", "transform", "selfParent", "cycle", "duplicate",
             "truncate", "misspell", "misspell"]
    # Keywords of the motion's dictionaries (a file with bodies), not used
    # by $ or #eval elsewhere (OpenFOAM's reader would stop first)
    hasCoeffs = any(e.key == "rigidBodyMotionCoeffs" for e in entries)
    spellable = []
    if any(e.key == "bodies" for e in entries):
        spellable = [(e, level(e, hasCoeffs)) for e in entries]
        spellable = [(e, l) for e, l in spellable
                     if l and e.key in KEYWORDS[l] and len(e.key) >= 4
                     and not re.search(r"\$\{?" + e.key + r"\b", text)]
    for _ in range(20):
        kind = rng.choice(kinds)

        if kind == "delete":
            e = rng.choice(entries)
            names = [e.key] + e.path
            return (text[:e.start] + text[e.end:],
                    "delete " + "/".join(e.path + [e.key]), names,
                    lineOf(text, e.start))

        if kind == "number" and numeric:
            e, (v, s, end) = rng.choice(numeric)
            new = rng.choice(NUMBERS)
            if new == "NEG":
                new = v[1:] if v.startswith("-") else "-" + v
            return replaceValue(e, v, s, end, new)

        if kind == "word" and wordVals:
            e, (v, s, end) = rng.choice(wordVals)
            new = rng.choice(["oops", "1", "Rq", "root", "linearSpringy"])
            return replaceValue(e, v, s, end, new)

        if kind == "length" and vectors:
            e, (ls, le, items) = rng.choice(vectors)
            if rng.random() < 0.5 or len(items) == 1:
                newList = "(" + " ".join(x[0] for x in items) + " 0)"
            else:
                newList = "(" + " ".join(x[0] for x in items[:-1]) + ")"
            return (text[:ls] + newList + text[le:],
                    "%s: list of %d -> %s" % ("/".join(e.path + [e.key]),
                                              len(items), newList),
                    [e.key] + e.path, lineOf(text, ls))

        if kind == "vector":
            threes = [(e, l) for e, l in vectors if len(l[2]) == 3]
            if threes:
                e, (ls, le, items) = rng.choice(threes)
                if rng.random() < 0.5:
                    newList = "(0 0 0)"
                else:
                    newList = "(" + " ".join(
                        "%.6g" % (3.7*float(x[0])) for x in items) + ")"
                return (text[:ls] + newList + text[le:],
                        "%s: %s" % ("/".join(e.path + [e.key]), newList),
                        [e.key] + e.path, lineOf(text, ls))

        if kind == "transform":
            nines = [(e, l) for e, l in vectors if len(l[2]) == 9]
            if nines:
                e, (ls, le, items) = rng.choice(nines)
                newList = "(" + " ".join(
                    "%.3f" % rng.uniform(-2, 2) for _ in range(9)) + ")"
                return (text[:ls] + newList + text[le:],
                        "%s: tensor %s" % ("/".join(e.path + [e.key]),
                                           newList),
                        [e.key] + e.path, lineOf(text, ls))

        if kind == "selfParent" and bodies:
            b = rng.choice(bodies)
            parents = [e for e in entries if e.path == b.path + [b.key]
                       and e.key == "parent" and e.values]
            if parents:
                p = parents[0]
                s, end = p.values[0][1], p.values[-1][2]
                return (text[:s] + b.key + text[end:],
                        "body %s: parent %s" % (b.key, b.key),
                        ["parent", b.key], lineOf(text, s))

        if kind == "cycle" and len(bodies) >= 2:
            a, b = rng.sample(bodies, 2)
            pa = [e for e in entries if e.path == a.path + [a.key]
                  and e.key == "parent" and e.values]
            pb = [e for e in entries if e.path == b.path + [b.key]
                  and e.key == "parent" and e.values]
            if pa and pb:
                edits = sorted([(pa[0].values[0][1], pa[0].values[-1][2],
                                 b.key),
                                (pb[0].values[0][1], pb[0].values[-1][2],
                                 a.key)], reverse=True)
                new = text
                for s, end, w in edits:
                    new = new[:s] + w + new[end:]
                return (new, "bodies %s and %s each other's parent"
                        % (a.key, b.key), ["parent", a.key, b.key],
                        lineOf(text, edits[-1][0]))

        if kind == "duplicate" and bodies:
            b = rng.choice(bodies)
            block = text[b.start:b.end]
            return (text[:b.end] + "\n" + block + text[b.end:],
                    "body %s written twice" % b.key, [b.key],
                    lineOf(text, b.start))

        if kind == "misspell" and spellable:
            e, l = rng.choice(spellable)
            new = misspelling(e.key, rng, KEYWORDS[l])
            if new:
                return (text[:e.start] + new + text[e.start + len(e.key):],
                        "misspell %s -> %s" % ("/".join(e.path + [e.key]),
                                               new),
                        [new, e.key], lineOf(text, e.start))

        if kind == "truncate":
            cut = rng.randrange(len(text) // 4, len(text))
            return (text[:cut], "truncated at character %d of %d"
                    % (cut, len(text)), [], lineOf(text, cut))
    return None


# ------------------------------------------------------------------ Cases

def makeCase(seeds, seed, i, root):
    """Case i: a copy of a seed case with one mutation; returns (dir,
    seed name, file, description, names, line) or None."""
    rng = random.Random("%d:%d" % (seed, i))
    seedDir = rng.choice(seeds)
    d = os.path.join(root, "case%05d" % i)
    shutil.copytree(seedDir, d)
    dictFile = "constant/dynamicMeshDict"
    if not os.path.isfile(os.path.join(d, dictFile)):
        dictFile = "constant/rigidBodyMotionDict"
    target = "system/controlDict" if rng.random() < 0.15 else dictFile
    path = os.path.join(d, target)
    text = open(path, errors="replace").read()
    m = mutate(text, rng)
    if m is None:
        return None
    newText, what, names, line = m
    with open(path, "w") as f:
        f.write(newText)
    return (d, os.path.basename(seedDir), target, what, names, line)


FATAL_RE = re.compile(r"--> FOAM FATAL (IO )?ERROR")
PROGRESS_RE = re.compile(r"^rigidBodySim: t = (\S+) s", re.M)
NONFINITE_RE = re.compile(r"(?<![\w.])-?(nan|inf)(?![\w])", re.I)


def nonFiniteIn(caseDir, log):
    """Where a nan or inf is, in the log (outside a fatal message, which
    may quote the value that failed) or in the written output; or None."""
    head = FATAL_RE.split(log)[0]
    if NONFINITE_RE.search(head):
        return "log"
    for dirpath, _, files in os.walk(caseDir):
        rel = os.path.relpath(dirpath, caseDir)
        if rel.startswith(("constant", "system")):
            continue
        for f in files:
            if f.endswith(".lastGood"):
                continue   # the state before a failed step: may be huge
            p = os.path.join(dirpath, f)
            try:
                text = open(p, errors="replace").read()
            except OSError:
                continue
            if NONFINITE_RE.search(text):
                return os.path.relpath(p, caseDir)
    return None


def runCase(case, timeout, stock):
    d, seedName, target, what, names, line = case
    if stock:
        cmd = [os.path.join(TOP, "test", "stockDriver", "runStock"),
               "-case", d, "-endOnly"]
    else:
        cmd = ["rigidBodySim", "-case", d]
    env = dict(os.environ)
    env.pop("FOAM_ABORT", None)
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=timeout,
                           env=env, start_new_session=True)
        rc, out = p.returncode, p.stdout
        timedOut = False
    except subprocess.TimeoutExpired as ex:
        rc, out, timedOut = None, ex.stdout or b"", True
    log = out.decode(errors="replace")
    with open(os.path.join(d, "log"), "w") as f:
        f.write(log)

    if timedOut:
        times = PROGRESS_RE.findall(log)
        if len(times) >= 2 and times[-1] != times[0]:
            return "slow", "progress to t = %s at the time limit" % times[-1]
        return "hang", "killed after %g s" % timeout
    if rc < 0 or rc >= 128 or re.search(r"^#\d+ ", log, re.M) \
            or "sigFpe" in log or "sigSegv" in log:
        return "signal", "exit status %d" % rc
    fatal = FATAL_RE.search(log)
    if rc == 0 and not fatal:
        where = nonFiniteIn(d, log)
        if where:
            return "nonFinite", "nan or inf in " + where
        if not re.search(r"^End\s*$", log, re.M):
            return "other", "exit status 0 without End"
        return "completed", ""
    if not fatal:
        return "other", "exit status %d, no fatal error: %s" \
            % (rc, log.strip().splitlines()[-1][:100] if log.strip() else "")
    msg = log[fatal.start():]
    if what.startswith("misspell ") and "did you mean " + names[1] not in msg:
        return "unnoticed", " ".join(msg.split())[:160]
    lines = re.findall(r"line (\d+)", msg)
    named = any(re.search(r"(?<![\w])" + re.escape(w) + r"(?![\w])", msg)
                for w in names if w)
    named = named or str(line) in lines
    if not names:
        named = target.split("/")[-1] in msg
    summary = " ".join(msg.split())[:160]
    if not named and "Foam::parsing::" in msg:
        return "reader", summary
    return ("error" if named else "vague"), summary


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20)
    ap.add_argument("--stock", action="store_true",
                    help="run the stock library (test/stockDriver)")
    ap.add_argument("--keep", help="make the cases in DIR and keep them")
    ap.add_argument("--replay", type=int, help="make and run case I only")
    ap.add_argument("--summary", help="write the counts to FILE")
    args = ap.parse_args()

    root = args.keep or tempfile.mkdtemp(prefix="fuzz.")
    os.makedirs(root, exist_ok=True)
    seeds = seedCases(os.path.join(root, "seeds"))

    indices = [args.replay] if args.replay is not None \
        else range(args.cases)
    cases = {}
    for i in indices:
        c = makeCase(seeds, args.seed, i, root)
        if c:
            cases[i] = c

    counts = {k: 0 for k in OUTCOMES}
    bad = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(runCase, c, args.timeout, args.stock): i
                   for i, c in cases.items()}
        for fut in concurrent.futures.as_completed(futures):
            i = futures[fut]
            outcome, detail = fut.result()
            counts[outcome] += 1
            if outcome in BAD or args.replay is not None:
                d, seedName, target, what, _, _ = cases[i]
                bad.append((i, outcome, seedName, target, what, detail))

    print("fuzz: %s, seed %d, %d cases (%d seed cases)"
          % ("stock library" if args.stock else "rigidBodySim",
             args.seed, len(cases), len(seeds)))
    for k in OUTCOMES:
        print("    %-10s %d" % (k, counts[k]))
    for i, outcome, seedName, target, what, detail in sorted(bad):
        print("%s: case %d (seed case %s, %s): %s: %s"
              % (outcome, i, seedName, target, what, detail))

    if args.summary:
        with open(args.summary, "w") as f:
            f.write("cases %d;\nseed %d;\n" % (len(cases), args.seed))
            f.write("misspelt %d;\n" % sum(
                1 for c in cases.values() if c[3].startswith("misspell ")))
            for k in OUTCOMES:
                f.write("%s %d;\n" % (k, counts[k]))

    if not args.keep:
        shutil.rmtree(root, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
