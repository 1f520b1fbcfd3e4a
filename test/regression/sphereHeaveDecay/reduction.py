#!/usr/bin/env python3
"""The sphere tutorial's reduction (tutorials/interDyMFoam/sphereHeaveDecay/
results) on synthetic heave series whose answers are known exactly.  Each
check prints PASS: or FAIL: with its tolerance; the exit status is 0.

    reduction.py RESULTS TMP

RESULTS: the ./results script to check; TMP: a folder to work in.

The series, each over 6 s at 1 ms, about a level of -0.7 mm:
1. a damped cosine, A exp(-r t) cos(w t): its crossings are at
   w t = pi/2 + k pi, so T1 and the first cycle are both 2 pi/w; its
   first trough is where tan(w t) = -r/w; its extremes decay at r;
2. a chirp, A exp(-r t) cos(w t + b t^2): its crossings t_k solve
   w t + b t^2 = pi/2 + k pi, so T1 = 2 (t_1 - t_0) and the first cycle
   t_2 - t_0 differ;
3. a damped cosine whose decay rate jumps from r to 4 r at its seventh
   crossing: the reduction fits the six extremes before it, so it must
   give r.
4. the damped cosine stopped at 1.3 s: its last 2 s hold the extremes, so
   ./results says it is not comparable and gives no error.
The reduction's equilibrium, the mean of the last 2 s, carries a little
of the motion left there (a part cycle): 0.035 mm for series 1, which
moves its T1 by 0.11%, hence T1's tolerance of 0.2%.  The same
reduction about the exact level must give T1 within 0.01%, and about the
mean of the whole cycles left (./results' sensitivity) within 0.1%.
"""
import math
import os
import re
import shutil
import subprocess
import sys

T, RATE, A, EQ = 0.7869, 0.831, 0.03, -0.0007
W = 2*math.pi/T


def say(what, passed):
    print('%s: %s' % ('PASS' if passed else 'FAIL', what))


def series(name, z, end=6.0):
    """Writes z(t) as a body table in TMP/NAME/, runs ./results there;
    returns (its figures, its printed text)."""
    folder = os.path.join(TMP, name)
    os.makedirs(folder, exist_ok=True)
    shutil.copy(RESULTS, os.path.join(folder, 'results'))
    table = os.path.join(folder, name + '.dat')
    with open(table, 'w') as f:
        f.write('# %s\n# t x y z\n' % name)
        for i in range(int(round(end/0.001)) + 1):
            t = 0.001*i
            f.write('%.6f 0 0 %.15g\n' % (t, EQ + z(t)))
    out = subprocess.run([os.path.join(folder, 'results'), table],
                         capture_output=True, text=True)
    figures = {}
    path = os.path.join(folder, 'postProcessing', 'heaveDecay')
    if os.path.isfile(path):
        for line in open(path):
            m = re.match(r'\s*(\w+)\s+([-+0-9.eE]+);', line)
            if m:
                figures[m.group(1)] = float(m.group(2))
    return figures, out.stdout + out.stderr


def module():
    """The ./results script, imported for its reduce()."""
    import importlib.machinery
    import importlib.util
    loader = importlib.machinery.SourceFileLoader('heaveResults', RESULTS)
    spec = importlib.util.spec_from_loader('heaveResults', loader)
    m = importlib.util.module_from_spec(spec)
    loader.exec_module(m)
    return m


def within(value, exact, rel):
    return value is not None and abs(value/exact - 1) < rel


