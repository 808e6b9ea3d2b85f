/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "backgroundWriter.H"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <unordered_set>
#include <vector>

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

Foam::backgroundWriter* Foam::backgroundWriter::collecting_ = nullptr;
Foam::backgroundWriter* Foam::backgroundWriter::live_ = nullptr;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef std::unordered_set<std::string> dirSet;

std::string reason
(
    const std::string& what,
    const std::string& path,
    const std::string& why
)
{
    return "cannot " + what + " " + path + ": " + why;
}


std::string parentOf(const std::string& path)
{
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos || slash == 0
      ? std::string()
      : path.substr(0, slash);
}


// Make dir and its parents (false: errno says why); made: the directories
// known to exist
bool makeDir(const std::string& dir, dirSet& made)
{
    if (dir.empty() || made.count(dir))
    {
        return true;
    }
    bool ok = ::mkdir(dir.c_str(), 0777) == 0 || errno == EEXIST;
    if (!ok && errno == ENOENT)
    {
        ok =
            makeDir(parentOf(dir), made)
         && (::mkdir(dir.c_str(), 0777) == 0 || errno == EEXIST);
    }
    if (ok)
    {
        made.insert(dir);
    }
    return ok;
}


// Remove a file, if there is one
bool removeFile(const std::string& path)
{
    return ::unlink(path.c_str()) == 0 || errno == ENOENT;
}


// A new file holding the bytes
bool writeFile(const std::string& path, const std::string& bytes)
{
    const int fd = Foam::backgroundWriter::createFile(path);
    return
        fd >= 0
     && Foam::backgroundWriter::closeFile
        (
            fd, path,
            Foam::backgroundWriter::writeAll(fd, bytes.data(), bytes.size())
        );
}


// The file's bytes (false: unreadable)
bool readFile(const std::string& path, std::string& bytes)
{
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0)
    {
        return false;
    }
    bytes.clear();
    char buffer[1 << 16];
    ssize_t r;
    while ((r = ::read(fd, buffer, sizeof(buffer))) != 0)
    {
        if (r < 0 && errno == EINTR)
        {
            continue;
        }
        if (r < 0)
        {
            const int err = errno;
            ::close(fd);
            errno = err;
            return false;
        }
        bytes.append(buffer, std::size_t(r));
    }
    return ::close(fd) == 0;
}


// A new compressed file gz holding the bytes
bool deflateFile(const std::string& gz, const std::string& bytes)
{
    gzFile_s* f = Foam::backgroundWriter::createCompressed(gz);
    return
        f
     && Foam::backgroundWriter::closeCompressed
        (
            f, gz,
            Foam::backgroundWriter::deflateAll(f, bytes.data(), bytes.size())
        );
}


