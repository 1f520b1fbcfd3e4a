#!/usr/bin/env python3
"""Work-precision of the project's solvers against the stock library's.

Run through bench/workPrecision/run, which sets the environment.  Usage:

    workPrecision.py [-quick] [-o DIR]

For each problem below, each solver (ours: Newmark, CrankNicolson,
symplectic, and RK4 when rigidBodySim accepts it; stock: Newmark,
CrankNicolson, symplectic, the stock library in its own process through
test/stockDriver/runStock) and each deltaT (halved from coarse to fine), it
runs the same case, nIter 1 (one solve per step) for every solver, reads
the status blocks both print at the start and the end, and computes the
error at the end time.

The problems and their errors (all dimensionless):

  springMass   a 2 kg mass on a Pz joint hung by a spring (k 50 N/m, rest
               length 0.5 m) and damper (c 0.2 N s/m, damping ratio 0.01)
               from (0 0 1) in gravity, released at rest from z = 0, for
               10 s.  Exact: z = ze + (z0 - ze) e^(-zeta w t)
               (cos wd t + zeta w/wd sin wd t).  Error:
               sqrt((z - zx)^2 + ((zDot - zDotx)/w)^2)/|z0 - ze|.
  twoBody      two bodies in series on Pz joints (B's joint rides on A's),
               each held by an undamped spring from (0 0 1), in gravity,
               for 5 s.  In joint coordinates the mass matrix couples them;
               the modes (modal analysis of K phi = w^2 M phi) are each
               body's own height, w = sqrt(k/m) for each.  Exact: each
               height a cosine about its equilibrium.  Error:
               sqrt(sum_i (z_i - zx_i)^2 + ((zDot_i - zDotx_i)/w_i)^2)
               / sqrt(sum_i a_i^2) (a_i the amplitudes).
  pendulum     a compound pendulum on an Ry joint (1 kg, centre of mass
               1 m below the pivot, 0.01 kg m^2 about it) released at rest
               from 150 degrees, run for exactly one period
               T = 4 K(sin(theta0/2))/w0, w0^2 = m g d/I (K the complete
               elliptic integral of the first kind, by the
               arithmetic-geometric mean).  Exact: back at the start.
               Error: sqrt((theta - theta0)^2 + (thetaDot/w0)^2)/theta0
               (theta from the orientation, thetaDot from the angular
               velocity the status prints).
  top          a torque-free asymmetric body (principal inertias 1, 2, 3
               kg m^2, Pxyz + Rs joints, no gravity) spinning at 2 rad/s about
               the intermediate axis with 0.01 rad/s about the others, for
               10 s: it flips over once.  Exact: energy E and angular
               momentum L conserved.  Error: |E - E0|/E0 + |L - L0|/|L0|
               (L in global axes from the orientation and angular velocity
               printed).
  chain        a 10-link chain of Rz joints (links 0.1 m, 1 kg, released
               horizontal under gravity) for 0.5 s, against a converged
               reference: the most accurate of our solvers (RK4 when there,
               else Newmark) at deltaT 1/16 of the finest in the sweep,
               shown converged by halving it once more.  Error:
               sqrt(mean over links of (|r - rRef|/0.1 m)^2
               + |E - ERef|_F^2/2) (r the link's joint position, E its
               orientation: in the plane |dE|_F^2/2 is about the angle
               error squared).

Cost: the CPU time (std::clock) of the time loop each driver prints in
its summary ("N steps, M solves, W s of wall time, X us per step, C s of
CPU time"), less that of a
one-step run of the same case: the start-up of the loop and the output at
the end (the table row, the state and the status; about 1 ms for ours)
are the same for every deltaT and are not the solver's cost.  Each run is
repeated (3 times, 1 with -quick; 9 times, 3 with -quick, for the runs of
500 steps or fewer, 250 with -quick, and the one-step runs) and the
minimum taken, since other jobs share the machine.  A run whose time is
not above the one-step run's is shown as not measured (n/m) and left out
of the plot and the summary.

Prints per problem a table and one line
    workprecision PROBLEM: at stock's best error ours is X times faster
X: the smallest error any stock run reached; the cheapest of our runs at or
below it (interpolated log-log along each of our solvers' curves between
the two runs that bracket it; our coarsest run if already below); the
stock run's cost divided by that.  Writes one PNG per problem,
DIR/workPrecision-PROBLEM.png, and the tables (markdown) into the
workPrecision section of DIR/README.md (DIR: bench unless -o).
"""

