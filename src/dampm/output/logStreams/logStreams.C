/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "logStreams.H"
#include "backgroundWriter.H"

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
        // (what is refused is dropped: the result is not looked at)
        Foam::backgroundWriter::writeAll(fd_, pbase(), pptr() - pbase());
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
