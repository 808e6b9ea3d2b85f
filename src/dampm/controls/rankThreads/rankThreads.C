/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "rankThreads.H"
#include "Pstream.H"
#include <cstdlib>
#include <thread>
#include <omp.h>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::rankThreads::localProcesses()
{
    if (!Pstream::parRun())
    {
        return 1;
    }
    // Open MPI, then MPICH; else every process on one machine
    for (const char* var : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    {
        const char* value = std::getenv(var);
        if (value && std::atoi(value) > 0)
        {
            return std::atoi(value);
        }
    }
    return Pstream::nProcs();
}


void Foam::rankThreads::set(Ostream& os)
{
    if (!Pstream::parRun())
    {
        return;
    }
    const bool given = std::getenv("OMP_NUM_THREADS");
    if (!given)
    {
        // OpenMP's default follows the process's CPU binding (mpirun binds
        // each of 1 or 2 processes to a core): never more than it
        const label cores = max(label(std::thread::hardware_concurrency()), 1);
        const label share = max(cores/localProcesses(), label(1));
        omp_set_num_threads(min(share, label(omp_get_max_threads())));
    }
    os  << "Parallel run: " << Pstream::nProcs() << " processes x "
        << omp_get_max_threads() << " OpenMP threads"
        << (given ? " (OMP_NUM_THREADS)" : " (the machine's cores shared)")
        << nl << endl;
}


// ************************************************************************* //
