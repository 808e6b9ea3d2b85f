/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The parameter distributions' inverse CDFs against known quantiles: the
    uniform's exactly, the normal's median and 0.8413 quantile at mean and
    mean + sigma, the log-normal's at the median and median exp(sigma), the
    truncated ones inside their bounds with the truncated CDF's quantiles,
    the discrete's cumulative weights; and their bad coefficients refused
    naming the keyword and what is allowed.

\*---------------------------------------------------------------------------*/

#include "parameterDistribution.H"
#include "standardNormal.H"
#include "testCase.H"
#include "IStringStream.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

//- Phi(1): the probability below one standard deviation above the mean
constexpr double phi1 = 0.8413447460685429;

//- The quantiles' accuracy: Acklam's 1e-9 refined by a Halley step
constexpr double quantileTol = 1e-6;

//- The distribution of a parameter's dictionary text
autoPtr<parameterDistribution> distributionOf(const std::string& text)
{
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = "system/ensembleDict.parameters.p";
    return parameterDistribution::New(dict);
}

} // End anonymous namespace


TEST(parameterDistribution, UniformMapsProbabilityLinearly)
{
    const auto d = distributionOf("distribution uniform; min 2; max 6;");
    EXPECT_EQ(d->value(0.25), 3.0);
    EXPECT_EQ(d->value(0.5), 4.0);
    EXPECT_EQ(d->level(0, 4), 2.5);
    EXPECT_EQ(d->level(3, 4), 5.5);
}


TEST(parameterDistribution, StandardNormalQuantileInvertsTheCdf)
{
    // To round-off in the lower tail, where cdf keeps its relative
    // precision (above, 1 - cdf loses digits; the upper tail is the
    // mirror image): the Halley step's work
    constexpr double tol = 1e-12;
    for (double z = -8; z <= 0; z += 0.25)
    {
        EXPECT_NEAR(standardNormal::quantile(standardNormal::cdf(z)), z, tol)
            << "z = " << z;
    }
    EXPECT_NEAR(standardNormal::quantile(0.975), 1.959963984540054, 1e-14);
}


TEST(parameterDistribution, NormalMedianAndOneSigmaQuantile)
{
    const auto d =
        distributionOf("distribution normal; mean 10; standardDeviation 2;");
    EXPECT_NEAR(d->value(0.5), 10, quantileTol);
    EXPECT_NEAR(d->value(phi1), 12, quantileTol);
    EXPECT_NEAR(d->value(1 - phi1), 8, quantileTol);
}


TEST(parameterDistribution, TruncatedNormalStaysInBoundsWithTruncatedQuantiles)
{
    // Half normal: the truncated median is the untruncated 0.75 quantile
    const auto half = distributionOf
    (
        "distribution normal; mean 0; standardDeviation 1; min 0;"
    );
    EXPECT_NEAR(half->value(0.5), 0.6744897501960817, quantileTol);

    // Symmetric truncation keeps the median; the ends reach the bounds
    const auto two = distributionOf
    (
        "distribution normal; mean 5; standardDeviation 2; min 3; max 7;"
    );
    EXPECT_NEAR(two->value(0.5), 5, quantileTol);
    EXPECT_NEAR(two->value(1e-12), 3, 1e-9);
    EXPECT_NEAR(two->value(1 - 1e-12), 7, 1e-9);

    // Far in the upper tail (worked with the complementary CDF):
    // P(Z > z) = (1 - u) P(Z > 5)
    const auto tail = distributionOf
    (
        "distribution normal; mean 0; standardDeviation 1; min 5;"
    );
    for (const double u : {1e-6, 0.1, 0.5, 0.9, 0.999999})
    {
        const double z = tail->value(u);
        EXPECT_GE(z, 5);
        EXPECT_NEAR
        (
            standardNormal::complementaryCdf(z)
           /standardNormal::complementaryCdf(5),
            1 - u,
            1e-9
        ) << "u = " << u;
    }
}


TEST(parameterDistribution, LogNormalMedianAndOneSigmaQuantile)
{
    const auto d = distributionOf
    (
        "distribution logNormal; median 200; logStandardDeviation 0.5;"
    );
    EXPECT_NEAR(d->value(0.5), 200, 200*quantileTol);
    EXPECT_NEAR(d->value(phi1), 200*std::exp(0.5), 200*quantileTol);

    const auto bounded = distributionOf
    (
        "distribution logNormal; median 200; logStandardDeviation 0.5;"
        " min 150; max 250;"
    );
    for (double u = 0.0005; u < 1; u += 0.001)
    {
        const double x = bounded->value(u);
        EXPECT_GE(x, 150);
        EXPECT_LE(x, 250);
    }
}


TEST(parameterDistribution, DiscreteFollowsCumulativeWeights)
{
    const auto d = distributionOf
    (
        "distribution discrete; values (1 2 3 4); weights (1 0 2 1);"
    );
    EXPECT_EQ(d->nValues(), 4);
    EXPECT_EQ(d->value(0.2), 1);
    EXPECT_EQ(d->value(0.26), 3);
    EXPECT_EQ(d->value(0.74), 3);
    EXPECT_EQ(d->value(0.76), 4);
    EXPECT_EQ(d->level(1, 4), 2);

    // A zero weight last is never drawn, even at a u above the rounded sum
    const auto lastZero = distributionOf
    (
        "distribution discrete; values (1 2); weights (0.1 0);"
    );
    EXPECT_EQ(lastZero->value(std::nextafter(1.0, 0.0)), 1);
}


TEST(parameterDistribution, BadCoefficientsAreRefused)
{
    const auto refused = [](const std::string& text, const std::string& words)
    {
        const std::string msg =
            foamIOErrorText([&]{ distributionOf(text); });
        EXPECT_NE(msg.find(words), std::string::npos)
            << text << "\n" << msg;
        EXPECT_NE(msg.find("ensembleDict"), std::string::npos) << msg;
    };
    refused("distribution uniform; min 6; max 2;", "allowed: min < max");
    refused("distribution uniform; min 2;", "max");
    refused("distribution gaussian;", "discrete");
    refused
    (
        "distribution normal; mean 0; standardDeviation 0;",
        "standardDeviation = 0 is invalid; allowed: standardDeviation > 0"
    );
    refused
    (
        "distribution normal; mean 0; standardDeviation 1; min 40;",
        "allowed: bounds that hold a probability"
    );
    refused
    (
        "distribution logNormal; median -1; logStandardDeviation 1;",
        "median = -1 is invalid; allowed: median > 0"
    );
    refused
    (
        "distribution logNormal; median 1; logStandardDeviation 1; min -1;",
        "min = -1 is invalid; allowed: min > 0"
    );
    refused
    (
        "distribution discrete; values (1 2); weights (0 0);",
        "allowed: finite weights >= 0 with a sum > 0"
    );
    refused
    (
        "distribution discrete; values (1 2); weights (1);",
        "allowed: one weight per value"
    );
    refused("distribution discrete; values ();", "allowed: at least one");
}


// ************************************************************************* //
