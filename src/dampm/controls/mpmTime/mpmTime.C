/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "mpmTime.H"
#include <cmath>
#include "argList.H"
#include "localIOdictionary.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "exactPrecision.H"
#include "errorsThrown.H"
#include "mpmTimeControls.H"

#include <fstream>
#include <zlib.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::mpmTime::recordName("writeComplete");

volatile std::sig_atomic_t Foam::mpmTime::stopSignal_ = 0;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpmTime::catchStop(int sig)
{
    stopSignal_ = sig;
    // A second signal, any of them, stops at once
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGUSR1, SIG_DFL);
}


void Foam::mpmTime::catchStopSignals()
{
    struct sigaction action{};
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    action.sa_handler = catchStop;
    // SIGUSR1 too: mpirun forwards it to every process (a SIGTERM to
    // mpirun kills them)
    for (const int sig : {SIGTERM, SIGINT, SIGUSR1})
    {
        sigaction(sig, &action, nullptr);
    }
    // A file-size limit fails the write like a full disk (the write is
    // checked) instead of killing the process in the middle of it
    std::signal(SIGXFSZ, SIG_IGN);
}


void Foam::mpmTime::checkStartTime()
{
    // OpenFOAM may name the start time at timePrecision ("2.016") when its
    // directory took more digits ("2.015995", a stop's): without the
    // directory's name the run would take it for a fresh start
    const instantList all(times());
    if (!isDir(timePath()))
    {
        for (const instant& t : all)
        {
            // (OpenFOAM lists constant/ as a time 0)
            if (t.name() != constant() && sameTime(t.value(), value()))
            {
                setTime(t, timeIndex());
                break;
            }
        }
    }
    const fileName dir(timePath());
    label here = -1;
    forAll(all, i)
    {
        here = all[i].name() == timeName() ? i : here;
    }
    const directoryState s =
        here < 0 ? state(dir) : state(path(), all, here);
    if (s != directoryState::incomplete)
    {
        startAt(all, s == directoryState::fresh ? freshStart : ownStart);
        return;
    }

    // Incomplete: the last complete time directory before it
    const label previous = lastCompleteBefore(path(), all, value());
    const word startFrom =
        controlDict().getOrDefault<word>("startFrom", "latestTime");
    if (startFrom != "latestTime" || previous < 0)
    {
        FatalErrorInFunction
            << "time directory " << dir << " is incomplete: it has no uniform/"
            << recordName << " (the run that wrote it was stopped while"
            << " writing, or the disk was full; or dampm wrote it before these"
            << " records: doc/faults.md), so it cannot be restarted from. ";
        if (previous < 0)
        {
            FatalError
                << "No complete time directory precedes it: remove it and"
                << " start again";
        }
        else
        {
            FatalError
                << "The last complete time directory is "
                << all[previous].name() << ": set startFrom latestTime (it"
                << " falls back to it) or startTime " << all[previous].name()
                << " in " << path()/system()/controlDictName;
        }
        FatalError << exit(FatalError);
    }

    WarningInFunction
        << "time directory " << timeName() << " is incomplete (no uniform/"
        << recordName << ": the run that wrote it was stopped while writing,"
        << " or the disk was full). Starting from " << all[previous].name()
        << ", the last complete time directory; " << timeName()
        << " is written again when the run reaches it" << nl << endl;
    startAt(all, previous);
}


void Foam::mpmTime::startAt(const instantList& all, const label from)
{
    if (Pstream::parRun())
    {
        agreeStartTime(all, from);
    }
    else if (from >= 0)
    {
        this->startFrom(all[from]);
    }
    else if (from == ownStart)
    {
        continueStart();
    }
}


void Foam::mpmTime::continueStart()
{
    startWriter_ = writer(timePath());
    lastComplete_ = timeName();
    continueRun();
}


