/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "ensembleRunner.H"
#include "runProgress.H"
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The signal received while members run (0: none)
volatile std::sig_atomic_t stopSignal = 0;

//- The number of signals received
volatile std::sig_atomic_t nSignals = 0;

extern "C" void recordSignal(int sig)
{
    stopSignal = sig;
    nSignals = nSignals + 1;
}


//- Catches SIGINT and SIGTERM while it lives
class signalCatcher
{
    struct sigaction previous_[2];

public:

    signalCatcher()
    {
        stopSignal = 0;
        nSignals = 0;
        struct sigaction action{};
        action.sa_handler = recordSignal;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_[0]);
        sigaction(SIGTERM, &action, &previous_[1]);
    }

    ~signalCatcher()
    {
        sigaction(SIGINT, &previous_[0], nullptr);
        sigaction(SIGTERM, &previous_[1], nullptr);
    }
};


//- Wall time [s] since a fixed start
double wallTime()
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now().time_since_epoch()
    ).count();
}


//- A member under way
struct runningMember
{
    pid_t pid;
    Foam::ensembleMember* member;
    double start;
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

pid_t Foam::ensembleRunner::launch(const ensembleMember& member) const
{
    const std::string caseDir(member.dir());
    const std::string log(member.dir()/("log." + application_));
    const std::string threads(std::to_string(threads_));
    const std::string app(application_);
    std::cout.flush();

    const pid_t pid = fork();
    if (pid == 0)
    {
        // The child: its own process group, output to the member's log
        setpgid(0, 0);
        const int fd = open(log.c_str(), O_WRONLY|O_CREAT|O_APPEND, 0644);
        if (fd >= 0)
        {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        setenv("OMP_NUM_THREADS", threads.c_str(), 1);
        const char* argv[] =
            {app.c_str(), "-case", caseDir.c_str(), nullptr};
        execvp(argv[0], const_cast<char* const*>(argv));
        std::fprintf
        (
            stderr, "dampmEnsemble: cannot run %s: %s\n",
            app.c_str(), std::strerror(errno)
        );
        _exit(127);
    }
    if (pid < 0)
    {
        FatalErrorInFunction
            << "cannot start a process for member " << member.name() << ": "
            << std::strerror(errno) << exit(FatalError);
    }
    return pid;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ensembleRunner::ensembleRunner
(
    const word& application,
    const label jobs,
    const label threads
)
:
    application_(application),
    jobs_(jobs),
    threads_(threads)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

int Foam::ensembleRunner::run(UPtrList<ensembleMember>& members) const
{
    const signalCatcher catcher;
    std::vector<runningMember> running;
    label next = 0, nDone = 0, nFailed = 0, nForwarded = 0;
    double doneTime = 0;

    auto progress = [&](const double now)
    {
        const label nWaiting = members.size() - next;
        Info<< "  done " << nDone << ", failed " << nFailed << ", running "
            << label(running.size()) << ", waiting " << nWaiting;
        if (nDone)
        {
            double left = doneTime/nDone*(nWaiting + running.size());
            for (const runningMember& r : running)
            {
                left -= std::min(now - r.start, doneTime/nDone);
            }
            Info<< "; about "
                << runProgress::duration(std::max(left, 0.0)/jobs_).c_str()
                << " left";
        }
        Info<< endl;
    };

    while ((!stopSignal && next < members.size()) || !running.empty())
    {
        if (stopSignal && nForwarded < nSignals)
        {
            for (const runningMember& r : running)
            {
                kill(r.pid, SIGTERM);
            }
            nForwarded = nSignals;
        }
        while
        (
            !stopSignal && next < members.size()
         && label(running.size()) < jobs_
        )
        {
            ensembleMember& member = members[next++];
            member.setStatus(ensembleMember::statusType::running, 0, 0);
            running.push_back({launch(member), &member, wallTime()});
            Info<< "member " << member.name() << " started" << endl;
        }

        int status = 0;
        const pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid <= 0)
        {
            usleep(50000);
            continue;
        }
        auto r = std::find_if
        (
            running.begin(), running.end(),
            [pid](const runningMember& m){ return m.pid == pid; }
        );
        if (r == running.end())
        {
            continue;
        }
        const double now = wallTime();
        const double seconds = now - r->start;
        ensembleMember& member = *r->member;
        running.erase(r);

        const label code =
            WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        // Done: ended well, with the hazard maps of its end
        typedef ensembleMember::statusType statusType;
        string why;
        const bool maps = code == 0 && member.mapsAtEnd(why);
        const statusType result =
            maps ? statusType::done
          : stopSignal ? statusType::interrupted
          : statusType::failed;
        member.setStatus(result, code, seconds);

        Info<< "member " << member.name() << ' '
            << ensembleMember::statusTypeNames[result] << " in "
            << runProgress::duration(seconds).c_str();
        if (result == statusType::failed)
        {
            ++nFailed;
            Info<< " with exit code " << code << ": "
                << (code ? member.failure(application_) : why).c_str();
        }
        else if (result == statusType::done)
        {
            ++nDone;
            doneTime += seconds;
        }
        Info<< nl;
        progress(now);
    }
    return stopSignal;
}


// ************************************************************************* //