def main():
    # 1. The damped cosine
    f, text = series('cosine',
                     lambda t: A*math.exp(-RATE*t)*math.cos(W*t))
    p, c, r = f.get('period'), f.get('firstCycle'), f.get('decayRate')
    say('damped cosine: T1 %s s within 0.2%% of %.4f s' % (p, T),
        within(p, T, 2e-3))
    q = f.get('periodCycles')
    say('damped cosine: T1 about the whole cycles\' level %s s within 0.1%% '
        'of %.4f s' % (q, T), within(q, T, 1e-3))
    red = module()
    ts = [0.001*i for i in range(6001)]
    zs = [A*math.exp(-RATE*u)*math.cos(W*u) for u in ts]
    e = red.reduce(ts, zs, 0.0)
    say('damped cosine about its exact level: T1 %.6f s and the first '
        'cycle %.6f s within 0.01%% of %.4f s' % (e['period'], e['cycle'], T),
        within(e['period'], T, 1e-4) and within(e['cycle'], T, 1e-4))
    say('damped cosine: first cycle %s s within 0.1%% of %.4f s' % (c, T),
        within(c, T, 1e-3))
    say('damped cosine: decay rate %s 1/s within 1%% of %.3f 1/s'
        % (r, RATE), within(r, RATE, 1e-2))
    t1 = (math.pi - math.atan(RATE/W))/W
    d1 = -A*math.exp(-RATE*t1)*math.cos(W*t1)
    d = f.get('firstTrough')
    say('damped cosine: first trough %s m within 0.5%% of %.6f m (at '
        '%.5f s)' % (d, d1, t1), within(d, d1, 5e-3))
    e = f.get('extreme1Time')
    say('damped cosine: the first extreme, not the release, at %s s '
        'within 1 ms of %.5f s' % (e, t1),
        e is not None and abs(e - t1) < 1e-3)
    say('damped cosine (6 s, released 29.3 mm up: the 0.1 D drop) is '
        'comparable and gives its errors against the experiment',
        'NOT COMPARABLE' not in text and '  error: T1' in text)

    # 2. The chirp: T1 and the first cycle differ
    b = 0.5

    def crossing(k):
        return (-W + math.sqrt(W*W + 4*b*(math.pi/2 + k*math.pi)))/(2*b)

    tc = [crossing(k) for k in range(3)]
    f, text = series('chirp', lambda t: A*math.exp(-RATE*t)
                     * math.cos(W*t + b*t*t))
    p, c = f.get('period'), f.get('firstCycle')
    say('chirp: T1 %s s within 0.2%% of 2 (t1 - t0) = %.5f s'
        % (p, 2*(tc[1] - tc[0])), within(p, 2*(tc[1] - tc[0]), 2e-3))
    say('chirp: first cycle %s s within 0.1%% of t2 - t0 = %.5f s'
        % (c, tc[2] - tc[0]), within(c, tc[2] - tc[0], 1e-3))
    say('chirp: T1 and the first cycle told apart (they differ by %.2f%%)'
        % (100*(2*(tc[1] - tc[0])/(tc[2] - tc[0]) - 1)),
        p is not None and c is not None
        and abs(p - c) > 0.5*abs(2*(tc[1] - tc[0]) - (tc[2] - tc[0])))

    # 3. The decay rate jumps at the seventh crossing: six extremes fitted
    t7 = (math.pi/2 + 6*math.pi)/W

    def envelope(t):
        if t < t7:
            return math.exp(-RATE*t)
        return math.exp(-RATE*t7 - 4*RATE*(t - t7))

    f, text = series('jump', lambda t: A*envelope(t)*math.cos(W*t))
    r = f.get('decayRate')
    say('decay rate jumping to %.3f 1/s at the seventh crossing (%.3f s): '
        '%s 1/s, within 1%% of the first six extremes\' %.3f 1/s'
        % (4*RATE, t7, r, RATE), within(r, RATE, 1e-2))
    say('... fitted over 6 extremes', 'over 6 extremes' in text)

    # 4. Stopped at 1.3 s: not comparable
    f, text = series('early', lambda t: A*math.exp(-RATE*t)*math.cos(W*t),
                     end=1.3)
    say('the cosine stopped at 1.3 s is said to be not comparable',
        'NOT COMPARABLE' in text)
    say('... and gives no error against the experiment',
        '  error:' not in text and 'periodExperiment' not in f)


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    RESULTS, TMP = sys.argv[1], sys.argv[2]
    main()
