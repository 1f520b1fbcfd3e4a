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
Application
    Test-mooring

Description
    The catenaryLine restraint (a quasi-static elastic catenary) against
    published numbers and exact answers:
    - OC3-Hywind's mooring (Jonkman 2010, NREL/TP-500-47535): each line's
      fairlead tension against MAP++'s frictionless solve, H 736,938 N and
      V 535,727 N, within 0.1%; the three lines' force on the body;
    - Lowe and Langley's (2006) line of MoorDyn's verification set at rest:
      the force on the fairlead (-11.40, 0, -45.71) kN and on the anchor
      (11.40, 0, -24.04) kN, within 0.2 kN;
    - a weightless line is a spring of stiffness EA/length once taut, within
      1e-9 relative, and slack pulls nothing;
    - in each state (resting on the seabed, with and without friction;
      fully lifted; taut; slack; vertical, taut and resting; an anchor
      above the seabed) the shape ends at the fairlead (1e-9 of the
      length) and satisfies the line's equations at every point:
      equilibrium T t = (H, V_A + w s) on the lifted part, (T, 0) on the
      seabed, residual under 1e-8 of the fairlead tension; and the stretch
      |dr/ds| = 1 + T/EA within 1e-9 (derivatives by 4th-order
      differences, over a step under the radius of curvature);
    - a line slack along the seabed, hanging straight down to the fairlead,
      has no horizontal tension and V the weight of its hanging length;
    - Newton from the previous answer takes at most 4 iterations after a
      10 cm move of the fairlead;
    - the dynamic line (lumpedLine): its first axial period, its energy
      without damping or drag, its fairlead force at the start and under a
      slow motion against the catenary's, Lowe and Langley's line settled,
      and a heavily damped line stable;
    - the table's columns (tension, groundedLength, fairleadAngle).
    Tolerances are stated with each check.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "catenaryLine.H"
#include "elasticCatenary.H"
#include "lumpedLine.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"

using namespace Foam;