import datetime
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

# ----------------------------------------------------------------- options

quick = '-quick' in sys.argv
outDir = 'docs'
if '-o' in sys.argv:
    outDir = sys.argv[sys.argv.index('-o') + 1]

levels = 5 if quick else 7
repeats = 1 if quick else 3
# The short runs' times are the noisiest: more repeats for them and for the
# one-step runs subtracted from every run
shortRun = 250 if quick else 500
shortRepeats = 3 if quick else 9

top = os.environ.get('RBD_PROJECT_DIR', os.getcwd())
runStock = os.path.join(top, 'test', 'stockDriver', 'runStock')


# ----------------------------------------------------------------- cases

def header(cls, location, obj):
    return ('FoamFile\n{\n    version 2.0;\n    format ascii;\n'
            '    class %s;\n    location "%s";\n    object %s;\n}\n'
            % (cls, location, obj))


def writeCase(caseDir, coeffs, solver, dt, nSteps, nIter=1):
    """A case of nSteps steps of dt, written and reported at the end only"""
    os.makedirs(os.path.join(caseDir, 'constant'), exist_ok=True)
    os.makedirs(os.path.join(caseDir, 'system'), exist_ok=True)
    for d in os.listdir(caseDir):
        if d not in ('constant', 'system'):
            shutil.rmtree(os.path.join(caseDir, d))
    with open(os.path.join(caseDir, 'system', 'controlDict'), 'w') as f:
        f.write(header('dictionary', 'system', 'controlDict'))
        f.write('application rigidBodySim;\nstartFrom startTime;\n'
                'startTime 0;\nstopAt endTime;\nendTime %.17g;\n'
                'deltaT %.17g;\nwriteControl timeStep;\nwriteInterval %d;\n'
                'writeFormat ascii;\nwritePrecision 17;\n'
                'timeFormat general;\ntimePrecision 17;\n'
                'runTimeModifiable false;\n'
                % (nSteps*dt, dt, nSteps))
    with open(os.path.join(caseDir, 'constant', 'rigidBodyMotionDict'),
              'w') as f:
        f.write(header('dictionary', 'constant', 'rigidBodyMotionDict'))
        f.write('report on;\nnIter %d;\nsolver { type %s; }\n'
                % (nIter, solver))
        f.write(coeffs)


def cuboidPz(name, parent, mass):
    return ('    %s\n    {\n        type cuboid; parent %s; mass %g;\n'
            '        L (0.2 0.2 0.1); centreOfMass (0 0 0);\n'
            '        transform (1 0 0 0 1 0 0 0 1) (0 0 0);\n'
            '        joint { type Pz; }\n    }\n' % (name, parent, mass))


def spring(name, body, k, c, restLength):
    return ('    %s\n    {\n        type linearSpring; body %s;\n'
            '        anchor (0 0 1); refAttachmentPt (0 0 0);\n'
            '        stiffness %g; damping %g; restLength %g;\n    }\n'
            % (name, body, k, c, restLength))


g = 9.81


class Problem:
    """name, title, the model, endTime, the coarsest number of steps"""
    reference = False

    def states(self, log):
        return parseStatus(log)


