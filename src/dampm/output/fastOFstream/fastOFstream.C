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
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The powers of ten that an x87 extended double holds exactly (5^27 < 2^64)
constexpr int nExactPowers = 28;
constexpr long double exactPowers[nExactPowers] =
{
    1e0L, 1e1L, 1e2L, 1e3L, 1e4L, 1e5L, 1e6L, 1e7L, 1e8L, 1e9L, 1e10L,
    1e11L, 1e12L, 1e13L, 1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L, 1e20L,
    1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L
};

// The longest precision of the rounded path: 17 digits, the text that
// reads every double back (exactPrecision). Its product is one operation
// rounded to 64 bits: below 10^16 < 2^53.2 within 2^-11 of the exact one,
// below 10^17 < 2^56.5 within 2^-8
constexpr int maxRoundedPrecision = 17;

// How near a rounding midpoint the rounded path leaves a number to
// std::to_chars. A midpoint n + 1/2 is a long double and rounding is
// monotonic, so the product can reach a midpoint but not cross it: only a
// fraction of exactly 1/2 is in doubt. The margin is an allowance of four
// times the product's error: 2^-9 up to 16 digits (0.4 % of the numbers),
// 2^-6 at 17 (3 %)
inline long double midpointMargin(const int p)
{
    return p < maxRoundedPrecision ? 1.0L/512 : 1.0L/64;
}

// The texts of 00 to 99
constexpr char digitPairs[] =
    "0001020304050607080910111213141516171819"
    "2021222324252627282930313233343536373839"
    "4041424344454647484950515253545556575859"
    "6061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";


//- The p decimal digits of n < 10^p (leading zeros kept)
inline void digitsOf(std::int64_t n, const int p, char digits[])
{
    // The last eight digits and those before them in 32-bit arithmetic
    std::uint32_t low = std::uint32_t(n % 100000000);
    std::uint32_t high = std::uint32_t(n/100000000);
    int i = p;
    for (int pair = 0; pair < 4 && i > 0; ++pair)
    {
        const std::uint32_t r = low % 100;
        low /= 100;
        if (i >= 2)
        {
            i -= 2;
            std::memcpy(digits + i, digitPairs + 2*r, 2);
        }
        else
        {
            digits[--i] = digitPairs[2*r + 1];
        }
    }
    for (; i >= 2; i -= 2)
    {
        std::memcpy(digits + i - 2, digitPairs + 2*(high % 100), 2);
        high /= 100;
    }
    if (i)
    {
        digits[0] = char('0' + high);
    }
}


//- The text of printf's %.<p>g for the significand digits (nDigits of
//  them, no trailing zero) and decimal exponent x of a number; its length
inline int generalText
(
    char* buffer,
    const bool negative,
    const char digits[],
    const int nDigits,
    const int p,
    const int x
)
{
    char* s = buffer;
    if (negative)
    {
        *s++ = '-';
    }
    if (x < -4 || x >= p)
    {
        // d.ddde+XX
        *s++ = digits[0];
        if (nDigits > 1)
        {
            *s++ = '.';
            std::memcpy(s, digits + 1, nDigits - 1);
            s += nDigits - 1;
        }
        *s++ = 'e';
        *s++ = x < 0 ? '-' : '+';
        unsigned u = x < 0 ? -x : x;
        if (u >= 100)
        {
            *s++ = char('0' + u/100);
            u %= 100;
        }
        std::memcpy(s, digitPairs + 2*u, 2);
        s += 2;
    }
    else if (x >= 0)
    {
        // ddd.ddd
        std::memcpy(s, digits, x + 1);
        s += x + 1;
        if (nDigits > x + 1)
        {
            *s++ = '.';
            std::memcpy(s, digits + x + 1, nDigits - x - 1);
            s += nDigits - x - 1;
        }
    }
    else
    {
        // 0.000ddd
        *s++ = '0';
        *s++ = '.';
        for (int i = 0; i < -x - 1; ++i)
        {
            *s++ = '0';
        }
        std::memcpy(s, digits, nDigits);
        s += nDigits;
    }
    return int(s - buffer);
}


//- Does the x87 unit round to its 64-bit significand? Not where its
//  precision control is set to 53 bits, nor under valgrind, which computes
//  long doubles as doubles
bool extendedPrecision()
{
    volatile long double one = 1;
    return one + 0x1p-63L != one;
}


