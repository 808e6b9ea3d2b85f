/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    fastOFstream writes what OFstream writes, byte for byte (a list of
    20,000 doubles of every magnitude, signed zeros, denormals, infinities,
    and floats, at precisions 6, 12, 16 and 17; and numbers between words,
    labels, changes of precision, short, uniform and long lists, longer
    than the tape it formats in parallel, labels among the numbers as in
    a cloud's positions), and counts lines as OFstream does. A number's
    text is printf's at every precision from 1 to 17 (the doubles nearest
    to the midpoints of p-digit numbers, to powers of ten, exact ties,
    every magnitude). OpenFOAM's reader reads 200,000 normal doubles
    within 1e+-290 written at exactPrecision back as the same doubles. Point
    fields (scalar and vector; mostly zeros, signed zeros, every magnitude;
    uniform), a cloud's vector field and lists (long, short, empty,
    uniform, of labels) written by
    fastWriteIO and writeList, whose long lists are formatted from memory,
    are byte for byte OpenFOAM's, in ASCII and binary, and so are lists
    whose second half repeats (or nearly repeats) the first. A file written
    where a hard link was is a new file: the file linked to is unchanged.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "fileContents.H"
#include "fastOFstream.H"
#include "OFstream.H"
#include "exactPrecision.H"
#include "scalarList.H"
#include "vectorField.H"
#include "labelList.H"
#include "pointFields.H"
#include "IOField.H"
#include "testCase.H"
#include "OSspecific.H"
#include "IFstream.H"
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unistd.h>
#include <limits>
#include <random>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Doubles of every magnitude and sign, and the special ones
scalarList testValues()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-320, 300);
    scalarList v(20000);
    forAll(v, i)
    {
        v[i] = mantissa(rng)*std::pow(10.0, exponent(rng));
    }
    const double special[] =
    {
        0.0, -0.0, 1.0, -1.0, 0.1, 1.0/3, 100, 1e-5, 12345678.9,
        123456789012345.0, std::numeric_limits<double>::denorm_min(),
        std::numeric_limits<double>::max(),
        std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()
    };
    label i = 0;
    for (const double x : special)
    {
        v[i++] = x;
    }
    return v;
}


//- Write values and a float as a list with OFstream type Stream
template<class Stream>
std::string written
(
    const fileName& file,
    const scalarList& values,
    const unsigned precision,
    label& lines
)
{
    {
        Stream os(file);
        os.precision(precision);
        os  << values << nl << 0.1f << token::SPACE << 3.25f << nl;
        lines = os.lineNumber();
    }
    return contents(file);
}

