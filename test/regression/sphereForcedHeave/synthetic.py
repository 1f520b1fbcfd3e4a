#!/usr/bin/env python3
"""The forced heave's reduction (tutorials/interDyMFoam/sphereForcedHeave/
results) on synthetic tables whose answers are known exactly.  Each check
prints PASS: or FAIL: with its tolerance; the exit status is 0.

    synthetic.py TUTORIAL TMP

TUTORIAL: the tutorial's folder (its results, hulme1982.dat and
constant/); TMP: a folder to work in.

The table's driving force is the one a body of the tutorial's mass needs
against a fluid force F = F0 - C z - A z'' - B z' (linear potential flow,
C = rho g pi a^2), on the wedge, with A and B known, the tutorial's ramped
heave, and time steps that vary from 1 to 5 ms.  With one outer corrector
(system/fvSolution) each row's driving force is made with the fluid's
force of the previous row's time, as the solver gives it; with three,
with the row's own.  Added to F: a second
harmonic (a nonlinearity) and, before the ramp's end, a decaying start-up
transient, neither of which a projection over whole periods after the ramp
may see.  The reduction must give A and B back within 2e-4 of rho V (the
trapezoidal rule's error at these steps is about 1e-5).  A table shorter
than the ramp and one period must stop ./results with a message.
"""
import math
import os
import shutil
import subprocess
import sys

A_SPHERE, MASS, G, RHO = 0.15, 7.056, 9.82, 998.2
BODY_SHARE = 5.0/360.0
MESH_SHARE = math.sin(math.radians(5))/(2*math.pi)
RHO_V = RHO*2.0/3.0*math.pi*A_SPHERE**3


def say(what, passed):
    print('%s: %s' % ('PASS' if passed else 'FAIL', what))


def heave(t, amplitude, omega):
    """z, z', z'' of the tutorial's ramped sine (half-cosine ramp over
    two periods)."""
    d = 2*2*math.pi/omega
    if t < d:
        r = 0.5*(1 - math.cos(math.pi*t/d))
        r1 = 0.5*math.pi/d*math.sin(math.pi*t/d)
        r2 = 0.5*(math.pi/d)**2*math.cos(math.pi*t/d)
    else:
        r, r1, r2 = 1.0, 0.0, 0.0
    s, c = math.sin(omega*t), math.cos(omega*t)
    z = amplitude*r*s
    z1 = amplitude*(r1*s + r*omega*c)
    z2 = amplitude*(r2*s + 2*r1*omega*c - r*omega*omega*s)
    return z, z1, z2


def make_case(tmp, tutorial, ka, amplitude, mu, lam, periods, nOuter=1):
    c = os.path.join(tmp, 'ka%g-%d' % (ka, nOuter))
    shutil.rmtree(c, ignore_errors=True)
    os.makedirs(os.path.join(c, 'postProcessing', 'rigidBodyMotion', '0'))
    shutil.copytree(os.path.join(tutorial, 'constant'),
                    os.path.join(c, 'constant'))
    for f in ('results', 'hulme1982.dat'):
        shutil.copy(os.path.join(tutorial, f), c)
    os.makedirs(os.path.join(c, 'system'))
    with open(os.path.join(c, 'system', 'fvSolution'), 'w') as f:
        f.write('FoamFile { version 2.0; format ascii; class dictionary;'
                ' object fvSolution; }\nPIMPLE { nOuterCorrectors %d; }\n'
                % nOuter)
    with open(os.path.join(c, 'log.parameters'), 'w') as f:
        f.write('FoamFile { version 2.0; format ascii; class dictionary;'
                ' object parameters; }\nka %g;\nheaveAmplitude %g;\n'
                % (ka, amplitude))
    omega = math.sqrt(ka*G/A_SPHERE)
    a33, b33 = mu*RHO_V, lam*RHO_V*omega
    stiffness = RHO*G*math.pi*A_SPHERE**2
    m = MASS*BODY_SHARE
    def fluid(t):
        z, z1, z2 = heave(t, amplitude, omega)
        return (RHO_V*G - stiffness*z - a33*z2 - b33*z1
                + 0.05*stiffness*amplitude*math.sin(2*omega*t + 0.3)
                + 2*stiffness*amplitude*math.exp(-3*omega*t))
    rows, t, i = [], 0.0, 0
    end = periods*2*math.pi/omega + 0.01     # as Allrun's
    while t < end:
        tPrev = t
        t += 0.001*(3 + 2*math.sin(0.7*i))      # 1 to 5 ms
        i += 1
        z, z1, z2 = heave(t, amplitude, omega)
        tau = m*(z2 + G) - MESH_SHARE*fluid(tPrev if nOuter == 1 else t)
        rows.append('%.12g %.12g %.12g' % (t, z, tau))
    with open(os.path.join(c, 'postProcessing', 'rigidBodyMotion', '0',
                           'sphere.dat'), 'w') as f:
        f.write('# t q0 heave.force\n' + '\n'.join(rows) + '\n')
    return c


def coefficients(c):
    out = subprocess.run(['./results'], cwd=c, capture_output=True,
                         text=True)
    values = {}
    path = os.path.join(c, 'postProcessing', 'forcedHeave', 'coefficients')
    if out.returncode == 0 and os.path.isfile(path):
        for line in open(path):
            name, value = line.split()
            values[name] = float(value.rstrip(';'))
    return out, values


def main():
    tutorial, tmp = sys.argv[1], sys.argv[2]
    os.makedirs(tmp, exist_ok=True)
    for ka, mu, lam, nOuter in ((0.4, 0.6452, 0.3410, 1),
                                (1.6, 0.3871, 0.1469, 1),
                                (0.8, 0.55, 0.20, 3)):
        c = make_case(tmp, tutorial, ka, 0.003, mu, lam, 6, nOuter)
        out, v = coefficients(c)
        what = 'ka %g, %d outer corrector%s' \
            % (ka, nOuter, 's' if nOuter > 1 else '')
        if not v:
            say('%s: ./results ran: %s' % (what, out.stderr.strip()), False)
            continue
        say('%s: added mass %.5f against %.5f (2e-4)'
            % (what, v['addedMass'], mu), abs(v['addedMass'] - mu) < 2e-4)
        say('%s: damping %.5f against %.5f (2e-4)'
            % (what, v['damping'], lam), abs(v['damping'] - lam) < 2e-4)
        say('%s: 4 whole periods after the ramp (%g)'
            % (what, v['periods']), v['periods'] == 4)
    c = make_case(tmp, tutorial, 1.6, 0.003, 0.4, 0.1, 2.9)
    out, v = coefficients(c)
    say('a table with no whole period after the ramp stops ./results with'
        ' a message: "%s"' % out.stderr.strip(),
        out.returncode != 0 and 'no whole period' in out.stderr)


if __name__ == '__main__':
    main()
