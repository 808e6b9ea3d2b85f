/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "particleMemory.H"
#include "rankThreads.H"
#include "error.H"
#include <cmath>
#include <fstream>
#include <new>
#include <sys/resource.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// mpm3dFlow: a flag, 3 node velocities (volumetric smoothing) and 3 start
// positions (the barriers' guard); depthAveragedFlow needs less
const double Foam::particleMemory::workBytes = 56;

const double Foam::particleMemory::warnFraction = 0.75;


namespace
{

//- A field of a /proc file ("MemAvailable:", "VmSize:") in bytes, or -1
double procBytes(const char* file, const std::string& field)
{
    std::ifstream is(file);
    std::string key;
    double kB;
    while (is >> key)
    {
        if (key == field && is >> kB)
        {
            return 1024*kB;
        }
        is.ignore(4096, '\n');
    }
    return -1;
}


//- What is left of a resource limit (ulimit -v, -d) above the use now
double leftOfLimit(const int resource, const char* usedField)
{
    rlimit lim;
    if (getrlimit(resource, &lim) != 0 || lim.rlim_cur == RLIM_INFINITY)
    {
        return HUGE_VAL;
    }
    const double used = procBytes("/proc/self/status", usedField);
    return double(lim.rlim_cur) - (used > 0 ? used : 0);
}


//- Released by the out-of-memory handler, so that its message can be made
char* emergencyReserve = nullptr;


void outOfMemory()
{
    std::set_new_handler(nullptr);
    delete[] emergencyReserve;
    emergencyReserve = nullptr;
    FatalErrorInFunction
        << "out of memory: an allocation failed with "
        << Foam::particleMemory::available() << " bytes available"
        << " (MemAvailable of /proc/meminfo within ulimit -v and -d). The"
        << " particle count (particlesPerCell, the release or the initial"
        << " regions), the mesh or a raster is too large for this machine"
        << Foam::exit(Foam::FatalError);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

double Foam::particleMemory::bytesPerParticle
(
    const particleArrays& particles
)
{
    // A double per component and the sort's scratch component, each with
    // the room kept before and after the particles (an eighth), the cell
    // and the sort's order (labels), and the solvers' work arrays
    return
        1.125*sizeof(double)*(particles.nComponentArrays() + 1)
      + 2*sizeof(label) + workBytes;
}


double Foam::particleMemory::available()
{
    const double memAvailable = procBytes("/proc/meminfo", "MemAvailable:");
    const double limit = min
    (
        leftOfLimit(RLIMIT_AS, "VmSize:"),
        leftOfLimit(RLIMIT_DATA, "VmData:")
    );
    return min(memAvailable > 0 ? memAvailable : HUGE_VAL, limit);
}


double Foam::particleMemory::seedsInBox
(
    const gridGeometry& g,
    const label nPerCell,
    const boundBox& box
)
{
    // Per axis: the positions origin + (k + 1/2) s in [min, max], s the
    // spacing, k over the cells this part owns (all of them but on a
    // decomposed grid), nPerCell per cell (one across a plane slice)
    double n = 1;
    for (int d = 0; d < g.dim; ++d)
    {
        const label perCell = g.varies(d) ? nPerCell : 1;
        const double s = g.dx[d]/perCell;
        const double first = (g.offset[d] + g.ownFirst(d))*perCell;
        const double last = (g.offset[d] + g.ownEnd(d))*perCell - 1;
        const double lo =
            max(std::ceil((box.min()[d] - g.origin[d])/s - 0.5), first);
        const double hi =
            min(std::floor((box.max()[d] - g.origin[d])/s - 0.5), last);
        n *= max(hi - lo + 1, 0.0);
    }
    return n;
}


void Foam::particleMemory::reserve
(
    particleArrays& particles,
    const double n,
    const std::string& setBy
)
{
    if (!(n > 0))
    {
        return;
    }
    const double perParticle = bytesPerParticle(particles);
    const double needed = n*perParticle;
    // The processes of a -parallel run on this machine share it
    const double free = available()/rankThreads::localProcesses();
    const double total = particles.size() + n;
    if (total > labelMax || needed > free)
    {
        FatalErrorInFunction
            << n << " particles requested by " << setBy.c_str() << ": "
            << needed << " bytes needed (" << perParticle << " per particle: "
            << particles.nComponentArrays() << " component arrays of 8 bytes, sorting and work"
            << " arrays), " << free << " bytes available (MemAvailable of"
            << " /proc/meminfo within ulimit -v and -d)";
        if (rankThreads::localProcesses() > 1)
        {
            FatalError
                << " for one of the " << rankThreads::localProcesses()
                << " processes of the run on this machine";
        }
        FatalError
            << ". Allowed: at most "
            << min(std::floor(free/perParticle), double(labelMax))
            << " particles (and " << labelMax << " in all, 32-bit labels)"
            << exit(FatalError);
    }
    if (needed > warnFraction*free)
    {
        WarningInFunction
            << n << " particles requested by " << setBy.c_str() << " need "
            << needed << " bytes, " << label(100*needed/free + 0.5)
            << " % of the "
            << free << " bytes available: the run may swap or be stopped"
            << " by the system" << endl;
    }
    particles.reserve(label(total));
}


void Foam::particleMemory::reserve
(
    particleArrays& particles,
    const double n,
    const std::string& setBy,
    const gridGeometry& g,
    const label nPerCell
)
{
    std::string mesh =
        std::to_string(g.nCells[0]) + " x " + std::to_string(g.nCells[1]);
    if (g.dim == 3)
    {
        mesh += " x " + std::to_string(g.nCells[2]);
    }
    reserve
    (
        particles,
        n,
        setBy + ", particlesPerCell " + std::to_string(nPerCell) + " ("
      + std::to_string(label(std::pow(nPerCell, g.dim))) + " per cell) and"
        " the mesh of " + mesh + " cells (system/blockMeshDict)"
    );
}


void Foam::particleMemory::exitOnOutOfMemory()
{
    if (!emergencyReserve)
    {
        emergencyReserve = new char[1 << 20];
    }
    std::set_new_handler(outOfMemory);
}


// ************************************************************************* //
