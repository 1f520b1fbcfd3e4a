#!/usr/bin/env python3
"""The figures of bench/floatingBox/coupling and decay, and of any run of
tutorials/interDyMFoam/floatingBoxInWaves (slide), from the run's
postProcessing/joined/rigidBodyMotion.dat (its ./results joins there the
pieces of a continued run).

    analyse.py windows CASE REF FROMLINE
        heave and pitch half-ranges over 3.6-4.8 s and 4.2-5.4 s, and the
        heave against REF's (a run's folder, or - for none), the mean
        deltaT over each window, the share of its steps flagged "coupling
        not converged" and the mean outer correctors a step
    analyse.py decay CASE FROMLINE heave|pitch STIFFNESS INERTIA
        the free motion's extremes, damped period, logarithmic decrement
        and the added mass (heave) or inertia (pitch) they give with the
        hydrostatic STIFFNESS [N/m or N m/rad] and the body's own mass or
        moment of inertia INERTIA [kg or kg m^2]
    analyse.py slide CASE
        the heave and pitch amplitudes (half the range) and the mean pitch
        over windows of three wave periods (3.6 s), the last one the run's
        last three periods (those of ./results), each earlier by half a
        period (0.6 s), none before 3.2 s: how a run's figures depend on
        the window

windows and decay print the piece of CASE/log.interFoam after line FROMLINE
(the run this script is about, where a continued run's log was appended to):
its clock time, time steps and the range of its deltaT. Exit status 1 where
the figures cannot be made.
"""
import math
import os
import sys


def motion(case):
    """Time, heave (q1) and pitch (q2), the columns found by the header."""
    f = os.path.join(case, 'postProcessing', 'joined', 'rigidBodyMotion.dat')
    if not os.path.isfile(f):
        return None
    names, rows = None, []
    for line in open(f):
        if line.startswith('#'):
            fields = line[1:].split()
            if fields and fields[0] == 't':
                names = fields
        elif line.strip():
            rows.append([float(x) for x in line.split()])
    if not names or 'q1' not in names or 'q2' not in names or not rows:
        return None
    cz, cr = names.index('q1'), names.index('q2')
    return [r[0] for r in rows], [r[cz] for r in rows], [r[cr] for r in rows]


def piece(case, fromLine):
    """The log after fromLine: the times of its steps, and a summary of its
    clock and CPU time, time steps and deltaT range; sets the module's
    FLAGGED (the times of the steps flagged "coupling not converged") and
    OUTER (each step's time and its number of PIMPLE outer correctors)."""
    global FLAGGED, OUTER
    f = os.path.join(case, 'log.interFoam')
    clock, cpu, times, dts = '?', '?', [], []
    FLAGGED, OUTER = set(), []
    if os.path.isfile(f):
        for i, line in enumerate(open(f, errors='replace')):
            if i < fromLine:
                continue
            w = line.split()
            if line.startswith('Time = ') and len(w) == 3:
                times.append(float(w[2]))
                OUTER.append([times[-1], 0])
            elif line.startswith('deltaT = ') and len(w) == 3:
                dts.append(float(w[2]))
            elif line.startswith('PIMPLE: iteration ') and OUTER:
                OUTER[-1][1] += 1
            elif line.startswith('rigidBodyMotion: coupling not converged'):
                FLAGGED.add(float(w[7].rstrip(':')))
            elif 'ClockTime = ' in line:
                clock = w[-2]
                cpu = w[2]
    dt = ('deltaT %.3g to %.3g s' % (min(dts), max(dts))) if dts else 'deltaT ?'
    return times, ('interFoam clock %s s, CPU %s s, %d steps, %s'
                   % (clock, cpu, len(times), dt))


FLAGGED, OUTER = set(), []


def correctorsAndFlags(times, a, b):
    """Over a < t <= b: the steps, the share flagged "coupling not
    converged", and the mean outer correctors per step."""
    inside = [t for t in times if a < t <= b]
    flagged = sum(1 for t in FLAGGED if a < t <= b + 1e-9)
    outer = [n for t, n in OUTER if a < t <= b]
    return (len(inside), flagged/max(len(inside), 1),
            sum(outer)/max(len(outer), 1))


def halfRange(t, x, a, b):
    w = [xi for ti, xi in zip(t, x) if a <= ti <= b]
    inside = [ti for ti in t if a <= ti <= b]
    if not w or inside[-1] < b - 0.01 or inside[0] > a + 0.01:
        return None
    return (max(w) - min(w))/2


def windows(case, ref, fromLine):
    ours = motion(case)
    theirs = motion(ref) if ref != '-' and os.path.isdir(ref) else None
    times, summary = piece(case, fromLine)
    parts, ok = [], ours is not None
    for a, b in ((3.6, 4.8), (4.2, 5.4)):
        h = ours and halfRange(ours[0], ours[1], a, b)
        if not h:
            parts.append('%g-%g s: not reached' % (a, b))
            ok = False
            continue
        s = '%g-%g s: heave %.4f m' % (a, b, h)
        hr = theirs and halfRange(theirs[0], theirs[1], a, b)
        if hr:
            s += ' (%+.0f%% against %s)' % (100*(h/hr - 1),
                                              os.path.basename(ref))
        steps, flagged, outer = correctorsAndFlags(times, a, b)
        parts.append(s + ', pitch %.4f rad, mean deltaT %.3g s, flagged'
                     ' %.0f%% of %d steps, %.2f outer correctors a step'
                     % (halfRange(ours[0], ours[2], a, b),
                        (b - a)/steps if steps else float('nan'),
                        100*flagged, steps, outer))
    print('%s: %s; %s' % (os.path.basename(case), '; '.join(parts), summary))
    return ok


