#!/usr/bin/env python3
"""bench/sphereHeaveDecay/run's records, table and plot.

    analyse.py record NAME FOLDER
        keeps what the finished run in FOLDER gave in RESULTS/NAME/
        (committed, so a run made once is kept when the machine and its
        run folder are not): its figures (postProcessing/heaveDecay, by
        the tutorial's ./results as it is now, run again in FOLDER), the heave over time (t and q0 of its joined
        table) and, in RESULTS/NAME/log, its cells, CPU time, steps, outer
        correctors a step, steps flagged and largest coupling residual,
        with the date and commit
    analyse.py reduce RESULTS
        reduces every record in RESULTS again from its heave.dat, by the
        tutorial's ./results as it is now (no run needed), and rewrites
        its heaveDecay; its log is left as the run made it
    analyse.py RESULTS PNG

RESULTS: bench/sphereHeaveDecay/results.  Prints a markdown table: each
recorded run's mesh, first damped period T1, first full cycle, decay rate
and first trough (the tutorial's ./results, postProcessing/heaveDecay) and
their errors against the experiment, the interFoam CPU time, time steps, outer
correctors a step, steps flagged "coupling not converged" and the largest
coupling residual of the run (its log's coupling summary).  Writes PNG:
the 0.1 D runs' errors against their CPU time, beside the costs Kramer et
al. (2021) give for the OpenFOAM cases of OES Task 10, and beside it
sphereHeaveDecay-drops.png: each recorded drop's heave about its
equilibrium against the experiment's damped cosine.  Runs missing are
left out; exit status 1 if none is there.
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', 'coupled'))
from analyse import logFigures, made  # noqa: E402  (bench/coupled/analyse.py)

ORDER = ['d0.1', 'd0.3', 'd0.5', 'd0.02', 'd0.02fine', 'd0.02dt', 'd0.02alpha',
         'd0.1alpha', 'coarse', 'fine', 'co0.25', 'co1', 'fixed3', 'mass7.456']
# The runs of the cost plot: the 0.1 D drop on the tutorial's settings but
# one (d0.1alpha, whose CPU time was measured beside .ci/run, is left out)
COSTS = ('d0.1', 'coarse', 'fine', 'co0.25', 'co1', 'fixed3')
WHAT = {
    'd0.1': '0.1 D, default mesh, maxCo 0.5, on demand (tol 0.1)',
    'd0.3': '0.3 D, default mesh, maxCo 0.5, on demand',
    'd0.5': '0.5 D, default mesh, maxCo 0.5, on demand',
    'd0.02': '0.02 D (6 mm), default mesh, maxCo 0.5, on demand',
    'd0.02fine': '0.02 D (6 mm), fine mesh',
    'd0.02dt': '0.02 D (6 mm), maxCo 0.25, maxDeltaT 0.0025 s',
    'd0.02alpha': 'setAlphaField fill (the tutorial\'s since): 0.02 D',
    'd0.1alpha': 'setAlphaField fill (the tutorial\'s since): 0.1 D',
    'coarse': '0.1 D, coarse mesh',
    'fine': '0.1 D, fine mesh',
    'co0.25': '0.1 D, maxCo 0.25',
    'co1': '0.1 D, maxCo 1',
    'fixed3': '0.1 D, 3 fixed outer correctors',
    'mass7.456': 'a sensitivity: 0.1 D, mass 7.456 kg (0.4 kg more)',
}


def dictionary(path):
    out = {}
    for line in open(path):
        m = re.match(r'\s*(\w+)\s+([-+0-9.eE]+);', line)
        if m:
            out[m.group(1)] = float(m.group(2))
    return out


def cells(folder):
    for line in open(os.path.join(folder, 'log.checkMesh')):
        if line.strip().startswith('cells:'):
            return int(line.split()[1])
    return 0


def largestResidual(log):
    value = None
    for line in open(log, errors='replace'):
        m = re.search(r'coupling summary: .*the largest residual ([-+0-9.eE]+)',
                      line)
        if m:
            value = float(m.group(1))
    return value


LOGFIGURES = ('cells', 'cpu', 'steps', 'outer', 'flagged', 'residual')


def record(name, folder):
    """Keep a finished run's figures, heave and log figures in
    RESULTS/name (RESULTS: this script's results folder)."""
    # The figures by the tutorial's reduction as it is now (a run's copy
    # may be older)
    here = os.path.dirname(os.path.abspath(__file__))
    shutil.copy(os.path.join(here, '..', '..', 'tutorials', 'interDyMFoam',
                             'sphereHeaveDecay', 'results'),
                os.path.join(folder, 'results'))
    subprocess.run([os.path.join(folder, 'results')], check=True,
                   stdout=subprocess.DEVNULL)
    figures = os.path.join(folder, 'postProcessing', 'heaveDecay')
    table = os.path.join(folder, 'postProcessing', 'joined', 'sphere.dat')
    log = os.path.join(folder, 'log.interFoam')
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'results',
                       name)
    os.makedirs(out, exist_ok=True)
    with open(figures) as f, open(os.path.join(out, 'heaveDecay'), 'w') as g:
        g.write(f.read())
    # The heave over time: columns t and q0, found by the header
    names, rows = None, []
    for line in open(table):
        w = line[1:].split() if line.startswith('#') else None
        if w and w[0] == 't':
            names = w
        elif w is None and line.strip() and names:
            v = line.split()
            rows.append((v[0], v[names.index('q0')]))
    with open(os.path.join(out, 'heave.dat'), 'w') as g:
        g.write('# t q0 (heave [m]): bench/sphereHeaveDecay/run %s\n' % name)
        for t, z in rows:
            g.write('%s %s\n' % (t, z))
    cpu, steps, outer, flagged = logFigures(log)
    with open(os.path.join(out, 'log'), 'w') as g:
        g.write('# bench/sphereHeaveDecay/run %s, %s\n' % (name, made()))
        for k, v in zip(LOGFIGURES, (cells(folder), cpu, steps, outer,
                                     flagged, largestResidual(log))):
            g.write('%s %s\n' % (k, v))
    return out


