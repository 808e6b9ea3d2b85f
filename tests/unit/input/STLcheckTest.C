/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    STLcheck: the format by the size rule (a binary file whose header starts
    with "solid" is binary), ASCII in the forms OpenFOAM's scanner reads
    (upper case, colour lines, facets without normal, several solids), and
    every refusal with where and what is allowed: NaN (also signalling, with
    the traps on: no signal), infinite and out-of-range vertices, the bound
    itself accepted, a missing endsolid, a facet cut short or of four
    vertices, text that is neither format, an empty solid.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "STLcheck.H"
#include "stlText.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <cfenv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace Foam;

namespace
{

//- Binary STL bytes; bits: {(triangle, vertex, component): raw uint32}
std::string binary
(
    const triangleList& tris,
    const std::string& header,
    const std::map<std::tuple<int, int, int>, std::uint32_t>& bits = {}
)
{
    std::string s(header);
    s.resize(80, ' ');
    const std::uint32_t n = std::uint32_t(tris.size());
    s.append(reinterpret_cast<const char*>(&n), 4);
    for (size_t t = 0; t < tris.size(); ++t)
    {
        s.append(12, '\0');
        for (int v = 0; v < 3; ++v)
        {
            for (int c = 0; c < 3; ++c)
            {
                const auto it = bits.find(std::make_tuple(int(t), v, c));
                std::uint32_t raw;
                if (it != bits.end())
                {
                    raw = it->second;
                }
                else
                {
                    std::memcpy(&raw, &tris[t][v][c], 4);
                }
                s.append(reinterpret_cast<const char*>(&raw), 4);
            }
        }
        s.append(2, '\0');
    }
    return s;
}


//- Write the bytes to a test file and check it. One file per process: CTest
//  runs the tests of this suite in parallel (Alltest: -j 2), and a shared
//  file was read while another test rewrote it
STLcheck checked(const std::string& bytes)
{
    const fileName dir(scratchDir("STLcheck"));
    mkDir(dir);
    const fileName path(dir/("surface" + Foam::name(pid()) + ".stl"));
    std::ofstream(path, std::ios::binary) << bytes;
    const STLcheck result(path);
    rm(path);
    return result;
}


//- Does the text hold every word?
::testing::AssertionResult holds
(
    const std::string& text,
    const std::vector<std::string>& words
)
{
    for (const std::string& w : words)
    {
        if (text.find(w) == std::string::npos)
        {
            return ::testing::AssertionFailure()
                << "'" << w << "' not in: " << text;
        }
    }
    return ::testing::AssertionSuccess();
}

const std::string allowed
(
    "allowed: finite coordinates within 1e+07 m of the origin"
);

} // End anonymous namespace


TEST(STLcheck, BinaryWithSolidHeaderIsBinary)
{
    const STLcheck s(checked(binary(cube(), "solid cube from a CAD tool")));
    EXPECT_TRUE(s.valid()) << s.error();
    EXPECT_TRUE(s.binary());
    EXPECT_EQ(s.nTriangles(), 12);
}


TEST(STLcheck, AsciiInTheFormsOpenFOAMReads)
{
    const STLcheck plain(checked(ascii(cube())));
    EXPECT_TRUE(plain.valid()) << plain.error();
    EXPECT_FALSE(plain.binary());
    EXPECT_EQ(plain.nTriangles(), 12);

    // Upper case, a colour line, a facet without normal, two solids
    std::string upper(ascii(cube()));
    for (char& c : upper)
    {
        c = char(std::toupper(static_cast<unsigned char>(c)));
    }
    std::string variety
    (
        "solid a\ncolor 0.5 0.5 0.5\n" + ascii(cube()).substr(11)
    );
    variety.replace(variety.find("facet normal 0 0 0"), 18, "facet");
    const STLcheck u(checked(upper + ascii(cube())));
    EXPECT_TRUE(u.valid()) << u.error();
    EXPECT_EQ(u.nTriangles(), 24);
    const STLcheck v(checked(variety));
    EXPECT_TRUE(v.valid()) << v.error();
    EXPECT_EQ(v.nTriangles(), 12);
}


