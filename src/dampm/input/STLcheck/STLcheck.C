/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "STLcheck.H"
#include "fpTrapsHeld.H"
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::STLcheck::maxCoordinate = 1e7;


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The 80-byte header and the triangle count of a binary STL
constexpr size_t headerSize = 84;

//- Bytes per triangle of a binary STL: normal, three vertices (float32),
//  attribute (uint16)
constexpr size_t triangleSize = 50;


//- Does the text start with "solid" (or "SOLID") after white space, as
//  OpenFOAM's scanner expects an ASCII file?
bool startsWithSolid(const std::string& s)
{
    size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
    {
        ++i;
    }
    return
        s.compare(i, 5, "solid") == 0 || s.compare(i, 5, "SOLID") == 0;
}


//- Is the keyword tok, in lower or upper case (as OpenFOAM's scanner)?
bool isKeyword(const std::string& tok, const char* key)
{
    bool lower = true, upper = true;
    size_t i = 0;
    for (; key[i] && i < tok.size(); ++i)
    {
        lower = lower && tok[i] == key[i];
        upper = upper
         && tok[i] == char(std::toupper(static_cast<unsigned char>(key[i])));
    }
    return !key[i] && i == tok.size() && (lower || upper);
}


//- A number as OpenFOAM's scanner reads one: [+-] digits [. digits]
//  [e [+-] digits] (no nan, inf or hexadecimal)
bool isNumber(const std::string& t)
{
    size_t i = 0;
    const size_t n = t.size();
    auto digits = [&]()
    {
        const size_t first = i;
        while (i < n && std::isdigit(static_cast<unsigned char>(t[i])))
        {
            ++i;
        }
        return i - first;
    };
    if (i < n && (t[i] == '+' || t[i] == '-'))
    {
        ++i;
    }
    size_t nDigits = digits();
    if (i < n && t[i] == '.')
    {
        ++i;
        nDigits += digits();
    }
    if (!nDigits)
    {
        return false;
    }
    if (i < n && (t[i] == 'e' || t[i] == 'E'))
    {
        ++i;
        if (i < n && (t[i] == '+' || t[i] == '-'))
        {
            ++i;
        }
        if (!digits())
        {
            return false;
        }
    }
    return i == n;
}


//- A token for a message: at most 24 characters, non-text shown as '?'
std::string shown(const std::string& tok)
{
    std::string s(tok, 0, 24);
    for (char& c : s)
    {
        if (!std::isprint(static_cast<unsigned char>(c)))
        {
            c = '?';
        }
    }
    return "'" + s + (tok.size() > 24 ? "...'" : "'");
}


//- What is allowed of a vertex coordinate, for the messages
std::string allowedCoordinates()
{
    std::ostringstream os;
    const Foam::scalar bound = Foam::STLcheck::maxCoordinate;
    os  << "allowed: finite coordinates within " << bound << " m of the"
        << " origin (|x|, |y|, |z| <= " << bound << " m)";
    return os.str();
}


//- The words of an ASCII STL with their line numbers
class wordScanner
{
    const std::string& s_;
    size_t pos_;
    Foam::label line_;

public:

    explicit wordScanner(const std::string& s)
    :
        s_(s),
        pos_(0),
        line_(1)
    {}

    //- The next word and its line; false at the end
    bool next(std::string& word, Foam::label& line)
    {
        while (pos_ < s_.size())
        {
            const unsigned char c = static_cast<unsigned char>(s_[pos_]);
            if (!std::isspace(c))
            {
                break;
            }
            line_ += (c == '\n');
            ++pos_;
        }
        if (pos_ >= s_.size())
        {
            line = line_;
            return false;
        }
        const size_t first = pos_;
        while
        (
            pos_ < s_.size()
         && !std::isspace(static_cast<unsigned char>(s_[pos_]))
        )
        {
            ++pos_;
        }
        word.assign(s_, first, pos_ - first);
        line = line_;
        return true;
    }

