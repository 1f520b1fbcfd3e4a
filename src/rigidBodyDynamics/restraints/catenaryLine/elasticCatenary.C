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
    elasticCatenary: the quasi-static elastic catenary (elasticCatenary.H)
\*---------------------------------------------------------------------------*/

#include "elasticCatenary.H"
#include "scalar.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::elasticCatenary::position
(
    const scalar H,
    const scalar V,
    scalar& x,
    scalar& z,
    scalar J[4]
) const
{
    const scalar L = p_.L;
    const scalar w = p_.w;
    const scalar EA = p_.EA;

    const scalar a = V/H;
    const scalar ra = sqrt(1 + sqr(a));

    if (p_.grounded && V < w*L)
    {
        // Part of the line on the seabed: L_B = L - V/w
        const scalar LB = L - V/w;

        x = LB + H/w*asinh(a) + H*L/EA;
        z = H/w*(ra - 1) + sqr(V)/(2*EA*w);

        J[0] = (asinh(a) - a/ra)/w + L/EA;     // dx/dH
        J[1] = (1/ra - 1)/w;                    // dx/dV
        J[2] = (1/ra - 1)/w;                    // dz/dH
        J[3] = a/(ra*w) + V/(EA*w);             // dz/dV

        if (p_.CB > 0)
        {
            // The friction's change of the grounded part's stretch
            const scalar c = p_.CB*w/(2*EA);
            const scalar d = LB - H/(p_.CB*w);
            x += c*(-sqr(LB) + d*max(d, scalar(0)));
            J[1] += 2*c*LB/w;
            if (d > 0)
            {
                J[0] += -2*c*d/(p_.CB*w);
                J[1] += -2*c*d/w;
            }
        }
    }
    else
    {
        // The whole line lifted: V_A = V - w L at the anchor
        const scalar b = (V - w*L)/H;
        const scalar rb = sqrt(1 + sqr(b));

        x = H/w*(asinh(a) - asinh(b)) + H*L/EA;
        z = H/w*(ra - rb) + (V*L - 0.5*w*sqr(L))/EA;

        J[0] = (asinh(a) - asinh(b) - a/ra + b/rb)/w + L/EA;
        J[1] = (1/ra - 1/rb)/w;
        J[2] = (1/ra - 1/rb)/w;
        J[3] = (a/ra - b/rb)/w + L/EA;
    }
}


void Foam::RBD::elasticCatenary::estimate
(
    const scalar l,
    const scalar h,
    scalar& H,
    scalar& V
) const
{
    const scalar L = p_.L;
    const scalar lambda =
        L <= sqrt(sqr(l) + sqr(h))
      ? 0.2
      : sqrt(3*((sqr(L) - sqr(h))/sqr(l) - 1));

    H = max(mag(p_.w*l/(2*lambda)), 1e-6*p_.w*L);
    V = 0.5*p_.w*(h/tanh(lambda) + L);
}