def reduceAgain(results):
    """Every record in RESULTS reduced again from its heave.dat by the
    tutorial's ./results as it is now; returns the names redone."""
    import tempfile
    here = os.path.dirname(os.path.abspath(__file__))
    script = os.path.join(here, '..', '..', 'tutorials', 'interDyMFoam',
                          'sphereHeaveDecay', 'results')
    done = []
    for name in sorted(os.listdir(results)):
        folder = os.path.join(results, name)
        heave = os.path.join(folder, 'heave.dat')
        figures = os.path.join(folder, 'heaveDecay')
        if not (os.path.isfile(heave) and os.path.isfile(figures)):
            continue
        # The table's z: q0 shifted so that its first row is the release
        # (the drop: the first row's z, kept in heaveDecay)
        drop = dictionary(figures)['drop']
        rows = [l.split() for l in open(heave)
                if l.strip() and not l.startswith('#')]
        q00 = float(rows[0][1])
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(script, os.path.join(tmp, 'results'))
            table = os.path.join(tmp, 'sphere.dat')
            with open(table, 'w') as f:
                f.write('# %s/heave.dat as a body table\n# t x y z\n'
                        % name)
                for t, q in rows:
                    f.write('%s 0 0 %.12g\n' % (t, float(q) - q00 + drop))
            subprocess.run([os.path.join(tmp, 'results'), table], check=True,
                           stdout=subprocess.DEVNULL)
            with open(os.path.join(tmp, 'postProcessing', 'heaveDecay')) as f:
                text = f.read()
        with open(figures, 'w') as g:
            g.write(text.replace(table, 'postProcessing/joined/sphere.dat'))
        done.append(name)
    return done


