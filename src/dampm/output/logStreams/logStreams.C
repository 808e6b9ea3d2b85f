/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "logStreams.H"

#include <cerrno>
#include <cstdio>
#include <iostream>
#include <streambuf>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Classes  * * * * * * * * * * * * * * //

namespace
{

//- A file descriptor's output buffer that never fails: what write(2)
//  refuses is dropped
class droppingBuffer
:
    public std::streambuf
{
    const int fd_;
    char buffer_[1 << 13];

    void drain()
    {
        const char* p = pbase();
        std::size_t n = pptr() - pbase();
        while (n)
        {
            const ssize_t w = ::write(fd_, p, n);
            if (w < 0 && errno == EINTR)
            {
                continue;
            }
            if (w <= 0)
            {
                break;
            }
            p += w;
            n -= std::size_t(w);
        }
        setp(buffer_, buffer_ + sizeof(buffer_));
    }

protected:

    virtual int_type overflow(int_type c)
    {
        drain();
        if (!traits_type::eq_int_type(c, traits_type::eof()))
        {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }

    virtual int sync()
    {
        drain();
        return 0;
    }

public:

    explicit droppingBuffer(const int fd)
    :
        fd_(fd)
    {
        setp(buffer_, buffer_ + sizeof(buffer_));
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::logStreams::install()
{
    static const bool installed = []
    {
        // What went through stdio so far first; the buffers are never
        // destroyed: static objects write to the log up to the exit, and
        // the iostreams' own clean-up flushes them
        std::fflush(stdout);
        std::cout.flush();
        std::cerr.flush();
        std::cout.rdbuf(new droppingBuffer(STDOUT_FILENO));
        std::cerr.rdbuf(new droppingBuffer(STDERR_FILENO));
        return true;
    }();
    (void)installed;
}


// ************************************************************************* //