# springMass ------------------------------------------------------------
class SpringMass(Problem):
    name = 'springMass'
    title = 'damped spring-mass (exact solution)'
    m, k, c, L0 = 2.0, 50.0, 0.2, 0.5
    endTime = 10.0
    n0 = 200

    def coeffs(self):
        return ('g (0 0 -%g);\nbodies\n{\n%s}\nrestraints\n{\n%s}\n'
                % (g, cuboidPz('mass', 'root', self.m),
                   spring('spring', 'mass', self.k, self.c, self.L0)))

    def error(self, start, end, ref=None):
        m, k, c = self.m, self.k, self.c
        w = math.sqrt(k/m)
        zeta = c/(2*math.sqrt(k*m))
        wd = w*math.sqrt(1 - zeta**2)
        ze = 1 - self.L0 - m*g/k
        a = 0 - ze
        t = self.endTime
        e = math.exp(-zeta*w*t)
        zx = ze + a*e*(math.cos(wd*t) + zeta*w/wd*math.sin(wd*t))
        vx = -a*e*w**2/wd*math.sin(wd*t)
        z = end['mass']['r'][2]
        v = end['mass']['v'][2]
        return math.hypot(z - zx, (v - vx)/w)/abs(a)


# twoBody ---------------------------------------------------------------
class TwoBody(Problem):
    name = 'twoBody'
    title = 'undamped two-body spring system (exact, modal)'
    mA, kA, LA = 1.0, 40.0, 0.5
    mB, kB, LB = 0.5, 90.0, 0.3
    qB0 = 0.3
    endTime = 5.0
    n0 = 250

    def coeffs(self):
        return ('g (0 0 -%g);\nqDot (0 0);\nq (0 %g);\n'
                'bodies\n{\n%s%s}\nrestraints\n{\n%s%s}\n'
                % (g, self.qB0,
                   cuboidPz('A', 'root', self.mA),
                   cuboidPz('B', 'A', self.mB),
                   spring('springA', 'A', self.kA, 0, self.LA),
                   spring('springB', 'B', self.kB, 0, self.LB)))

    def error(self, start, end, ref=None):
        t = self.endTime
        num = 0
        den = 0
        for body, m, k, L, z0 in (('A', self.mA, self.kA, self.LA, 0.0),
                                  ('B', self.mB, self.kB, self.LB,
                                   self.qB0)):
            w = math.sqrt(k/m)
            ze = 1 - L - m*g/k
            a = z0 - ze
            zx = ze + a*math.cos(w*t)
            vx = -a*w*math.sin(w*t)
            num += (end[body]['r'][2] - zx)**2 \
                + ((end[body]['v'][2] - vx)/w)**2
            den += a**2
        return math.sqrt(num/den)


# pendulum --------------------------------------------------------------
def ellipticK(k):
    """Complete elliptic integral of the first kind, modulus k, by the
    arithmetic-geometric mean: K = pi/(2 agm(1, sqrt(1 - k^2)))"""
    a, b = 1.0, math.sqrt(1 - k*k)
    for _ in range(60):
        a, b = 0.5*(a + b), math.sqrt(a*b)
        if abs(a - b) < 1e-16*a:
            break
    return math.pi/(2*a)


class Pendulum(Problem):
    name = 'pendulum'
    title = 'large-angle pendulum, 150 degrees, one period'
    m, d, Icm = 1.0, 1.0, 0.01
    theta0 = 150*math.pi/180

    def __init__(self):
        I = self.Icm + self.m*self.d**2
        self.w0 = math.sqrt(self.m*g*self.d/I)
        self.endTime = 4*ellipticK(math.sin(self.theta0/2))/self.w0
        self.n0 = 100

    def coeffs(self):
        return ('g (0 0 -%g);\nq (%.17g);\nqDot (0);\nbodies\n{\n'
                '    bob\n    {\n        type rigidBody; parent root;'
                ' mass %g;\n        centreOfMass (0 0 -%g);\n'
                '        inertia (%g 0 0 %g 0 %g);\n'
                '        transform (1 0 0 0 1 0 0 0 1) (0 0 0);\n'
                '        joint { type Ry; }\n    }\n}\n'
                % (g, self.theta0, self.m, self.d, self.Icm, self.Icm,
                   self.Icm))

    @staticmethod
    def angle(s):
        E = s['bob']['E']
        return math.atan2(E[2], E[0]), s['bob']['w'][1]

    def error(self, start, end, ref=None):
        th0, om0 = self.angle(start)
        th, om = self.angle(end)
        dth = (th - th0 + math.pi) % (2*math.pi) - math.pi
        return math.hypot(dth, (om - om0)/self.w0)/self.theta0