bool Foam::RBD::elasticCatenary::newton
(
    const scalar l,
    const scalar h,
    scalar& H,
    scalar& V
)
{
    const scalar tol = 1e-12*(p_.L + l + mag(h));

    for (iterations_ = 0; iterations_ < 100; ++iterations_)
    {
        scalar x, z, J[4];
        position(H, V, x, z, J);

        const scalar fx = x - l;
        const scalar fz = z - h;

        if (!std::isfinite(fx) || !std::isfinite(fz))
        {
            return false;
        }
        if (mag(fx) + mag(fz) <= tol)
        {
            return true;
        }

        const scalar det = J[0]*J[3] - J[1]*J[2];
        if (mag(det) < VSMALL)
        {
            return false;
        }
        scalar dH = -(J[3]*fx - J[1]*fz)/det;
        scalar dV = -(J[0]*fz - J[2]*fx)/det;

        // Keep H positive, and V too where the line may rest on the
        // seabed (the grounded form has a second root with V < 0, a line
        // longer than itself on the seabed): at most a tenth of either left
        scalar alpha = 1;
        if (H + dH <= 0)
        {
            alpha = 0.9*H/(-dH);
        }
        if (p_.grounded && V > 0 && V + alpha*dV <= 0)
        {
            alpha = 0.9*V/(-dV);
        }
        dH *= alpha;
        dV *= alpha;

        H += dH;
        V += dV;

        if (mag(dH) + mag(dV) <= 1e-15*(H + mag(V)))
        {
            // Stalled: an answer only if the residual is small too
            scalar x1, z1, J1[4];
            position(H, V, x1, z1, J1);
            return mag(x1 - l) + mag(z1 - h) <= 1e3*tol;
        }
    }

    return false;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::elasticCatenary::elasticCatenary(const properties& p)
:
    p_(p),
    H_(0),
    V_(0),
    l_(0),
    h_(0),
    started_(false),
    iterations_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::RBD::elasticCatenary::solve(const scalar l, const scalar h)
{
    const scalar L = p_.L;
    const scalar w = p_.w;
    const scalar EA = p_.EA;

    l_ = l;
    h_ = h;
    iterations_ = 0;

    if (w <= 0)
    {
        // Weightless: straight, a spring of stiffness EA/L once taut
        const scalar d = sqrt(sqr(l) + sqr(h));
        const scalar T = d > L ? EA*(d/L - 1) : 0;
        H_ = d > 0 ? T*l/d : 0;
        V_ = d > 0 ? T*h/d : 0;
        started_ = false;
        return true;
    }

    if (p_.grounded && h >= 0)
    {
        // So slack that the line lies along the seabed from the anchor and
        // hangs straight down to the fairlead, with line to spare: its
        // hanging length s is h = s (1 + w s/(2 EA)), the rest is on the
        // seabed, and it pulls only down (no catenary with H > 0 exists)
        const scalar s = (sqrt(1 + 2*w*h/EA) - 1)*EA/w;
        if (l + s <= L)
        {
            H_ = 0;
            V_ = w*s;
            started_ = false;
            return true;
        }
    }

    if (l <= 1e-9*L)
    {
        // Vertical: no horizontal tension
        H_ = 0;
        const scalar VTaut = (h - L)*EA/L + 0.5*w*L;
        if (VTaut >= w*L)
        {
            V_ = VTaut;                         // taut, lifted from the anchor
        }
        else if (p_.grounded)
        {
            // Below the anchor's height: resting
            V_ = 0;
        }
        else
        {
            // Hanging clear in a U: the strand from the fairlead down to the
            // lowest point is a = (L + h/(1 + w L/(2 EA)))/2 long
            V_ = 0.5*w*(L + h/(1 + 0.5*w*L/EA));
        }
        started_ = false;
        return true;
    }

    scalar H = H_, V = V_;
    if (!started_ || H <= 0 || !newton(l, h, H, V))
    {
        estimate(l, h, H, V);
        if (!newton(l, h, H, V))
        {
            return false;
        }
    }

    H_ = H;
    V_ = V;
    started_ = true;
    return true;
}


Foam::scalar Foam::RBD::elasticCatenary::tension() const
{
    return sqrt(sqr(H_) + sqr(V_));
}


void Foam::RBD::elasticCatenary::anchorTension(scalar& HA, scalar& VA) const
{
    const scalar LB = groundedLength();
    if (LB > 0)
    {
        HA = max(H_ - p_.CB*p_.w*LB, scalar(0));
        VA = 0;
    }
    else if (p_.w > 0 && H_ == 0 && !p_.grounded && V_ < p_.w*p_.L)
    {
        // A vertical U: the anchor's strand hangs below it
        HA = 0;
        VA = -(p_.w*p_.L - V_);
    }
    else
    {
        HA = H_;
        VA = V_ - p_.w*p_.L;
    }
}


Foam::scalar Foam::RBD::elasticCatenary::groundedLength() const
{
    if (!p_.grounded || p_.w <= 0 || V_ >= p_.w*p_.L)
    {
        return 0;
    }
    return p_.L - V_/p_.w;
}


Foam::scalar Foam::RBD::elasticCatenary::lowestHeight() const
{
    const scalar w = p_.w;
    const scalar VA = V_ - w*p_.L;

    if (w <= 0 || p_.grounded || VA >= 0)
    {
        return min(scalar(0), h_);
    }
    if (H_ == 0)
    {
        // A vertical U: its lowest point, the anchor's strand below it
        return shape((p_.L - V_/w)).z;
    }
    if (V_ <= 0)
    {
        return min(scalar(0), h_);
    }
    // The lowest point, where the vertical tension is zero: s = -V_A/w
    return min(scalar(0), shape(-VA/w).z);
}


Foam::RBD::elasticCatenary::point Foam::RBD::elasticCatenary::shape
(
    const scalar s
) const
{
    const scalar L = p_.L;
    const scalar w = p_.w;
    const scalar EA = p_.EA;
    const scalar H = H_;
    const scalar V = V_;

    point pt;

    if (w <= 0)
    {
        // Straight
        // Straight from the anchor to the fairlead (a slack one drawn so
        // too)
        pt.x = s/L*l_;
        pt.z = s/L*h_;
        pt.T = tension();
        return pt;
    }

    const scalar LB = groundedLength();

    if (H == 0)
    {
        // No horizontal tension: vertical, or slack along the seabed
        pt.x = 0;
        if (LB > 0)
        {
            // Along the seabed to under the fairlead (the spare line
            // spread evenly), then hanging
            pt.x = l_*min(s, LB)/LB;
            const scalar sigma = max(s - LB, scalar(0));
            pt.z = sigma + w*sqr(sigma)/(2*EA);
            pt.T = w*sigma;
        }
        else if (!p_.grounded && V < w*L)
        {
            // A U: the anchor's strand of b = L - V/w down, then up
            const scalar b = L - V/w;
            const scalar sb = min(s, b);
            pt.z = -(sb + w*(b*sb - 0.5*sqr(sb))/EA);
            const scalar sigma = max(s - b, scalar(0));
            pt.z += sigma + w*sqr(sigma)/(2*EA);
            pt.T = s < b ? w*(b - s) : w*sigma;
        }
        else
        {
            const scalar VA = V - w*L;
            pt.z = s + (VA*s + 0.5*w*sqr(s))/EA;
            pt.T = VA + w*s;
        }
        return pt;
    }

    if (LB > 0)
    {
        // The grounded part's stretch at arc length sg <= L_B
        auto grounded = [&](const scalar sg, scalar& T)
        {
            if (p_.CB > 0)
            {
                const scalar c = p_.CB*w;
                const scalar s0 = LB - H/c;
                T = c*max(sg - s0, scalar(0));
                return
                    sg
                  + 0.5*c*(sqr(max(sg - s0, scalar(0)))
                  - sqr(max(-s0, scalar(0))))/EA;
            }
            T = H;
            return sg + H*sg/EA;
        };

        if (s <= LB)
        {
            pt.x = grounded(s, pt.T);
            pt.z = 0;
            return pt;
        }

        scalar TB;
        const scalar sigma = s - LB;
        const scalar q = w*sigma/H;
        pt.x = grounded(LB, TB) + H/w*asinh(q) + H*sigma/EA;
        pt.z = H/w*(sqrt(1 + sqr(q)) - 1) + w*sqr(sigma)/(2*EA);
        pt.T = sqrt(sqr(H) + sqr(w*sigma));
        return pt;
    }

    const scalar VA = V - w*L;
    const scalar Vs = VA + w*s;
    pt.x = H/w*(asinh(Vs/H) - asinh(VA/H)) + H*s/EA;
    pt.z =
        H/w*(sqrt(1 + sqr(Vs/H)) - sqrt(1 + sqr(VA/H)))
      + (VA*s + 0.5*w*sqr(s))/EA;
    pt.T = sqrt(sqr(H) + sqr(Vs));
    return pt;
}


void Foam::RBD::elasticCatenary::stiffness(scalar K[4]) const
{
    // Central differences of solves on a copy (one-sided in l at a
    // vertical line); for reports, not the time step
    const scalar delta = 1e-6*max(p_.L, scalar(1));
    elasticCatenary c(*this);

    const scalar l0 = l_, h0 = h_;
    const scalar la = max(l0 - delta, scalar(0));
    const scalar lb = l0 + delta;

    c.solve(lb, h0);
    const scalar Hlb = c.H(), Vlb = c.V();
    c.solve(la, h0);
    const scalar Hla = c.H(), Vla = c.V();
    c.solve(l0, h0 + delta);
    const scalar Hhb = c.H(), Vhb = c.V();
    c.solve(l0, h0 - delta);
    const scalar Hha = c.H(), Vha = c.V();

    K[0] = (Hlb - Hla)/(lb - la);
    K[1] = (Hhb - Hha)/(2*delta);
    K[2] = (Vlb - Vla)/(lb - la);
    K[3] = (Vhb - Vha)/(2*delta);
}


Foam::vector Foam::RBD::elasticCatenary::fairleadForce
(
    const vector& anchor,
    const vector& fairlead,
    const vector& up
)
{
    const vector r(fairlead - anchor);
    const scalar h = r & up;
    const vector horizontal(r - h*up);
    const scalar l = mag(horizontal);
    if (!solve(l, h))
    {
        return Zero;
    }
    return
        -H_*(l > VSMALL ? horizontal/l : vector::zero)
      - V_*up;
}


Foam::tensor Foam::RBD::elasticCatenary::fairleadForceGradient
(
    const vector& anchor,
    const vector& fairlead,
    const vector& up
) const
{
    const scalar delta = 1e-6*max(p_.L, scalar(1));
    tensor G(Zero);
    elasticCatenary c(*this);
    for (direction k = 0; k < 3; ++k)
    {
        vector dp(Zero);
        dp[k] = delta;
        const vector dF
        (
            (
                c.fairleadForce(anchor, fairlead + dp, up)
              - c.fairleadForce(anchor, fairlead - dp, up)
            )/(2*delta)
        );
        for (direction i = 0; i < 3; ++i)
        {
            G[3*i + k] = dF[i];
        }
    }
    return G;
}


// ************************************************************************* //
