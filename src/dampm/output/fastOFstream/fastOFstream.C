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
#include "OFstream.H"
#include "OSspecific.H"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
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
    // (this class's stdStream writes the tape first). In pieces: a file's
    // buffer hands a longer text to one write(2) (backgroundWriter's
    // pieceSize says why not)
    std::ostream& os = OSstream::stdStream();
    const std::streamsize piece = backgroundWriter::pieceSize;
    for (std::streamsize done = 0; done < n; done += piece)
    {
        const std::streamsize m = std::min(piece, n - done);
        if (os.rdbuf()->sputn(data + done, m) != m)
        {
            os.setstate(std::ios::badbit);
            setState(os.rdstate());
            return;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::Detail::collectBuffer::collectBuffer(const std::string& path)
:
    path_(path),
    fd_(-1),
    toFile_(false),
    error_(0)
{}


Foam::Detail::collectBuffer::~collectBuffer()
{
    if (fd_ >= 0)
    {
        backgroundWriter::closeFile(fd_, path_, false);
    }
}


Foam::Detail::fastOFstreamTarget::fastOFstreamTarget
(
    const fileName& pathname,
    const IOstream::compressionType compression
)
:
    collector_
    (
        compression == IOstream::UNCOMPRESSED
      ? backgroundWriter::collecting()
      : nullptr
    ),
    buffer_(pathname),
    memory_(&buffer_)
{
    if (!collector_)
    {
        // A file written again is a new one (OFstream would write through
        // a hard link that other time directories share)
        mkDir(pathname.path());
        backgroundWriter::unlinkFile(pathname);
        file_.reset
        (
            new OFstream
            (
                pathname, IOstream::ASCII, IOstream::currentVersion,
                compression
            )
        );
    }
}


Foam::Detail::fastOFstreamTarget::~fastOFstreamTarget()
{}


bool Foam::Detail::collectBuffer::writeOut
(
    const char* s,
    const std::streamsize n
)
{
    if (!toFile_)
    {
        toFile_ = true;
        if (backgroundWriter::makeParent(path_))
        {
            fd_ = backgroundWriter::createFile(path_);
        }
    }
    const bool ok =
        fd_ >= 0
     && backgroundWriter::writeAll(fd_, bytes_.data(), bytes_.size())
     && backgroundWriter::writeAll(fd_, s, n);
    bytes_.clear();
    if (!ok)
    {
        error_ = errno ? errno : EIO;
    }
    return ok;
}


Foam::Detail::collectBuffer::int_type
Foam::Detail::collectBuffer::overflow(int_type c)
{
    if (traits_type::eq_int_type(c, traits_type::eof()))
    {
        return traits_type::not_eof(c);
    }
    const char ch = traits_type::to_char_type(c);
    return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
}


std::streamsize Foam::Detail::collectBuffer::xsputn
(
    const char* s,
    const std::streamsize n
)
{
    // Collected up to one piece; more goes to the file as it comes
    if (error_)
    {
        return 0;
    }
    if (bytes_.size() + n <= std::size_t(backgroundWriter::pieceSize))
    {
        bytes_.append(s, n);
        return n;
    }
    return writeOut(s, n) ? n : 0;
}


int Foam::Detail::collectBuffer::sync()
{
    return !toFile_ || bytes_.empty() || writeOut(nullptr, 0) ? 0 : -1;
}


std::string Foam::Detail::collectBuffer::close()
{
    if (fd_ < 0)
    {
        return error_ ? std::strerror(error_) : "";
    }
    const bool written = !error_ && sync() == 0;
    const int fd = fd_;
    fd_ = -1;
    if (!backgroundWriter::closeFile(fd, path_, written))
    {
        return std::strerror(error_ ? error_ : errno);
    }
    return "";
}


std::ostream& Foam::Detail::fastOFstreamTarget::target()
{
    return file_ ? file_->stdStream() : memory_;
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
    fastOFstream os(io.objectPath(), fmt, ver, cmp);
    const bool ok = os.good() && io.writeHeader(os) && io.writeData(os);
    IOobject::writeEndDivider(os);
    os.flush();
    return ok && os.good();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fastOFstream::fastOFstream
(
    const fileName& pathname,
    streamFormat format,
    versionNumber version,
    compressionType compression
)
:
    Detail::fastOFstreamTarget(pathname, compression),
    OSstream(target(), pathname, format, version, compression)
{
    // As OFstream's
    setClosed();
    setState(target().rdstate());
    if (good())
    {
        setOpened();
    }
    else
    {
        setBad();
    }
    lineNumber_ = 1;
}


Foam::fastOFstream::~fastOFstream()
{
    drain();
    if (!collector_ || collector_ != backgroundWriter::collecting())
    {
        return;
    }
    typedef backgroundWriter::operation::kind kind;
    if (!buffer_.toFile())
    {
        collector_->add({kind::writeFile, name(), std::move(buffer_.bytes())});
        return;
    }
    // Written as it came: closed now; what failed stops the write time
    const std::string why = buffer_.close();
    if (!why.empty())
    {
        collector_->add({kind::failure, name(), why});
    }
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
        return OSstream::write(val);
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
    return OSstream::write(tok);
}


Foam::Ostream& Foam::fastOFstream::write(const char* str)
{
    drain();
    return OSstream::write(str);
}


Foam::Ostream& Foam::fastOFstream::write(const word& str)
{
    drain();
    return OSstream::write(str);
}


Foam::Ostream& Foam::fastOFstream::write(const string& str)
{
    drain();
    return OSstream::write(str);
}


Foam::Ostream& Foam::fastOFstream::writeQuoted
(
    const std::string& str,
    const bool quoted
)
{
    drain();
    return OSstream::writeQuoted(str, quoted);
}


Foam::Ostream& Foam::fastOFstream::write(const int32_t val)
{
    if (format() == BINARY)
    {
        drain();
        return OSstream::write(val);
    }
    return writeInteger(val);
}


Foam::Ostream& Foam::fastOFstream::write(const int64_t val)
{
    if (format() == BINARY)
    {
        drain();
        return OSstream::write(val);
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
    return OSstream::write(data, count);
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
    return OSstream::beginRawWrite(count);
}


bool Foam::fastOFstream::endRawWrite()
{
    drain();
    return OSstream::endRawWrite();
}


void Foam::fastOFstream::indent()
{
    drain();
    OSstream::indent();
}


void Foam::fastOFstream::flush()
{
    drain();
    OSstream::flush();
}


void Foam::fastOFstream::endl()
{
    drain();
    OSstream::endl();
}


int Foam::fastOFstream::precision(const int p)
{
    drain();
    return OSstream::precision(p);
}


std::ostream& Foam::fastOFstream::stdStream()
{
    drain();
    return OSstream::stdStream();
}


// ************************************************************************* //