# top -------------------------------------------------------------------
def matVec(E, v):
    return [sum(E[3*i + j]*v[j] for j in range(3)) for i in range(3)]


def matTVec(E, v):
    return [sum(E[3*j + i]*v[j] for j in range(3)) for i in range(3)]


class Top(Problem):
    name = 'top'
    title = 'torque-free asymmetric top through an intermediate-axis flip'
    I = (1.0, 3.0, 2.0)
    endTime = 10.0
    n0 = 250

    def coeffs(self):
        return ('g (0 0 0);\nqDot (0 0 0 2 0.01 0.01);\nbodies\n{\n'
                '    top\n    {\n        type rigidBody; parent root;'
                ' mass 1;\n        centreOfMass (0 0 0);\n'
                '        inertia (%g 0 0 %g 0 %g);\n'
                '        transform (1 0 0 0 1 0 0 0 1) (0 0 0);\n'
                '        joint { type floating; }\n    }\n}\n'
                % self.I)

    def invariants(self, s):
        E = s['top']['E']            # global to body
        wg = s['top']['w']           # angular velocity, global axes
        wb = matVec(E, wg)
        Lb = [self.I[i]*wb[i] for i in range(3)]
        energy = 0.5*sum(wb[i]*Lb[i] for i in range(3))
        return energy, matTVec(E, Lb)

    def error(self, start, end, ref=None):
        E0, L0 = self.invariants(start)
        E1, L1 = self.invariants(end)
        dL = math.sqrt(sum((L1[i] - L0[i])**2 for i in range(3)))
        nL = math.sqrt(sum(L0[i]**2 for i in range(3)))
        return abs(E1 - E0)/E0 + dL/nL


# chain -----------------------------------------------------------------
class Chain(Problem):
    name = 'chain'
    title = '10-link Rz chain in gravity, against a converged reference'
    reference = True
    endTime = 0.5
    n0 = 125
    nLinks = 10
    length = 0.1

    def coeffs(self):
        s = 'g (0 -%g 0);\nbodies\n{\n' % g
        parent, origin = 'root', '(0 0 0)'
        for i in range(self.nLinks):
            s += ('    link%d\n    {\n        type rigidBody; parent %s;'
                  ' mass 1;\n        centreOfMass (0.05 0 0);\n'
                  '        inertia (1e-4 0 0 1e-3 0 1e-3);\n'
                  '        transform (1 0 0 0 1 0 0 0 1) %s;\n'
                  '        joint { type Rz; }\n    }\n'
                  % (i, parent, origin))
            parent, origin = 'link%d' % i, '(0.1 0 0)'
        return s + '}\n'

    def error(self, start, end, ref=None):
        total = 0
        for i in range(self.nLinks):
            a, b = end['link%d' % i], ref['link%d' % i]
            dr = sum((a['r'][j] - b['r'][j])**2 for j in range(3))
            dE = sum((a['E'][j] - b['E'][j])**2 for j in range(9))
            total += dr/self.length**2 + dE/2
        return math.sqrt(total/self.nLinks)


# ----------------------------------------------------------------- running

number = r'[-+0-9.eEinfa]+'


def parseVector(text):
    return [float(x) for x in text.strip().strip('()').split()]


def parseStatus(log):
    """The status blocks of a log: a list of (time, {body: state})"""
    blocks = []
    body = None
    for line in log.splitlines():
        if line.startswith('Time = '):
            blocks.append((float(line.split()[2]), {}))
        elif line.startswith('Rigid-body motion of the '):
            body = line[len('Rigid-body motion of the '):].strip()
            blocks[-1][1][body] = {}
        elif body is not None and ':' in line and blocks:
            key, _, value = line.strip().partition(':')
            short = {'Centre of rotation': 'r', 'Orientation': 'E',
                     'Linear velocity': 'v',
                     'Angular velocity': 'w'}.get(key)
            if short:
                blocks[-1][1][body][short] = parseVector(value)
    return blocks


