/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    ensembleSample on a small case (constant/dampmProperties with Voellmy
    coefficients and a release): the same seed gives the same sample and
    another seed another; a Latin hypercube of 7 and of 50 members puts
    one member in each stratum of each parameter; bounds hold over many
    members; a full factorial has every combination of levels once;
    Monte Carlo reproduces discrete weights in frequency; the CSV holds the
    values to the last bit; a sample without correlations is the one
    recorded before they existed; correlations re-pair the values of the
    uncorrelated sample of the same seed to the target rank correlation
    within bounds; bad input is refused naming ensembleDict, the keyword
    and what is allowed.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "ensembleSample.H"
#include "testCase.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <cmath>
#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

using namespace Foam;

namespace
{

//- A case with the dictionary entries the parameters name
fileName ensembleCase()
{
    const fileName dir(scratchDir("ensembleCase"));
    mkDir(dir/"constant");
    mkDir(dir/"system");
    std::ofstream os(dir/"constant"/"dampmProperties");
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object dampmProperties; }\n"
        << "bedFriction Voellmy;\n"
        << "VoellmyCoeffs { phi 20; xi 200; }\n"
        << "release { type box; height 2; }\n";
    return dir;
}


//- The sample of the ensembleDict text on ensembleCase()
ensembleSample sampleOf(const std::string& text)
{
    const fileName dir(ensembleCase());
    // Named before reading: sub-dictionaries take their names from it
    IStringStream is(text);
    is.name() = dir/"system"/"ensembleDict";
    const dictionary dict(is);
    return ensembleSample(dict, dir);
}


//- Parameters xi (uniform 100 to 300) and phi (normal) with the design
std::string twoParameters(const std::string& design)
{
    return design +
        " parameters {"
        " xi { entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
        " distribution uniform; min 100; max 300; levels 2; }"
        " phi { entry \"constant/dampmProperties/VoellmyCoeffs/phi\";"
        " distribution normal; mean 20; standardDeviation 3; min 15; max 24;"
        " levels 3; } }";
}


//- Parameters xi (uniform), phi (normal) and thickness (logNormal) of a
//  Latin hypercube of 200 members with the seed and the correlations
std::string threeParameters(const label seed, const std::string& correlations)
{
    return
        "members 200; seed " + std::to_string(seed) + "; parameters {"
        " xi { entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
        " distribution uniform; min 100; max 300; }"
        " phi { entry \"constant/dampmProperties/VoellmyCoeffs/phi\";"
        " distribution normal; mean 20; standardDeviation 3; min 15;"
        " max 24; }"
        " thickness { entry \"constant/dampmProperties/release/height\";"
        " distribution logNormal; median 2; logStandardDeviation 0.3; } }"
      + correlations;
}


//- The values of x in increasing order
std::vector<double> sorted(std::vector<double> x)
{
    std::sort(x.begin(), x.end());
    return x;
}


//- The text of the error thrown by sampling text ("" when none)
std::string refusal(const std::string& text)
{
    return foamIOErrorText([&]{ sampleOf(text); });
}

} // End anonymous namespace


TEST(ensembleSample, SameSeedSameSampleAnotherSeedAnother)
{
    const ensembleSample a = sampleOf(twoParameters("members 20; seed 5;"));
    const ensembleSample b = sampleOf(twoParameters("members 20; seed 5;"));
    const ensembleSample c = sampleOf(twoParameters("members 20; seed 6;"));
    ASSERT_EQ(a.size(), 20);
    for (const label parami : {0, 1})
    {
        EXPECT_EQ(a.values(parami), b.values(parami));
        for (label memberi = 0; memberi < 20; ++memberi)
        {
            EXPECT_NE(a.values(parami)[memberi], c.values(parami)[memberi]);
        }
    }
}


