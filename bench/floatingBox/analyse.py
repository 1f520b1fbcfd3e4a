#!/usr/bin/env python3
"""The figures of bench/floatingBox/coupling and decay, from a run of
tutorials/interDyMFoam/floatingBoxInWaves (its ./results joins the pieces
of a continued run into postProcessing/joined/rigidBodyMotion.dat).

    analyse.py windows CASE REF FROMLINE
        heave and pitch half-ranges over 3.6-4.8 s and 4.2-5.4 s, and the
        heave against REF's (a run's folder, or - for none), and the mean
        deltaT over each window
    analyse.py decay CASE FROMLINE MASS LBOX W
        the free heave's extremes, damped period, logarithmic decrement
        and the added mass in heave they give

Both print the piece of CASE/log.interFoam after line FROMLINE (the run
this script is about, where a continued run's log was appended to): its
clock time, time steps and the range of its deltaT.  Exit status 1 where
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
    clock time, time steps and deltaT range."""
    f = os.path.join(case, 'log.interFoam')
    clock, times, dts = '?', [], []
    if os.path.isfile(f):
        for i, line in enumerate(open(f, errors='replace')):
            if i < fromLine:
                continue
            w = line.split()
            if line.startswith('Time = ') and len(w) == 3:
                times.append(float(w[2]))
            elif line.startswith('deltaT = ') and len(w) == 3:
                dts.append(float(w[2]))
            elif 'ClockTime = ' in line:
                clock = w[-2]
    dt = ('deltaT %.3g to %.3g s' % (min(dts), max(dts))) if dts else 'deltaT ?'
    return times, ('interFoam clock %s s, %d steps, %s'
                   % (clock, len(times), dt))


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
        steps = sum(1 for t in times if a < t <= b)
        parts.append(s + ', pitch %.4f rad, mean deltaT %.3g s'
                     % (halfRange(ours[0], ours[2], a, b),
                        (b - a)/steps if steps else float('nan')))
    print('%s: %s; %s' % (os.path.basename(case), '; '.join(parts), summary))
    return ok


def extremes(t, z):
    """The heave's extremes, alternately highs and lows: each the vertex of
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


def decay(case, fromLine, mass, Lbox, W):
    m = motion(case)
    ext = extremes(m[0], m[1]) if m else []
    for te, ze, high in ext:
        print('  %s at t = %.4f s: heave %+.5f m'
              % ('high' if high else 'low ', te, ze))
    name = os.path.basename(case)
    if len(ext) < 4:
        print('%s: %d heave extremes, too few to measure; %s'
              % (name, len(ext), piece(case, fromLine)[1]))
        return False
    swing = [abs(ext[i+1][1] - ext[i][1])/2 for i in range(len(ext) - 1)]
    Td = sum(ext[i+2][0] - ext[i][0]
             for i in range(len(ext) - 2))/(len(ext) - 2)
    delta = sum(math.log(swing[i]/swing[i+2])
                for i in range(len(swing) - 2))/(len(swing) - 2)
    zeta = delta/math.sqrt(4*math.pi**2 + delta**2)
    omegaN = 2*math.pi/Td/math.sqrt(1 - zeta**2)
    k = 1000*9.81*Lbox*W
    print('%s: damped period %.4f s, decrement %.3f per period (damping'
          ' ratio %.4f), heave added mass %.2f kg (k = rho g Lbox W = %.0f'
          ' N/m, m = %g kg); first swing %.5f m; %s'
          % (name, Td, delta, zeta, k/omegaN**2 - mass, k, mass, swing[0],
             piece(case, fromLine)[1]))
    return True


if __name__ == '__main__':
    a = sys.argv[1:]
    if len(a) == 4 and a[0] == 'windows':
        ok = windows(a[1], a[2], int(a[3]))
    elif len(a) == 6 and a[0] == 'decay':
        ok = decay(a[1], int(a[2]), *map(float, a[3:]))
    else:
        sys.exit(__doc__)
    sys.exit(0 if ok else 1)