summaryRe = re.compile(r'^(?:rigidBodySim|stockRigidBodySim): (\d+) steps, '
                       r'(\d+) solves, \S+ s of wall time, \S+ us per step, '
                       r'(\S+) s of CPU time', re.M)


def runOnce(lib, caseDir):
    cmd = (['rigidBodySim', '-case', caseDir] if lib == 'ours'
           else [runStock, '-case', caseDir, '-endOnly'])
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    m = summaryRe.search(p.stdout)
    if p.returncode != 0 or not m:
        return None
    nSteps = int(m.group(1))
    return p.stdout, nSteps, int(m.group(2)), float(m.group(3))


def run(problem, lib, solver, n, tmp, nIter=1, nRepeats=None):
    """(final state, start state, loop wall time [s], steps, solves):
    the minimum wall time of the repeats; None if the run failed"""
    caseDir = os.path.join(tmp, '%s-%s-%s-%d' % (problem.name, lib, solver, n))
    writeCase(caseDir, problem.coeffs(), solver, problem.endTime/n, n, nIter)
    best = None
    for r in range(repeats if nRepeats is None else nRepeats):
        for d in os.listdir(caseDir):
            if d not in ('constant', 'system'):
                shutil.rmtree(os.path.join(caseDir, d))
        result = runOnce(lib, caseDir)
        if result is None:
            print('  %s %s nIter %d, %d steps: the run failed'
                  % (lib, solver, nIter, n))
            shutil.rmtree(caseDir)
            return None
        log, nSteps, nSolves, wall = result
        if nSteps != n:
            raise RuntimeError('%s: %d steps, not %d' % (caseDir, nSteps, n))
        if best is None:
            blocks = problem.states(log)
            best = wall
        best = min(best, wall)
    shutil.rmtree(caseDir)
    return blocks[-1][1], blocks[0][1], best, nSteps, nSolves


def oursAccepts(solver, tmp):
    caseDir = os.path.join(tmp, 'probe-' + solver)
    writeCase(caseDir, SpringMass().coeffs(), solver, 0.01, 1)
    p = subprocess.run(['rigidBodySim', '-case', caseDir],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    shutil.rmtree(caseDir)
    return p.returncode == 0


def slope(xs, ys):
    """Least-squares slope of log y against log x"""
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-300)) for y in ys]
    mx, my = sum(lx)/len(lx), sum(ly)/len(ly)
    sxx = sum((a - mx)**2 for a in lx)
    return sum((a - mx)*(b - my) for a, b in zip(lx, ly))/sxx


def costAt(points, target):
    """The cost at which a curve of (cost, error) points, coarse to fine,
    first reaches error <= target: interpolated log-log between the two
    runs that bracket it, the first run if already there; None if never"""
    if points[0][1] <= target:
        return points[0][0]
    for (c0, e0), (c1, e1) in zip(points, points[1:]):
        if e1 <= target < e0:
            f = (math.log(e0) - math.log(target)) \
                / (math.log(e0) - math.log(e1))
            return math.exp(math.log(c0) + f*(math.log(c1) - math.log(c0)))
    return None


# ----------------------------------------------------------------- main

def splice(fileName, name, lines):
    """Replace the lines between the markers <!-- NAME: begin --> and
    <!-- NAME: end --> of a file (made if missing, the section added at
    its end if it has no markers)"""
    begin = '<!-- %s: begin (written by a script: edits here are lost) -->' \
        % name
    end = '<!-- %s: end -->' % name
    text = open(fileName).read().splitlines() \
        if os.path.exists(fileName) else []
    starts = [i for i, l in enumerate(text) if l.startswith(begin[:-4])]
    ends = [i for i, l in enumerate(text) if l == end]
    if starts and ends and starts[0] < ends[0]:
        text = text[:starts[0]] + [begin] + lines + text[ends[0]:]
    else:
        text += ['', begin] + lines + [end]
    with open(fileName, 'w') as f:
        f.write('\n'.join(text) + '\n')