def plotDrops(results, png):
    """PNG: the recorded drops' heave about their equilibrium, one panel
    each, beside a damped cosine with the experiment's period and decay
    rate from the same drop (where the experiment's figures are given)."""
    panels = []
    for name in ('d0.1', 'd0.3', 'd0.5'):
        folder = os.path.join(results, name)
        heave = os.path.join(folder, 'heave.dat')
        figures = os.path.join(folder, 'heaveDecay')
        if os.path.isfile(heave) and os.path.isfile(figures):
            panels.append((name, heave, dictionary(figures)))
    if not panels:
        return
    script = ['set terminal pngcairo size 900,%d' % (300*len(panels)),
              'set output "%s"' % png,
              'set multiplot layout %d,1' % len(panels),
              'set grid', 'set samples 2000',
              'set xlabel "time [s]"',
              'set ylabel "heave - equilibrium [mm]"']
    for name, heave, f in panels:
        eq, drop = f['equilibrium'], f['drop']
        # heave.dat holds the joint's q0, the centre's z less the release
        # height: z = q0 + (drop - q0 of the first row), drop being the
        # first row's z
        q00 = next(float(l.split()[1]) for l in open(heave)
                   if l.strip() and not l.startswith('#'))
        line = ('plot "%s" using 1:(1e3*($2 + %r - %r)) with lines lw 2 '
                'title "interFoam + this library"' % (heave, drop - q00, eq))
        if 'periodExperiment' in f:
            line += (', 1e3*(%r - %r)*exp(-%r*x)*cos(2*pi*x/%r) with lines '
                     'dt 2 lc rgb "black" title "experiment: T1 %g s, '
                     'decay rate %g 1/s"'
                     % (drop, eq, f['decayRateExperiment'],
                        f['periodExperiment'], f['periodExperiment'],
                        f['decayRateExperiment']))
        script += ['set title "Floating sphere, %s: heave decay from %.2f mm '
                   '(bench/sphereHeaveDecay/run)"' % (WHAT[name].split(',')[0],
                                                     1e3*(drop - eq)),
                   line]
    script.append('unset multiplot')
    subprocess.run(['gnuplot'], input='\n'.join(script) + '\n', text=True,
                   check=True)
    print('Written %s' % png)