TEST(ensembleSample, LatinHypercubeHasOneMemberPerStratumOfEachParameter)
{
    for (const label n : {7, 50})
    {
        // Uniform on [0, 1]: the stratum of a value is floor(x N)
        const ensembleSample s = sampleOf
        (
            "sampling latinHypercube; members " + std::to_string(n)
          + "; seed 11; parameters {"
            " a { entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
            " distribution uniform; min 0; max 1; }"
            " b { entry \"constant/dampmProperties/VoellmyCoeffs/phi\";"
            " distribution uniform; min 0; max 1; } }"
        );
        for (const label parami : {0, 1})
        {
            std::vector<label> count(n, 0);
            for (const double x : s.values(parami))
            {
                const label k = label(std::floor(x*n));
                ASSERT_GE(k, 0);
                ASSERT_LT(k, n);
                ++count[k];
            }
            for (label k = 0; k < n; ++k)
            {
                EXPECT_EQ(count[k], 1) << "stratum " << k << " of " << n;
            }
        }
    }
}


TEST(ensembleSample, WithoutCorrelationsTheSampleIsTheRecordedOne)
{
    // Drawn by the Latin hypercube as it was before correlations (and the
    // re-use of its permutation) existed
    const ensembleSample s = sampleOf
    (
        "members 20; seed 5; parameters {"
        " xi { entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
        " distribution uniform; min 100; max 300; }"
        " b { entry \"constant/dampmProperties/VoellmyCoeffs/phi\";"
        " distribution uniform; min 0; max 1; } }"
    );
    EXPECT_EQ(s.values(0)[0], 0x1.8ce59ff3b0d7ap+7);   // 198.44848596128196
    EXPECT_EQ(s.values(0)[1], 0x1.c07af39384db1p+7);   // 224.24013958927893
    EXPECT_EQ(s.values(0)[19], 0x1.fe5745aa50493p+6);  // 127.58522668948198
    EXPECT_EQ(s.values(1)[0], 0x1.65527ebf71c38p-1);   // 0.69789501273124355
    EXPECT_EQ(s.values(1)[19], 0x1.ebe68d10328d2p-2);  // 0.48037166987763869
    EXPECT_TRUE(s.correlations().empty());
}


TEST(ensembleSample, CorrelationsRepairTheValuesToTheTarget)
{
    const std::string correlations = " correlations ((phi xi -0.6));";
    const ensembleSample plain = sampleOf(threeParameters(17, ""));
    const ensembleSample s = sampleOf(threeParameters(17, correlations));
    const ensembleSample again = sampleOf(threeParameters(17, correlations));
    ASSERT_EQ(s.correlations().size(), 1u);

    // Iman-Conover comes close to the target for N >> parameters: a few
    // hundredths for 200 members and 3 parameters; the pairs not given
    // stay near 0
    constexpr double tolTarget = 0.05;
    constexpr double tolZero = 0.1;
    const auto rank = [&](const label a, const label b)
    {
        return rankCorrelation::spearman(s.values(a), s.values(b));
    };
    EXPECT_NEAR(rank(0, 1), -0.6, tolTarget);
    EXPECT_NEAR(rank(0, 2), 0, tolZero);
    EXPECT_NEAR(rank(1, 2), 0, tolZero);

    // The values of the same seed without correlations, re-paired: every
    // parameter's marginal (and Latin hypercube strata) and bounds kept
    for (const label parami : {0, 1, 2})
    {
        EXPECT_EQ(sorted(s.values(parami)), sorted(plain.values(parami)));
        EXPECT_NE(s.values(parami), plain.values(parami));
        EXPECT_EQ(s.values(parami), again.values(parami));
    }
    for (const double phi : s.values(1))
    {
        ASSERT_GE(phi, 15);
        ASSERT_LE(phi, 24);
    }
    std::vector<label> count(200, 0);
    for (const double xi : s.values(0))
    {
        ++count[label(std::floor((xi - 100)/200*200))];
    }
    EXPECT_EQ(count, std::vector<label>(200, 1));
}


TEST(ensembleSample, BoundsHoldOverManyMembers)
{
    const ensembleSample s =
        sampleOf(twoParameters("sampling monteCarlo; members 20000; seed 1;"));
    for (const double xi : s.values(0))
    {
        ASSERT_GE(xi, 100);
        ASSERT_LE(xi, 300);
    }
    double lowest = 24, highest = 15;
    for (const double phi : s.values(1))
    {
        ASSERT_GE(phi, 15);
        ASSERT_LE(phi, 24);
        lowest = std::min(lowest, phi);
        highest = std::max(highest, phi);
    }
    // The truncated normal reaches near both bounds (its density there is
    // of order 0.1 per degree: 20000 members leave no gap of 0.05)
    EXPECT_LT(lowest, 15.05);
    EXPECT_GT(highest, 23.95);
}


