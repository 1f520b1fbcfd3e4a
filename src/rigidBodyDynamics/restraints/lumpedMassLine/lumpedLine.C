/*---------------------------------------------------------------------------*\
    Rigid-body dynamics for OpenFOAM v1912
    Copyright (C) the authors of this project (its git history names them)
-------------------------------------------------------------------------------
License
    This file is part of the rigid-body dynamics for OpenFOAM v1912.

    It is free software: you can redistribute it and/or modify it under the
    terms of the GNU General Public License as published by the Free
    Software Foundation, either version 3 of the License, or (at your
    option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT ANY
    WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License along
    with it (the file LICENSE at the top of the project).  If not, see
    <https://www.gnu.org/licenses/>.
-------------------------------------------------------------------------------
    lumpedLine: a dynamic mooring line of lumped masses (lumpedLine.H)
\*---------------------------------------------------------------------------*/

#include "lumpedLine.H"
#include "elasticCatenary.H"
#include "mathematicalConstants.H"
#include "error.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::RBD::lumpedLine::direction
(
    const vectorField& x,
    const label i
) const
{
    const label a = max(i - 1, label(0));
    const label b = min(i + 1, p_.N);
    const vector r(x[b] - x[a]);
    const scalar m = mag(r);
    return m > VSMALL ? r/m : vector::zero;
}


void Foam::RBD::lumpedLine::forces
(
    const vectorField& x,
    const vectorField& v,
    vectorField& f
) const
{
    const label N = p_.N;
    const vector W((p_.mu - p_.rho*A_)*p_.g);

    for (label i = 0; i <= N; ++i)
    {
        const scalar s = share(i);

        // Weight less buoyancy
        vector F(s*W);

        // Drag in still water
        const vector q(direction(x, i));
        const vector vt((v[i] & q)*q);
        const vector vn(v[i] - vt);
        F -= 0.5*p_.rho*p_.Cdn*p_.d*s*mag(vn)*vn;
        F -= 0.5*p_.rho*p_.Cdt*pi*p_.d*s*mag(vt)*vt;

        // The seabed
        if (p_.hasSeabed)
        {
            const scalar depth = p_.seabed - (x[i] & up_);
            if (depth > 0)
            {
                F +=
                    (p_.kSeabed*depth - p_.cSeabed*(v[i] & up_))
                   *p_.d*s*up_;
            }
        }

        f[i] = F;
    }

    // The segments: tension, no compression
    for (label j = 0; j < N; ++j)
    {
        const vector r(x[j + 1] - x[j]);
        const scalar l = mag(r);
        if (l > l0_)
        {
            const vector t(r/l);
            const scalar rate = t & (v[j + 1] - v[j]);
            const scalar T = p_.EA*(l/l0_ - 1) + p_.BA*rate/l0_;
            if (T > 0)
            {
                f[j] += T*t;
                f[j + 1] -= T*t;
            }
        }
    }
}


void Foam::RBD::lumpedLine::massTerms
(
    const vectorField& x,
    const label i,
    scalar& alpha,
    scalar& beta,
    vector& q
) const
{
    // Node i's mass and added mass: alpha I + beta q q^T, alpha = m +
    // rho V Can, beta = rho V (Cat - Can), q the line's direction there
    const scalar s = share(i);
    alpha = p_.mu*s + p_.rho*A_*s*p_.Can;
    beta = p_.rho*A_*s*(p_.Cat - p_.Can);
    q = direction(x, i);
}


Foam::vector Foam::RBD::lumpedLine::accelerate
(
    const vectorField& x,
    const label i,
    const vector& F
) const
{
    // (alpha I + beta q q^T)^-1 F
    scalar alpha, beta;
    vector q;
    massTerms(x, i, alpha, beta, q);
    return (F - beta/(alpha + beta)*(q & F)*q)/alpha;
}


Foam::vector Foam::RBD::lumpedLine::inertia
(
    const vectorField& x,
    const label i,
    const vector& a
) const
{
    scalar alpha, beta;
    vector q;
    massTerms(x, i, alpha, beta, q);
    return alpha*a + beta*(q & a)*q;
}


void Foam::RBD::lumpedLine::derivatives
(
    vectorField& x,
    vectorField& v,
    const vector& xf,
    const vector& vf,
    vectorField& dx,
    vectorField& dv
)
{
    const label N = p_.N;
    x[N] = xf;
    v[N] = vf;
    forces(x, v, f_);
    dx[0] = dv[0] = dx[N] = dv[N] = Zero;
    for (label i = 1; i < N; ++i)
    {
        dx[i] = v[i];
        dv[i] = accelerate(x, i, f_[i]);
    }
}