    //- Skip the rest of the line (a solid's name)
    void skipLine()
    {
        while (pos_ < s_.size() && s_[pos_] != '\n')
        {
            ++pos_;
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::STLcheck::refuseCoordinate
(
    const scalar x,
    const std::string& where
)
{
    std::ostringstream os;
    os  << where << " has the coordinate " << x << "; "
        << allowedCoordinates();
    error_ = os.str();
}


void Foam::STLcheck::checkBinary(const std::string& bytes)
{
    for (label t = 0; t < nTriangles_; ++t)
    {
        // The three vertices follow the normal (not used: OpenFOAM computes
        // its own)
        const char* v = bytes.data() + headerSize + t*triangleSize + 12;
        for (int k = 0; k < 9; ++k)
        {
            std::uint32_t bits;
            std::memcpy(&bits, v + 4*k, 4);
            // The bits first: a signalling NaN is not loaded
            const bool nonFinite = ((bits >> 23) & 0xff) == 0xff;
            float x = 0;
            if (!nonFinite)
            {
                std::memcpy(&x, &bits, 4);
            }
            if (nonFinite || !allowedCoordinate(x))
            {
                // The message only for the refused vertex
                std::ostringstream where;
                where
                    << "triangle " << t + 1 << " of " << nTriangles_
                    << " (counted from 1), vertex " << k/3 + 1;
                if (nonFinite)
                {
                    error_ = where.str()
                      + " has a coordinate that is not a number (NaN) or is"
                        " infinite; " + allowedCoordinates();
                }
                else
                {
                    refuseCoordinate(x, where.str());
                }
                return;
            }
        }
    }
}


void Foam::STLcheck::checkAscii(const std::string& text)
{
    wordScanner words(text);
    std::string tok;
    label line = 0;

    // The next word must be key; else error_ says what was found, or
    // that the file ended inside what began at line 'begun'
    auto expect = [&](const char* key, const char* inside, label begun)
    {
        if (!words.next(tok, line))
        {
            error_ = "the file ends at line " + std::to_string(line)
              + " inside the " + inside + " begun at line "
              + std::to_string(begun) + ", before '" + key + "'";
            return false;
        }
        if (!isKeyword(tok, key))
        {
            error_ = "line " + std::to_string(line) + ": expected '" + key
              + "' but found " + shown(tok);
            return false;
        }
        return true;
    };

    // Three numbers; vertices are checked, normals and colours only read
    auto numbers = [&](const bool vertex, const char* inside, label begun)
    {
        for (int k = 0; k < 3; ++k)
        {
            if (!words.next(tok, line))
            {
                error_ = "the file ends at line " + std::to_string(line)
                  + " inside the " + inside + " begun at line "
                  + std::to_string(begun) + ", before its three numbers";
                return false;
            }
            scalar x = 0;
            if (!isNumber(tok) || (vertex && !fpTrapsHeld::readFinite(tok, x)))
            {
                error_ = "line " + std::to_string(line) + ": expected a"
                    " finite decimal number but found " + shown(tok)
                  + (vertex ? "; " + allowedCoordinates() : std::string());
                return false;
            }
            if (vertex && !allowedCoordinate(x))
            {
                refuseCoordinate(x, "line " + std::to_string(line));
                return false;
            }
        }
        return true;
    };

    nTriangles_ = 0;
    while (words.next(tok, line))
    {
        if (!isKeyword(tok, "solid"))
        {
            error_ = "line " + std::to_string(line) + ": expected 'solid' or"
                " the end of the file, but found " + shown(tok);
            return;
        }
        const label solidLine = line;
        words.skipLine();
        while (true)
        {
            if (!words.next(tok, line))
            {
                error_ = "the file ends at line " + std::to_string(line)
                  + " inside the solid begun at line "
                  + std::to_string(solidLine) + ": no 'endsolid' (the file"
                    " is incomplete, or was cut short)";
                return;
            }
            if (isKeyword(tok, "endsolid"))
            {
                words.skipLine();
                break;
            }
            if (isKeyword(tok, "color"))
            {
                if (!numbers(false, "colour", line))
                {
                    return;
                }
                continue;
            }
            if (!isKeyword(tok, "facet"))
            {
                error_ = "line " + std::to_string(line) + ": expected"
                    " 'facet' or 'endsolid' but found " + shown(tok);
                return;
            }
            const label facetLine = line;
            if (!words.next(tok, line))
            {
                error_ = "the file ends at line " + std::to_string(line)
                  + " inside the facet begun at line "
                  + std::to_string(facetLine);
                return;
            }
            if (isKeyword(tok, "normal"))
            {
                if (!numbers(false, "facet", facetLine))
                {
                    return;
                }
                if (!expect("outer", "facet", facetLine))
                {
                    return;
                }
            }
            else if (!isKeyword(tok, "outer"))
            {
                error_ = "line " + std::to_string(line) + ": expected"
                    " 'normal' or 'outer' but found " + shown(tok);
                return;
            }
            if (!expect("loop", "facet", facetLine))
            {
                return;
            }
            for (int v = 0; v < 3; ++v)
            {
                if
                (
                    !expect("vertex", "facet", facetLine)
                 || !numbers(true, "facet", facetLine)
                )
                {
                    return;
                }
            }
            if
            (
                !expect("endloop", "facet", facetLine)
             || !expect("endfacet", "facet", facetLine)
            )
            {
                if (isKeyword(tok, "vertex"))
                {
                    error_ += " (a facet has exactly three vertices)";
                }
                return;
            }
            ++nTriangles_;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::STLcheck::STLcheck(const fileName& path)
:
    binary_(false),
    nTriangles_(0)
{
    std::ifstream is(path, std::ios::binary);
    if (!is.good())
    {
        error_ = "cannot open it";
        return;
    }
    const std::string bytes
    (
        (std::istreambuf_iterator<char>(is)),
        std::istreambuf_iterator<char>()
    );

    // Binary by its size. An ASCII file cannot pass for binary: its bytes
    // 80-83 are text, which declares more than 1.5e8 triangles (7.5 GB)
    std::uint64_t expected = 0;
    std::uint32_t declared = 0;
    if (bytes.size() >= headerSize)
    {
        std::memcpy(&declared, bytes.data() + 80, 4);
        expected = headerSize + triangleSize*std::uint64_t(declared);
    }
    const bool solid = startsWithSolid(bytes);
    binary_ = bytes.size() >= headerSize && bytes.size() == expected;

    if (binary_)
    {
        nTriangles_ = label(declared);
        checkBinary(bytes);
    }
    else if (solid)
    {
        checkAscii(bytes);
    }
    else
    {
        std::ostringstream os;
        os  << "it is neither an ASCII STL (which starts with 'solid') nor"
            << " a valid binary STL (";
        if (bytes.size() >= headerSize)
        {
            os  << "84 + 50 x " << declared << " = " << expected
                << " bytes for the " << declared << " triangles its header"
                << " declares, but ";
        }
        os  << bytes.size() << " bytes)";
        error_ = os.str();
        return;
    }
    if (error_.empty() && nTriangles_ == 0)
    {
        error_ = "it holds no triangle";
    }
}


// ************************************************************************* //
