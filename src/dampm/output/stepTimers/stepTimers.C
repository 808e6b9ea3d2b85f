/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include "IOmanip.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const char* const Foam::stepTimers::names[Foam::stepTimers::nPhases] =
{
    "P2G", "grid", "G2P", "contact", "IO", "other"
};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepTimers::stepTimers()
:
    seconds_(),
    particleUpdates_(0),
    steps_(0),
    start_(clock::now())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

double Foam::stepTimers::elapsed() const
{
    return std::chrono::duration<double>(clock::now() - start_).count();
}


double Foam::stepTimers::updatesPerSecond() const
{
    return updatesPerSecond(elapsed());
}


double Foam::stepTimers::updatesPerSecond(const double seconds) const
{
    return seconds > 0 ? particleUpdates_/seconds : 0;
}


void Foam::stepTimers::report(Ostream& os) const
{
    const double total = elapsed();
    os  << nl << "Time split over " << steps_ << " steps, "
        << total << " s wall time:" << nl;
    double phases = 0;
    for (int p = 0; p < nPhases; ++p)
    {
        phases += seconds_[p];
        if (seconds_[p] > 0)
        {
            os  << "    " << setw(8) << names[p] << ' '
                << setw(12) << seconds_[p] << " s  "
                << setw(6) << 100*seconds_[p]/max(total, 1e-300) << " %"
                << nl;
        }
    }
    os  << "    " << setw(8) << "rest" << ' ' << setw(12) << total - phases
        << " s" << nl
        << "Particle-updates per second: " << updatesPerSecond() << endl;
}


// ************************************************************************* //
