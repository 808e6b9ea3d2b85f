/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    decomposeClouds

Group
    grpMPMUtilities

Description
    Splits the particle clouds and the run state of a case's time
    directories onto its processor directories, after decomposePar (which
    decomposes the mesh and the fields but cannot write dampm's clouds):
    each particle goes to the processor holding its cell, and uniform/ to
    every processor, the outflows to processor0 alone (processorClouds).
    A decomposed run (mpirun ... -parallel) then continues the time: a
    serial run's restart, or the start depthToParticles3D wrote.
    reconstructClouds does the reverse.

    Times: as decomposePar, the start time (system/controlDict) unless
    -time, -latestTime or -withZero select others; a time
    directory without a run's record (a fresh start) has nothing to
    split, an incomplete one (its run stopped while writing it) is not
    split: both skipped, said so.

Usage
    \verbatim
        decomposePar -force
        decomposeClouds [-latestTime | -time ...]
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "timeSelector.H"
#include "mpmGrid.H"
#include "mpmTime.H"
#include "processorClouds.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Decompose dampm's particle clouds and run state onto the processor"
        " directories (after decomposePar)"
    );
    timeSelector::addOptions(true, true);
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const string noProcessors("run decomposePar first");
    #include "createProcessorClouds.H"

    // As decomposePar: the start time, unless times are selected
    const instantList times = timeSelector::selectIfPresent(runTime, args);

    Info<< "Decomposing the clouds onto " << nProcs << " processors\n"
        << endl;
    for (const instant& t : times)
    {
        runTime.setTime(t, 0);
        Info<< "Time = " << runTime.timeName() << endl;
        switch (mpmTime::state(runTime.timePath()))
        {
            case mpmTime::directoryState::fresh:
            {
                Info<< "    a fresh start (no run's record): nothing to"
                    << " split" << endl;
                break;
            }
            case mpmTime::directoryState::incomplete:
            {
                Info<< "    incomplete (its run was stopped while writing"
                    << " it): not split; a run starts from the last"
                    << " complete time" << endl;
                break;
            }
            case mpmTime::directoryState::complete:
            {
                clouds.decompose();
                break;
            }
        }
    }

    Info<< "\nEnd\n" << endl;
    return 0;
}


// ************************************************************************* //
