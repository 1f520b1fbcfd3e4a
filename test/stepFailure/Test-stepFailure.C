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
    Test-stepFailure

Description
    The driver that both front-ends use (Foam::RBD::rigidBodyDriver) stops a
    run that goes wrong with a FatalError, never a signal, with OpenFOAM's
    floating-point traps on as a CFD solver has them (FOAM_SIGFPE):
    - the traps that were on are on again after the driver's construction
      and after every solve (floatingPointTraps gives them back);
    - a non-finite external (fluid) force is refused before the solve, the
      message naming the body, the fluid force and the time;
    - a finite but huge external force that overflows the state stops the
      step with a message naming the quantity, the body and the time, not
      with SIGFPE;
    - each failure writes the last good state (the start of the failed
      step), finite, where the message says.
    FatalError is made to throw here, so that one process can see several
    failures.  The case is made in a temporary directory.

\*---------------------------------------------------------------------------*/

#include "testCheck.H"
#include "testModels.H"
#include "rigidBodyDriver.H"
#include "Time.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IFstream.H"

#include <cfenv>
#include <cstdlib>

using namespace Foam;

namespace
{

//- A one-body model: a box on a floating joint
const char* coeffs =
    "solver { type Newmark; }"
    "g (0 0 -9.81);"
    "accelerationRelaxationType constant;"
    "bodies"
    "{"
    "    box"
    "    {"
    "        type cuboid; parent root; mass 0.001; L (0.2 0.2 0.2);"
    "        centreOfMass (0 0 0);"
    "        transform (1 0 0 0 1 0 0 0 1) (0 0 0);"
    "        joint { type floating; }"
    "    }"
    "}";

//- The message of a FatalError thrown by f, or "" if none was
template<class F>
std::string failure(F f)
{
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        return err.message();
    }
    return "";
}

bool has(const std::string& msg, const std::string& word)
{
    return msg.find(word) != std::string::npos;
}

//- Whether the last good state was written and is finite
bool lastGoodFinite(const fileName& path)
{
    if (!isFile(path))
    {
        return false;
    }
    IFstream is(path);
    const dictionary dict(is);
    for (const word key : {"q", "qDot"})
    {
        for (const scalar x : dict.get<scalarField>(key))
        {
            if (!std::isfinite(x))
            {
                return false;
            }
        }
    }
    return dict.found("t");
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    // A case: system/controlDict only
    char dirTemplate[] = "/tmp/Test-stepFailure.XXXXXX";
    const fileName root(mkdtemp(dirTemplate));
    const fileName caseDir(root/"case");
    mkDir(caseDir/"system");
    {
        OFstream os(caseDir/"system"/"controlDict");
        os  << "FoamFile { version 2.0; format ascii; class dictionary;"
            << " object controlDict; }" << nl
            << "startFrom startTime; startTime 0; stopAt endTime;"
            << " endTime 1; deltaT 0.01; writeControl timeStep;"
            << " writeInterval 100;" << nl;
    }

    Time runTime(Time::controlDictName, root, fileName("case"));

    FatalError.throwExceptions();

    // The traps a CFD solver runs with
    const int traps = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;
    feenableexcept(traps);

    RBD::rigidBodyDriver driver
    (
        runTime,
        test::dictFromString(coeffs),
        "stepFailure",
        true
    );
    test::check
    (
        fegetexcept() == traps,
        "the traps are on again after the driver's construction"
    );

    const RBD::rigidBodyModel& model = driver.model();
    const label box = model.bodyID("box");
    const fileName lastGood
    (
        caseDir/"postProcessing"/"stepFailure"/"0"
       /"rigidBodyMotionState.lastGood"
    );

    Field<spatialVector> fx(model.nBodies(), Zero);

    // A good step
    ++runTime;
    fx[box] = spatialVector(Zero, vector(0, 0, 0.00981));
    std::string msg = failure([&]{ driver.solve(fx, true); });
    test::check(msg.empty(), "a finite force: the step is solved");
    test::check
    (
        fegetexcept() == traps,
        "the traps are on again after a solve"
    );

    // A non-finite fluid force
    ++runTime;
    fx[box] = spatialVector(Zero, vector(0, std::nan(""), 0));
    msg = failure([&]{ driver.solve(fx, true); });
    test::check
    (
        has(msg, "external (fluid) force") && has(msg, "body box")
     && has(msg, "t = 0.02"),
        "a nan fluid force: a FatalError naming it, the body and the time"
        " (" + msg.substr(0, 120) + ")"
    );
    test::check
    (
        lastGoodFinite(lastGood) && has(msg, lastGood),
        "a nan fluid force: the last good state written, finite, and named"
    );
    test::check
    (
        fegetexcept() == traps,
        "the traps are on again after the failure"
    );
    rm(lastGood);

    // A finite force that overflows the accelerations (1e308 N on 1 g)
    fx[box] = spatialVector(Zero, vector(1e308, 0, 0));
    msg = failure([&]{ driver.solve(fx, true); });
    test::check
    (
        has(msg, "The step from t = 0.01 to 0.02 gave")
     && has(msg, "of the joint of body box"),
        "a force of 1e308 N on 1 g: a FatalError naming the quantity, the"
        " body and the time, not a signal (" + msg.substr(0, 160) + ")"
    );
    test::check
    (
        lastGoodFinite(lastGood),
        "a force of 1e308 N: the last good state written and finite"
    );
    test::check
    (
        fegetexcept() == traps,
        "the traps are on again after the failure"
    );

    fedisableexcept(FE_ALL_EXCEPT);
    rmDir(root);

    return test::testResult();
}
