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
#include <cstring>
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

// Elements of a long list formatted by one thread (writeLines)
constexpr Foam::label linesChunk = 1 << 14;

// Bytes handed to the stream buffer at once (see put)
constexpr std::streamsize writeSize = 1 << 18;

// Tape entries that stand for the next number: a double, or an integer
// (its bits in the number's place)
constexpr char doubleMark = 0;
constexpr char integerMark = 1;

// A positive zero, most of a field over a sparse grid, is written as its
// text "0" with no conversion
inline bool plainZero(const double val)
{
    return val == 0 && !std::signbit(val);
}

inline bool isMark(const char e)
{
    return e == doubleMark || e == integerMark;
}

// The text of a tape's number
inline int entryText
(
    char buffer[Foam::fastOFstream::numberSize],
    const char mark,
    const double number,
    const int precision
)
{
    if (mark == integerMark)
    {
        std::int64_t val;
        std::memcpy(&val, &number, sizeof(val));
        return std::to_chars
        (
            buffer, buffer + Foam::fastOFstream::numberSize, val
        ).ptr - buffer;
    }
    return Foam::fastOFstream::numberText(buffer, number, precision);
}

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
            if (!isMark(c))
            {
                put(&c, 1);
            }
            else
            {
                put(buffer, entryText(buffer, c, numbers_[k++], p));
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
          + std::count_if
            (
                tape_.begin() + c*chunkSize, tape_.begin() + end,
                isMark
            );
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
            const char e = tape_[i];
            if (!isMark(e))
            {
                t += e;
            }
            else
            {
                t.append(buffer, entryText(buffer, e, numbers_[k++], p));
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
    // (OFstream's stream: this class's stdStream writes the tape first).
    // In pieces of at most writeSize: the buffer hands a longer text to one
    // write(2), and on this platform a write(2) of 2 MB or more into a new
    // file took 20 times as long per byte as one of 1 MB (60 MB: 350-470 ms
    // against 15-19 ms)
    std::ostream& os = OFstream::stdStream();
    for (std::streamsize done = 0; done < n; done += writeSize)
    {
        const std::streamsize m = std::min(writeSize, n - done);
        if (os.rdbuf()->sputn(data + done, m) != m)
        {
            os.setstate(std::ios::badbit);
            setState(os.rdstate());
            return;
        }
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
    if (tape_.empty() || isMark(c))
    {
        // (a character that is a tape's mark is written as itself)
        drain();
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
    if (plainZero(val))
    {
        return write(char('0'));
    }
    return pushNumber(doubleMark, val);
}


Foam::Ostream& Foam::fastOFstream::writeInteger(const std::int64_t val)
{
    // As a number: the cells of a cloud's positions stay on the tape
    double bits;
    std::memcpy(&bits, &val, sizeof(bits));
    return pushNumber(integerMark, bits);
}


Foam::Ostream& Foam::fastOFstream::pushNumber
(
    const char mark,
    const double number
)
{
    tape_.push_back(mark);
    numbers_.push_back(number);
    if (tape_.size() >= tapeSize)
    {
        drain();
    }
    return *this;
}


void Foam::fastOFstream::writeLines
(
    const double* values,
    const label n,
    const direction nCmpt
)
{
    drain();
    const int p = precision();
    const label nChunks = (n + linesChunk - 1)/linesChunk;
    std::vector<std::string> text(nChunks);

    #pragma omp parallel for schedule(static)
    for (label c = 0; c < nChunks; ++c)
    {
        char buffer[numberSize];
        const label end = std::min(n, (c + 1)*linesChunk);
        std::string& t = text[c];
        t.reserve(8*nCmpt*(end - c*linesChunk));
        for (label i = c*linesChunk; i < end; ++i)
        {
            const double* v = values + i*nCmpt;
            if (nCmpt > 1)
            {
                t += token::BEGIN_LIST;
            }
            for (direction d = 0; d < nCmpt; ++d)
            {
                if (d)
                {
                    t += token::SPACE;
                }
                if (plainZero(v[d]))
                {
                    t += '0';
                }
                else
                {
                    t.append(buffer, numberText(buffer, v[d], p));
                }
            }
            if (nCmpt > 1)
            {
                t += token::END_LIST;
            }
            t += token::NL;
        }
    }
    for (const std::string& t : text)
    {
        put(t.data(), t.size());
    }
    lineNumber_ += n;
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
    if (format() == BINARY)
    {
        drain();
        return OFstream::write(val);
    }
    return writeInteger(val);
}


Foam::Ostream& Foam::fastOFstream::write(const int64_t val)
{
    if (format() == BINARY)
    {
        drain();
        return OFstream::write(val);
    }
    return writeInteger(val);
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
    // A binary list's block (write(data, count) comes here): in pieces
    drain();
    put(data, count);
    return *this;
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