// A hard link to source, or a copy where no link can be made
bool linkFile(const std::string& source, const std::string& path)
{
    if (!Foam::backgroundWriter::unlinkFile(path))
    {
        return false;
    }
    if (::link(source.c_str(), path.c_str()) == 0)
    {
        return true;
    }
    std::string bytes;
    return readFile(source, bytes) && writeFile(path, bytes);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

bool Foam::backgroundWriter::unlinkFile(const std::string& path)
{
    const std::string gz(".gz");
    const bool compressed =
        path.size() > gz.size()
     && path.compare(path.size() - gz.size(), gz.size(), gz) == 0;
    return
        removeFile(path)
     && removeFile
        (
            compressed ? path.substr(0, path.size() - gz.size()) : path + gz
        );
}


bool Foam::backgroundWriter::makeParent(const std::string& path)
{
    dirSet made;
    return makeDir(parentOf(path), made);
}


int Foam::backgroundWriter::createFile(const std::string& path)
{
    return
        unlinkFile(path)
      ? ::open(path.c_str(), O_WRONLY|O_CREAT|O_TRUNC, 0666)
      : -1;
}


bool Foam::backgroundWriter::writeAll
(
    const int fd,
    const char* data,
    const std::size_t n
)
{
    std::size_t done = 0;
    while (done < n)
    {
        const std::size_t piece = std::min<std::size_t>(n - done, pieceSize);
        const ssize_t w = ::write(fd, data + done, piece);
        if (w < 0 && errno == EINTR)
        {
            continue;
        }
        if (w <= 0)
        {
            if (w == 0)
            {
                errno = ENOSPC;
            }
            return false;
        }
        done += std::size_t(w);
    }
    return true;
}


bool Foam::backgroundWriter::closeFile
(
    const int fd,
    const std::string& path,
    const bool written
)
{
    const int err = errno;
    const bool closed = ::close(fd) == 0;
    if (written && closed)
    {
        return true;
    }
    // What did not fit removed: the space it took goes back to the log,
    // which says why the run stops
    const int why = written ? errno : err;
    ::unlink(path.c_str());
    errno = why;
    return false;
}


gzFile_s* Foam::backgroundWriter::createCompressed(const std::string& gz)
{
    const int fd = createFile(gz);
    gzFile_s* f = fd < 0 ? nullptr : gzdopen(fd, "wb1");
    if (fd >= 0 && !f)
    {
        closeFile(fd, gz, false);
        errno = ENOMEM;
    }
    return f;
}


bool Foam::backgroundWriter::deflateAll
(
    gzFile_s* f,
    const char* data,
    const std::size_t n
)
{
    // In pieces: zlib counts in 32 bits
    const std::size_t piece = pieceSize;
    for (std::size_t done = 0; done < n; done += piece)
    {
        const unsigned m = unsigned(std::min(n - done, piece));
        if (gzwrite(f, data + done, m) != int(m))
        {
            int status = Z_OK;
            gzerror(f, &status);
            if (status != Z_ERRNO)
            {
                errno = EIO;
            }
            return false;
        }
    }
    return true;
}


bool Foam::backgroundWriter::closeCompressed
(
    gzFile_s* f,
    const std::string& gz,
    const bool written
)
{
    // The stream's end deflated and written, the file closed
    const int err = errno;
    errno = 0;
    const bool closed = gzclose(f) == Z_OK;
    if (written && closed)
    {
        return true;
    }
    const int why = !written ? err : (errno ? errno : EIO);
    ::unlink(gz.c_str());
    errno = why;
    return false;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::backgroundWriter::perform(std::vector<operation>& ops)
{
    dirSet made;
    for (operation& op : ops)
    {
        typedef operation::kind kind;
        switch (op.what)
        {
            case kind::writeFile:
            case kind::writeCompressed:
            {
                const bool gz = op.what == kind::writeCompressed;
                const std::string file(gz ? op.path + ".gz" : op.path);
                if
                (
                    !makeDir(parentOf(file), made)
                 || !(gz ? deflateFile : writeFile)(file, op.data)
                )
                {
                    const std::string why(std::strerror(errno));
                    return reason("write", file, why);
                }
                std::string().swap(op.data);
                break;
            }
            case kind::linkFile:
                if
                (
                    !makeDir(parentOf(op.path), made)
                 || !linkFile(op.data, op.path)
                )
                {
                    const std::string why(std::strerror(errno));
                    return reason("link " + op.data + " as", op.path, why);
                }
                break;
            case kind::failure:
                return reason("write", op.path, op.data);
            case kind::removeDir:
            {
                // As OpenFOAM's rmDir for the purged times: not a failure
                // of this write time
                std::error_code ignored;
                std::filesystem::remove_all(op.path, ignored);
                made.clear();
                break;
            }
        }
    }
    return std::string();
}


void Foam::backgroundWriter::serve()
{
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;)
    {
        changed_.wait(lock, [this]{ return busy_ || ending_; });
        if (!busy_)
        {
            return;
        }
        std::vector<operation> ops(std::move(handedOver_));
        handedOver_.clear();
        lock.unlock();
        std::string failure;
        try
        {
            failure = perform(ops);
        }
        catch (...)
        {
            // A failed allocation, as the out-of-memory handler throws it
            // while the solver's thread has errors thrown (otherwise the
            // handler ends the process, see finishAtExit)
            failure =
                "cannot write the time directory: an allocation failed on"
                " the writer's thread (out of memory)";
        }
        lock.lock();
        failure_ = failure;
        busy_ = false;
        changed_.notify_all();
    }
}


void Foam::backgroundWriter::finishAtExit()
{
    // Not on the writer's own thread (the out-of-memory handler's exit):
    // it would wait for itself
    if (live_ && std::this_thread::get_id() != live_->thread_.get_id())
    {
        const std::string failure = live_->wait();
        if (!failure.empty())
        {
            std::cerr << failure << std::endl;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::backgroundWriter::backgroundWriter()
:
    busy_(false),
    ending_(false)
{
    // The thread inherits the mask: signals go to the solver's thread
    sigset_t all, previous;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &previous);
    thread_ = std::thread([this]{ serve(); });
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);

    static const bool registered = (std::atexit(finishAtExit) == 0);
    (void)registered;
    live_ = this;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::backgroundWriter::~backgroundWriter()
{
    if (live_ == this)
    {
        live_ = nullptr;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        ending_ = true;
    }
    changed_.notify_all();
    thread_.join();
}


Foam::backgroundWriter::collection::collection(backgroundWriter& writer)
:
    writer_(writer)
{
    writer_.collected_.clear();
    collecting_ = &writer_;
}


Foam::backgroundWriter::collection::~collection()
{
    collecting_ = nullptr;
    writer_.collected_.clear();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::backgroundWriter::add(operation&& op)
{
    collected_.push_back(std::move(op));
}


std::string Foam::backgroundWriter::collectedFailure() const
{
    for (const operation& op : collected_)
    {
        if (op.what == operation::kind::failure)
        {
            return reason("write", op.path, op.data);
        }
    }
    return std::string();
}


void Foam::backgroundWriter::submit()
{
    // (the caller has seen how the one before ended: wait)
    wait();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        handedOver_ = std::move(collected_);
        collected_.clear();
        failure_.clear();
        busy_ = true;
    }
    changed_.notify_all();
}


std::string Foam::backgroundWriter::wait()
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this]{ return !busy_; });
    return failure_;
}


// ************************************************************************* //
