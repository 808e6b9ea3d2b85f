/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    depthToParticles3D

Group
    grpMPMUtilities

Description
    Turns the columns of a depth-averaged dampmFoam case into the initial
    3D particles of this mpm3dFoam case (the paper's section 4): run from
    the 3D case, like mapFields,

    \verbatim
        depthToParticles3D ../runOut [-sourceTime 3] [-profile Bagnold]
    \endverbatim

    - reads the columns at the source time (default: the latest), the
      3D case's mesh, material, barriers and ground;
    - refuses, with the reason, an option's value that is not allowed
      (before reading anything), cases whose gravity, material or terrain
      disagree, a missing case or time, no column inside the 3D mesh, and
      particles that would start inside a barrier;
    - converts the columns whose footprint lies inside the 3D mesh
      (columnsTo3D: mass, volume, horizontal momentum and its kinetic
      energy kept to round-off; hydrostatic stress), and counts the others;
      with -merge, the columns smaller than the 3D particle spacing first
      merged per cell of it (columnsTo3D::merge: mass, volume, momentum
      and the horizontal centre of mass kept; the columns in
      conversion.dat are then the merged ones);
    - writes the particles as the cloud mpm3dCloud of this case at the
      source time (the same time name), so that mpm3dFoam (startFrom
      latestTime) carries on the physical time, and the totals to
      postProcessing/depthToParticles3D/<time>/conversion.dat, and the
      run-out's name and time (uniform/runOutMaps), with which mpm3dFoam
      continues the run-out's hazard maps.

    The ground of the 3D case is the highest of its terrain barriers, or
    else its mesh bottom if that is a wall.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmTime.H"
#include "mpmGrid.H"
#include "strictIOdictionary.H"
#include "depthAveragedFlow.H"
#include "mpm3dFlow.H"
#include "terrainGeometry.H"
#include "columnsTo3D.H"
#include "particleCloudIO.H"
#include "timeSeriesFile.H"
#include "runOutMaps.H"
#include "runOutCase.H"
#include "mpmTimeControls.H"
#include "particleMemory.H"
#include "fpTrapsHeld.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Turn the columns of a depth-averaged dampmFoam case into the"
        " initial 3D particles of this mpm3dFoam case"
    );
    argList::noParallel();
    argList::addArgument("sourceCase", "The dampmFoam case");
    argList::addOption
    (
        "sourceTime",
        "time",
        "Time of the columns: a time or latestTime (default)"
    );
    argList::addOption
    (
        "profile",
        "uniform|Bagnold",
        "Vertical profile of the horizontal velocity (default: uniform)"
    );
    argList::addOption
    (
        "verticalVelocity",
        "continuity|bed",
        "Vertical velocity: the depth-averaged flow's, u.grad Z - z' div u"
        " (continuity, default), or the bed's alone, u.grad Z (bed)"
    );
    argList::addOption
    (
        "terrainTolerance",
        "m",
        "Largest difference of the two cases' terrain under the converted"
        " columns (default: a quarter of the 3D cell height)"
    );

    argList::addBoolOption
    (
        "merge",
        "Merge the columns smaller than the 3D particle spacing, per cell of"
        " that spacing, before converting: fewer particles where the run-out"
        " split its columns finer than the 3D stage resolves (mass, volume,"
        " momentum and the horizontal centre of mass kept; the merge logs the"
        " kinetic energy of the velocity differences within a cell)"
    );

    #include "setRootCase.H"
    #include "readOptions.H"

    // The 3D case's time: it writes the start of the 3D run as a complete
    // time directory, whatever that time held before
    mpmTimeControls::checkControlDict(args.path(), false);
    particleMemory::exitOnOutOfMemory();
    Info<< "Create time\n" << endl;
    mpmTime runTime
    (
        Time::controlDictName, args, "depthToParticles3D", false
    );
    #include "createMesh.H"

    #include "createSourceCase.H"
    #include "create3DCase.H"
    #include "checkCases.H"

    columnsTo3D conversion
    (
        grid.bounds(),
        spacing,
        flow3D.material(),
        mag(g.value()),
        columnsTo3D::profileNames[profile],
        ground,
        columnsTo3D::verticalNames[vertical]
    );
    particleArrays particles3D(flow3D.particles());
    // With -merge the merged columns are converted (their storage kept
    // for the conversion), and the flags per column are their source's
    const bool merge = args.found("merge");
    columnsTo3D::mergedColumns merged;
    if (merge)
    {
        merged = conversion.merge(columns.runOut());
        merged.report(Info);
    }
    std::vector<char> converted;
    const columnsTo3D::totals totals = conversion.convert
    (
        merge ? merged.view() : columns.runOut(),
        particles3D, flow3D.stress(), &converted
    );
    if (merge)
    {
        converted = merged.perSource(converted);
    }

    #include "checkConversion.H"

    columnsTo3D::report(totals, Info);

    #include "writeConversion.H"

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
