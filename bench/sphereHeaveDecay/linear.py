#!/usr/bin/env python3
"""The floating sphere's heave decay by linear potential flow: an
independent estimate of the period and decay rate that the CFD runs of
bench/sphereHeaveDecay/run should approach as the drop goes to zero.

    linear.py [RESULTS [PNG]]
    linear.py --check

Hulme (1982) computed the added mass and the radiation damping of a
floating hemisphere heaving in deep water ("The wave forces acting on a
floating hemisphere undergoing forced periodic oscillations", J. Fluid
Mech. 121:443-463).  His table, as tabulated in LHEEA's
Hulme_Heaving_Sphere repository (comparison/HulmeResult.dat), gives
mu = A/(rho V) and lambda = B/(rho V omega) against K a = omega^2 a/g,
with V = 2/3 pi a^3 the hemisphere's volume.  Here rho V = 7.056 kg, the
sphere's own mass (it floats half-submerged).

Two estimates are printed:
1. the frequency domain: the natural frequency solving
   omega^2 (m + A(omega)) = C, C = rho g pi a^2 the waterplane's
   stiffness, and the damped period and decay rate of a linear
   oscillator with B(omega) there;
2. the time domain (Cummins 1962): the released sphere's heave from
   (m + A_inf) z'' + int_0^t K(t - s) z'(s) ds + C z = 0, with the
   radiation kernel K(t) = 2/pi int_0^inf B(omega) cos(omega t) d omega
   and A_inf = 0.5 rho V (half the sphere's added mass in an unbounded
   fluid), reduced as the tutorial reduces a run (its ./results).  The
   kernel is checked first: Ogilvie's relation
   A(omega) = A_inf - 1/omega int_0^inf K(t) sin(omega t) dt must give
   back Hulme's added mass.  A second time-domain model keeps the
   sphere's exact hydrostatic force (the submerged cap's volume): the
   hydrostatics' share of the period's growth with the drop.

Writes the table to stdout and, with RESULTS (a folder), to
RESULTS/linear.log, beside the CFD records in RESULTS/<name>/heaveDecay
for the drops that have them.  PNG: the period and the decay rate against
the drop, the time-domain model with exact hydrostatics as a curve, the
CFD records and the experiment's figures as points.  Pure Python and
gnuplot; about 10 s.

--check: the model's own checks, each with its tolerance, exit status 1
if one fails (test/regression/sphereHeaveDecay): with no radiation the
time-domain model is an undamped oscillator of period
2 pi sqrt((m + A_inf)/C), which the reduction's first cycle must give
within 0.01%,
its amplitude kept within 0.1% over 6 s;
the kernel must give back Hulme's added mass within 0.01 (Ogilvie); and
halving the time step must move T1 by under 0.05%.
"""
import importlib.machinery
import importlib.util
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# Kramer et al. (2021): the sphere and the water (docs/validation.md)
A_SPHERE = 0.15         # radius [m]
G = 9.82                # [m/s^2]
RHO = 998.2             # [kg/m^3]
MASS = 7.056            # [kg]
RHO_V = RHO*2.0/3.0*math.pi*A_SPHERE**3     # 7.0559 kg
C = RHO*G*math.pi*A_SPHERE**2               # 692.9 N/m

# Hulme (1982), heave: K a, mu, lambda (the table beside the forced-heave
# tutorial, which compares with it too)
HULME_FILE = os.path.join(HERE, '..', '..', 'tutorials', 'interDyMFoam',
                          'sphereForcedHeave', 'hulme1982.dat')
with open(HULME_FILE) as f:
    HULME = [tuple(float(v) for v in l.split()) for l in f
             if l.strip() and not l.startswith('#')]
MU_INF = 0.5

# The experiment's figures (the tutorial's ./results): release [m],
# first damped period T1 [s], decay rate [1/s]
EXPERIMENT = [(0.02916, 0.7869, 0.8310), (0.08918, 0.8093, 0.8014)]