def label(spec):
    lib, solver, nIter = spec
    return '%s %s%s' % (lib, solver, '' if nIter == 1 else ' nIter %d' % nIter)


def main():
    tmp = tempfile.mkdtemp(prefix='workPrecision.')
    try:
        # Warm up each driver (the first run of a process after a build or
        # an idle spell is slower)
        for lib in ('ours', 'stock'):
            run(SpringMass(), lib, 'Newmark', 100, tmp, nRepeats=2)
        oursSolvers = ['Newmark', 'CrankNicolson', 'symplectic']
        if oursAccepts('RK4', tmp):
            oursSolvers.append('RK4')
        specs = [('ours', s, 1) for s in oursSolvers] \
            + [('stock', s, 1) for s in ('Newmark', 'CrankNicolson',
                                         'symplectic')] \
            + [('stock', s, 2) for s in ('Newmark', 'CrankNicolson')]
        print('workPrecision: %s; %d levels of deltaT, minimum of %d repeats'
              % (', '.join(label(s) for s in specs), levels, repeats))
        refSolver = 'RK4' if 'RK4' in oursSolvers else 'Newmark'

        problems = [SpringMass(), TwoBody(), Pendulum(), Top(), Chain()]
        summary = []
        markdown = []
        for problem in problems:
            ns = [problem.n0*2**i for i in range(levels)]
            ref = None
            refNote = ''
            if problem.reference:
                nRef = ns[-1]*16
                ref = run(problem, 'ours', refSolver, nRef, tmp,
                          nRepeats=1)[0]
                ref2 = run(problem, 'ours', refSolver, 2*nRef, tmp,
                           nRepeats=1)[0]
                refChange = problem.error(None, ref, ref2)
                refNote = ('the reference: ours %s, %d steps (deltaT %.3g s);'
                           ' halving deltaT again changes it by %.2e'
                           % (refSolver, nRef, problem.endTime/nRef,
                              refChange))
            curves = {}
            for spec in specs:
                lib, solver, nIter = spec
                # The loop's fixed cost: a run of one step
                one = run(problem, lib, solver, 1, tmp, nIter,
                          nRepeats=shortRepeats)
                pts = []
                for n in ns:
                    r = run(problem, lib, solver, n, tmp, nIter,
                            nRepeats=shortRepeats if n <= shortRun
                            else repeats)
                    if r is None or one is None:
                        pts.append(None)
                        continue
                    end, start, wall, nSteps, nSolves = r
                    # None: not measured (no more than the one-step run)
                    cost = (wall - one[2])*n/max(n - 1, 1)
                    cost = cost if cost > 0 else None
                    err = max(problem.error(start, end, ref), 1e-16)
                    if not math.isfinite(err):
                        pts.append(None)
                        continue
                    pts.append((cost, err, n, nSolves))
                curves[spec] = pts
            if problem.reference:
                smallest = min(p[1] for c in curves.values() for p in c if p)
                refNote += (', %s the smallest error plotted (%.2e)'
                            % ('far below' if refChange < 0.01*smallest
                               else 'below' if refChange < 0.1*smallest
                               else 'NOT far below', smallest))

            # The summary line
            eS, cS, sS = min((p[1], p[0], label(spec))
                             for spec, c in curves.items()
                             if spec[0] == 'stock' for p in c
                             if p and p[0] is not None)
            best = None
            for spec, c in curves.items():
                if spec[0] != 'ours':
                    continue
                # The curve up to its first failure, its runs whose time
                # was measured
                pts = []
                for p in c:
                    if p is None:
                        break
                    if p[0] is not None:
                        pts.append((p[0], p[1]))
                cost = costAt(pts, eS) if pts else None
                if cost is not None and (best is None or cost < best[0]):
                    best = (cost, label(spec))
            if best is None:
                line = ('workprecision %s: at stock\'s best error ours is '
                        'never there' % problem.name)
            else:
                line = ('workprecision %s: at stock\'s best error ours is '
                        '%.3g times faster' % (problem.name, cS/best[0]))
            detail = ('%s: stock\'s best error %.2e (%s, %.3g ms); ours %s'
                      % (problem.name, eS, sS, 1e3*cS,
                         'did not reach it' if best is None else
                         'reached it with %s in %.3g ms'
                         % (best[1], 1e3*best[0])))
            summary.append((line, detail))

            # The table
            md = ['### %s: %s' % (problem.name, problem.title), '']
            md += ['Error at the end time, and in brackets the solve time'
                   ' in ms, at each deltaT (s); the order is the slope of'
                   ' log(error) against log(deltaT) over the three finest'
                   ' runs.', '']
            md.append('| solver | ' + ' | '.join(
                '%.4g' % (problem.endTime/n) for n in ns) + ' | order |')
            md.append('|---|' + '---|'*len(ns) + '---|')
            for spec, pts in curves.items():
                last = [p for p in pts[-3:] if p]
                order = ('%.2f' % slope([problem.endTime/p[2] for p in last],
                                        [p[1] for p in last])
                         if len(last) == 3 else '')
                md.append('| %s | ' % label(spec) + ' | '.join(
                    ('%.2e (%.3g)' % (p[1], 1e3*p[0]) if p[0] is not None
                     else '%.2e (n/m)' % p[1]) if p else 'failed'
                    for p in pts) + ' | %s |' % order)
            md.append('')
            if refNote:
                md += [refNote[0].upper() + refNote[1:] + '.', '']
            md += ['`%s`: %s.' % (line, detail[len(problem.name) + 2:]), '',
                   '![%s](workPrecision-%s.png)' % (problem.name,
                                                    problem.name), '']
            markdown += md
            print('\n'.join(md))
            sys.stdout.flush()

            plot(problem, curves, os.path.join(
                outDir, 'workPrecision-%s.png' % problem.name), tmp)

        splice(os.path.join(outDir, 'README.md'), 'workPrecision',
               ['Made with `bench/workPrecision/run%s` on %s.'
                % (' -quick' if quick else '',
                   datetime.date.today().isoformat()), '']
               + markdown)

        for line, detail in summary:
            print(detail)
        for line, detail in summary:
            print(line)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