//- Write list and a newline, by fastOFstream::writeList (fast) or as
//  OpenFOAM writes it
template<class List>
void writeListLine(Ostream& os, const List& list, const bool fast)
{
    if (fast)
    {
        fastOFstream::writeList(os, list);
    }
    else
    {
        os  << list;
    }
    os  << nl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(fastOFstream, WritesWhatOFstreamWritesByteForByte)
{
    const fileName dir(scratchDir("fastOFstream"));
    mkDir(dir);
    const scalarList values(testValues());
    for (const unsigned precision : {6u, 12u, 16u, exactPrecision::digits})
    {
        label linesSlow, linesFast;
        const std::string slow =
            written<OFstream>(dir/"slow", values, precision, linesSlow);
        const std::string fast =
            written<fastOFstream>(dir/"fast", values, precision, linesFast);
        EXPECT_EQ(fast, slow) << "precision " << precision;
        EXPECT_EQ(linesFast, linesSlow);
        EXPECT_GT(linesFast, label(values.size()));
    }
}


TEST(fastOFstream, WritesANewFileWhereAHardLinkWas)
{
    // As a static field linked between time directories, written again at
    // a restart: the other time directories keep theirs
    const fileName dir(scratchDir("fastOFstream"));
    mkDir(dir);
    rm(dir/"shared");
    rm(dir/"linked");
    std::ofstream(dir/"shared") << "the first write time's";
    ASSERT_EQ(::link((dir/"shared").c_str(), (dir/"linked").c_str()), 0);
    {
        fastOFstream os(dir/"linked");
        os  << word("rewritten") << nl;
    }
    EXPECT_EQ(contents(dir/"shared"), "the first write time's");
    EXPECT_EQ(contents(dir/"linked"), "rewritten\n");
    EXPECT_NE(inode(dir/"linked"), inode(dir/"shared"));
}


TEST(fastOFstream, MixedContentKeepsItsOrderAcrossTheTape)
{
    // Numbers between words, labels, a change of precision, short and
    // uniform lists, and a list longer than the tape holds at once
    const fileName dir(scratchDir("fastOFstream"));
    mkDir(dir);
    vectorField points(600000);
    forAll(points, i)
    {
        points[i] = vector(0.1*i, -1.0/(i + 1), std::sqrt(double(i)));
    }
    auto write = [&](Ostream& os)
    {
        os  << "points" << token::SPACE << points << token::END_STATEMENT
            << nl << label(42) << token::SPACE << 1.5 << token::SPACE
            << word("word") << nl;
        os.precision(6);
        os  << scalarList({1.0/3, 2.0/3, 1.0}) << token::SPACE
            << scalarList(20, 0.25) << nl << 1.0/7 << nl;
        os.precision(17);
        os  << 1.0/7 << nl;

        // Integers between numbers on the tape, as a cloud's positions
        // ((x y z) celli, more lines than the tape holds), an integer
        // beyond a double's, and the characters that mark the tape
        forAll(points, i)
        {
            os  << points[i] << token::SPACE << label(i - 7) << nl;
        }
        os  << int64_t(-9007199254740993) << token::SPACE
            << labelList({3, -4, 5}) << char(0) << char(1) << 2.5 << nl;
        os.indent();
        os  << vector(1, 2, 3) << endl;
    };
    label linesSlow, linesFast;
    {
        OFstream os(dir/"mixedSlow");
        write(os);
        linesSlow = os.lineNumber();
    }
    {
        fastOFstream os(dir/"mixedFast");
        write(os);
        linesFast = os.lineNumber();
    }
    EXPECT_EQ(contents(dir/"mixedFast"), contents(dir/"mixedSlow"));
    EXPECT_EQ(linesFast, linesSlow);
}


TEST(fastOFstream, NumberTextIsPrintfsAtEveryPrecision)
{
    // The numbers that the rounded path is nearest to getting wrong: the
    // doubles nearest to the midpoints between two p-digit numbers (the
    // margin's; at 17 digits doubles are too far apart for most of them to
    // be near one), to powers of ten (the exponent's correction) and to
    // 9.99...95 (the carry into the next power), exact ties (halves and
    // quarters; 16-digit integers and a half, 16-digit integers and a
    // quarter: the ties at 16 and 17 digits), and random doubles of every
    // magnitude
    const scalarList random(testValues());
    std::vector<double> values(random.begin(), random.end());
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> exponent(-30, 30);
    char text[64];
    for (int i = 0; i < 68000; ++i)
    {
        const int digits = 1 + i % 17;
        std::snprintf
        (
            text, sizeof(text), "%.0f5e%d",
            std::floor(unit(rng)*std::pow(10.0, digits)), exponent(rng)
        );
        const double midpoint = std::strtod(text, nullptr);
        for (const double x : {midpoint, -midpoint})
        {
            values.push_back(x);
            values.push_back(std::nextafter(x, 0.0));
            values.push_back(std::nextafter(x, 2*x));
        }
    }
    for (int k = -40; k <= 40; ++k)
    {
        for (int digits = 1; digits <= 17; ++digits)
        {
            const double power = std::pow(10.0, k);
            const double below = power*(1 - 0.5*std::pow(10.0, -digits));
            for (const double x : {power, below})
            {
                values.push_back(x);
                values.push_back(std::nextafter(x, 0.0));
                values.push_back(std::nextafter(x, 2*x));
            }
        }
    }
    for (int i = 0; i < 4000; ++i)
    {
        values.push_back(0.5*i);
        values.push_back(-0.25*i);
        values.push_back(i/1024.0);
    }
    // Odd multiples of 1/2 in [2^51, 2^52) and of 1/4 in [2^50, 2^51): 16
    // integer digits and .5, or .25 and .75
    const std::int64_t two51 = std::int64_t(1) << 51;
    std::uniform_int_distribution<std::int64_t> odd(0, two51 - 1);
    for (int i = 0; i < 4000; ++i)
    {
        const double k = double(2*two51 + 2*odd(rng) + 1);
        values.push_back(std::ldexp(k, -1));
        values.push_back(-std::ldexp(k, -2));
    }

    char printed[64], fast[fastOFstream::numberSize];
    label nDiffer = 0;
    for (int p = 1; p <= 17; ++p)
    {
        for (const double x : values)
        {
            const int n = std::snprintf(printed, sizeof(printed), "%.*g", p, x);
            const int m = fastOFstream::numberText(fast, x, p);
            if (n != m || std::memcmp(printed, fast, n))
            {
                if (++nDiffer <= 5)
                {
                    ADD_FAILURE()
                        << "precision " << p << ": printf "
                        << std::string(printed, n) << ", numberText "
                        << std::string(fast, m);
                }
            }
        }
    }
    EXPECT_EQ(nDiffer, 0) << "of " << 17*values.size();
}


TEST(fastOFstream, AListThatRepeatsItsFirstHalfIsOpenFOAMs)
{
    // The point fields of a one-cell-thick mesh: each value on both layers
    // of points. And lists that nearly repeat (one value, a signed zero),
    // of odd length, of vectors
    const fileName dir(scratchDir("fastOFstream"));
    mkDir(dir);
    const scalarList values(testValues());
    const label half = 5000;
    scalarList repeated(2*half);
    vectorField repeatedVectors(2*half);
    for (label i = 0; i < half; ++i)
    {
        const scalar v = i % 3 ? 0 : values[i];
        repeated[i] = repeated[half + i] = v;
        repeatedVectors[i] = repeatedVectors[half + i] =
            vector(v, -v, 1.0/(i + 1));
    }
    scalarList nearly(repeated);
    nearly[2*half - 1] = -nearly[half - 1] - 1;
    scalarList signedZero(repeated);
    signedZero[1] = 0;
    signedZero[half + 1] = -0.0;
    const scalarList odd(SubList<scalar>(repeated, 2*half - 1));

    auto writeLists = [&](Ostream& os, const bool fast)
    {
        os.precision(12);
        const scalarList* const lists[] =
            {&repeated, &nearly, &signedZero, &odd};
        for (const scalarList* list : lists)
        {
            writeListLine(os, *list, fast);
        }
        writeListLine(os, repeatedVectors, fast);
    };
    label linesSlow, linesFast;
    {
        OFstream slow(dir/"halvesSlow");
        writeLists(slow, false);
        linesSlow = slow.lineNumber();
    }
    {
        fastOFstream fast(dir/"halvesFast");
        writeLists(fast, true);
        linesFast = fast.lineNumber();
    }
    EXPECT_EQ(contents(dir/"halvesFast"), contents(dir/"halvesSlow"));
    EXPECT_EQ(linesFast, linesSlow);
}


TEST(fastOFstream, OpenFOAMReadsExactPrecisionBackExactly)
{
    const fileName dir(scratchDir("fastOFstream"));
    mkDir(dir);
    // Normal doubles within 1e+-290 (OpenFOAM's tokenizer refuses a
    // denormal, and -8.0062932127950335e+300)
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> mantissa(1, 10);
    std::uniform_int_distribution<int> exponent(-290, 290);
    scalarList values(200000);
    forAll(values, i)
    {
        const double sign = i % 2 ? -1 : 1;
        values[i] = sign*mantissa(rng)*std::pow(10.0, exponent(rng));
    }
    {
        const exactPrecision exact;
        fastOFstream os(dir/"values");
        os  << values;
    }
    IFstream is(dir/"values");
    const scalarList read(is);
    ASSERT_EQ(read.size(), values.size());
    label nDiffer = 0;
    forAll(values, i)
    {
        nDiffer += !(read[i] == values[i]);
    }
    EXPECT_EQ(nDiffer, 0);
}


// ************************************************************************* //


TEST(fastOFstream, FieldsAndListsFormattedFromMemoryAreOpenFOAMs)
{
    const fileName dir = testCase::scratchCopy("fastOFstreamCase");
    testCase tc(dir);
    const pointMesh& pMesh = pointMesh::New(tc.mesh());
    const scalarList values(testValues());

    auto io = [&](const word& name)
    {
        return IOobject(name, "0", tc.mesh(), IOobject::NO_READ);
    };
    fastWriteIO<pointScalarField> h
    (
        io("h"), pMesh, dimensionedScalar("zero", dimLength, 0)
    );
    fastWriteIO<pointVectorField> U
    (
        io("U"), pMesh, dimensionedVector("zero", dimVelocity, Zero)
    );
    fastWriteIO<pointScalarField> Z
    (
        io("Z"), pMesh, dimensionedScalar("Z", dimLength, 2.5)
    );
    ASSERT_GT(h.size(), 20);
    forAll(h, i)
    {
        // Mostly zeros, as a flow over a sparse grid, and -0
        const scalar v = i % 3 ? 0 : values[i % values.size()];
        h[i] = i % 7 == 1 ? -0.0 : v;
        U[i] = vector(v, i % 5 ? 0 : 1.0/(i + 1), -v);
    }

    // Through OpenFOAM's writers (the fields' own writeData) and fastOFstream
    auto compare = [&](const regIOobject& field, auto&& own)
    {
        for (const auto fmt : {IOstream::ASCII, IOstream::BINARY})
        {
            for (const unsigned p : {6u, exactPrecision::digits})
            {
                {
                    OFstream slow(dir/"slow", fmt);
                    slow.precision(p);
                    own(slow);
                }
                {
                    fastOFstream fast(dir/"fast", fmt);
                    fast.precision(p);
                    field.writeData(fast);
                }
                EXPECT_EQ(contents(dir/"fast"), contents(dir/"slow"))
                    << field.name() << " " << IOstream::formatNames[fmt]
                    << " precision " << p;
            }
        }
    };
    compare(h, [&](Ostream& os){ h.pointScalarField::writeData(os); });
    compare(U, [&](Ostream& os){ U.pointVectorField::writeData(os); });
    compare(Z, [&](Ostream& os){ Z.pointScalarField::writeData(os); });

    // A cloud's field
    fastWriteIO<IOField<vector>> cloudU(io("cloudU"), label(5000));
    forAll(cloudU, i)
    {
        cloudU[i] = vector(values[i], i % 4 ? 0 : -0.0, 1.0/(i + 3));
    }
    compare
    (
        cloudU, [&](Ostream& os){ cloudU.IOField<vector>::writeData(os); }
    );

    // Lists: long, short, empty, uniform, and not of doubles
    const scalarList longList(SubList<scalar>(values, 50));
    const scalarList shortList(SubList<scalar>(values, 7));
    const vectorField uniform(30, vector(1, 2, 3));
    const labelList labels(identity(40));
    auto writeLists = [&](Ostream& os, const bool fast)
    {
        writeListLine(os, longList, fast);
        writeListLine(os, shortList, fast);
        writeListLine(os, scalarList(), fast);
        writeListLine(os, uniform, fast);
        writeListLine(os, labels, fast);
    };
    {
        OFstream slow(dir/"listsSlow");
        writeLists(slow, false);
    }
    {
        fastOFstream fast(dir/"listsFast");
        writeLists(fast, true);
    }
    EXPECT_EQ(contents(dir/"listsFast"), contents(dir/"listsSlow"));
}