def main(results, png):
    rows = []
    for name in ORDER:
        folder = os.path.join(results, name)
        figures = os.path.join(folder, 'heaveDecay')
        log = os.path.join(folder, 'log')
        if not (os.path.isfile(figures) and os.path.isfile(log)):
            continue
        f = dictionary(figures)
        g = {}
        for line in open(log):
            w = line.split()
            if len(w) == 2 and w[0] in LOGFIGURES:
                g[w[0]] = None if w[1] == 'None' else float(w[1])
        rows.append((name, f, g.get('cpu'), int(g.get('steps') or 0),
                     g.get('outer') or 0, int(g.get('flagged') or 0),
                     g.get('residual'), int(g.get('cells') or 0)))
    if not rows:
        print('bench/sphereHeaveDecay: no runs recorded in %s' % results)
        return False

    print('| run | cells | T1 [s] | error | first cycle [s] '
          '| decay rate [1/s] | error | first trough [mm] | error [mm] '
          '| CPU [s] | steps | outer correctors a step | steps flagged '
          '| largest residual |')
    print('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|')
    points = []
    for name, f, cpu, steps, outer, flagged, res, n in rows:
        eT = eR = eD = None
        if 'periodExperiment' in f and 'period' in f:
            eT = 100*(f['period']/f['periodExperiment'] - 1)
            eR = 100*(f['decayRate']/f['decayRateExperiment'] - 1)
            eD = 1e3*(f['firstTrough'] - f['firstTroughExperiment'])
        print('| %s (%s) | %d | %s | %s | %s | %s | %s | %s | %s | %.0f | %d '
              '| %.2f | %d | %s |'
              % (name, WHAT[name], n,
                 '%.4f' % f['period'] if 'period' in f else '-',
                 '%+.2f%%' % eT if eT is not None else '-',
                 '%.4f' % f['firstCycle'] if 'firstCycle' in f else '-',
                 '%.4f' % f['decayRate'] if 'decayRate' in f else '-',
                 '%+.1f%%' % eR if eR is not None else '-',
                 '%.2f' % (1e3*f['firstTrough']) if 'firstTrough' in f
                 else '-',
                 '%+.2f' % eD if eD is not None else '-',
                 cpu or 0, steps, outer, flagged,
                 '%.3g' % res if res is not None else '-'))
        if name in COSTS and eT is not None and cpu:
            points.append((cpu, abs(eT), abs(eR), name))

    plotDrops(results, os.path.join(os.path.dirname(png) or '.',
                                    'sphereHeaveDecay-drops.png'))
    if not points:
        return True
    data = png + '.dat'
    with open(data, 'w') as out:
        for cpu, eT, eR, name in points:
            out.write('%g %g %g\n' % (cpu, max(eT, 0.01), max(eR, 0.01)))
    # The runs' names above their points; runs whose CPU times are within
    # a factor 2 of each other share one label ("d0.1, co1, fixed3"), so
    # that no name lies over another or where a point could be
    clusters = []
    for cpu, eT, eR, name in sorted(points):
        if clusters and cpu < 2*clusters[-1][-1][0]:
            clusters[-1].append((cpu, eT, eR, name))
        else:
            clusters.append([(cpu, eT, eR, name)])
    labels = []
    for c in clusters:
        top = max(max(p[1], p[2]) for p in c)
        labels.append('set label "%s" at %g,%g center font ",8"'
                      % (', '.join(p[3] for p in c), c[0][0], 1.6*top))
    # The paper's OpenFOAM cases (OES Task 10): 3D, 6-12 million cells,
    # 3,000-6,500 CPU hours, the period within 0.54-0.82%; a 2D wedge of
    # 20,000 cells on one laptop core (its time not given), within 0.19%
    # (the paper's figures, its own period); the RANS codes' T1 at 0.1 D
    # by the public reduction (the one ./results follows): 0.14-0.37%
    script = '''
set terminal pngcairo size 900,650
set output "%s"
set logscale xy
set xrange [30:1e8]
set yrange [0.01:100]
set xlabel "CPU time [s]"
set ylabel "|error| against the experiment [%%]"
set title "Floating sphere, 0.1 D heave decay: error against cost (bench/sphereHeaveDecay/run)"
set key outside bottom center horizontal
set object 1 rect from 3000*3600,0.54 to 6500*3600,0.82 fc rgb "#cccccc" fs solid 0.5
set label 1 "3D OpenFOAM, 6-12 M cells\\n(Kramer et al. 2021): period" at 3000*3600,2.5 right font ",9"
set object 2 rect from 30,0.14 to 1e8,0.37 fc rgb "#bbddff" fs solid 0.4 behind
set label 3 "OES Task 10 RANS codes at 0.1 D, T1 by the public reduction: 0.14-0.37%%" at 40,0.42 left font ",9"
set arrow 1 from 30,0.19 to 1e8,0.19 nohead dt 2
set label 2 "their 2D wedge, 20,000 cells, one laptop core (its time not given): period 0.19%%" at 1e8,0.13 right font ",9"
%s
plot "%s" using 1:2 with points pt 7 ps 1.5 title "T1 (this library)", \\
     "" using 1:3 with points pt 5 ps 1.5 title "decay rate (this library)"
''' % (png, '\n'.join(labels), data)
    subprocess.run(['gnuplot'], input=script, text=True, check=True)
    os.remove(data)
    print('Written %s' % png)
    return True


if __name__ == '__main__':
    if len(sys.argv) == 4 and sys.argv[1] == 'record':
        try:
            print('Recorded %s' % record(*sys.argv[2:]))
        except (OSError, ValueError, IndexError,
                subprocess.CalledProcessError) as e:
            sys.exit('analyse.py record %s: %s' % (sys.argv[2], e))
        sys.exit(0)
    if len(sys.argv) == 3 and sys.argv[1] == 'reduce':
        print('Reduced again: %s' % ' '.join(reduceAgain(sys.argv[2])))
        sys.exit(0)
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(0 if main(*sys.argv[1:]) else 1)