# slide's windows: three wave periods (1.2 s) each, half a period apart,
# none starting before 3.2 s (the waves reach the box at about 2 s and
# their front has passed it by then)
SPAN, STEP, FIRST = 3.6, 0.6, 3.2


def meanOver(t, x, a, b):
    """The time-weighted mean of x over a <= t <= b (trapezoidal)."""
    w = [(ti, xi) for ti, xi in zip(t, x) if a <= ti <= b]
    area = sum((w[i+1][0] - w[i][0])*(w[i+1][1] + w[i][1])/2
               for i in range(len(w) - 1))
    return area/(w[-1][0] - w[0][0])


def slide(case):
    m = motion(case)
    name = os.path.basename(case)
    if not m:
        print('%s: no motion' % name)
        return False
    t, z, r = m
    n = math.floor((t[-1] - SPAN - FIRST)/STEP + 1e-9)
    if n < 0:
        print('%s: ends at %g s, before %g s: no window'
              % (name, t[-1], FIRST + SPAN))
        return False
    print('%s: amplitudes (half the range) over three wave periods, and'
          ' the mean pitch' % name)
    for i in reversed(range(n + 1)):
        a = t[-1] - SPAN - STEP*i
        b = a + SPAN
        print('  %.1f-%.1f s: heave %.4f m, pitch %.4f rad, mean pitch'
              ' %+.4f rad' % (a, b, halfRange(t, z, a, b),
                              halfRange(t, r, a, b), meanOver(t, r, a, b)))
    return True


def extremes(t, z):
    """A motion's extremes, alternately highs and lows: each the vertex of
    the parabola through the sample at it and its two neighbours."""
    found = []
    for i in range(1, len(z) - 1):
        high = z[i] > z[i-1] and z[i] >= z[i+1]
        low = z[i] < z[i-1] and z[i] <= z[i+1]
        if not (high or low):
            continue
        t0, t1, t2 = t[i-1], t[i], t[i+1]
        z0, z1, z2 = z[i-1], z[i], z[i+1]
        # z = c0 + c1 (s - t1) + c2 (s - t1)^2 through the three samples
        d0, d2 = t0 - t1, t2 - t1
        c2 = ((z2 - z1)/d2 - (z0 - z1)/d0)/(d2 - d0)
        c1 = (z2 - z1)/d2 - c2*d2
        te, ze = t1, z1
        if c2 != 0 and d0 <= -c1/(2*c2) <= d2:
            te = t1 - c1/(2*c2)
            ze = z1 - c1*c1/(4*c2)
        e = (te, ze, high)
        if found and found[-1][2] == high:
            # Two highs (lows) in a row: keep the further one
            if (ze > found[-1][1]) == high:
                found[-1] = e
        else:
            found.append(e)
    return found


def decay(case, fromLine, which, k, inertia):
    m = motion(case)
    q = {'heave': 1, 'pitch': 2}[which]
    unit, added = {'heave': ('m', 'added mass %.2f kg (k = %.4g N/m, m = %g'
                             ' kg)'),
                   'pitch': ('rad', 'added inertia %.4f kg m^2 (k = %.4g'
                             ' N m/rad, Iyy = %g kg m^2)')}[which]
    ext = extremes(m[0], m[q]) if m else []
    for te, ze, high in ext:
        print('  %s at t = %.4f s: %s %+.5f %s'
              % ('high' if high else 'low ', te, which, ze, unit))
    name = os.path.basename(case)
    if len(ext) < 4:
        print('%s: %d %s extremes, too few to measure; %s'
              % (name, len(ext), which, piece(case, fromLine)[1]))
        return False
    swing = [abs(ext[i+1][1] - ext[i][1])/2 for i in range(len(ext) - 1)]
    Td = sum(ext[i+2][0] - ext[i][0]
             for i in range(len(ext) - 2))/(len(ext) - 2)
    if k <= 0 or min(swing) <= 0:
        print('%s: stiffness %g, smallest swing %g: not a decay to measure'
              % (name, k, min(swing)))
        return False
    delta = sum(math.log(swing[i]/swing[i+2])
                for i in range(len(swing) - 2))/(len(swing) - 2)
    if delta <= 0:
        print('%s: the %s swings grow (decrement %.3f per period): not a'
              ' decay' % (name, which, delta))
        return False
    zeta = delta/math.sqrt(4*math.pi**2 + delta**2)
    omegaN = 2*math.pi/Td/math.sqrt(1 - zeta**2)
    print(('%s: %s damped period %.4f s, decrement %.3f per period (damping'
           ' ratio %.4f), undamped period %.4f s, ' + added
           + '; first swing %.5f %s; %s')
          % (name, which, Td, delta, zeta, 2*math.pi/omegaN,
             k/omegaN**2 - inertia, k, inertia, swing[0], unit,
             piece(case, fromLine)[1]))
    return True


def parse(a):
    """The function and its arguments from the command line; None if the
    line is not one of the docstring's; ValueError for a bad number."""
    if len(a) == 4 and a[0] == 'windows':
        return windows, (a[1], a[2], int(a[3]))
    if len(a) == 2 and a[0] == 'slide':
        return slide, (a[1],)
    if len(a) == 6 and a[0] == 'decay' and a[3] in ('heave', 'pitch'):
        return decay, (a[1], int(a[2]), a[3], float(a[4]), float(a[5]))
    return None


if __name__ == '__main__':
    try:
        command = parse(sys.argv[1:])
    except ValueError as e:
        sys.exit('analyse.py: %s\n%s' % (e, __doc__))
    if command is None:
        sys.exit(__doc__)
    function, args = command
    sys.exit(0 if function(*args) else 1)
