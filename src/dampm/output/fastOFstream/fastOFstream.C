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
#include <charconv>

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

template<class Type>
void Foam::fastOFstream::writeNumber(const Type val)
{
    // As std::ostream: a float as the double it converts to
    char buffer[numberSize];
    put(buffer, numberText(buffer, double(val), precision()));
}


void Foam::fastOFstream::put(const char* data, const std::streamsize n)
{
    // The stream buffer itself: no sentry, no state check per character
    std::ostream& os = stdStream();
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

Foam::Ostream& Foam::fastOFstream::write(const char c)
{
    put(&c, 1);
    if (c == token::NL)
    {
        ++lineNumber_;
    }
    return *this;
}


Foam::Ostream& Foam::fastOFstream::write(const doubleScalar val)
{
    writeNumber(val);
    return *this;
}


Foam::Ostream& Foam::fastOFstream::write(const floatScalar val)
{
    writeNumber(val);
    return *this;
}


// ************************************************************************* //
