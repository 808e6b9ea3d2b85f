/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    mpm3dFoam

Group
    grpMPMSolvers

Description
    Explicit 3D Material Point Method solver for the impact of landslides,
    mudflows and debris flows on rigid barriers: update stress last, APIC
    (or FLIP/PIC) transfers on the 3D blockMesh grid, weakly compressible
    fluids (Newtonian, Bingham, Herschel-Bulkley) or solids (linear elastic,
    Drucker-Prager), barriers (planes, boxes, STL surfaces, terrain DTMs)
    with contact at the grid nodes. The method: doc/mpm3dFoam.md.

    Reads constant/mpm3dProperties, constant/g and system/controlDict
    (adjustTimeStep, maxCo, maxDeltaT, minDeltaT, progressInterval); writes
    the particle cloud mpm3dCloud and the node velocity U at every write
    time, and every step postProcessing/mpm3dFoam/<startTime>/summary.dat
    and energy.dat and, for every barrier,
    postProcessing/<barrier>/<startTime>/force.dat (and overtopping.dat when
    it measures overtopping). The log: a line per step, the progress
    (runProgress) every progressInterval seconds of wall time, ExecutionTime
    at write times.
    Runs decomposed (decomposePar, mpirun -np N mpm3dFoam -parallel; rigid
    barriers): every processor one box of the grid and its particles, the
    files written once by the master (doc/parallel.md).
    Started from a conversion (depthToParticles3D), it keeps accumulating
    the run-out's hazard maps on its grid (runOutMaps):
    postProcessing/hazardMaps/<time>/ cover the whole event.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmTime.H"
#include "rankThreads.H"
#include "exactPrecision.H"
#include "pointFields.H"
#include "mpmGrid.H"
#include "strictIOdictionary.H"
#include "localIOdictionary.H"
#include "mpm3dFlow.H"
#include "particleCloudIO.H"
#include "timeSeriesFile.H"
#include "surfaceProbes.H"
#include "stepTimers.H"
#include "runProgress.H"
#include "runOutMaps.H"
#include "mpmTimeControls.H"
#include "particleMemory.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit 3D MPM solver for the impact of flows on barriers"
    );

    #include "setRootCaseLists.H"
    const word solverName("mpm3dFoam");
    #include "createMPMTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    if (startedFromRegions)
    {
        #include "writeFields.H"
        runTime.writeNow();
    }

    Info<< "\nStarting time loop\n" << endl;
    timers.start();

    while (runTime.run())
    {
        timers.run(stepTimers::P2G, [&]{ flow.particlesToGrid(); });

        #include "setMPMDeltaT.H"

        ++runTime;

        timers.run
        (
            stepTimers::contact, [&]{ flow.pushFromMembranes(dt, maxCo); }
        );
        timers.run(stepTimers::grid, [&]{ flow.updateGrid(dt); });
        timers.run(stepTimers::contact, [&]{ flow.contact(dt); });
        timers.run(stepTimers::G2P, [&]
        {
            flow.gridToParticles(dt);
        });
        timers.countStep
        (
            returnReduce(flow.particles().size(), sumOp<label>())
        );

        if (eventMaps)
        {
            timers.run(stepTimers::IO, [&]
            {
                eventMaps->update(flow.particles());
            });
        }

        timers.run(stepTimers::IO, [&]
        {
            flow.monitorBarriers(runTime.value());
            #include "writeOutput.H"
        });
        progress.update(Info, runTime, timers);
    }

    // The last time directory, written in the background, finished
    timers.run(stepTimers::IO, [&]{ runTime.finishWrites(); });

    // The event's hazard maps as rasters, once, at the end
    if (eventMaps)
    {
        timers.run(stepTimers::IO, [&]{ eventMaps->writeRasters(runTime); });
    }
    #include "reportBarriers.H"
    const string movedWhat("Particles");
    #include "reportMigration.H"
    timers.report(Info);
    runTime.printExecutionTime(Info);
    Info<< "End\n" << endl;

    runTime.exitIfStopped();

    return 0;
}


// ************************************************************************* //