TEST(ensembleSample, FullFactorialGivesEveryCombinationOnce)
{
    const std::string discrete =
        " release { distribution discrete; scenarios {"
        " low { \"constant/dampmProperties/release/height\" 1; }"
        " high { constant { dampmProperties { release { height 4; } } } } } }";
    std::string text = twoParameters("sampling fullFactorial;");
    text.insert(text.rfind('}'), discrete);
    const ensembleSample s = sampleOf(text);

    // 2 x 3 levels and 2 scenarios
    ASSERT_EQ(s.size(), 12);
    std::set<std::vector<double>> combinations;
    for (label memberi = 0; memberi < s.size(); ++memberi)
    {
        combinations.insert
        (
            {s.values(0)[memberi], s.values(1)[memberi], s.values(2)[memberi]}
        );
    }
    EXPECT_EQ(combinations.size(), 12u);
    // xi's levels: the middles of [100, 200] and [200, 300]
    EXPECT_EQ(std::set<double>(s.values(0).begin(), s.values(0).end()),
        std::set<double>({150, 250}));
    EXPECT_EQ(std::set<double>(s.values(2).begin(), s.values(2).end()),
        std::set<double>({0, 1}));

    EXPECT_EQ(sampleOf("members 12; " + text).size(), 12);
    const std::string msg = refusal("members 10; " + text);
    EXPECT_NE(msg.find("members = 10 but the full factorial's levels"),
        std::string::npos) << msg;
}


TEST(ensembleSample, MonteCarloReproducesDiscreteWeights)
{
    constexpr label n = 40000;
    const ensembleSample s = sampleOf
    (
        "sampling monteCarlo; members " + std::to_string(n) + "; seed 3;"
        " parameters { xi { entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
        " distribution discrete; values (100 200 500); weights (2 5 3); } }"
    );
    std::vector<label> count(3, 0);
    for (const double xi : s.values(0))
    {
        ++count[xi == 100 ? 0 : xi == 200 ? 1 : 2];
    }
    // Binomial frequencies: standard deviation at most sqrt(0.25/n) =
    // 2.5e-3; five of them
    constexpr double tol = 1.25e-2;
    EXPECT_NEAR(count[0]/double(n), 0.2, tol);
    EXPECT_NEAR(count[1]/double(n), 0.5, tol);
    EXPECT_NEAR(count[2]/double(n), 0.3, tol);
}


TEST(ensembleSample, CsvHoldsEveryValueExactly)
{
    const ensembleSample s = sampleOf(twoParameters("members 12; seed 9;"));
    const fileName csv(ensembleCase()/"ensemble"/"samples.csv");
    rm(csv);
    s.write(csv);

    std::ifstream is(csv);
    std::string line;
    std::getline(is, line);
    EXPECT_EQ(line, "member,xi,phi");
    for (label memberi = 0; memberi < 12; ++memberi)
    {
        ASSERT_TRUE(std::getline(is, line));
        std::istringstream row(line);
        std::string member, xi, phi;
        std::getline(row, member, ',');
        std::getline(row, xi, ',');
        std::getline(row, phi, ',');
        EXPECT_EQ(member, ensembleSample::memberName(memberi, 12));
        EXPECT_EQ(std::stod(xi), s.values(0)[memberi]);
        EXPECT_EQ(std::stod(phi), s.values(1)[memberi]);
    }
    EXPECT_FALSE(std::getline(is, line));
    EXPECT_EQ(ensembleSample::memberName(7, 12), "0007");
    EXPECT_EQ(ensembleSample::memberName(123, 20000), "00123");
}


