/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "mpmTimeControls.H"
#include "mpmTime.H"
#include "fpTrapsHeld.H"
#include "errorsThrown.H"
#include "IFstream.H"
#include "OSspecific.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const bool Foam::mpmTimeControls::adjustTimeStepDefault = true;

const Foam::scalar Foam::mpmTimeControls::maxCoDefault = 0.4;

const Foam::scalar Foam::mpmTimeControls::minDeltaTDefault = 1e-10;

const Foam::label Foam::mpmTimeControls::maxWrites = 100000;

const Foam::scalar Foam::mpmTimeControls::minClockWriteInterval = 1;


namespace
{

using namespace Foam;

//- The controlDict as a dictionary, read with the floating-point traps off:
//  OpenFOAM's number reader converts a value out of range (1e400) to a
//  double before it rejects it, which traps (SIGFPE). Its rejection, an
//  "ill defined" entry, is reported with what is allowed.
dictionary readUntrapped(const fileName& file)
{
    dictionary dict;
    string failure, failedFile;
    label failedLine = -1;
    try
    {
        const fpTrapsHeld hold;
        const errorsThrown throwing;
        IFstream is(file);
        dict = dictionary(is);
    }
    catch (const IOerror& err)
    {
        failure = err.message();
        failedFile = err.ioFileName();
        failedLine = err.ioStartLineNumber();
    }
    if (!failure.empty())
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, failedFile, failedLine)
            << failure.c_str() << nl << file << " cannot be read: a number"
            << " out of range? Allowed: finite numbers within +-1e300"
            << exit(FatalIOError);
    }
    return dict;
}


//- The finite number of keyword key (found: false when absent), or a
//  FatalIOError naming the file, the keyword, the value and what is allowed
scalar finiteNumber
(
    const dictionary& dict,
    const word& key,
    const std::string& allowed,
    bool& found
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    found = e;
    if (!e)
    {
        return 0;
    }
    if (e->isDict())
    {
        FatalIOErrorInFunction(dict)
            << key << " is a dictionary; allowed: " << allowed.c_str()
            << exit(FatalIOError);
    }
    ITstream& is = e->stream();
    if (is.size() != 1 || !is[0].isNumber())
    {
        FatalIOErrorInFunction(is)
            << key << " = " << static_cast<const tokenList&>(is)
            << " is not a number; allowed: " << allowed.c_str()
            << exit(FatalIOError);
    }
    const scalar value = is[0].number();
    if (!std::isfinite(value))
    {
        FatalIOErrorInFunction(is)
            << key << " = " << value << " is not finite; allowed: "
            << allowed.c_str() << exit(FatalIOError);
    }
    return value;
}


//- What a zero read may have been: OpenFOAM reads values within 1e-300 of
//  zero as 0
const char* zeroNote(const scalar value)
{
    return value == 0 ? " (values within 1e-300 of 0 read as 0)" : "";
}


//- The stream of keyword key, for the position in error messages
const IOstream& where(const dictionary& dict, const word& key)
{
    return dict.findEntry(key, keyType::LITERAL)->stream();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::mpmTimeControls::sameLatestTime
(
    const fileName& caseDir,
    const instantList& times
)
{
    // OpenFOAM's Time starts every processor from its newest directory and
    // stops when they differ; a run killed while writing leaves the newest
    // on some processors only: say which, and what to do
    List<word> latest(Pstream::nProcs());
    latest[Pstream::myProcNo()] =
        times.size() ? times.last().name() : word("none");
    Pstream::gatherList(latest);
    Pstream::scatterList(latest);
    forAll(latest, p)
    {
        if (latest[p] != latest[0])
        {
            FatalErrorInFunction
                << "the processors' newest time directories differ (";
            forAll(latest, q)
            {
                FatalError<< (q ? ", " : "") << "processor" << q << ": "
                    << latest[q];
            }
            FatalError
                << ") in " << caseDir.path() << ". A run stopped while"
                << " writing leaves"
                << " its last time on some processors only, incomplete:"
                << " move those directories away, then restart (startFrom"
                << " latestTime falls back to the latest time complete on"
                << " every processor)" << exit(FatalError);
        }
    }
}


bool Foam::mpmTimeControls::writeInBackground(const dictionary& dict)
{
    const word key("writeInBackground");
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return true;
    }
    ITstream& is = e->stream();
    const token t(is);
    const Switch value
    (
        t.isWord() ? Switch(t.wordToken(), true)
      : t.isBool() ? Switch(t.boolToken())
      : Switch(Switch::INVALID)
    );
    if (!value.valid() || !is.eof())
    {
        FatalIOErrorInFunction(is)
            << key << " " << e->stream().toString().c_str() << " is invalid;"
            << " allowed: yes (the default) or no (on/off, true/false)"
            << exit(FatalIOError);
    }
    return value;
}