//- The text of val at precision p as printf's %.<p>g, rounded from one
//  extended-precision product of val and a power of ten: its length, or 0
//  where the product lies within midpointMargin of a midpoint between two
//  p-digit numbers (ties too), where the power would not be exact, for
//  p > 17, zero, a subnormal, an infinity or a NaN: std::to_chars then.
//  About 40 ns a number against std::to_chars' 95 (its exact decimal
//  expansion; 3e6 doubles of 1e-11 to 1e11, p = 12, this machine).
inline int roundedText(char* buffer, const double val, const int p)
{
    static const bool extended =
        std::numeric_limits<long double>::digits >= 64
     && extendedPrecision();
    if (!extended || p < 1 || p > maxRoundedPrecision || !std::isnormal(val))
    {
        return 0;
    }
    const double a = std::fabs(val);

    // The decimal exponent from the binary one, floor(e2 log10 2): never
    // above the number's (checked for every e2), one below it or a carry
    // (9.99..5 rounding up) corrected: the scaled number must round to p
    // digits
    std::uint64_t bits;
    std::memcpy(&bits, &a, sizeof(bits));
    int x = ((int(bits >> 52) - 1023)*315653) >> 20;
    const long double margin = midpointMargin(p);
    std::int64_t n = 0;
    for (int tries = 0; ; ++tries)
    {
        const int k = p - 1 - x;
        if (tries == 3 || k >= nExactPowers || k <= -nExactPowers)
        {
            return 0;
        }
        const long double y = k >= 0 ? a*exactPowers[k] : a/exactPowers[-k];
        n = std::int64_t(y);
        const long double fraction = y - n;
        if (std::fabs(fraction - 0.5L) < margin)
        {
            return 0;
        }
        if (y < exactPowers[p - 1] - 0.5L)
        {
            // Not reached: the exponent was not too large
            return 0;
        }
        if (y >= exactPowers[p] - 0.5L)
        {
            ++x;
        }
        else
        {
            n += fraction > 0.5L;
            break;
        }
    }

    char digits[maxRoundedPrecision];
    digitsOf(n, p, digits);
    int nDigits = p;
    while (nDigits > 1 && digits[nDigits - 1] == '0')
    {
        --nDigits;
    }
    return generalText(buffer, std::signbit(val), digits, nDigits, p, x);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * //

int Foam::fastOFstream::numberText
(
    char buffer[numberSize],
    const double val,
    const int precision
)
{
    const int length = roundedText(buffer, val, precision);
    if (length)
    {
        return length;
    }
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
constexpr Foam::label linesChunk = 1 << 12;

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

Foam::Detail::collectBuffer::collectBuffer
(
    const std::string& path,
    const bool compressed
)
:
    path_(path),
    compressed_(compressed),
    fd_(-1),
    gz_(nullptr),
    toFile_(false),
    error_(0)
{}


Foam::Detail::collectBuffer::~collectBuffer()
{
    if (fd_ >= 0)
    {
        backgroundWriter::closeFile(fd_, path_, false);
    }
    if (gz_)
    {
        backgroundWriter::closeCompressed(gz_, path_ + ".gz", false);
    }
}


Foam::Detail::fastOFstreamTarget::fastOFstreamTarget
(
    const fileName& pathname,
    const IOstream::compressionType compression
)
:
    collector_(backgroundWriter::collecting()),
    buffer_(pathname, compression == IOstream::COMPRESSED),
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
            // (a compressed file at the writer's level)
            if (compressed_)
            {
                gz_ = backgroundWriter::createCompressed(path_ + ".gz");
            }
            else
            {
                fd_ = backgroundWriter::createFile(path_);
            }
        }
    }
    const bool ok =
        compressed_
      ? gz_
     && backgroundWriter::deflateAll(gz_, bytes_.data(), bytes_.size())
     && backgroundWriter::deflateAll(gz_, s, n)
      : fd_ >= 0
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
    // Collected up to one piece (a compressed file up to wholeSize); more
    // goes to the file as it comes
    if (error_)
    {
        return 0;
    }
    const std::size_t most =
        compressed_ ? wholeSize : std::size_t(backgroundWriter::pieceSize);
    if (bytes_.size() + n <= most)
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
    if (gz_)
    {
        // Deflated as it came: the rest, then the stream's end
        const bool written = !error_ && sync() == 0;
        gzFile_s* gz = gz_;
        gz_ = nullptr;
        if
        (
            !backgroundWriter::closeCompressed(gz, path_ + ".gz", written)
        )
        {
            return std::strerror(error_ ? error_ : errno);
        }
        return "";
    }
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
        collector_->add
        ({
            buffer_.compressed() ? kind::writeCompressed : kind::writeFile,
            name(),
            std::move(buffer_.bytes())
        });
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

    // A point field of a one-cell-thick (2D) mesh has the same values on
    // its two layers of points: the list's second half is then its first,
    // formatted once and written twice
    const label half = n/2;
    const bool repeated =
        n > 1 && n % 2 == 0
     && !std::memcmp
        (
            values, values + half*nCmpt, sizeof(double)*half*nCmpt
        );
    const label nFormatted = repeated ? half : n;

    // The longest line: (a b c) of numbers of at most p + 7 characters
    // (-d.ddde-XXX), or of the text of any number
    const label lineSize =
        3 + nCmpt*(1 + std::min(p + 7, int(numberSize)));
    const label nChunks = (nFormatted + linesChunk - 1)/linesChunk;
    std::vector<std::unique_ptr<char[]>> text(nChunks);
    std::vector<label> textSize(nChunks);

    #pragma omp parallel for schedule(dynamic)
    for (label c = 0; c < nChunks; ++c)
    {
        const label end = std::min(nFormatted, (c + 1)*linesChunk);
        // (numberText is given room for any number past the last line)
        text[c].reset
        (
            new char[lineSize*(end - c*linesChunk) + numberSize]
        );
        char* s = text[c].get();
        for (label i = c*linesChunk; i < end; ++i)
        {
            const double* v = values + i*nCmpt;
            if (nCmpt > 1)
            {
                *s++ = token::BEGIN_LIST;
            }
            for (direction d = 0; d < nCmpt; ++d)
            {
                if (d)
                {
                    *s++ = token::SPACE;
                }
                if (plainZero(v[d]))
                {
                    *s++ = '0';
                }
                else
                {
                    s += numberText(s, v[d], p);
                }
            }
            if (nCmpt > 1)
            {
                *s++ = token::END_LIST;
            }
            *s++ = token::NL;
        }
        textSize[c] = s - text[c].get();
    }
    for (label pass = 0; pass < (repeated ? 2 : 1); ++pass)
    {
        for (label c = 0; c < nChunks; ++c)
        {
            put(text[c].get(), textSize[c]);
        }
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