namespace mooringTest
{

using test::check;
using test::checkAbs;
using test::checkRel;
using Foam::cos;
using Foam::sin;
using Foam::sqrt;

const std::string oc3Line =
    " type catenaryLine; body hull; length 902.2; wetWeight 698.094;"
    " EA 384.243e6; seabed -320;";


//- A hull on a floating joint with the given restraints
autoPtr<RBD::rigidBodyMotion> hull(const std::string& restraints)
{
    return test::motion
    (
        "solver { type Newmark; } g (0 0 -9.81);"
        " bodies { hull { type cuboid; parent root; mass 7466330;"
        " L (20 20 20); centreOfMass (0 0 0);"
        " joint { type floating; } } }"
        " restraints { " + restraints + " }"
    );
}


//- The restraints' force on the hull at its initial state
vector lineForce(RBD::rigidBodyMotion& m)
{
    scalarField tau(m.model().nDoF(), Zero);
    Field<spatialVector> fx(m.model().nBodies(), Zero);
    m.restraintForces(tau, fx);
    vector F(Zero);
    for (const spatialVector& f : fx)
    {
        F += f.l();
    }
    return F;
}


const RBD::restraints::catenaryLine& line
(
    const RBD::rigidBodyMotion& m,
    const label i
)
{
    return refCast<const RBD::restraints::catenaryLine>(m.restraints()[i]);
}


void oc3()
{
    std::string lines;
    for (const int deg : {0, 120, 240})
    {
        const scalar a = degToRad(scalar(deg));
        lines +=
            "line" + std::to_string(deg) + " {" + oc3Line
          + " anchor (" + std::to_string(853.87*cos(a)) + " "
          + std::to_string(853.87*sin(a)) + " -320);"
          + " refAttachmentPt (" + std::to_string(5.2*cos(a)) + " "
          + std::to_string(5.2*sin(a)) + " -70); } ";
    }
    autoPtr<RBD::rigidBodyMotion> m = hull(lines);
    const vector F(lineForce(m()));

    for (label i = 0; i < 3; ++i)
    {
        const RBD::elasticCatenary& c = line(m(), i).line();
        checkRel(c.H(), 736938, 1e-3, "OC3-Hywind line " + std::to_string(i)
            + ": fairlead H against MAP++ (736,938 N), 0.1%");
        checkRel(c.V(), 535727, 1e-3, "OC3-Hywind line " + std::to_string(i)
            + ": fairlead V against MAP++ (535,727 N), 0.1%");
        check(c.groundedLength() > 0, "OC3-Hywind line "
            + std::to_string(i) + ": part of it on the seabed ("
            + std::to_string(c.groundedLength()) + " m)");
    }
    checkRel(-F.z(), 3*535727, 1e-3,
        "OC3-Hywind: the three lines pull the hull down by 3 V, 0.1%");
    checkAbs(mag(vector(F.x(), F.y(), 0)), 0, 1e-6*3*736938,
        "OC3-Hywind: their horizontal pulls cancel, 1e-6 of 3 H");
}


void loweLangley()
{
    // Submerged weight per metre: (165 kg/m - rho pi d^2/4) g
    const scalar w =
        (165 - 1000*constant::mathematical::pi/4*sqr(0.396))*9.807;
    autoPtr<RBD::rigidBodyMotion> m = test::motion
    (
        "solver { type Newmark; } g (0 0 -9.807);"
        " bodies { buoy { type sphere; parent root; mass 1000; radius 1;"
        " centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (0 0 -5);"
        " joint { type Pxyz; } } }"
        " restraints { line { type catenaryLine; body buoy;"
        " anchor (-100 0 -55); refAttachmentPt (0 0 0); length 170;"
        " wetWeight " + std::to_string(w) + "; EA 500e6; seabed -100; } }"
    );
    const vector F(lineForce(m()));
    checkAbs(F.x(), -11400, 200,
        "Lowe and Langley's line at rest: force on the fairlead x"
        " (-11.40 kN), 0.2 kN");
    checkAbs(F.z(), -45710, 200,
        "Lowe and Langley's line at rest: force on the fairlead z"
        " (-45.71 kN), 0.2 kN");
    scalar HA, VA;
    line(m(), 0).line().anchorTension(HA, VA);
    checkAbs(HA, 11400, 200,
        "Lowe and Langley's line at rest: force on the anchor x"
        " (11.40 kN), 0.2 kN");
    checkAbs(VA, -24040, 200,
        "Lowe and Langley's line at rest: force on the anchor z"
        " (-24.04 kN), 0.2 kN");
    check(line(m(), 0).line().groundedLength() == 0,
        "Lowe and Langley's line hangs clear of the seabed");
}


void weightless()
{
    const scalar L = 10, EA = 2e5;
    for (const scalar d : {10.5, 12.0, 9.0})
    {
        autoPtr<RBD::rigidBodyMotion> m = hull
        (
            "line { type catenaryLine; body hull; anchor (0 0 0);"
            " refAttachmentPt (" + std::to_string(0.6*d) + " 0 "
          + std::to_string(0.8*d) + "); length 10; wetWeight 0;"
            " EA 2e5; }"
        );
        const vector F(lineForce(m()));
        const scalar T = d > L ? EA*(d/L - 1) : 0;
        const std::string what =
            "weightless line, ends " + std::to_string(d) + " m apart";
        if (T > 0)
        {
            checkRel(mag(F), T, 1e-9, what
                + ": a spring of stiffness EA/length, 1e-9");
            checkAbs(mag(F/mag(F) + vector(0.6, 0, 0.8)), 0, 1e-12,
                what + ": pulling straight at the anchor, 1e-12");
        }
        else
        {
            check(mag(F) == 0, what + ": slack, no force");
        }
    }
}


//- The derivative of the shape at s, 4th-order central differences
void derivative
(
    const RBD::elasticCatenary& c,
    const scalar s,
    const scalar d,
    scalar& dx,
    scalar& dz
)
{
    const RBD::elasticCatenary::point a(c.shape(s - 2*d)), b(c.shape(s - d));
    const RBD::elasticCatenary::point e(c.shape(s + d)), f(c.shape(s + 2*d));
    dx = (a.x - 8*b.x + 8*e.x - f.x)/(12*d);
    dz = (a.z - 8*b.z + 8*e.z - f.z)/(12*d);
}


//- The shape ends at the fairlead and satisfies the line's equations
void checkShape
(
    const std::string& state,
    RBD::elasticCatenary c,
    const scalar l,
    const scalar h
)
{
    const RBD::elasticCatenary::properties& p = c.props();
    if (!check(c.solve(l, h), state + ": solved"))
    {
        return;
    }
    const RBD::elasticCatenary::point end(c.shape(p.L));
    checkAbs(mag(vector(end.x - l, 0, end.z - h)), 0, 1e-9*p.L,
        state + ": the shape ends at the fairlead, 1e-9 of the length");

    // Differences over a step well under the length and the radius of
    // curvature at the lowest point, H/w
    const scalar Tf = c.tension();
    const scalar LB = c.groundedLength();
    const scalar R = c.H() > 0 && p.w > 0 ? c.H()/p.w : p.L;
    const scalar d = min(1e-3*p.L, 2e-3*R);

    // Kinks: where the line leaves the seabed, the bottom of a vertical
    // U (an anchor above the seabed, the line hanging below it)
    const bool U = c.H() == 0 && !p.grounded && c.V() < p.w*p.L;
    const scalar kink = U ? p.L - c.V()/p.w : LB;

    // With friction, where the grounded part's tension starts
    const scalar s0 = p.CB > 0 ? LB - c.H()/(p.CB*p.w) : -1;

    scalar worstForce = 0, worstStrain = 0;
    for (label i = 1; i < 400; ++i)
    {
        const scalar s = p.L*i/400;
        if
        (
            s < 2*d || s > p.L - 2*d || mag(s - kink) < 2*d
         || mag(s - s0) < 2*d
         || (c.H() == 0 && s < LB)  // a vertical line's heap at the anchor
        )
        {
            continue;
        }
        scalar dx, dz;
        derivative(c, s, d, dx, dz);
        const RBD::elasticCatenary::point pt(c.shape(s));
        const scalar stretch = sqrt(sqr(dx) + sqr(dz));

        // Equilibrium: the tension along the tangent is (H, V_A + w s)
        // lifted, (T, 0) on the seabed
        const scalar Hs = s < LB ? pt.T : c.H();
        const scalar Vs = s < LB ? 0 : c.V() - p.w*(p.L - s);
        worstForce = max(worstForce, mag(pt.T*dx/stretch - Hs)/Tf);
        worstForce = max(worstForce, mag(pt.T*dz/stretch - Vs)/Tf);

        // The stretch: |dr/ds| = 1 + T/EA
        worstStrain = max(worstStrain, mag(stretch - 1 - pt.T/p.EA));
    }
    checkAbs(worstForce, 0, 1e-8, state
        + ": equilibrium along the line, residual 1e-8 of the fairlead"
          " tension");
    checkAbs(worstStrain, 0, 1e-9, state
        + ": the stretch |dr/ds| = 1 + T/EA along the line, 1e-9");
}


void states()
{
    RBD::elasticCatenary::properties oc3{902.2, 698.094, 384.243e6, 0, true};
    checkShape("OC3 line, resting on the seabed", RBD::elasticCatenary(oc3),
        848.67, 250);

    RBD::elasticCatenary::properties fr(oc3);
    fr.CB = 0.5;
    checkShape("OC3 line, resting on the seabed with friction 0.5",
        RBD::elasticCatenary(fr), 848.67, 250);
    fr.CB = 20;
    checkShape("OC3 line, resting on the seabed with friction 20 (the"
        " anchor unloaded)", RBD::elasticCatenary(fr), 848.67, 250);

    checkShape("OC3 line, fully lifted", RBD::elasticCatenary(oc3), 870,
        300);
    checkShape("OC3 line, taut (ends further apart than its length)",
        RBD::elasticCatenary(oc3), 880, 330);
    checkShape("OC3 line, slack (most of it on the seabed)",
        RBD::elasticCatenary(oc3), 700, 250);
    checkShape("OC3 line, vertical and resting", RBD::elasticCatenary(oc3),
        0, 250);
    checkShape("OC3 line, vertical and taut", RBD::elasticCatenary(oc3), 0,
        905);

    checkShape("OC3 line, slack along the seabed, hanging straight down to"
        " the fairlead", RBD::elasticCatenary(oc3), 500, 250);
    {
        // No catenary with H > 0 exists: H = 0, and V the weight of the
        // hanging length s, h = s (1 + w s/(2 EA))
        RBD::elasticCatenary c(oc3);
        c.solve(500, 250);
        const scalar w = oc3.w, EA = oc3.EA;
        const scalar sh = (sqrt(1 + 2*w*250/EA) - 1)*EA/w;
        check(c.H() == 0, "OC3 line slack along the seabed: no horizontal"
            " tension");
        checkRel(c.V(), w*sh, 1e-12, "OC3 line slack along the seabed: V"
            " the weight of its hanging length, 1e-12");
    }

    RBD::elasticCatenary::properties clear(oc3);
    clear.grounded = false;
    checkShape("OC3 line from an anchor above the seabed, hanging below it",
        RBD::elasticCatenary(clear), 700, 250);
    checkShape("OC3 line from an anchor above the seabed, vertical U",
        RBD::elasticCatenary(clear), 0, 250);

    // Warm start: a 10 cm move from the answer
    RBD::elasticCatenary c(oc3);
    c.solve(848.67, 250);
    c.solve(848.77, 250);
    check(c.iterations() <= 4, "Newton from the previous answer after a"
        " 10 cm move: " + std::to_string(c.iterations())
      + " iterations (at most 4)");
}


void table()
{
    autoPtr<RBD::rigidBodyMotion> m = hull
    (
        "line {" + oc3Line + " anchor (853.87 0 -320);"
        " refAttachmentPt (5.2 0 -70); }"
    );
    lineForce(m());
    const RBD::restraint& r = m->restraints()[0];
    const wordList names(r.tableColumns());
    check
    (
        names.size() == 3 && names[0] == "line.tension"
     && names[1] == "line.groundedLength" && names[2] == "line.fairleadAngle",
        "catenaryLine's table columns: line.tension, line.groundedLength,"
        " line.fairleadAngle"
    );
    scalarField row(3, Zero);
    label k = 0;
    r.tableValues(row, k);
    checkRel(row[0], sqrt(sqr(736938.) + sqr(535727.)), 1e-3,
        "table: the fairlead tension, 0.1%");
    checkRel(row[2], radToDeg(std::atan2(535727., 736938.)), 1e-3,
        "table: the fairlead angle from the horizontal, 0.1%");
}


// * * * * * * * * * * * * * * * The dynamic line  * * * * * * * * * * * * //

//- A line's properties: no drag, added mass, damping or seabed
RBD::lumpedLine::properties bare
(
    const label N,
    const scalar L,
    const scalar mu,
    const scalar d,
    const scalar EA,
    const vector& g
)
{
    RBD::lumpedLine::properties p;
    p.N = N; p.L = L; p.mu = mu; p.d = d; p.EA = EA; p.BA = 0;
    p.Cdn = p.Cdt = p.Can = p.Cat = 0;
    p.rho = 1000; p.g = g;
    p.hasSeabed = false; p.seabed = 0; p.kSeabed = 0; p.cSeabed = 0;
    return p;
}


//- BA for a damping ratio of each segment's axial mode
scalar dampingBA(const RBD::lumpedLine::properties& p, const scalar zeta)
{
    return zeta*2*(p.L/p.N)*sqrt(p.EA*p.mu);
}


void axialMode()
{
    // A weightless line stretched 1% between fixed ends, released in its
    // first axial mode: the discrete chain's exact eigenvector
    // sin(pi i/N); continuum period 2 L/sqrt(EA/mu)
    const label N = 40;
    const scalar L = 170, mu = 165, EA = 500e6;
    RBD::lumpedLine::properties p(bare(N, L, mu, 0.396, EA, Zero));
    const vector anchor(Zero), fairlead(1.01*L, 0, 0);
    RBD::lumpedLine line(p, anchor, fairlead, 0);

    const scalar T = 2*L/sqrt(EA/mu);
    const scalar V = 0.1*constant::mathematical::twoPi/T;  // 0.1 m amplitude
    {
        vectorField x(N + 1), v(N + 1, Zero);
        for (label i = 0; i <= N; ++i)
        {
            x[i] = fairlead*i/N;
            v[i] = vector(V*sin(constant::mathematical::pi*i/N), 0, 0);
        }
        OStringStream os;
        os.writeEntry("t", scalar(0));
        os.writeEntry("x", x);
        os.writeEntry("v", v);
        IStringStream is(os.str());
        line.readState(dictionary(is));
    }

    const scalar E0 = line.energy();
    const scalar dt = T/200;
    const scalar xMid = 0.5*fairlead.x();
    scalar prev = 0, tPrev = 0, Emax = 0;
    DynamicList<scalar> crossings;
    for (label n = 1; n <= 2000; ++n)
    {
        const scalar t = n*dt;
        line.advance(t, fairlead);
        line.commit();
        const scalar u = line.nodes()[N/2].x() - xMid;
        if (n > 1 && (u < 0) != (prev < 0))
        {
            crossings.append(tPrev - prev*(t - tPrev)/(u - prev));
        }
        prev = u;
        tPrev = t;
        Emax = max(Emax, mag(line.energy() - E0));
    }
    const label nc = crossings.size();
    const scalar period =
        nc >= 3 ? 2*(crossings[nc - 1] - crossings[0])/(nc - 1) : 0;
    checkRel(period, T, 1e-2, "lumpedLine: the first axial mode's period"
        " against 2 L/sqrt(EA/mu) = " + std::to_string(T) + " s, 1%");
    checkRel(E0 + Emax, E0, 1e-3, "lumpedLine: no damping, no drag: the"
        " energy over 10 periods, 0.1%");
    check(line.nSubSteps() >= 1 && dt/line.nSubSteps() <= line.maxSubStep(),
        "lumpedLine: sub-steps at most 0.2 of a segment's transit time ("
      + std::to_string(line.nSubSteps()) + " a step)");
}


void quasiStatic()
{
    // OC3-Hywind's line (77.7066 kg/m, 0.09 m: 698.094 N/m in water), 20
    // segments, damped (ratio 0.5), with drag, on a seabed; the fairlead
    // moved 10 m away from the anchor over 100 s and held 20 s: its
    // tension against the catenary's at the same place
    const label N = 20;
    RBD::lumpedLine::properties p
    (
        bare(N, 902.2, 77.7066, 0.09, 384.243e6, vector(0, 0, -9.80665))
    );
    p.rho = 1025;
    p.BA = dampingBA(p, 0.5);
    p.Cdn = 1.6; p.Cdt = 0.1; p.Can = 1; p.Cat = 0;
    p.hasSeabed = true; p.seabed = -320; p.kSeabed = 3e6; p.cSeabed = 3e5;

    const vector anchor(-848.67, 0, -320), f0(0, 0, -70);
    RBD::lumpedLine line(p, anchor, f0, 0);

    RBD::elasticCatenary::properties cp{902.2, 698.094, 384.243e6, 0, true};
    RBD::elasticCatenary c(cp);

    // It starts settled: its own equilibrium, near the catenary's
    c.solve(f0.x() - anchor.x(), f0.z() - anchor.z());
    checkAbs(mag(line.force() - vector(-c.H(), 0, -c.V()))/c.tension(), 0,
        1e-2, "lumpedLine starts in its own equilibrium: the fairlead force"
        " against the catenary's, 1% (in "
      + std::to_string(line.settledIn()) + " sub-steps of settling)");

    const scalar dt = 0.05;
    scalar worst = 0;
    for (label n = 1; n <= 2400; ++n)
    {
        const scalar t = n*dt;
        const scalar s = min(t/100, scalar(1));
        const vector f(f0 + vector(10*0.5*(1 - cos(constant::mathematical::pi*s)), 0, 0));
        line.advance(t, f);
        line.commit();
        if (n % 200 == 0)
        {
            c.solve(f.x() - anchor.x(), f.z() - anchor.z());
            const vector F(line.force());
            const vector Fc(-c.H(), 0, -c.V());
            worst = max(worst, mag(F - Fc)/mag(Fc));
        }
    }
    checkAbs(worst, 0, 1e-2, "lumpedLine under a slow motion (10 m in"
        " 100 s): the fairlead force against the catenary's, 1% of it");
}


void loweLangleyDynamic()
{
    // Lowe and Langley's line, 40 segments, settled for 60 s from the
    // catenary: the forces within 0.2 kN of MoorDyn's verification values
    const label N = 40;
    RBD::lumpedLine::properties p
    (
        bare(N, 170, 165, 0.396, 500e6, vector(0, 0, -9.807))
    );
    p.BA = dampingBA(p, 0.5);
    p.Cdn = 1; p.Cdt = 0; p.Can = 1; p.Cat = 0;
    p.hasSeabed = true; p.seabed = -100; p.kSeabed = 3e6; p.cSeabed = 3e5;

    const vector anchor(-100, 0, -55), fairlead(0, 0, -5);
    RBD::lumpedLine line(p, anchor, fairlead, 0);
    for (label n = 1; n <= 600; ++n)
    {
        line.advance(0.1*n, fairlead);
        line.commit();
    }
    const vector F(line.force());

    // Heavily damped (ratio 5): the sub-step shrinks to stay stable
    {
        RBD::lumpedLine::properties p5(p);
        p5.BA = dampingBA(p5, 5);
        RBD::lumpedLine l5(p5, anchor, fairlead, 0);
        for (label n = 1; n <= 100; ++n)
        {
            l5.advance(0.1*n, fairlead + vector(0.5*sin(0.5*n*0.1), 0, 0));
            l5.commit();
        }
        checkAbs(mag(l5.force() - F), 0, 2e3, "lumpedLine heavily damped"
            " (ratio 5) through 10 s of motion: stable, within 2 kN of the"
            " settled force");
    }

    checkAbs(F.x(), -11400, 200, "lumpedLine, Lowe and Langley's line"
        " settled: force on the fairlead x (-11.40 kN), 0.2 kN");
    checkAbs(F.z(), -45710, 200, "lumpedLine, Lowe and Langley's line"
        " settled: force on the fairlead z (-45.71 kN), 0.2 kN");

    // On the anchor: the first segment's pull and the anchor node's share
    // of the weight in water
    const vectorField& x = line.nodes();
    const vector t0((x[1] - x[0])/mag(x[1] - x[0]));
    const scalar A = 0.25*constant::mathematical::pi*sqr(p.d);
    const vector FA
    (
        line.tension(0)*t0 + 0.5*(p.L/N)*(p.mu - p.rho*A)*p.g
    );
    checkAbs(FA.x(), 11400, 200, "lumpedLine, Lowe and Langley's line"
        " settled: force on the anchor x (11.40 kN), 0.2 kN");
    checkAbs(FA.z(), -24040, 200, "lumpedLine, Lowe and Langley's line"
        " settled: force on the anchor z (-24.04 kN), 0.2 kN");
}

} // End namespace mooringTest


int main(int argc, char *argv[])
{
    mooringTest::oc3();
    mooringTest::loweLangley();
    mooringTest::weightless();
    mooringTest::states();
    mooringTest::table();
    mooringTest::axialMode();
    mooringTest::quasiStatic();
    mooringTest::loweLangleyDynamic();
    return test::testResult();
}

// ************************************************************************* //