void Foam::mpmTimeControls::checkControlDict
(
    const fileName& caseDir,
    const bool run
)
{
    // A processor directory of a decomposed case (-parallel): the case's
    // controlDict, the processor's time directories
    const bool processor = Pstream::parRun();
    const fileName file =
        (processor ? caseDir.path() : caseDir)/"system"/Time::controlDictName;
    if (!isFile(file))
    {
        // Time names the missing file
        return;
    }
    const dictionary dict(readUntrapped(file));
    bool found = false;

    // The start time, as Time::setControls finds it
    const word startFrom =
        dict.getOrDefault<word>("startFrom", "latestTime");
    const wordList startFromNames({"startTime", "firstTime", "latestTime"});
    if (!startFromNames.found(startFrom))
    {
        FatalIOErrorInFunction(where(dict, "startFrom"))
            << "startFrom " << startFrom << " is invalid; allowed: "
            << startFromNames << exit(FatalIOError);
    }
    const scalar startTime =
        finiteNumber(dict, "startTime", "a finite time [s]", found);
    if (startFrom == "startTime" && !found)
    {
        FatalIOErrorInFunction(dict)
            << "startTime is missing (startFrom startTime); allowed: a"
            << " finite time [s]" << exit(FatalIOError);
    }
    scalar start = startTime;
    word startDir;
    if (startFrom != "startTime")
    {
        const instantList times = Time::findTimes(caseDir);
        if (processor && startFrom == "latestTime")
        {
            sameLatestTime(caseDir, times);
        }
        start = 0;
        if (startFrom == "firstTime" && times.size() > 1
         && times.first().name() == "constant")
        {
            startDir = times[1].name();
            start = times[1].value();
        }
        else if (times.size())
        {
            // The latest: mpmTime falls back from an incomplete one
            const label last =
                startFrom == "firstTime"
              ? 0
              : mpmTime::latestStart(caseDir, times);
            if (last >= 0 && times[last].name() != "constant")
            {
                startDir = times[last].name();
                start = times[last].value();
            }
        }
    }

    // The end: endTime with stopAt endTime (the default); with the others
    // Time ignores it and stops at the first step or write
    const word stopAt = dict.getOrDefault<word>("stopAt", "endTime");
    if (!Time::stopAtControlNames.found(stopAt))
    {
        FatalIOErrorInFunction(where(dict, "stopAt"))
            << "stopAt " << stopAt << " is invalid; allowed: "
            << Time::stopAtControlNames.sortedToc() << exit(FatalIOError);
    }
    const bool toEndTime = stopAt == "endTime";
    scalar endTime = finiteNumber
    (
        dict, "endTime", "a finite time after the start time [s]", found
    );
    if (!found && toEndTime)
    {
        FatalIOErrorInFunction(dict)
            << "endTime is missing (stopAt endTime); allowed: a finite time"
            << " after the start time [s]" << exit(FatalIOError);
    }
    if (!toEndTime)
    {
        endTime = GREAT;
    }

    // Steps
    const bool adjustTimeStep =
        dict.getOrDefault<bool>("adjustTimeStep", adjustTimeStepDefault);
    const scalar deltaT =
        finiteNumber(dict, "deltaT", "finite deltaT > 0 [s]", found);
    if (!found)
    {
        FatalIOErrorInFunction(dict)
            << "deltaT is missing; allowed: finite deltaT > 0 [s]"
            << exit(FatalIOError);
    }
    if (!(deltaT > 0))
    {
        FatalIOErrorInFunction(where(dict, "deltaT"))
            << "deltaT = " << deltaT << zeroNote(deltaT) << " is invalid;"
            << " allowed: finite deltaT > 0 [s]" << exit(FatalIOError);
    }
    const scalar maxCo =
        finiteNumber(dict, "maxCo", "0 < maxCo <= 1", found);
    if (found && !(maxCo > 0 && maxCo <= 1))
    {
        FatalIOErrorInFunction(where(dict, "maxCo"))
            << "maxCo = " << maxCo << " is invalid; allowed: 0 < maxCo <= 1"
            << exit(FatalIOError);
    }
    scalar maxDeltaT =
        finiteNumber(dict, "maxDeltaT", "finite maxDeltaT > 0 [s]", found);
    if (!found)
    {
        maxDeltaT = GREAT;
    }
    else if (!(maxDeltaT > 0))
    {
        FatalIOErrorInFunction(where(dict, "maxDeltaT"))
            << "maxDeltaT = " << maxDeltaT << " is invalid; allowed: finite"
            << " maxDeltaT > 0 [s]" << exit(FatalIOError);
    }
    scalar minDeltaT = finiteNumber
    (
        dict, "minDeltaT", "finite 0 <= minDeltaT <= maxDeltaT [s]", found
    );
    if (!found)
    {
        minDeltaT = min(minDeltaTDefault, maxDeltaT);
    }
    else if (!(minDeltaT >= 0 && minDeltaT <= maxDeltaT))
    {
        FatalIOErrorInFunction(where(dict, "minDeltaT"))
            << "minDeltaT = " << minDeltaT << " is invalid; allowed: 0 <="
            << " minDeltaT <= maxDeltaT (" << maxDeltaT << ") [s]; 0: no"
            << " floor of the time step" << exit(FatalIOError);
    }
    if (!adjustTimeStep && deltaT < minDeltaT)
    {
        FatalIOErrorInFunction(where(dict, "deltaT"))
            << "deltaT = " << deltaT << " is below minDeltaT = " << minDeltaT
            << " s with adjustTimeStep off (every step would be deltaT);"
            << " allowed: deltaT >= " << minDeltaT << " [s] (or lower"
            << " minDeltaT)" << exit(FatalIOError);
    }

    // The wall time between the log's progress lines (runProgress)
    const char* const progressAllowed =
        "finite progressInterval >= 0 [s] (0: a progress line every step)";
    const scalar progressInterval =
        finiteNumber(dict, "progressInterval", progressAllowed, found);
    if (found && !(progressInterval >= 0))
    {
        FatalIOErrorInFunction(where(dict, "progressInterval"))
            << "progressInterval = " << progressInterval << " is invalid;"
            << " allowed: " << progressAllowed << exit(FatalIOError);
    }

    // Writes: Time divides by writeInterval and counts the intervals in a
    // label
    const word writeControl =
        dict.getOrDefault<word>("writeControl", "timeStep");
    if (!Time::writeControlNames.found(writeControl))
    {
        FatalIOErrorInFunction(where(dict, "writeControl"))
            << "writeControl " << writeControl << " is invalid; allowed: "
            << Time::writeControlNames.sortedToc() << exit(FatalIOError);
    }
    const Time::writeControls wc = Time::writeControlNames[writeControl];
    const word intervalKey =
        dict.found("writeInterval") || !dict.found("writeFrequency")
      ? "writeInterval" : "writeFrequency";

    std::string allowed;
    scalar lowest = 0;
    scalar highest = GREAT;
    const scalar span = toEndTime ? max(endTime - start, 0.0) : 0;
    switch (wc)
    {
        case Time::wcTimeStep:
            allowed = "a whole number of steps from 1 to "
                + std::to_string(labelMax);
            lowest = 1;
            highest = labelMax;
            break;
        case Time::wcRunTime:
        case Time::wcAdjustableRunTime:
        {
            // At most maxWrites write times to endTime
            lowest = span/maxWrites;
            OStringStream os;
            os  << "writeInterval > 0 [s]";
            if (toEndTime)
            {
                os  << " and at most " << maxWrites << " write times from"
                    << " the start time " << start << " to endTime "
                    << endTime << " (writeInterval >= " << lowest << " s)";
            }
            allowed = os.str();
            break;
        }
        case Time::wcClockTime:
        case Time::wcCpuTime:
            lowest = minClockWriteInterval;
            allowed = "writeInterval >= "
                + std::to_string(label(minClockWriteInterval)) + " [s]";
            break;
        default:
            allowed = "a finite number (unused with writeControl none)";
            lowest = -GREAT;
            break;
    }
    const scalar interval = finiteNumber(dict, intervalKey, allowed, found);
    if (!found)
    {
        FatalIOErrorInFunction(dict)
            << "writeInterval is missing; allowed for writeControl "
            << writeControl << ": " << allowed.c_str() << exit(FatalIOError);
    }
    const bool whole =
        wc != Time::wcTimeStep || interval == std::round(interval);
    if
    (
        !(interval >= lowest && interval <= highest && whole)
     || (wc != Time::wcNone && !(interval > 0))
    )
    {
        FatalIOErrorInFunction(where(dict, intervalKey))
            << intervalKey << " = " << interval << zeroNote(interval)
            << " is invalid for"
            << " writeControl " << writeControl << "; allowed: "
            << allowed.c_str() << exit(FatalIOError);
    }

    writeInBackground(dict);

    // The run: endTime after the start
    if (run && toEndTime && !(endTime > start))
    {
        if (startDir.empty())
        {
            FatalIOErrorInFunction(where(dict, "endTime"))
                << "endTime = " << endTime << " is not after the start time "
                << start << " (startFrom " << startFrom << "): the run would"
                << " take no step; allowed: endTime > " << start
                << exit(FatalIOError);
        }
        FatalIOErrorInFunction(where(dict, "endTime"))
            << "the case already reached endTime = " << endTime
            << ": it starts from its time directory " << startDir
            << " (startFrom " << startFrom << "), so there is nothing to"
            << " run; allowed: endTime > " << start << " to run on"
            << exit(FatalIOError);
    }
}


