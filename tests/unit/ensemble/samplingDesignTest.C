/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The sampling designs: probabilities strictly inside (0, 1), the same
    draws from the same seed (and the recorded ones: the sample must not
    depend on the compiler or machine), a Latin hypercube with exactly one
    member in each stratum of each parameter, and a full factorial with
    every combination of levels once.

\*---------------------------------------------------------------------------*/

#include "samplingDesign.H"
#include "oneMemberPerStratum.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <set>

using namespace Foam;

TEST(samplingDesign, UnitUniformIsStrictlyInsideZeroOne)
{
    std::mt19937_64 rng(1);
    double sum = 0;
    constexpr label n = 100000;
    for (label i = 0; i < n; ++i)
    {
        const double u = samplingDesign::unitUniform(rng);
        ASSERT_GT(u, 0);
        ASSERT_LT(u, 1);
        sum += u;
    }
    // Mean of n uniforms: standard deviation sqrt(1/12/n) = 9e-4; 5 of them
    EXPECT_NEAR(sum/n, 0.5, 5e-3);
}


TEST(samplingDesign, SeedGivesTheRecordedDraws)
{
    // mt19937_64's sequence is fixed by the C++ standard, the doubles by
    // unitUniform: these are the first draws of seed 42 anywhere
    std::mt19937_64 rng(42);
    const double first = samplingDesign::unitUniform(rng);
    const double second = samplingDesign::unitUniform(rng);
    std::mt19937_64 again(42);
    EXPECT_EQ(samplingDesign::unitUniform(again), first);
    EXPECT_EQ(samplingDesign::unitUniform(again), second);
    EXPECT_EQ(first, 0x1.82a3befaddcbcp-1);   // 0.75515553295453897
    EXPECT_EQ(second, 0x1.472f1f73724ap-1);  // 0.63903139385469743
}


TEST(samplingDesign, UniformIndexCoversItsRangeEvenly)
{
    std::mt19937_64 rng(7);
    constexpr label n = 60000;
    std::vector<label> count(3, 0);
    for (label i = 0; i < n; ++i)
    {
        const auto k = samplingDesign::uniformIndex(rng, 3);
        ASSERT_LT(k, 3u);
        ++count[k];
    }
    // Each 20000 +- sqrt(n p (1 - p)) = 115; 5 standard deviations
    for (const label c : count)
    {
        EXPECT_NEAR(c, 20000, 580);
    }
}


TEST(samplingDesign, LatinHypercubeHasOneMemberPerStratum)
{
    for (const label n : {7, 50})
    {
        std::mt19937_64 rng(3);
        const samplingDesign::probabilities u =
            samplingDesign::latinHypercube(rng, 4, n);
        ASSERT_EQ(u.size(), 4u);
        EXPECT_TRUE(oneMemberPerStratum(u)) << n << " members";
        // The parameters' strata are permuted independently
        EXPECT_NE(u[0], u[1]);
    }
}


TEST(samplingDesign, FullFactorialGivesEveryCombinationOnce)
{
    const labelList levels({2, 3, 4});
    const std::vector<labelList> index = samplingDesign::fullFactorial(levels);
    ASSERT_EQ(index.size(), 3u);
    ASSERT_EQ(index[0].size(), 24);

    std::set<std::vector<label>> combinations;
    for (label memberi = 0; memberi < 24; ++memberi)
    {
        std::vector<label> c;
        forAll(levels, parami)
        {
            ASSERT_GE(index[parami][memberi], 0);
            ASSERT_LT(index[parami][memberi], levels[parami]);
            c.push_back(index[parami][memberi]);
        }
        combinations.insert(c);
    }
    EXPECT_EQ(combinations.size(), 24u);

    // The last parameter changes fastest
    EXPECT_EQ(index[2][1], 1);
    EXPECT_EQ(index[1][4], 1);
    EXPECT_EQ(index[0][12], 1);
}


// ************************************************************************* //
