/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "runProgress.H"
#include <cmath>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::runProgress::intervalDefault = 5;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runProgress::runProgress(const scalar startTime, const scalar interval)
:
    startTime_(startTime),
    interval_(interval),
    lastLine_(0)
{}


Foam::runProgress::runProgress(const Time& runTime)
:
    runProgress
    (
        runTime.startTime().value(),
        runTime.controlDict().getOrDefault<scalar>
        (
            "progressInterval",
            intervalDefault
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::runProgress::percent
(
    const scalar t,
    const scalar endTime
) const
{
    const scalar span = endTime - startTime_;
    return span > 0 ? 100*(t - startTime_)/span : 100;
}


Foam::scalar Foam::runProgress::timeLeft
(
    const scalar t,
    const scalar endTime,
    const scalar wall
) const
{
    const scalar done = t - startTime_;
    if (!(done > 0 && wall > 0))
    {
        return -1;
    }
    // Wall time per simulated time so far, times the simulated time left,
    // from the share done f: numbers in [0, 1] and wall only, so that a
    // tiny step and a far endTime cap the estimate instead of overflowing
    // (the solvers trap overflow)
    const scalar left = max(endTime - t, scalar(0));
    const scalar f = done/(done + left);
    return wall*(1 - f) < f*GREAT ? wall*(1 - f)/f : GREAT;
}


std::string Foam::runProgress::line
(
    const scalar t,
    const scalar endTime,
    const scalar wall,
    const scalar updatesPerSecond
) const
{
    std::ostringstream os;
    os  << "Progress: t = " << t << " s ("
        << std::floor(percent(t, endTime)) << " %), "
        << std::setprecision(3) << updatesPerSecond
        << " particle-updates/s, " << duration(timeLeft(t, endTime, wall))
        << " left";
    return os.str();
}


bool Foam::runProgress::due(const double wall)
{
    if (wall - lastLine_ < interval_)
    {
        return false;
    }
    lastLine_ = wall;
    return true;
}


void Foam::runProgress::update
(
    OSstream& os,
    const Time& runTime,
    const stepTimers& timers
)
{
    const scalar t = runTime.value();
    const scalar endTime = runTime.endTime().value();

    // The one clock reading of the step
    const double wall = timers.elapsed();
    if (due(wall))
    {
        // Flushed: a log followed with tail -f shows it at once
        os  << line(t, endTime, wall, timers.updatesPerSecond(wall)).c_str()
            << endl;
    }

    // At write times but the last step (Time::run()'s test; a hand-off or
    // a stop sets endTime to the current time): the solver's closing line
    // gives that one
    const bool last = !(t < endTime - 0.5*runTime.deltaTValue());
    if (runTime.writeTime() && !last)
    {
        runTime.printExecutionTime(os);
    }
}


std::string Foam::runProgress::duration(const scalar seconds)
{
    if (seconds < 0)
    {
        return "unknown";
    }
    const long long s = std::llround(seconds);
    std::ostringstream os;
    if (s < 60)
    {
        os  << s << " s";
    }
    else if (s < 3600)
    {
        os  << s/60 << " min " << s % 60 << " s";
    }
    else
    {
        os  << s/3600 << " h " << s % 3600/60 << " min";
    }
    return os.str();
}


// ************************************************************************* //
