/*---------------------------------------------------------------------------*\
Application
    rigidBodySim

Group
    grpRigidBodyDynamicsUtilities

Description
    Runs a rigid-body model from its dictionary, with no fluid: a dry run of
    the mechanism of a floating-body case, or a multibody simulation.

    The coefficients come from the rigidBodyMotionCoeffs sub-dictionary of
    constant/dynamicMeshDict (so an interDyMFoam case runs unchanged, without
    its fluid), or else from the top level of constant/rigidBodyMotionDict.
    Gravity is their g entry, or else constant/g.  system/controlDict gives
    deltaT, endTime and the write controls.

    Prints "Time = t" and the status block of every body named in bodies
    (merged bodies included), first for the initial state and then after
    every step.  Writes, for every body, the table
        postProcessing/rigidBodySim/<startTime>/<body>.dat
    of time, centre of rotation, orientation, linear and angular velocity,
    the body's joint positions q and velocities qDot, and its kinetic and
    potential energy.  At every write time the model state is written to
    <time>/uniform/rigidBodyMotionState; a run started from a written time
    (startFrom latestTime) continues from that state.

Usage
    rigidBodySim [-case DIR]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "rigidBodyMotion.H"
#include "jointBody.H"
#include "rigidBodySimInput.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

//- The joint slots that move a body of the tree: its own joint's and those
//  of the jointBodies of its composite joint
labelList bodySlots(const RBD::rigidBodyModel& model, const label bodyID)
{
    DynamicList<label> slots;

    label i = model.masterID(bodyID);
    while (i > 0)
    {
        const RBD::joint& J = model.joints()[i];
        for (label k = J.nDoF() - 1; k >= 0; --k)
        {
            slots.append(J.qIndex() + k);
        }

        i = model.lambda()[i];
        if (!isA<RBD::jointBody>(model.bodies()[i]))
        {
            break;
        }
    }

    labelList result(slots.size());
    forAll(slots, k)
    {
        result[k] = slots[slots.size() - 1 - k];
    }
    return result;
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Runs a rigid-body model from its dictionary, with no fluid"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    Sout.precision(IOstream::defaultPrecision());

    if (!(runTime.deltaTValue() > 0))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry deltaT " << runTime.deltaTValue()
            << " must be positive" << nl
            << exit(FatalIOError);
    }

    const dictionary coeffs(readCoeffs(runTime));

    // The written state of the start time, for a restart
    IOobject stateIO
    (
        "rigidBodyMotionState",
        runTime.timeName(),
        "uniform",
        runTime,
        IOobject::READ_IF_PRESENT,
        IOobject::NO_WRITE,
        false
    );

    autoPtr<RBD::rigidBodyMotion> motionPtr;

    if (stateIO.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary stateDict(stateIO);
        Info<< "Restarting from " << stateDict.objectPath() << nl << endl;
        motionPtr.reset(new RBD::rigidBodyMotion(coeffs, stateDict));
    }
    else
    {
        motionPtr.reset(new RBD::rigidBodyMotion(coeffs));
        motionPtr->state().t() = runTime.value();
    }

    RBD::rigidBodyMotion& motion = motionPtr();
    motion.setG(readG(runTime, coeffs));

    Info<< "Model: " << motion.bodyNames().size() - 1 << " bodies, "
        << motion.nDoF() << " degrees of freedom, g " << motion.g() << nl
        << endl;

    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);

    motion.initialAcceleration(tau, fx);
    motion.newTime();

    // Bodies to report, in the order of the dictionary
    const wordList names(coeffs.subDict("bodies").toc());
    labelList bodyIDs(names.size());
    List<labelList> slots(names.size());
    forAll(names, bi)
    {
        bodyIDs[bi] = motion.bodyID(names[bi]);
        slots[bi] = bodySlots(motion, bodyIDs[bi]);
    }

    // Tables
    const fileName tableDir
    (
        runTime.globalPath()/"postProcessing"/"rigidBodySim"
       /runTime.timeName()
    );
    mkDir(tableDir);

    PtrList<OFstream> tables(names.size());
    forAll(names, bi)
    {
        tables.set(bi, new OFstream(tableDir/names[bi] + ".dat"));
        OFstream& os = tables[bi];
        os.precision(IOstream::defaultPrecision());
        os  << "# Motion of body " << names[bi] << nl
            << "# t CofR(x y z) Orientation(xx xy xz yx yy yz zx zy zz)"
            << " v(x y z) omega(x y z)";
        forAll(slots[bi], k)
        {
            os << " q" << slots[bi][k];
        }
        forAll(slots[bi], k)
        {
            os << " qDot" << slots[bi][k];
        }
        os  << " kineticEnergy potentialEnergy" << nl;
    }

    auto report = [&]()
    {
        Info<< "Time = " << runTime.timeName() << endl;

        const RBD::rigidBodyModelWorkspace& ws = motion.workspace();

        forAll(names, bi)
        {
            const label id = bodyIDs[bi];
            motion.status(id);

            const spatialTransform X(motion.X0(id));
            const spatialVector v(motion.v(id, Zero));
            const label master = motion.masterID(id);
            const RBD::rigidBody& body = motion.bodies()[master];

            OFstream& os = tables[bi];
            os  << runTime.value();
            for (const scalar s : X.r()) os << ' ' << s;
            for (const scalar s : X.E()) os << ' ' << s;
            for (const scalar s : v.l()) os << ' ' << s;
            for (const scalar s : v.w()) os << ' ' << s;
            for (const label k : slots[bi]) os << ' ' << motion.state().q()[k];
            for (const label k : slots[bi])
            {
                os << ' ' << motion.state().qDot()[k];
            }
            os  << ' ' << body.kineticEnergy(ws.v[master])
                << ' '
                << -body.m()
                   *(motion.g() & motion.globalPoint(master, body.c(), ws))
                << nl;
        }
    };

    report();

    while (runTime.run())
    {
        ++runTime;

        motion.newTime();
        for (label iter = 0; iter < motion.nIter(); ++iter)
        {
            motion.solve
            (
                runTime.value(),
                runTime.deltaTValue(),
                tau,
                fx
            );
        }

        report();

        if (runTime.writeTime())
        {
            const fileName dir(runTime.timePath()/"uniform");
            mkDir(dir);
            OFstream os(dir/"rigidBodyMotionState");
            IOobject io
            (
                "rigidBodyMotionState",
                runTime.timeName(),
                "uniform",
                runTime
            );
            io.writeHeader(os, IOdictionary::typeName);
            motion.state().write(os);
            IOobject::writeEndDivider(os);
        }
    }

    Info<< "End" << nl << endl;

    return 0;
}