# The drops compared: the CFD records' names and releases [m] (the 6 mm
# drop's record with the water filled as the tutorial now fills it)
DROPS = [('d0.02alpha', 0.006), ('d0.1', 0.02916), ('d0.3', 0.08918),
         ('d0.5', 0.15006)]


def load_reduction():
    """The tutorial's ./results, for its reduction."""
    path = os.path.join(HERE, '..', '..', 'tutorials', 'interDyMFoam',
                        'sphereHeaveDecay', 'results')
    loader = importlib.machinery.SourceFileLoader('heaveResults', path)
    spec = importlib.util.spec_from_loader('heaveResults', loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def hermite(xs, ys):
    """A monotone piecewise-cubic interpolant through (xs, ys) (Fritsch
    and Carlson 1980): no overshoot between the table's points."""
    n = len(xs)
    h = [xs[i + 1] - xs[i] for i in range(n - 1)]
    d = [(ys[i + 1] - ys[i])/h[i] for i in range(n - 1)]
    m = [d[0]] + [0.0]*(n - 2) + [d[-1]]
    for i in range(1, n - 1):
        if d[i - 1]*d[i] > 0:
            w1, w2 = 2*h[i] + h[i - 1], h[i] + 2*h[i - 1]
            m[i] = (w1 + w2)/(w1/d[i - 1] + w2/d[i])

    def f(x):
        lo, hi = 0, n - 1
        while hi - lo > 1:
            mid = (lo + hi)//2
            if xs[mid] <= x:
                lo = mid
            else:
                hi = mid
        s = (x - xs[lo])/h[lo]
        h00 = (1 + 2*s)*(1 - s)**2
        h10 = s*(1 - s)**2
        h01 = s*s*(3 - 2*s)
        h11 = s*s*(s - 1)
        return (h00*ys[lo] + h10*h[lo]*m[lo] + h01*ys[lo + 1]
                + h11*h[lo]*m[lo + 1])
    return f


KA = [r[0] for r in HULME]
MU = hermite(KA, [r[1] for r in HULME])
LAMBDA_TABLE = hermite(KA, [r[2] for r in HULME])
# Beyond K a = 10 the damping falls as a power of K a, fitted to the
# table's last two points
TAIL = math.log(HULME[-2][2]/HULME[-1][2])/math.log(HULME[-1][0]/HULME[-2][0])


def lam(ka):
    if ka <= KA[-1]:
        return LAMBDA_TABLE(ka)
    return HULME[-1][2]*(KA[-1]/ka)**TAIL


def ka_of(omega):
    return omega*omega*A_SPHERE/G


def damping(omega):
    """B(omega) [kg/s]."""
    return lam(ka_of(omega))*RHO_V*omega


def frequency_domain():
    """The natural frequency: omega^2 (m + A) = C, by bisection."""
    lo, hi = 1.0, 30.0
    for _ in range(100):
        w = 0.5*(lo + hi)
        if w*w*(MASS + MU(ka_of(w))*RHO_V) < C:
            lo = w
        else:
            hi = w
    w = 0.5*(lo + hi)
    total = MASS + MU(ka_of(w))*RHO_V
    sigma = damping(w)/(2*total)
    wd = math.sqrt(w*w - sigma*sigma)
    return w, ka_of(w), MU(ka_of(w)), 2*math.pi/w, 2*math.pi/wd, sigma


def kernel(times, omega_max=None, d_omega=0.004):
    """K(t) = 2/pi int_0^omega_max B cos(omega t) d omega (trapezoid)."""
    if omega_max is None:
        omega_max = math.sqrt(60*G/A_SPHERE)     # K a = 60
    n = int(omega_max/d_omega)
    omegas = [i*d_omega for i in range(n + 1)]
    b = [damping(w) for w in omegas]
    b[0] *= 0.5
    b[-1] *= 0.5
    return [2/math.pi*d_omega*sum(bi*math.cos(w*t) for bi, w in
                                  zip(b, omegas)) for t in times]


# The time step of the time-domain model [s], and how far back its memory
# integral reaches [s] (the kernel has died out well before)
DT = 0.002
MEMORY = 4.0


def kernel_steps(dt):
    """K at the half steps (j + 1/2) dt, over MEMORY."""
    return kernel([(j + 0.5)*dt for j in range(int(MEMORY/dt))])


def ogilvie(ka_points, dt, k):
    """Hulme's added mass given back by the kernel K (sampled at the
    half steps (j + 1/2) dt): A(omega)/(rho V) at each K a."""
    out = []
    for ka in ka_points:
        w = math.sqrt(ka*G/A_SPHERE)
        s = sum(kj*math.sin(w*(j + 0.5)*dt) for j, kj in enumerate(k))*dt
        out.append(MU_INF - s/(w*RHO_V))
    return out


def restoring(z, exact):
    """The hydrostatic force [N] on the sphere whose centre is z above
    its rest: -C z, or (exact) the submerged cap's buoyancy less the
    weight."""
    if not exact:
        return -C*z
    h = min(max(A_SPHERE - z, 0.0), 2*A_SPHERE)
    return RHO*G*math.pi*h*h*(3*A_SPHERE - h)/3 - MASS*G


def cummins(drop, dt, k, end, exact=False, extra=0.0):
    """The heave after a release from rest at DROP: leapfrog, the memory
    integral by the midpoint rule over the half-step velocities (k holds
    K at (j + 1/2) dt).  EXTRA [kg]: more inertia, the weight and the
    hydrostatics unchanged (a sensitivity)."""
    m = MASS + extra + MU_INF*RHO_V
    steps = int(round(end/dt))
    t, z = [0.0], [drop]
    v = []                                  # v at (j + 1/2) dt
    vh = 0.5*dt*restoring(drop, exact)/m
    for n in range(1, steps + 1):
        v.append(vh)
        z.append(z[-1] + dt*vh)
        t.append(n*dt)
        kmax = min(len(k), n)
        memory = dt*sum(k[j]*v[n - 1 - j] for j in range(kmax))
        vh += dt*(restoring(z[-1], exact) - memory)/m
    return t, z


def cfd_record(results, name):
    path = os.path.join(results, name, 'heaveDecay')
    if not os.path.isfile(path):
        return None
    figures = {}
    for line in open(path):
        if line.startswith('//') or not line.strip():
            continue
        key, value = line.split()[:2]
        figures[key] = float(value.rstrip(';'))
    return figures


def self_check(red):
    """The model's checks against exact answers; True if all pass."""
    dt = DT
    ok = True

    def say(what, passed):
        print('%s: %s' % ('PASS' if passed else 'FAIL', what))
        return passed

    exact = 2*math.pi*math.sqrt((MASS + MU_INF*RHO_V)/C)
    t, z = cummins(0.02916, dt, [], 6.0)
    r = red.reduce(t, z)
    last = max(abs(v) for v, u in zip(z, t) if u > t[-1] - exact)
    # The full cycle (first to third crossing), not T1: the undamped
    # motion never settles, so the mean of its last 2 s (the reduction's
    # equilibrium) is off the true one, which moves each half-period
    # but not the cycle
    ok &= say('no radiation: first cycle %.5f s against the exact %.5f s '
              '(within 0.01%%); the last period\'s amplitude %.4f of the '
              'drop (within 0.1%%)' % (r['cycle'], exact, last/0.02916),
              abs(r['cycle']/exact - 1) < 1e-4
              and abs(last/0.02916 - 1) < 1e-3)

    k = kernel_steps(dt)
    ka = [0.5, 1.0, 1.5, 2.0]
    given = ogilvie(ka, dt, k)
    worst = max(abs(a - MU(x)) for a, x in zip(given, ka))
    ok &= say('the kernel gives back Hulme\'s added mass at K a 0.5-2 '
              'within %.4f (tolerance 0.01)' % worst, worst < 0.01)

    t, z = cummins(0.02916, dt, k, 6.0)
    p1 = red.reduce(t, z)['period']
    k2 = kernel_steps(dt/2)
    t, z = cummins(0.02916, dt/2, k2, 6.0)
    p2 = red.reduce(t, z)['period']
    ok &= say('T1 at dt %g and %g s: %.5f and %.5f s '
              '(within 0.05%%)' % (dt, dt/2, p1, p2),
              abs(p1/p2 - 1) < 5e-4)
    return ok


def main():
    red = load_reduction()
    if sys.argv[1:] == ['--check']:
        sys.exit(0 if self_check(red) else 1)
    results = sys.argv[1] if len(sys.argv) > 1 else None
    lines = []
    say = lines.append

    w, ka, mu, tn, td, sigma = frequency_domain()
    say('Linear potential flow (Hulme 1982), the sphere of Kramer et al. '
        '(2021): m %.3f kg, rho V %.4f kg, C %.1f N/m' % (MASS, RHO_V, C))
    say('  frequency domain: omega %.4f rad/s, K a %.4f, A/(rho V) %.4f; '
        'natural period %.4f s, damped %.4f s, decay rate %.3f 1/s'
        % (w, ka, mu, tn, td, sigma))

    dt = DT
    k = kernel_steps(dt)
    check = [0.5, 1.0, 1.5, 2.0]
    given = ogilvie(check, dt, k)
    worst = max(abs(a - MU(x)) for a, x in zip(given, check))
    say('  kernel check (Ogilvie): A/(rho V) from K(t) against Hulme at '
        'K a %s: %s against %s (largest difference %.4f)'
        % (' '.join('%g' % x for x in check),
           ' '.join('%.4f' % a for a in given),
           ' '.join('%.4f' % MU(x) for x in check), worst))
    if worst > 0.01:
        sys.exit('linear.py: the kernel does not give back Hulme\'s added '
                 'mass within 0.01: K(t) is wrong')

    say('')
    say('| drop | model | T1 [s] | decay rate [1/s] | '
        'first extreme [mm] |')
    say('|---|---|---|---|---|')
    # The linear model once (its heave scales with the drop), the one with
    # exact hydrostatics once for each drop
    unit = 0.02916
    linear = red.reduce(*cummins(unit, dt, k, 6.0))
    exact = {drop: red.reduce(*cummins(drop, dt, k, 6.0, exact=True))
             for name, drop in DROPS}
    for name, drop in DROPS:
        rows = [('Cummins, linear', linear['period'], linear['rate'],
                 1e3*linear['extremes'][0][1]*drop/unit),
                ('Cummins, exact hydrostatics', exact[drop]['period'],
                 exact[drop]['rate'], 1e3*exact[drop]['extremes'][0][1])]
        cfd = cfd_record(results, name) if results else None
        if cfd:
            rows.append(('CFD (record %s)' % name, cfd['period'],
                         cfd['decayRate'], 1e3*cfd['extreme1']))
        for label, p, rate, e1 in rows:
            say('| %.2f mm | %s | %.4f | %.3f | %+.2f |'
                % (1e3*drop, label, p, rate, e1))

    # The crossings: where the CFD departs from the model
    say('')
    for drop in (0.006, 0.02916):
        c = exact[drop]['crossings']
        say('  exact hydrostatics, %.2f mm: crossings %s s; periods from '
            'crossing i to i + 2: %s s'
            % (1e3*drop, ' '.join('%.4f' % x for x in c[:6]),
               ' '.join('%.4f' % (c[i + 2] - c[i]) for i in range(4))))

    # A sensitivity: how much more inertia the experiment's periods need
    say('')
    for drop in (0.02916, 0.08918):
        t, z = cummins(drop, dt, k, 6.0, exact=True, extra=0.4)
        r = red.reduce(t, z)
        say('  exact hydrostatics and 0.4 kg more inertia, %.2f mm: T1 '
            '%.4f s, decay rate %.3f 1/s' % (1e3*drop, r['period'],
                                           r['rate']))

    text = '\n'.join(lines)
    print(text)
    if results:
        with open(os.path.join(results, 'linear.log'), 'w') as f:
            f.write('# bench/sphereHeaveDecay/linear.py %s\n' % results)
            f.write(text + '\n')
    if results and len(sys.argv) > 2:
        plot(sys.argv[2], results, red, dt, k,
             (linear['period'], linear['rate']))


def plot(png, results, red, dt, k, linear):
    """PNG: period and decay rate against the drop; LINEAR: the linear
    model's (period, decay rate), the same at every drop."""
    curve = png + '.curve'
    with open(curve, 'w') as f:
        for i in range(1, 31):
            drop = 0.005*i
            t, z = cummins(drop, dt, k, 6.0, exact=True)
            r = red.reduce(t, z)
            f.write('%g %g %g\n' % (1e3*drop, r['period'], r['rate']))
    points, fine = png + '.cfd', png + '.fine'
    for path, names in ((points, [n for n, d in DROPS]),
                        (fine, ['fine'])):
        with open(path, 'w') as f:
            for name in names:
                cfd = cfd_record(results, name)
                if cfd:
                    f.write('%g %g %g\n'
                            % (1e3*(cfd['drop'] - cfd['equilibrium']),
                               cfd['period'], cfd['decayRate']))
    experiment = png + '.exp'
    with open(experiment, 'w') as f:
        for drop, p, rate in EXPERIMENT:
            f.write('%g %g %g\n' % (1e3*drop, p, rate))
    script = '''
set terminal pngcairo size 900,900
set output "%(png)s"
set multiplot layout 2,1 title "Floating sphere (Kramer et al. 2021): heave decay against the drop (bench/sphereHeaveDecay/linear.py)"
set grid
set xrange [0:155]
set key left top
set xlabel "drop [mm]"
set ylabel "first damped period T1 [s]"
plot "%(curve)s" using 1:2 with lines lw 2 title "linear potential flow (Hulme 1982), exact hydrostatics", \\
     %(tl)r with lines dt 2 lc rgb "gray40" title "linear potential flow, linear hydrostatics", \\
     "%(points)s" using 1:2 with points pt 7 ps 1.6 title "interFoam + this library (default mesh)", \\
     "%(fine)s" using 1:2 with points pt 6 ps 2.2 lw 2 title "the same, fine mesh", \\
     "%(experiment)s" using 1:2 with points pt 5 ps 1.6 lc rgb "black" title "experiment (the issue's figures)"
set ylabel "decay rate [1/s]"
set key left bottom
plot "%(curve)s" using 1:3 with lines lw 2 title "linear potential flow (Hulme 1982), exact hydrostatics", \\
     %(rl)r with lines dt 2 lc rgb "gray40" title "linear potential flow, linear hydrostatics", \\
     "%(points)s" using 1:3 with points pt 7 ps 1.6 title "interFoam + this library (default mesh)", \\
     "%(fine)s" using 1:3 with points pt 6 ps 2.2 lw 2 title "the same, fine mesh", \\
     "%(experiment)s" using 1:3 with points pt 5 ps 1.6 lc rgb "black" title "experiment (the issue's figures)"
unset multiplot
''' % {'png': png, 'curve': curve, 'points': points, 'fine': fine,
       'experiment': experiment, 'tl': linear[0], 'rl': linear[1]}
    subprocess.run(['gnuplot'], input=script, text=True, check=True)
    for f in (curve, points, fine, experiment):
        os.remove(f)
    print('Written %s' % png)


if __name__ == '__main__':
    main()