void Foam::RBD::lumpedLine::subStep
(
    const scalar h,
    const vector& xf,
    const vector& vf
)
{
    const label N = p_.N;

    xs_ = x_;
    vs_ = v_;
    derivatives(xs_, vs_, xf, vf, ax_, av_);
    kx_ = ax_;
    kv_ = av_;

    for (const scalar c : {0.5, 0.5, 1.0})
    {
        for (label i = 1; i < N; ++i)
        {
            xs_[i] = x_[i] + c*h*ax_[i];
            vs_[i] = v_[i] + c*h*av_[i];
        }
        derivatives(xs_, vs_, xf + c*h*vf, vf, ax_, av_);
        const scalar wgt = c < 1 ? 2 : 1;
        for (label i = 1; i < N; ++i)
        {
            kx_[i] += wgt*ax_[i];
            kv_[i] += wgt*av_[i];
        }
    }

    for (label i = 1; i < N; ++i)
    {
        x_[i] += h/6*kx_[i];
        v_[i] += h/6*kv_[i];
    }
}


Foam::label Foam::RBD::lumpedLine::settle()
{
    // Kinetic damping: integrate with the ends held, and stop every node
    // whenever the kinetic energy has passed a peak, until the nodes' net
    // forces are under 1e-6 of the largest segment tension (or the
    // weight of a segment)
    const label N = p_.N;
    const scalar h = maxSubStep();
    const vector xf(x_[N]);
    const scalar weight = mag((p_.mu - p_.rho*A_)*p_.g)*l0_;

    scalar KE0 = 0;
    label n = 0;
    for (; n < 1000000; ++n)
    {
        if (n % 50 == 0)
        {
            forces(x_, v_, f_);
            scalar Tmax = weight;
            for (label j = 0; j < N; ++j)
            {
                Tmax = max(Tmax, tension(j));
            }
            scalar fmax = 0;
            for (label i = 1; i < N; ++i)
            {
                fmax = max(fmax, mag(f_[i]));
            }
            if (fmax <= 1e-6*Tmax)
            {
                break;
            }
        }

        subStep(h, xf, Zero);

        scalar KE = 0;
        for (label i = 1; i < N; ++i)
        {
            KE += 0.5*(inertia(x_, i, v_[i]) & v_[i]);
        }
        if (KE < KE0)
        {
            v_ = Zero;
            KE = 0;
        }
        KE0 = KE;
    }
    v_ = Zero;
    return n;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::lumpedLine::lumpedLine
(
    const properties& p,
    const vector& anchor,
    const vector& fairlead,
    const scalar t,
    const vector& fairleadVelocity
)
:
    p_(p),
    up_(mag(p.g) > VSMALL ? -p.g/mag(p.g) : vector(0, 0, 1)),
    l0_(p.L/p.N),
    A_(0.25*pi*sqr(p.d)),
    anchor_(anchor),
    t0_(t),
    x0_(p.N + 1, anchor),
    v0_(p.N + 1, Zero),
    t_(t),
    x_(p.N + 1),
    v_(p.N + 1, Zero),
    force_(Zero),
    xs_(p.N + 1),
    vs_(p.N + 1),
    ax_(p.N + 1),
    av_(p.N + 1),
    kx_(p.N + 1),
    kv_(p.N + 1),
    f_(p.N + 1),
    nSub_(0),
    settled_(0)
{
    // The initial shape: the quasi-static catenary (straight for a line
    // lighter than water)
    elasticCatenary::properties cp;
    cp.L = p.L;
    cp.w = max((p.mu - p.rho*A_)*mag(p.g), scalar(0));
    cp.EA = p.EA;
    cp.CB = 0;
    cp.grounded =
        p.hasSeabed && mag((anchor & up_) - p.seabed) <= 1e-6*p.L;
    elasticCatenary c(cp);

    const vector r(fairlead - anchor);
    const scalar h = r & up_;
    const vector horizontal(r - h*up_);
    const scalar l = mag(horizontal);
    const vector across(l > VSMALL ? horizontal/l : vector::zero);

    if (!c.solve(l, h))
    {
        FatalErrorInFunction
            << "lumpedLine: no catenary for the initial shape from the"
            << " anchor " << anchor << " to the fairlead " << fairlead
            << exit(FatalError);
    }

    for (label i = 0; i <= p.N; ++i)
    {
        const elasticCatenary::point pt(c.shape(p.L*i/p.N));
        x0_[i] = anchor + pt.x*across + pt.z*up_;
    }
    x0_[p.N] = fairlead;
    x_ = x0_;

    // Nodes on the catenary make chords shorter than its arcs, so the
    // segments start short of their stretch: settle them to the lumped
    // line's own equilibrium
    settled_ = settle();
    x0_ = x_;
    v0_ = Zero;
    v0_[p.N] = fairleadVelocity;
    v_ = v0_;

    forces(x_, v_, f_);
    force_ = f_[p.N];
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::RBD::lumpedLine::maxSubStep() const
{
    // 0.2 of a segment's axial transit time; and within RK4's stability
    // (to 2.79 on the negative real axis, 2.83 on the imaginary one) with
    // a margin: the internal damping's fastest mode, 4 BA/(l0^2 mu), to
    // 2.0; the seabed's spring on a node, sqrt(kSeabed d/mu), and its
    // damper, cSeabed d/mu, to 2.0
    scalar h = 0.2*l0_/sqrt(p_.EA/p_.mu);
    if (p_.BA > 0)
    {
        h = min(h, 0.5*sqr(l0_)*p_.mu/p_.BA);
    }
    if (p_.hasSeabed)
    {
        const scalar k = p_.kSeabed*p_.d/p_.mu;
        const scalar c = p_.cSeabed*p_.d/p_.mu;
        if (k > 0)
        {
            h = min(h, 2/sqrt(k));
        }
        if (c > 0)
        {
            h = min(h, 2/c);
        }
    }
    return h;
}


void Foam::RBD::lumpedLine::advance(const scalar t, const vector& fairlead)
{
    const label N = p_.N;
    const scalar dt = t - t0_;
    t_ = t;
    x_ = x0_;
    v_ = v0_;

    if (dt <= 0)
    {
        // At the committed time: the fairlead placed, nothing integrated
        x_[N] = fairlead;
        nSub_ = 0;
        forces(x_, v_, f_);
        force_ = f_[N];
        return;
    }

    const vector xf0(x0_[N]);
    const vector vf((fairlead - xf0)/dt);

    nSub_ = label(std::ceil(dt/maxSubStep() - 1e-9));
    nSub_ = max(nSub_, label(1));
    const scalar h = dt/nSub_;

    for (label n = 0; n < nSub_; ++n)
    {
        subStep(h, xf0 + n*h*vf, vf);
    }

    x_[N] = fairlead;
    v_[N] = vf;

    // The force on the body: all the line puts on the fairlead node, less
    // that node's inertia
    forces(x_, v_, f_);
    force_ = f_[N] - inertia(x_, N, (vf - v0_[N])/dt);
}


void Foam::RBD::lumpedLine::commit()
{
    t0_ = t_;
    x0_ = x_;
    v0_ = v_;
}


Foam::scalar Foam::RBD::lumpedLine::tension(const label j) const
{
    const vector r(x_[j + 1] - x_[j]);
    const scalar l = mag(r);
    if (l <= l0_)
    {
        return 0;
    }
    const scalar rate = (r/l) & (v_[j + 1] - v_[j]);
    return max(p_.EA*(l/l0_ - 1) + p_.BA*rate/l0_, scalar(0));
}


Foam::scalar Foam::RBD::lumpedLine::energy() const
{
    const label N = p_.N;
    const vector W((p_.mu - p_.rho*A_)*p_.g);
    scalar E = 0;

    for (label i = 1; i < N; ++i)
    {
        const scalar s = share(i);
        E += 0.5*(inertia(x_, i, v_[i]) & v_[i]);
        E -= s*(W & x_[i]);
        if (p_.hasSeabed)
        {
            const scalar depth = p_.seabed - (x_[i] & up_);
            if (depth > 0)
            {
                E += 0.5*p_.kSeabed*sqr(depth)*p_.d*s;
            }
        }
    }
    for (label j = 0; j < N; ++j)
    {
        const scalar l = mag(x_[j + 1] - x_[j]);
        if (l > l0_)
        {
            E += 0.5*p_.EA/l0_*sqr(l - l0_);
        }
    }
    return E;
}


void Foam::RBD::lumpedLine::writeState(Ostream& os) const
{
    os.writeEntry("t", t0_);
    os.writeEntry("x", x0_);
    os.writeEntry("v", v0_);
}


void Foam::RBD::lumpedLine::readState(const dictionary& dict)
{
    vectorField x(dict.get<vectorField>("x"));
    vectorField v(dict.get<vectorField>("v"));
    if (x.size() != p_.N + 1 || v.size() != p_.N + 1)
    {
        FatalIOErrorInFunction(dict)
            << "The state of a line of " << p_.N << " segments has "
            << x.size() << " nodes and " << v.size() << " velocities, not "
            << p_.N + 1 << nl << exit(FatalIOError);
    }
    t0_ = dict.get<scalar>("t");
    x0_ = x;
    v0_ = v;
    t_ = t0_;
    x_ = x0_;
    v_ = v0_;
}


// ************************************************************************* //
