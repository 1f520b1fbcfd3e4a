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
    Test-restraintCommit

Description
    Restraints with a state of their own keep their committed state apart
    from their trial evaluations (issue 41), and a table's columns are
    defined once:
    - a buoy held by a dynamic lumpedMassLine and a quasi-static
      catenaryLine (test/mooring's mooredBuoy), five steps of 10 ms, the
      restraints committed at the end: trial evaluations at another state
      (q + 0.1 m, t + 5 ms), as the coupling's finite-difference Jacobian
      makes them, leave each restraint's table columns and the restart
      state (restraintStates) exactly as they were;
    - the same trials made before the commit: the lumpedMassLine's columns
      and state exactly those of a run without them, the catenaryLine's
      within 1e-9 (its Newton solve starts from the latest trial);
    - five more steps after the trials: q within 1e-9 m of a run without
      them;
    - tableRow: the header of the first row, and a later row that names
      another column, lacks one or adds one stops with a FatalError naming
      the column, not a write past the end.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "tableRow.H"
#include "OStringStream.H"

using namespace Foam;

namespace restraintCommitTest
{

using test::check;
using test::checkAbs;

const scalar dt = 0.01;

const std::string buoy =
    "g (0 0 -9.807); solver { type Newmark; }"
    " bodies { buoy { type sphere; parent root; mass 20000; radius 1;"
    " centreOfMass (0 0 0); transform (1 0 0 0 1 0 0 0 1) (0 0 -5);"
    " joint { type composite; joints ( { type Px; } { type Pz; } ); } } }"
    " q (2 0);"
    " restraints {"
    " dynamic { type lumpedMassLine; body buoy; anchor (-100 0 -55);"
    " refAttachmentPt (0 0 0); length 170; seabed -100; nSegments 20;"
    " massPerLength 165; diameter 0.396; EA 500e6; dampingRatio 0.5;"
    " Cdn 1; Cdt 0; Can 1; Cat 0; rhoWater 1000; }"
    " quasiStatic { type catenaryLine; body buoy; anchor (100 0 -100);"
    " refAttachmentPt (0 0 0); length 150; wetWeight 410.3; EA 500e6;"
    " seabed -100; }"
    " buoyancy { type linearSpring; body buoy; anchor (0 0 1000);"
    " refAttachmentPt (0 0 0); stiffness 5000; damping 0;"
    " restLength 949.772; } }";


//- What the table and the restart see of the restraints: each one's
//  columns, and the restart state's text
struct committedView
{
    List<scalarField> columns;
    std::string restart;
};


committedView view(const RBD::rigidBodyMotion& m)
{
    committedView v;
    v.columns.setSize(m.restraints().size());
    forAll(m.restraints(), ri)
    {
        const RBD::restraint& r = m.restraints()[ri];
        scalarField row(r.tableColumns().size(), Zero);
        label k = 0;
        r.tableValues(row, k);
        v.columns[ri] = row;
    }
    OStringStream os;
    os.precision(17);
    m.writeRestraintStates(os);
    v.restart = os.str();
    return v;
}


//- Trial evaluations of every restraint at the motion's state moved by
//  0.1 m in each degree of freedom and 5 ms on
void trials(const RBD::rigidBodyMotion& m)
{
    RBD::rigidBodyModelState s(m.state());
    forAll(s.q(), i)
    {
        s.q()[i] += 0.1;
    }
    s.t() += 0.5*dt;
    RBD::rigidBodyModelWorkspace ws(m.model());
    m.model().kinematics(s, ws);
    scalarField tau(m.model().nDoF(), Zero);
    Field<spatialVector> fx(m.model().nBodies(), Zero);
    for (const RBD::restraint& r : m.restraints())
    {
        r.restrain(tau, fx, s, ws);
    }
}


//- Five steps of the buoy, its restraints committed at the end; with
//  trials before the commit if asked
autoPtr<RBD::rigidBodyMotion> fiveSteps(const bool trialsFirst)
{
    autoPtr<RBD::rigidBodyMotion> m(test::motion(buoy));
    test::run(m(), dt, 5, [](RBD::rigidBodyMotion&){});
    if (trialsFirst)
    {
        trials(m());
    }
    m->commitRestraints();
    return m;
}


scalar maxRelDiff(const scalarField& a, const scalarField& b)
{
    scalar d = 0;
    forAll(a, i)
    {
        d = max(d, mag(a[i] - b[i])/max(mag(b[i]), scalar(1)));
    }
    return d;
}


void committedStateIsKept()
{
    autoPtr<RBD::rigidBodyMotion> m(fiveSteps(false));
    const committedView before(view(m()));
    check
    (
        before.columns.size() == 3
     && before.columns[0].size() == 2 && before.columns[1].size() == 3
     && before.columns[0][0] > 0 && before.columns[1][0] > 0,
        "the lines give their columns (2 and 3), tensions above 0"
    );

    trials(m());
    const committedView after(view(m()));
    forAll(m->restraints(), ri)
    {
        check
        (
            after.columns[ri] == before.columns[ri],
            "trials after the commit leave the table columns of "
          + m->restraints()[ri].name() + " exactly as they were"
        );
    }
    check
    (
        after.restart == before.restart && before.restart.size() > 100,
        "trials after the commit leave the restart state exactly as it"
        " was (" + std::to_string(before.restart.size()) + " characters)"
    );

    // The trials before the commit
    autoPtr<RBD::rigidBodyMotion> t(fiveSteps(true));
    const committedView tried(view(t()));
    check
    (
        tried.columns[0] == before.columns[0],
        "trials before the commit: the lumpedMassLine's columns exactly"
        " those of a run without them"
    );
    check
    (
        tried.restart == before.restart,
        "trials before the commit: the restart state exactly that of a"
        " run without them"
    );
    checkAbs
    (
        maxRelDiff(tried.columns[1], before.columns[1]), 0, 1e-9,
        "trials before the commit: the catenaryLine's columns those of a"
        " run without them, 1e-9 relative"
    );

    // On from there: the trials change nothing of the motion
    test::run(m(), dt, 5, [](RBD::rigidBodyMotion&){});
    autoPtr<RBD::rigidBodyMotion> clean(fiveSteps(false));
    test::run(clean(), dt, 5, [](RBD::rigidBodyMotion&){});
    scalar dq = 0;
    forAll(clean->state().q(), i)
    {
        dq = max(dq, mag(m->state().q()[i] - clean->state().q()[i]));
    }
    checkAbs
    (
        dq, 0, 1e-9,
        "five steps on, q of the run with trials against one without, 1e-9 m"
    );
}


//- The message of the FatalError that f raises ("" if none)
template<class F>
std::string fatalMessage(F f)
{
    const bool throwing = FatalError.throwExceptions(true);
    std::string message;
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        message = err.message();
    }
    FatalError.throwExceptions(throwing);
    return message;
}


void tableColumns()
{
    RBD::tableRow row;
    row.start();
    row.add("t", 1.0);
    row.add("CofR", vector(1, 2, 3));
    row.add("kineticEnergy", 4.0);
    row.end();

    OStringStream os;
    row.writeHeader(os);
    check
    (
        os.str() == "# t CofR(x y z) kineticEnergy\n",
        "tableRow: the header of the first row, '# t CofR(x y z)"
        " kineticEnergy'"
    );
    check
    (
        row.size() == 5 && row.name(2) == "CofR.y" && row[2] == 2,
        "tableRow: column 3 is CofR.y, 2"
    );

    const std::string renamed = fatalMessage([&]()
    {
        row.start();
        row.add("t", 1.0);
        row.add("v", vector(1, 2, 3));
        row.add("kineticEnergy", 4.0);
        row.end();
    });
    check
    (
        renamed.find("v.x") != std::string::npos
     && renamed.find("CofR.x") != std::string::npos,
        "tableRow: a row naming another column stops with a FatalError"
        " naming both (" + renamed.substr(0, 60) + "...)"
    );

    const std::string shorter = fatalMessage([&]()
    {
        row.start();
        row.add("t", 1.0);
        row.add("CofR", vector(1, 2, 3));
        row.end();
    });
    check
    (
        shorter.find("4 columns") != std::string::npos,
        "tableRow: a row lacking a column stops with a FatalError"
        " counting them"
    );

    const std::string longer = fatalMessage([&]()
    {
        row.start();
        row.add("t", 1.0);
        row.add("CofR", vector(1, 2, 3));
        row.add("kineticEnergy", 4.0);
        row.add("extra", 5.0);
        row.end();
    });
    check
    (
        longer.find("extra") != std::string::npos,
        "tableRow: a row with a column more stops with a FatalError"
        " naming it, not a write past the end"
    );
}

} // End namespace restraintCommitTest


int main(int argc, char *argv[])
{
    restraintCommitTest::committedStateIsKept();
    restraintCommitTest::tableColumns();
    return test::testResult();
}


// ************************************************************************* //