TEST(ensembleSample, BadInputIsRefusedNamingFileAndKeyword)
{
    const auto refused = [](const std::string& text, const std::string& words)
    {
        const std::string msg = refusal(text);
        EXPECT_NE(msg.find(words), std::string::npos) << text << "\n" << msg;
        EXPECT_NE(msg.find("system/ensembleDict"), std::string::npos) << msg;
    };
    refused
    (
        twoParameters("members 0; seed 1;"),
        "members = 0 is invalid; allowed: 1 <= members"
    );
    refused
    (
        twoParameters("members 5; seed -2;"),
        "seed = -2 is invalid; allowed: an integer 0 <= seed"
    );
    refused
    (
        twoParameters("sampling random; members 5; seed 1;"),
        "sampling random is invalid; allowed: sampling 3(fullFactorial"
        " latinHypercube monteCarlo)"
    );
    refused
    (
        "members 5; seed 1; parameters { xi {"
        " entry \"constant/dampmProperties/VoellmyCoeffs/xj\";"
        " distribution uniform; min 1; max 2; } }",
        "entry \"constant/dampmProperties/VoellmyCoeffs/xj\":"
        " constant/dampmProperties/VoellmyCoeffs has no xj"
    );
    refused
    (
        "members 5; seed 1; parameters { xi {"
        " entry \"constant/nonsense/xi\";"
        " distribution uniform; min 1; max 2; } }",
        "no leading part of it is a file of the case"
    );
    refused
    (
        "members 5; seed 1; parameters { xi {"
        " entry \"constant/dampmProperties/VoellmyCoeffs\";"
        " distribution uniform; min 1; max 2; } }",
        "has the dictionary VoellmyCoeffs, not a value"
    );
    refused
    (
        "members 5; seed 1; parameters { xi {"
        " entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
        " distribution gaussian; } }",
        "Unknown distribution type gaussian"
    );
    refused
    (
        "members 5; seed 1; parameters { xi {"
        " entry \"constant/dampmProperties/VoellmyCoeffs/xi\";"
        " distribution uniform; min 3; max 2; } }",
        "allowed: min < max"
    );
    refused
    (
        "members 5; seed 1; parameters { r { distribution discrete;"
        " scenarios { a { \"constant/dampmProperties/release/hieght\" 1; }"
        " } } }",
        "constant/dampmProperties/release has no hieght"
    );
    refused
    (
        twoParameters("sampling fullFactorial;").replace
        (
            twoParameters("sampling fullFactorial;").find("levels 2"), 8,
            "levels 0"
        ),
        "levels = 0 is invalid; allowed: levels >= 1"
    );
    refused
    (
        "members 5; seed 1; parameters { r { distribution uniform; min 0;"
        " max 1; scenarios { a {"
        " \"constant/dampmProperties/release/height\" 1; } } } }",
        "has scenarios but distribution uniform; allowed: distribution discrete"
    );
    refused("members 5; seed 1; parameters { }", "no parameters");

    const auto correlated = [](const std::string& pairs)
    {
        return threeParameters(1, " correlations (" + pairs + ");");
    };
    const std::string allowed =
        "allowed: (<parameter> <parameter> <rho>), two different parameters"
        " and -1 < rho < 1, each pair once";
    refused
    (
        correlated("(xi phj 0.5)"),
        "correlations entry (xi phj 0.5): no parameter phj; allowed: the"
        " parameters 3(xi phi thickness)"
    );
    refused(correlated("(xi xi 0.5)"), "correlates xi with itself; " + allowed);
    refused
    (
        correlated("(xi phi 0.5) (phi xi 0.2)"),
        "the pair phi xi is given twice; " + allowed
    );
    refused(correlated("(xi phi -1)"), "rho = -1 is invalid; " + allowed);
    refused(correlated("(xi phi)"), "(xi phi) is invalid; " + allowed);
    refused
    (
        correlated("(xi phi 0.8) (phi thickness 0.8) (xi thickness -0.5)"),
        "the correlations given do not make a positive definite matrix"
    );
    refused
    (
        threeParameters(1, " correlations ((xi phi 0.5));")
        .replace(0, 12, "members 3;"),
        "correlations among 3 parameters need more members than parameters,"
        " members = 3; allowed: members >= 4"
    );
    refused
    (
        twoParameters("sampling fullFactorial; correlations ((xi phi 0.5));"),
        "correlations are not possible with sampling fullFactorial"
    );
}


// ************************************************************************* //
