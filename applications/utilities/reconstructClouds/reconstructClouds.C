/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    reconstructClouds

Group
    grpMPMUtilities

Description
    Puts the particle clouds and the run state of a decomposed dampmFoam or
    mpm3dFoam run back together on the undecomposed case, after
    reconstructPar (which reconstructs the mesh fields but cannot read
    dampm's clouds): every processor's cloud in rank order, written as a
    serial run writes it, and uniform/ with the processors' outflows summed
    (processorClouds). decomposeClouds does the reverse. A serial run, depthToParticles3D, ParaView and
    dampmPost then read the case as if it had run serially.

    Times: as reconstructPar (-time, -latestTime, -noZero; all by default);
    each must be complete on every processor.

Usage
    \verbatim
        reconstructPar -withZero -noLagrangian
        reconstructClouds [-latestTime | -time ...]
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "timeSelector.H"
#include "mpmGrid.H"
#include "processorClouds.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Reconstruct dampm's particle clouds and run state of a decomposed"
        " case (after reconstructPar)"
    );
    timeSelector::addOptions(true, true);
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const string noProcessors
    (
        "nothing to reconstruct (decomposePar and a -parallel run make them)"
    );
    #include "createProcessorClouds.H"

    const instantList times = timeSelector::select(clouds.procTimes(), args);
    if (times.empty())
    {
        FatalErrorInFunction
            << "no time of processor0 selected; its times: "
            << clouds.procTimes() << exit(FatalError);
    }
    Info<< "Reconstructing the clouds of " << nProcs << " processors\n"
        << endl;
    for (const instant& t : times)
    {
        runTime.setTime(t, 0);
        Info<< "Time = " << runTime.timeName() << endl;
        clouds.reconstruct();
    }

    Info<< "\nEnd\n" << endl;
    return 0;
}


// ************************************************************************* //
