/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "fastOFstream.H"
#include "Time.H"
#include "OSspecific.H"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

// * * * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * //

int Foam::fastOFstream::numberText
(
    char buffer[numberSize],
    const double val,
    const int precision
)
{
    return std::to_chars
    (
        buffer, buffer + numberSize, val, std::chars_format::general,
        precision
    ).ptr - buffer;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

// Tape entries formatted by one thread; a longer tape is written first
constexpr std::size_t chunkSize = 1 << 16;
constexpr std::size_t tapeSize = 1 << 22;

} // End anonymous namespace


void Foam::fastOFstream::drain()
{
    const std::size_t n = tape_.size();
    if (!n)
    {
        return;
    }
    const int p = precision();
    char buffer[numberSize];
    if (n <= chunkSize)
    {
        // One chunk: straight into the stream, nothing to share
        std::size_t k = 0;
        for (const char c : tape_)
        {
            if (c)
            {
                put(&c, 1);
            }
            else
            {
                put(buffer, numberText(buffer, numbers_[k++], p));
            }
        }
        tape_.clear();
        numbers_.clear();
        return;
    }

    // Each chunk's first number: the numbers of the chunks before it
    const std::size_t nChunks = (n + chunkSize - 1)/chunkSize;
    std::vector<std::size_t> first(nChunks + 1, 0);
    for (std::size_t c = 0; c < nChunks; ++c)
    {
        const std::size_t end = std::min(n, (c + 1)*chunkSize);
        first[c + 1] = first[c]
          + std::count(tape_.begin() + c*chunkSize, tape_.begin() + end, 0);
    }

    std::vector<std::string> text(nChunks);
    #pragma omp parallel for schedule(static) private(buffer)
    for (std::size_t c = 0; c < nChunks; ++c)
    {
        const std::size_t begin = c*chunkSize;
        const std::size_t end = std::min(n, begin + chunkSize);
        std::string& t = text[c];
        t.reserve(20*(end - begin));
        std::size_t k = first[c];
        for (std::size_t i = begin; i < end; ++i)
        {
            if (tape_[i])
            {
                t += tape_[i];
            }
            else
            {
                t.append(buffer, numberText(buffer, numbers_[k++], p));
            }
        }
    }
    tape_.clear();
    numbers_.clear();
    for (const std::string& t : text)
    {
        put(t.data(), t.size());
    }
}


void Foam::fastOFstream::put(const char* data, const std::streamsize n)
{
    // The stream buffer itself: no sentry, no state check per character
    // (OFstream's stream: this class's stdStream writes the tape first)
    std::ostream& os = OFstream::stdStream();
    if (os.rdbuf()->sputn(data, n) != n)
    {
        os.setstate(std::ios::badbit);
        setState(os.rdstate());
    }
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

bool Foam::fastOFstream::writeObject
(
    const regIOobject& io,
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp
)
{
    const Time& time = io.time();
    if (io.instance() != time.constant() && io.instance() != time.system())
    {
        const_cast<regIOobject&>(io).instance() = time.timeName();
    }
    const fileName file(io.objectPath());
    mkDir(file.path());

    fastOFstream os(file, fmt, ver, cmp);
    const bool ok = os.good() && io.writeHeader(os) && io.writeData(os);
    IOobject::writeEndDivider(os);
    os.flush();
    return ok && os.good();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fastOFstream::~fastOFstream()
{
    drain();
}


Foam::Ostream& Foam::fastOFstream::write(const char c)
{
    if (tape_.empty())
    {
        put(&c, 1);
    }
    else
    {
        tape_.push_back(c);
        if (tape_.size() >= tapeSize)
        {
            drain();
        }
    }
    if (c == token::NL)
    {
        ++lineNumber_;
    }
    return *this;
}


Foam::Ostream& Foam::fastOFstream::write(const doubleScalar val)
{
    if (format() == BINARY)
    {
        return OFstream::write(val);
    }
    if (val == 0 && !std::signbit(val))
    {
        // The commonest value of a field over a sparse grid: its text "0"
        // as a character, no conversion
        return write(char('0'));
    }
    tape_.push_back(0);
    numbers_.push_back(val);
    if (tape_.size() >= tapeSize)
    {
        drain();
    }
    return *this;
}


Foam::Ostream& Foam::fastOFstream::write(const floatScalar val)
{
    // As std::ostream: a float as the double it converts to
    return write(doubleScalar(val));
}


bool Foam::fastOFstream::write(const token& tok)
{
    drain();
    return OFstream::write(tok);
}


Foam::Ostream& Foam::fastOFstream::write(const char* str)
{
    drain();
    return OFstream::write(str);
}


Foam::Ostream& Foam::fastOFstream::write(const word& str)
{
    drain();
    return OFstream::write(str);
}


Foam::Ostream& Foam::fastOFstream::write(const string& str)
{
    drain();
    return OFstream::write(str);
}


Foam::Ostream& Foam::fastOFstream::writeQuoted
(
    const std::string& str,
    const bool quoted
)
{
    drain();
    return OFstream::writeQuoted(str, quoted);
}


Foam::Ostream& Foam::fastOFstream::write(const int32_t val)
{
    drain();
    return OFstream::write(val);
}


Foam::Ostream& Foam::fastOFstream::write(const int64_t val)
{
    drain();
    return OFstream::write(val);
}


Foam::Ostream& Foam::fastOFstream::write
(
    const char* data,
    std::streamsize count
)
{
    drain();
    return OFstream::write(data, count);
}


Foam::Ostream& Foam::fastOFstream::writeRaw
(
    const char* data,
    std::streamsize count
)
{
    drain();
    return OFstream::writeRaw(data, count);
}


bool Foam::fastOFstream::beginRawWrite(std::streamsize count)
{
    drain();
    return OFstream::beginRawWrite(count);
}


bool Foam::fastOFstream::endRawWrite()
{
    drain();
    return OFstream::endRawWrite();
}


void Foam::fastOFstream::indent()
{
    drain();
    OFstream::indent();
}


void Foam::fastOFstream::flush()
{
    drain();
    OFstream::flush();
}


void Foam::fastOFstream::endl()
{
    drain();
    OFstream::endl();
}


int Foam::fastOFstream::precision(const int p)
{
    drain();
    return OFstream::precision(p);
}


std::ostream& Foam::fastOFstream::stdStream()
{
    drain();
    return OFstream::stdStream();
}


// ************************************************************************* //