TEST(STLcheck, NonFiniteBinaryVerticesRefusedWithoutSignal)
{
    // The traps of FOAM_SIGFPE on: a signalling NaN loaded into a register
    // would end the test with a signal
    const int traps = fegetexcept();
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    const STLcheck quiet
    (
        checked(binary(cube(), "solid", {{{3, 1, 0}, 0x7fc00000u}}))
    );
    const STLcheck signalling
    (
        checked(binary(cube(), "b", {{{6, 2, 1}, 0x7f800001u}}))
    );
    const STLcheck infinite
    (
        checked(binary(cube(), "b", {{{0, 0, 2}, 0xff800000u}}))
    );
    fedisableexcept(FE_ALL_EXCEPT);
    feenableexcept(traps);

    EXPECT_TRUE(holds(quiet.error(), {"triangle 4 of 12", "vertex 2",
        "not a number (NaN) or is infinite", allowed}));
    EXPECT_TRUE(holds(signalling.error(), {"triangle 7 of 12", "vertex 3",
        "not a number (NaN)", allowed}));
    EXPECT_TRUE(holds(infinite.error(), {"triangle 1 of 12", "vertex 1",
        "infinite", allowed}));
}


TEST(STLcheck, CoordinateBoundIsInclusive)
{
    triangleList at(cube()), beyond(cube());
    at[2][0][0] = 1e7f;
    beyond[2][0][0] = -1.5e7f;
    EXPECT_TRUE(checked(binary(at, "b")).valid());
    EXPECT_TRUE
    (
        holds(checked(binary(beyond, "b")).error(),
            {"triangle 3 of 12", "vertex 1", "-1.5e+07", allowed})
    );
    EXPECT_TRUE(checked(ascii(at)).valid());
    EXPECT_TRUE
    (
        holds(checked(ascii(beyond)).error(),
            {"line 18", "-1.5e+07", allowed})
    );
}


TEST(STLcheck, BrokenAsciiRefusedWithItsLine)
{
    const std::string text(ascii(cube()));
    EXPECT_TRUE
    (
        holds(checked(ascii(cube(), false)).error(),
            {"ends at line 86", "solid begun at line 1", "no 'endsolid'"})
    );

    // Cut after "vertex 0" of facet 3's second vertex (line 19; the facet
    // begins at line 16)
    size_t line19 = 0;
    for (int l = 1; l < 19; ++l)
    {
        line19 = text.find('\n', line19) + 1;
    }
    EXPECT_TRUE
    (
        holds(checked(text.substr(0, line19 + 14)).error(),
            {"ends at line 19", "facet begun at line 16",
             "before its three numbers"})
    );

    std::string four(text);
    four.insert(four.find("    endloop"), "      vertex 0 0 0\n");
    EXPECT_TRUE
    (
        holds(checked(four).error(),
            {"line 7", "expected 'endloop' but found 'vertex'",
             "exactly three vertices"})
    );

    std::string overflow(text);
    overflow.replace(overflow.find("vertex 1.0") + 7, 8, "1e400");
    EXPECT_TRUE
    (
        holds(checked(overflow).error(),
            {"expected a finite decimal number but found '1e400'", allowed})
    );
    std::string nan(text);
    nan.replace(nan.find("vertex 0.0") + 7, 8, "nan");
    EXPECT_TRUE(holds(checked(nan).error(), {"found 'nan'"}));
}


TEST(STLcheck, NeitherFormatOrNoTriangleRefused)
{
    EXPECT_TRUE
    (
        holds(checked(std::string(200, '\x01')).error(),
            {"neither an ASCII STL", "84 + 50 x 16843009", "200 bytes"})
    );
    EXPECT_TRUE
    (
        holds(checked("solid empty\nendsolid empty\n").error(),
            {"holds no triangle"})
    );
    EXPECT_TRUE(holds(checked("").error(), {"neither", "0 bytes"}));
}


// ************************************************************************* //
