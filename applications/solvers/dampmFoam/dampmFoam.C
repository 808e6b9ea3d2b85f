/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    dampmFoam

Group
    grpMPMSolvers

Description
    Depth-averaged Material Point Method (DAMPM) solver for the run-out of
    landslides, mudflows and debris flows over terrain: the shallow-flow
    equations (1) of Fois, Katili et al. with Voellmy bed friction and
    depth-integrated Bingham rheology, on the 2D blockMesh grid.
    The method: doc/dampmFoam-discretisation.md.

    Reads constant/dampmProperties, constant/g and system/controlDict
    (adjustTimeStep, maxCo, maxDeltaT, minDeltaT, progressInterval); writes
    the particle cloud dampmCloud, the grid fields h, U, Z and the hazard
    maps at every write time, and
    postProcessing/dampmFoam/<startTime>/summary.dat every step. The log:
    a line per step, the progress (runProgress) every progressInterval
    seconds of wall time, ExecutionTime at write times.
    With a handOff sub-dictionary it ends the run-out by itself, writing the
    time for depthToParticles3D, at a set time or when the front comes
    within a distance of the 3D region (handOff.H).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmTime.H"
#include "rankThreads.H"
#include "exactPrecision.H"
#include "pointFields.H"
#include "mpmGrid.H"
#include "strictIOdictionary.H"
#include "localIOdictionary.H"
#include "depthAveragedFlow.H"
#include "particleCloudIO.H"
#include "staticFieldIO.H"
#include "hazardMaps.H"
#include "handOff.H"
#include "stepTimers.H"
#include "runProgress.H"
#include "mpmTimeControls.H"
#include "particleMemory.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Depth-averaged MPM solver for landslide and mudflow run-out"
    );

    #include "setRootCaseLists.H"
    const word solverName("dampmFoam");
    #include "createMPMTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    if (startedFromRelease)
    {
        #include "writeFields.H"
        timers.run(stepTimers::IO, [&]{ runTime.writeNow(); });
    }

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        timers.run(stepTimers::P2G, [&]{ flow.particlesToGrid(); });
        timers.run(stepTimers::grid, [&]
        {
            hazard.update(flow.nodes(), flow.activeNodes());
        });

        #include "setMPMDeltaT.H"
        #include "limitWriteDeltaT.H"
        #include "limitHandOffDeltaT.H"

        ++runTime;

        timers.run(stepTimers::P2G, [&]{ flow.computeForces(); });
        timers.run(stepTimers::grid, [&]{ flow.updateGrid(dt); });
        timers.run(stepTimers::G2P, [&]{ flow.gridToParticles(dt); });
        timers.countStep
        (
            returnReduce(flow.particles().size(), sumOp<label>())
        );

        timers.run(stepTimers::IO, [&]
        {
            #include "writeOutput.H"
        });
        if
        (
            handOff3D.due
            (
                runTime.value(), flow.particles(), flow.hField(),
                flow.topography()
            )
        )
        {
            // Written first: the log names the triggering column by its
            // index in the cloud written
            #include "writeFields.H"
            Info<< nl << "Hand-off to the 3D stage at t = "
                << runTime.timeName() << " s: "
                << handOff3D.reason(flow.particles()).c_str() << nl << endl;
            timers.run(stepTimers::IO, [&]{ runTime.writeAndEnd(); });
        }
        else if (runTime.writeTime())
        {
            #include "writeFields.H"
            timers.run(stepTimers::IO, [&]{ runTime.write(); });
        }
        progress.update(Info, runTime, timers);
    }

    // The last time directory, written in the background, finished
    timers.run(stepTimers::IO, [&]{ runTime.finishWrites(); });

    // The event's hazard maps as rasters, once, at the end
    timers.run(stepTimers::IO, [&]{ hazard.writeRasters(runTime); });
    if (!handOff3D.ended())
    {
        handOff3D.reportNotDue(Info);
    }
    const string movedWhat("Columns");
    #include "reportMigration.H"
    flow.resting().report(Info);
    timers.report(Info);
    runTime.printExecutionTime(Info);
    Info<< "End\n" << endl;

    runTime.exitIfStopped();

    return 0;
}


// ************************************************************************* //