colours = {'Newmark': '#d62728', 'CrankNicolson': '#1f77b4',
           'symplectic': '#2ca02c', 'RK4': '#9467bd'}


def plot(problem, curves, png, tmp):
    data = os.path.join(tmp, problem.name + '.dat')
    plots = []
    with open(data, 'w') as f:
        for i, (spec, pts) in enumerate(curves.items()):
            lib, solver, nIter = spec
            f.write('# %s\n' % label(spec))
            for p in pts:
                if p and p[0] is not None:
                    f.write('%.6e %.6e\n' % (p[0], p[1]))
                else:
                    f.write('\n')
            f.write('\n\n')
            plots.append("'%s' index %d using 1:2 with linespoints lw %g "
                         "dt %d pt %d ps %g lc rgb '%s' title '%s'"
                         % (data, i, 2 if lib == 'ours' else 1.5,
                            1 if lib == 'ours' else (2 if nIter == 1 else 4),
                            7 if lib == 'ours' else (6 if nIter == 1 else 4),
                            1 if lib == 'ours' else 1.3,
                            colours.get(solver, 'black'), label(spec)))
    script = ('set terminal pngcairo size 900,650\n'
              "set output '%s'\n"
              "set title '%s'\n"
              "set xlabel 'solve time [s] (loop time less a one-step run)'\n"
              "set ylabel 'error at the end time'\n"
              'set logscale xy\nset grid\nset format x "%%.0e"\n'
              'set format y "%%.0e"\nset key outside right\n'
              'plot %s\n' % (png, problem.title, ', \\\n     '.join(plots)))
    subprocess.run(['gnuplot'], input=script, universal_newlines=True,
                   check=True)


if __name__ == '__main__':
    main()