void Foam::mpmTimeControls::checkFirstStep(const Time& runTime)
{
    const scalar t = runTime.value();
    const scalar dt = runTime.deltaTValue();
    const scalar endTime = runTime.endTime().value();
    if (!(t < endTime - 0.5*dt))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "endTime = " << endTime << " is within half a time step ("
            << dt << " s) of the start time " << t << ": the run would take"
            << " no step (the case has reached endTime); allowed: endTime >= "
            << t + 0.5*dt << exit(FatalIOError);
    }
}


void Foam::mpmTimeControls::checkStep
(
    const scalar dt,
    const word& limit,
    const scalar minDeltaT,
    const scalar maxCo,
    const Time& runTime
)
{
    // isfinite first: an ordered comparison with NaN traps (SIGFPE)
    const bool positive = std::isfinite(dt) && dt > 0;
    if (positive && dt >= minDeltaT)
    {
        return;
    }
    const char* hint =
        limit == "viscous"
      ? "the viscosity (mu; with a yield stress, muMax or m tauY) and the"
        " cell size"
      : "the wave speed (c, E, shearModulus), the speeds and the cell size";
    FatalErrorInFunction
        << "the time step " << dt << " s at t = " << runTime.timeName()
        << " s, set by the " << limit << " limit (maxCo " << maxCo << "), is "
        << (positive ? "below minDeltaT = " : "not a positive finite number")
        << (positive ? Foam::name(minDeltaT) : word::null)
        << (positive ? " s (" : " (")
        << runTime.controlDict().name() << "): the run would not reach"
        << " endTime " << runTime.endTime().value() << " s. Check what sets"
        << " the " << limit << " limit: " << hint << "; or lower minDeltaT"
        << " (0: no floor)"
        << exit(FatalError);
}


// ************************************************************************* //
