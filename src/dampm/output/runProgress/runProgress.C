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

const Foam::scalar Foam::runProgress::minRateWindow = 60;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

double Foam::runProgress::rateWindow(const double wall)
{
    return max(minRateWindow, 0.5*wall);
}


size_t Foam::runProgress::rateLine(const double wall) const
{
    const double window = rateWindow(wall);
    size_t i = 0;
    while (i + 1 < recent_.size() && wall - recent_[i + 1].first >= window)
    {
        ++i;
    }
    return i;
}


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


void Foam::runProgress::record(const double wall, const scalar t)
{
    // Lines a hundredth of the window apart at most: a line every step
    // (progressInterval 0) keeps a few hundred, not half the run's steps
    if
    (
        recent_.empty()
     || wall - recent_.back().first >= 0.01*rateWindow(wall)
    )
    {
        recent_.emplace_back(wall, t);
    }
    // The lines before the rate's are not needed again: the window's start
    // only moves on
    recent_.erase(recent_.begin(), recent_.begin() + rateLine(wall));
}


Foam::scalar Foam::runProgress::timeLeft
(
    const scalar t,
    const scalar endTime,
    const scalar wall
) const
{
    // The rate since the latest line at least a window before, or since
    // the start
    const size_t i = rateLine(wall);
    const bool windowed =
        !recent_.empty() && wall - recent_[i].first >= rateWindow(wall);
    const double wall0 = windowed ? recent_[i].first : 0;
    const scalar done = t - (windowed ? recent_[i].second : startTime_);
    const scalar elapsed = wall - wall0;
    if (!(done > 0 && elapsed > 0))
    {
        return -1;
    }
    // Wall time per simulated time, times the simulated time left, from
    // the share f of the two: numbers in [0, 1] and elapsed only, so that a
    // tiny step and a far endTime cap the estimate instead of overflowing
    // (the solvers trap overflow)
    const scalar left = max(endTime - t, scalar(0));
    const scalar f = done/(done + left);
    return elapsed*(1 - f) < f*GREAT ? elapsed*(1 - f)/f : GREAT;
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
        // Kept for the rate of the time left
        record(wall, t);
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