bool Foam::mpmTime::sameTime(const scalar a, const scalar b)
{
    // (instant::equal's absolute SMALL is below half the spacing of
    // doubles from 8 s on: 30 would not equal 30)
    return mag(a - b) <= 1e-12*max(scalar(1), mag(b));
}


void Foam::mpmTime::agreeStartTime(const instantList& all, const label from)
{
    // A processor stopped while writing has an earlier complete time than
    // the others: all of them start from the earliest start. Time::setTime
    // reads collectively: either every processor continues its own start
    // directory or every one starts from the common time
    const bool fresh = from == freshStart;
    if (returnReduce(fresh, orOp<bool>()) != returnReduce(fresh, andOp<bool>()))
    {
        FatalErrorInFunction
            << "the start directory " << timeName() << " is "
            << (fresh ? "fresh (no output)" : "written") << " on processor"
            << Pstream::myProcNo() << " but not on every processor (a run"
            << " killed while writing its start): remove the processors'"
            << " time directories " << timeName() << " and start again"
            << exit(FatalError);
    }
    const scalar mine = from >= 0 ? all[from].value() : value();
    const scalar common = returnReduce(mine, minOp<scalar>());
    const bool own = from < 0 && sameTime(mine, common);
    if (returnReduce(own, andOp<bool>()))
    {
        if (from == ownStart)
        {
            continueStart();
        }
        return;
    }
    forAll(all, i)
    {
        if
        (
            all[i].name() != constant() && sameTime(all[i].value(), common)
         && state(path(), all, i) == directoryState::complete
        )
        {
            if (!sameTime(mine, common))
            {
                WarningInFunction
                    << "processor" << Pstream::myProcNo() << " starts from"
                    << " time " << all[i].name() << " instead of "
                    << (from >= 0 ? all[from].name() : timeName()) << ": the"
                    << " latest time directory complete on every processor"
                    << nl << endl;
            }
            this->startFrom(all[i]);
            return;
        }
    }
    FatalErrorInFunction
        << "time " << common << " (the latest start of every processor) is"
        << " not a complete time directory of " << path() << ": the"
        << " processors' time directories do not match. Decompose the case"
        << " again (decomposePar -force) from a complete time"
        << exit(FatalError);
}


void Foam::mpmTime::startFrom(const instant& t)
{
    // As Time::setControls: deltaT from the directory only when the
    // controlDict adjusts it
    const scalar dtControl = deltaT_;
    setTime(t, 0);
    if (!isAdjustTimeStep())
    {
        deltaT_ = dtControl;
    }
    deltaTSave_ = deltaT_;
    startTime_ = value();
    startedAt_ = value();
    startTimeIndex_ = timeIndex_;
    startWriter_ = writer(timePath());
    lastComplete_ = timeName();
    continueRun();
}


void Foam::mpmTime::continueRun()
{
    // The exact time (the directory's name is rounded to timePrecision)
    {
        IFstream is(timePath()/"uniform"/"time");
        const dictionary timeDict(is);
        scalar exact = 0;
        if (timeDict.readIfPresent("value", exact))
        {
            value() = userTimeToTime(exact);
            startedAt_ = value();
        }
    }
    // The schedule of a run of this application (not of a conversion)
    if
    (
        !restart()
     || (writeControl_ != wcRunTime && writeControl_ != wcAdjustableRunTime)
    )
    {
        return;
    }
    IFstream is(timePath()/"uniform"/recordName);
    const dictionary record(is);
    if
    (
        record.getOrDefault<word>("writeControl", word::null)
     == writeControlNames[writeControl_]
     && record.getOrDefault<scalar>("writeInterval", -1) == writeInterval_
    )
    {
        startTime_ = record.get<scalar>("scheduleStart");
        writeTimeIndex_ = record.get<label>("writeTimeIndex");
    }
}


