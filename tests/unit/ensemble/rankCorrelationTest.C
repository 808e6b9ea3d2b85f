/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    rankCorrelation on the probabilities of a design: Spearman's
    coefficient with ties against a hand count; the induced rank
    correlation near its target, on average over 100 seeds and for each,
    and the other pairs near 0; each parameter keeps its probabilities
    (the same multiset), so a Latin hypercube keeps one member per
    stratum; a sample of one member more than parameters; no correlations
    leave the probabilities and the generator untouched.

\*---------------------------------------------------------------------------*/

#include "rankCorrelation.H"
#include "oneMemberPerStratum.H"
#include "IStringStream.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>

using namespace Foam;

namespace
{

//- rankCorrelation of the text (an ensembleDict's correlations entry)
//  among the parameters a, b and c
rankCorrelation correlationOf(const std::string& text, const label nMembers)
{
    IStringStream is(text);
    const wordList names({"a", "b", "c"});
    return rankCorrelation(dictionary(is), names, nMembers);
}


//- The values of x in increasing order
std::vector<double> sorted(std::vector<double> x)
{
    std::sort(x.begin(), x.end());
    return x;
}

} // End anonymous namespace


TEST(rankCorrelation, SpearmanGivesTiesTheirMeanRank)
{
    // Ranks (0 1 2 3 4) and (0 1 2.5 4 2.5): deviations (-2 -1 0 1 2) and
    // (-2 -1 0.5 2 0.5), products 8, squares 10 and 9.5
    EXPECT_DOUBLE_EQ
    (
        rankCorrelation::spearman({1, 2, 3, 4, 5}, {5, 6, 7, 8, 7}),
        8/std::sqrt(95.0)
    );
    // Any increasing map keeps the ranks
    EXPECT_DOUBLE_EQ(rankCorrelation::spearman({1, 2, 3}, {1, 10, 1000}), 1);
    EXPECT_DOUBLE_EQ(rankCorrelation::spearman({1, 2, 3}, {0, -1, -5}), -1);
}


TEST(rankCorrelation, LatinHypercubeReachesTargetAndKeepsItsStrata)
{
    constexpr label n = 200;
    const rankCorrelation correlation
    (
        correlationOf("correlations ((a b -0.6));", n)
    );
    // Iman-Conover gives the scores the target's Pearson correlation
    // exactly; their ranks' correlation scatters about the target with
    // the sampling error of the ranks, which is small for N >> parameters:
    // a standard deviation of 0.017 at 200 members and 3 parameters
    // (measured over 1000 seeds, largest error 0.068), so 0.07 per seed,
    // and 0.006 for the mean of 100 seeds (3.5 of its standard deviations;
    // without the arcsine conversion of the target it would be 0.021 off)
    constexpr double tolSeed = 0.07;
    constexpr double tolMean = 0.006;
    // The pairs not given scatter about 0 as much (largest 0.074 over 1000
    // seeds; 1/sqrt(N - 1) = 0.07 is one standard deviation without the
    // induction)
    constexpr double tolZero = 0.1;
    constexpr label nSeeds = 100;
    double sum = 0;
    for (label seed = 1; seed <= nSeeds; ++seed)
    {
        std::mt19937_64 rng(seed);
        samplingDesign::probabilities u =
            samplingDesign::latinHypercube(rng, 3, n);
        const samplingDesign::probabilities before(u);
        correlation.induce(rng, u);

        const double ab = rankCorrelation::spearman(u[0], u[1]);
        sum += ab;
        EXPECT_NEAR(ab, -0.6, tolSeed) << "seed " << seed;
        EXPECT_NEAR(rankCorrelation::spearman(u[0], u[2]), 0, tolZero);
        EXPECT_NEAR(rankCorrelation::spearman(u[1], u[2]), 0, tolZero);
        EXPECT_TRUE(oneMemberPerStratum(u)) << "seed " << seed;
        for (label parami = 0; parami < 3; ++parami)
        {
            EXPECT_EQ(sorted(u[parami]), sorted(before[parami]));
        }
    }
    EXPECT_NEAR(sum/nSeeds, -0.6, tolMean);
}


TEST(rankCorrelation, MonteCarloOfFewMembersGetsTheSign)
{
    // One member more than parameters: the scores' columns are drawn
    // until independent; the sample keeps its probabilities. Four members
    // have rank correlations in steps of 0.2: a target of 0.9 gives 0.8 or
    // 1 (so for each of 1000 seeds tried)
    const rankCorrelation correlation
    (
        correlationOf("correlations ((a c 0.9) (b a -0.2));", 4)
    );
    std::mt19937_64 rng(8);
    samplingDesign::probabilities u = samplingDesign::monteCarlo(rng, 3, 4);
    const samplingDesign::probabilities before(u);
    correlation.induce(rng, u);
    EXPECT_GT(rankCorrelation::spearman(u[0], u[2]), 0);
    for (label parami = 0; parami < 3; ++parami)
    {
        EXPECT_EQ(sorted(u[parami]), sorted(before[parami]));
    }
}


TEST(rankCorrelation, NoCorrelationsLeaveSampleAndGeneratorAlone)
{
    for (const std::string text : {"", "correlations ();"})
    {
        const rankCorrelation correlation(correlationOf(text, 10));
        EXPECT_TRUE(correlation.pairs().empty());
        std::mt19937_64 rng(4);
        samplingDesign::probabilities u =
            samplingDesign::latinHypercube(rng, 3, 10);
        const samplingDesign::probabilities before(u);
        std::mt19937_64 untouched(rng);
        correlation.induce(rng, u);
        EXPECT_EQ(u, before);
        EXPECT_EQ(rng(), untouched());
    }
}


// ************************************************************************* //