Foam::fileNameList Foam::mpmTime::cutShort
(
    const fileName& dir,
    const double since
)
{
    fileNameList broken;
    for (const fileName& f : readDir(dir, fileName::FILE, false))
    {
        const fileName file(dir/f);
        if (highResLastModified(file) >= since && !whole(file))
        {
            broken.append(file);
        }
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY))
    {
        broken.append(cutShort(dir/d, since));
    }
    return broken;
}


bool Foam::mpmTime::writeRecord() const
{
    localIOdictionary record
    (
        IOobject
        (
            recordName,
            timeName(),
            "uniform",
            *this,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    // The write schedule too, which a restart continues (exactly:
    // dictionary entries keep a value as printed)
    const exactPrecision exact;
    record.add("application", application_);
    record.add("writeControl", writeControlNames[writeControl_]);
    record.add("writeInterval", writeInterval_);
    record.add("scheduleStart", startTime_);
    record.add("writeTimeIndex", writeTimeIndex_);
    return
        record.regIOobject::writeObject
        (
            IOstream::ASCII,
            IOstream::currentVersion,
            IOstream::UNCOMPRESSED,
            true
        )
     && (backgroundWriter::collecting() || whole(record.objectPath()));
}


void Foam::mpmTime::purgeOldTimes() const
{
    if (!purgeWrite_)
    {
        return;
    }
    if (previousWriteTimes_.empty() || previousWriteTimes_.top() != timeName())
    {
        previousWriteTimes_.push(timeName());
    }
    while (previousWriteTimes_.size() > purgeWrite_)
    {
        const fileName old(path()/previousWriteTimes_.pop());
        backgroundWriter* collector = backgroundWriter::collecting();
        if (collector)
        {
            collector->add
            ({backgroundWriter::operation::kind::removeDir, old, ""});
        }
        else
        {
            rmDir(old);
        }
    }
}


void Foam::mpmTime::writeInBackground
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    // Formatted here, written by the writer's thread in the order
    // collected: the record last, and the purge after it
    string failure;
    bool collected = false;
    {
        const backgroundWriter::collection collecting(*writer_);
        try
        {
            const errorsThrown throwing;
            collected =
                writeTimeDict()
             && objectRegistry::writeObject(fmt, ver, cmp, valid)
             && writeRecord();
        }
        catch (const IOerror& e)
        {
            failure = e.ioFileName() + ": " + e.message();
        }
        catch (const error& e)
        {
            failure = e.message();
        }
        if (collected)
        {
            purgeOldTimes();
            writer_->submit();
            writing_ = timeName();
        }
        else
        {
            // A file written as it came: the C library's reason
            const std::string why = writer_->collectedFailure();
            failure = why.empty() ? failure : string(why);
        }
    }
    if (!collected)
    {
        cannotWrite(timePath(), failure);
    }
}


void Foam::mpmTime::cannotWrite
(
    const fileName& dir,
    const std::string& why
) const
{
    FatalErrorInFunction
        << "cannot write time directory " << dir << ": "
        << (why.empty() ? "a file could not be written" : why.c_str())
        << " (disk full, or the directory not writable?). The run stops;"
        << " the last complete time directory is "
        << (lastComplete_.empty() ? word("none") : lastComplete_)
        << ", and a restart (startFrom latestTime) starts from it"
        << exit(FatalError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpmTime::mpmTime
(
    const word& ctrlDictName,
    const argList& args,
    const word& application,
    const bool solver
)
:
    Time(ctrlDictName, args),
    application_(application),
    startedAt_(startTime_),
    stopAnnounced_(false)
{
    if (solver)
    {
        catchStopSignals();
        checkStartTime();
    }
    if
    (
        solver && !Pstream::parRun()
     && isA<backgroundFileOperation>(fileHandler())
     && mpmTimeControls::writeInBackground(controlDict())
    )
    {
        writer_.reset(new backgroundWriter());
    }
    if (solver)
    {
        Info<< "Time directories written "
            << (writer_ ? "in the background" : "by the solver's thread")
            << nl << endl;
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::mpmTime::~mpmTime()
{
    // The solvers finish their writes first; here (a run ended otherwise)
    // not through finishWrites, whose FatalError may be thrown
    if (writer_ && !writing_.empty())
    {
        const std::string failure = writer_->wait();
        if (!failure.empty())
        {
            std::cerr << failure << std::endl;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::mpmTime::directoryState Foam::mpmTime::state(const fileName& timeDir)
{
    const fileName record(timeDir/"uniform"/recordName);
    if (isFile(record) && whole(record))
    {
        return directoryState::complete;
    }
    if
    (
        isFile(record)
     || isFile(timeDir/"uniform"/"time")
     || isDir(timeDir/"lagrangian")
    )
    {
        return directoryState::incomplete;
    }
    return directoryState::fresh;
}


Foam::mpmTime::directoryState Foam::mpmTime::state
(
    const fileName& caseDir,
    const instantList& times,
    const label i
)
{
    const directoryState s = state(caseDir/times[i].name());
    return
        s == directoryState::fresh
     && lastCompleteBefore(caseDir, times, times[i].value()) >= 0
      ? directoryState::incomplete
      : s;
}


Foam::label Foam::mpmTime::lastCompleteBefore
(
    const fileName& caseDir,
    const instantList& times,
    const scalar t
)
{
    label previous = -1;
    forAll(times, i)
    {
        if
        (
            times[i].name() != "constant"
         && times[i].value() < t
         && state(caseDir/times[i].name()) == directoryState::complete
        )
        {
            previous = i;
        }
    }
    return previous;
}


Foam::label Foam::mpmTime::latestStart
(
    const fileName& caseDir,
    const instantList& times
)
{
    const label last = times.size() - 1;
    if (last < 0 || times[last].name() == "constant")
    {
        return -1;
    }
    return
        state(caseDir, times, last) == directoryState::incomplete
      ? lastCompleteBefore(caseDir, times, times[last].value())
      : last;
}


Foam::word Foam::mpmTime::writer(const fileName& timeDir)
{
    if (state(timeDir) != directoryState::complete)
    {
        return word::null;
    }
    IFstream is(timeDir/"uniform"/recordName);
    const dictionary record(is);
    return record.getOrDefault<word>("application", word::null);
}


bool Foam::mpmTime::whole(const fileName& file)
{
    static const std::string divider = []
    {
        OStringStream os;
        IOobject::writeEndDivider(os);
        std::string s(os.str());
        return s.substr(s.find_first_not_of("\n"));
    }();

    // The last bytes of the file (decompressed)
    std::string tail;
    const std::size_t keep = 2*divider.size();
    if (file.hasExt("gz"))
    {
        gzFile gz = gzopen(file.c_str(), "rb");
        if (!gz)
        {
            return false;
        }
        char buffer[65536];
        int n = 0;
        while ((n = gzread(gz, buffer, sizeof(buffer))) > 0)
        {
            tail.append(buffer, n);
            if (tail.size() > 4*keep)
            {
                tail.erase(0, tail.size() - keep);
            }
        }
        int status = Z_OK;
        gzerror(gz, &status);
        gzclose(gz);
        if (n < 0 || (status != Z_OK && status != Z_STREAM_END))
        {
            return false;
        }
    }
    else
    {
        std::ifstream is(file, std::ios::binary | std::ios::ate);
        if (!is)
        {
            return false;
        }
        const std::streamoff size = is.tellg();
        const std::streamoff start = std::max<std::streamoff>(0, size - keep);
        tail.resize(size - start);
        is.seekg(start);
        is.read(&tail[0], tail.size());
        if (!is)
        {
            return false;
        }
    }
    return
        tail.size() >= divider.size()
     && tail.compare(tail.size() - divider.size(), divider.size(), divider)
     == 0;
}


Foam::dimensionedScalar Foam::mpmTime::startTime() const
{
    return dimensionedScalar("startTime", dimTime, startedAt_);
}


void Foam::mpmTime::exitIfStopped() const
{
    // A signal after the last step's start stopped nothing
    if (stopAnnounced_)
    {
        Info<< "Stopped by signal " << int(stopSignal_) << " at time "
            << timeName() << " (written): exit code " << 128 + stopSignal_
            << endl;
        Pstream::exit(128 + stopSignal_);
    }
}


Foam::Time& Foam::mpmTime::operator++()
{
    // Every processor of a decomposed run stops at the same step
    label signal = stopSignal_;
    if (Pstream::parRun())
    {
        reduce(signal, maxOp<label>());
    }
    if (signal && !stopAnnounced_)
    {
        stopSignal_ = signal;
        stopAnnounced_ = true;
        Info<< nl << "Caught signal " << int(stopSignal_) << " ("
            << (
                   stopSignal_ == SIGTERM ? "SIGTERM"
                 : stopSignal_ == SIGINT ? "SIGINT" : "SIGUSR1"
               )
            << "): this"
            << " step is the last, and it is written" << nl << endl;
        stopAt(stopAtControls::saWriteNow);
    }
    return Time::operator++();
}


void Foam::mpmTime::limitDeltaT(const scalar dtMax)
{
    if (!(deltaT_ > dtMax))
    {
        return;
    }
    scalar dt = dtMax;
    if (writeControl_ == wcAdjustableRunTime)
    {
        // As Time::adjustDeltaT, with the number of steps rounded up
        const scalar left =
            (writeTimeIndex_ + 1)*writeInterval_ - (value() - startTime_);
        if (left > 0)
        {
            dt = min(left/std::ceil(left/dtMax), dtMax);
        }
    }
    setDeltaT(dt, false);
}


bool Foam::mpmTime::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    if (!writeTime())
    {
        return false;
    }

    // The write before, written in the background, checked first
    finishWrites();

    // Written again (a restart from before it): incomplete until the record
    const fileName dir(timePath());
    rm(dir/"uniform"/recordName);

    if (writer_)
    {
        writeInBackground(fmt, ver, cmp, valid);
        return true;
    }

    // uniform/time first: files at least as new as it are this write's.
    // OpenFOAM's streams end the process when a write fails: caught, to
    // say what is lost and what is not
    const fileName timeDict(dir/"uniform"/"time");
    bool written = false;
    fileNameList broken;
    string failure;
    try
    {
        const errorsThrown throwing;
        bool ok = writeTimeDict() && whole(timeDict);
        const double since = ok ? highResLastModified(timeDict) : 0;
        ok = ok && objectRegistry::writeObject(fmt, ver, cmp, valid);
        broken = ok ? cutShort(dir, since) : fileNameList();
        written = ok && broken.empty() && writeRecord();
    }
    catch (const IOerror& e)
    {
        failure = e.ioFileName() + ": " + e.message();
    }
    catch (const error& e)
    {
        failure = e.message();
    }

    if (!written)
    {
        cannotWrite
        (
            dir,
            broken.size()
          ? Foam::name(broken.size()) + " file(s) cut short, first "
          + broken.first()
          : failure
        );
    }
    lastComplete_ = timeName();
    // Decomposed: older times go only once every processor has this one (a
    // processor that failed has stopped the run before this point)
    if (Pstream::parRun())
    {
        returnReduce(written, andOp<bool>());
    }
    purgeOldTimes();
    return true;
}


const Foam::word& Foam::mpmTime::lastComplete() const
{
    finishWrites();
    return lastComplete_;
}


void Foam::mpmTime::finishWrites() const
{
    if (!writer_ || writing_.empty())
    {
        return;
    }
    const std::string failure = writer_->wait();
    const fileName dir(path()/writing_);
    const word written(writing_);
    writing_.clear();
    if (!failure.empty())
    {
        cannotWrite(dir, failure);
    }
    lastComplete_ = written;
}


// ************************************************************************* //
