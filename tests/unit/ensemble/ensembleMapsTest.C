/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    ensembleMaps on hand-made member rasters: exceedance maps are the
    members' indicator averages exactly, percentiles are the interpolated
    order statistics (two members, and seven checked against numbers
    computed by hand), intensity classes take the highest class any field
    exceeds, the class map follows classProbability, the run-out length of
    an L-shaped reached set is its diagonal, the GeoTIFF and the ASCII grid
    of a map hold the same doubles; rasters on another grid and missing
    ones are refused naming the files, bad maps input naming
    system/ensembleDict, the keyword and what is allowed.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "ensembleMaps.H"
#include "knownKeywords.H"
#include "exactPrecision.H"
#include "testCase.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <cmath>
#include <map>

using namespace Foam;

namespace
{

//- The maps of an ensembleDict's text, named system/ensembleDict
ensembleMaps mapsOf(const std::string& text)
{
    // Named before reading: sub-dictionaries take their names from it
    IStringStream is(text);
    is.name() = scratchDir("ensembleMapsCase")/"system"/"ensembleDict";
    const dictionary dict(is);
    return ensembleMaps(dict);
}


//- The text of the error thrown by reading text ("" when none)
std::string refusal(const std::string& text)
{
    return foamIOErrorText([&]{ mapsOf(text); });
}


//- The rasters' grid: nx x ny nodes, spacing dx, dy, the lower-left node
//  at map (1000, 2000)
struct gridShape
{
    label nx;
    label ny;
    scalar dx = 1;
    scalar dy = 1;
    vector2D lowerLeftNode = vector2D(1000, 2000);
};


//- Write a member's four rasters into dir: the values given, else zeros
void writeMember
(
    const fileName& dir,
    const gridShape& g,
    const std::map<word, scalarList>& fields
)
{
    for (const word& field : ensembleMaps::fieldNames)
    {
        const auto it = fields.find(field);
        const scalarList values
        (
            it == fields.end() ? scalarList(g.nx*g.ny, Zero) : it->second
        );
        const terrainRaster raster
        (
            vector2D::zero, g.dx, g.dy, g.nx, g.ny, values, g.lowerLeftNode
        );
        raster.writeAsc(dir/(field + ".asc"));
    }
}


//- The members' folders member.0000 ... in base
fileNameList memberDirs(const fileName& base, const label n)
{
    fileNameList dirs(n);
    forAll(dirs, memberi)
    {
        dirs[memberi] =
            base/("member." + std::to_string(10000 + memberi).substr(1));
    }
    return dirs;
}


//- The values of map name in dir (its ESRI ASCII grid)
scalarList mapValues(const fileName& dir, const word& name)
{
    return terrainRaster(dir/(name + ".asc")).values();
}


//- The maps of ensembleDict text written from members: their figures
List<ensembleMaps::memberFigures> writeMaps
(
    const std::string& text,
    const fileNameList& members,
    const fileName& outDir
)
{
    OStringStream report;
    return mapsOf(text).write(members, outDir, report);
}

} // End anonymous namespace


TEST(ensembleMaps, TwoMembersGiveIndicatorAveragesAndInterpolatedPercentiles)
{
    const fileName base(scratchDir("ensembleMapsCase"));
    rmDir(base, true);
    const gridShape g{4, 2};
    // Dyadic values: the mean of two is exact
    const scalarList a({0, 0.25, 1, 2, 0.0625, 0.5, 3, 0.75});
    const scalarList b({0, 1, 0.25, 3, 0.5, 0.5, 0.125, 0.75});
    const fileNameList members(memberDirs(base, 2));
    writeMember(members[0], g, {{"maxHeight", a}, {"maxSpeed", b}});
    writeMember(members[1], g, {{"maxHeight", b}, {"maxSpeed", a}});

    const std::string text =
        "maps { percentiles (10 90); maxHeight (0.1 0.5 2); maxSpeed (1); }";
    const fileName out(base/"maps");
    writeMaps(text, members, out);

    for (const scalar threshold : {0.1, 0.5, 2.0})
    {
        const scalarList P
        (
            mapValues
            (
                out, "P_maxHeight_gt_" + ensembleMaps::numberName(threshold)
            )
        );
        forAll(a, nodei)
        {
            const int n = (a[nodei] > threshold) + (b[nodei] > threshold);
            EXPECT_EQ(P[nodei], n/2.0)
                << "node " << nodei << " threshold " << threshold;
        }
    }
    const scalarList Pspeed(mapValues(out, "P_maxSpeed_gt_1"));
    forAll(a, nodei)
    {
        EXPECT_EQ(Pspeed[nodei], ((a[nodei] > 1) + (b[nodei] > 1))/2.0);
    }

    // Type 7 with N = 2: pos = p/100, between the smaller and the larger
    for (const word field : {"maxHeight", "maxSpeed"})
    {
        const scalarList p10(mapValues(out, field + "_p10"));
        const scalarList p50(mapValues(out, field + "_p50"));
        const scalarList p90(mapValues(out, field + "_p90"));
        forAll(a, nodei)
        {
            const scalar lo = min(a[nodei], b[nodei]);
            const scalar hi = max(a[nodei], b[nodei]);
            EXPECT_EQ(p50[nodei], (a[nodei] + b[nodei])/2) << field;
            EXPECT_DOUBLE_EQ(p10[nodei], lo + 0.1*(hi - lo)) << field;
            EXPECT_DOUBLE_EQ(p90[nodei], lo + 0.9*(hi - lo)) << field;
        }
    }
    for (const word field : {"maxIntensity", "maxDischarge"})
    {
        EXPECT_EQ(mapValues(out, field + "_p50"), scalarList(a.size(), Zero));
    }
}


TEST(ensembleMaps, PercentilesOfSevenMembersMatchHandComputedValues)
{
    const fileName base(scratchDir("ensembleMapsCase"));
    rmDir(base, true);
    const gridShape g{2, 1};
    // Node 0 holds 1 ... 7 and node 1 holds 0 0 0 10 10 10 20, shuffled
    const scalar node0[7] = {5, 1, 4, 2, 7, 3, 6};
    const scalar node1[7] = {10, 0, 20, 0, 10, 0, 10};
    const fileNameList members(memberDirs(base, 7));
    forAll(members, memberi)
    {
        writeMember
        (
            members[memberi], g,
            {{"maxIntensity", scalarList({node0[memberi], node1[memberi]})}}
        );
    }
    const fileName out(base/"maps");
    writeMaps("maps { percentiles (10 25 97.5); }", members, out);

    // By hand, pos = p/100 x 6 on the sorted values v0 ... v6:
    // p10: pos 0.6, v0 + 0.6 (v1 - v0);  p25: pos 1.5, v1 + 0.5 (v2 - v1);
    // p50: pos 3, v3;  p97.5: pos 5.85, v5 + 0.85 (v6 - v5)
    // node 0: 1.6, 2.5, 4, 6.85;  node 1: 0, 0, 10, 18.5
    constexpr double tol = 1e-12;   // p/100 x 6 is rounded (0.6, 5.85)
    const std::map<word, std::pair<scalar, scalar>> expected
    {
        {"maxIntensity_p10", {1.6, 0}},
        {"maxIntensity_p25", {2.5, 0}},
        {"maxIntensity_p50", {4, 10}},
        {"maxIntensity_p97.5", {6.85, 18.5}},
    };
    for (const auto& e : expected)
    {
        const scalarList p(mapValues(out, e.first));
        EXPECT_NEAR(p[0], e.second.first, tol) << e.first;
        EXPECT_NEAR(p[1], e.second.second, tol) << e.first;
    }
}


TEST(ensembleMaps, IntensityClassTakesTheHighestClassThatAnyFieldExceeds)
{
    const fileName base(scratchDir("ensembleMapsCase"));
    rmDir(base, true);
    const gridShape g{4, 1};
    // Heights and discharges of 4 members at 4 nodes; their classes:
    // node 0: none everywhere;
    // node 1: medium (h and q), low (h), medium (q only: h 0.05 is none),
    //         none: P(>= low) 3/4, P(>= medium) 1/2, P(high) 0;
    // node 2: high (h), medium (h 0.5 and q 1 are not above medium's 0.5
    //         and high's 1: q 1 > 0.5 is), high (h), high (q only):
    //         P 1, 1, 3/4;
    // node 3: low, none, none, none: P(>= low) 1/4
    const scalarList h[4] =
    {
        {0.05, 0.2, 2, 0.3}, {0.05, 0.2, 0.5, 0}, {0.05, 0.05, 1.5, 0},
        {0.05, 0, 0, 0}
    };
    const scalarList q[4] =
    {
        {0, 0.7, 0, 0}, {0, 0, 1, 0}, {0, 0.6, 0, 0}, {0, 0, 1.5, 0}
    };
    const fileNameList members(memberDirs(base, 4));
    forAll(members, memberi)
    {
        writeMember
        (
            members[memberi], g,
            {{"maxHeight", h[memberi]}, {"maxDischarge", q[memberi]}}
        );
    }
    const std::string classes =
        "intensityClasses {"
        " low { maxHeight 0.1; }"
        " medium { maxHeight 0.5; maxDischarge 0.5; }"
        " high { maxHeight 1; maxDischarge 1; } }";

    const fileName out(base/"maps");
    writeMaps("maps { " + classes + " classProbability 0.5; }", members, out);
    const std::map<word, scalarList> P
    {
        {"P_intensityClass_low", {0, 0.75, 1, 0.25}},
        {"P_intensityClass_medium", {0, 0.5, 1, 0}},
        {"P_intensityClass_high", {0, 0, 0.75, 0}},
    };
    for (const auto& e : P)
    {
        EXPECT_EQ(mapValues(out, e.first), e.second) << e.first;
    }
    EXPECT_EQ(mapValues(out, "intensityClass"), scalarList({0, 2, 3, 0}));

    // At 1/4, node 3's low and node 1's medium are likely enough
    const fileName out4(base/"maps4");
    writeMaps("maps { " + classes + " classProbability 0.25; }", members, out4);
    EXPECT_EQ(mapValues(out4, "intensityClass"), scalarList({0, 2, 3, 1}));

    // Only at certainty: node 2's medium
    const fileName out1(base/"maps1");
    writeMaps("maps { " + classes + " classProbability 1; }", members, out1);
    EXPECT_EQ(mapValues(out1, "intensityClass"), scalarList({0, 0, 2, 0}));
}


TEST(ensembleMaps, RunOutLengthOfAnLShapeIsItsDiagonal)
{
    const fileName base(scratchDir("ensembleMapsCase"));
    rmDir(base, true);
    // 6 x 5 nodes, dx 2, dy 3; reached: column i = 0 and row j = 0 (10
    // nodes); (5, 4) holds reachHeight itself, which is not reached
    const gridShape g{6, 5, 2, 3};
    scalarList L(g.nx*g.ny, Zero);
    for (label i = 0; i < g.nx; ++i)
    {
        L[i] = 1;
    }
    for (label j = 0; j < g.ny; ++j)
    {
        L[g.nx*j] = 0.5;
    }
    L[5 + g.nx*4] = 0.2;
    scalarList one(g.nx*g.ny, Zero);
    one[7] = 1;
    scalarList speed(g.nx*g.ny, Zero);
    speed[13] = 7.5;

    const fileNameList members(memberDirs(base, 3));
    writeMember(members[0], g, {{"maxHeight", L}, {"maxSpeed", speed}});
    writeMember(members[1], g, {{"maxHeight", one}});
    writeMember(members[2], g, {});
    const List<ensembleMaps::memberFigures> figures
    (
        writeMaps("maps { reachHeight 0.2; }", members, base/"maps")
    );

    // The ends of the L: (5 dx, 0) and (0, 4 dy), sqrt(10^2 + 12^2)
    ASSERT_EQ(figures.size(), 3);
    EXPECT_DOUBLE_EQ(figures[0].runOutLength, std::sqrt(244.0));
    EXPECT_EQ(figures[0].affectedArea, 10*2*3);
    EXPECT_EQ(figures[0].maxSpeed, 7.5);
    EXPECT_EQ(figures[1].runOutLength, 0);
    EXPECT_EQ(figures[1].affectedArea, 2*3);
    EXPECT_EQ(figures[2].runOutLength, 0);
    EXPECT_EQ(figures[2].affectedArea, 0);
    EXPECT_EQ(figures[2].maxSpeed, 0);
}


TEST(ensembleMaps, RunOutLengthIsTheFarthestPairOfAllReachedNodes)
{
    // A scattered reached set (a fixed pattern): the hull's diameter
    // against all pairs of reached nodes
    const label nx = 40;
    const label ny = 30;
    scalarList h(nx*ny, Zero);
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label k = (7*i + 13*j + i*j) % 23;
            const scalar r2 = sqr(i - 20.0) + sqr(j - 12.0);
            h[i + nx*j] = (k == 0 && r2 < 150) ? 1 : 0;
        }
    }
    const scalar dx = 2.5;
    const scalar dy = 1.5;
    const terrainRaster raster
    (
        vector2D::zero, dx, dy, nx, ny, h, vector2D::zero
    );
    scalar longest = 0;
    label nReached = 0;
    for (label a = 0; a < nx*ny; ++a)
    {
        nReached += (h[a] > 0.5);
        for (label b = 0; b < nx*ny; ++b)
        {
            if (h[a] > 0.5 && h[b] > 0.5)
            {
                const scalar Dx = (a % nx - b % nx)*dx;
                const scalar Dy = (a/nx - b/nx)*dy;
                longest = max(longest, std::sqrt(Dx*Dx + Dy*Dy));
            }
        }
    }
    ASSERT_GT(nReached, 10);
    EXPECT_EQ(ensembleMaps::runOutLength(raster, 0.5), longest);
}


TEST(ensembleMaps, GeoTiffAndAsciiMapsHoldTheSameNumbers)
{
    const fileName base(scratchDir("ensembleMapsCase"));
    rmDir(base, true);
    gridShape g{5, 3, 2.5, 2.5, vector2D(612345.25, 5123456.75)};
    const fileNameList members(memberDirs(base, 3));
    forAll(members, memberi)
    {
        scalarList h(g.nx*g.ny);
        forAll(h, nodei)
        {
            h[nodei] = std::sqrt(0.3*nodei + memberi);   // not dyadic
        }
        writeMember(members[memberi], g, {{"maxHeight", h}});
    }
    const std::string text =
        "maps { percentiles (10 90); maxHeight (0.5 1.5);"
        " intensityClasses { low { maxHeight 1; } } }";
    const fileName out(base/"maps");
    writeMaps(text, members, out);

    const terrainRaster member(members[0]/"maxHeight.asc");
    const wordList names(mapsOf(text).mapNames());
    EXPECT_EQ(names.size(), 4*3 + 2 + 2);
    for (const word& name : names)
    {
        // Read without a projection: the members' .asc have none
        const terrainRaster asc(out/(name + ".asc"));
        const terrainRaster tif(out/(name + ".tif"));
        EXPECT_EQ(tif.values(), asc.values()) << name;
        EXPECT_FALSE(tif.hasProjection()) << name;
        for (const terrainRaster* r : {&asc, &tif})
        {
            EXPECT_EQ(r->nx(), member.nx()) << name;
            EXPECT_EQ(r->ny(), member.ny()) << name;
            EXPECT_EQ(r->dx(), member.dx()) << name;
            EXPECT_EQ(r->dy(), member.dy()) << name;
            EXPECT_EQ(r->mapLowerLeft(), member.mapLowerLeft()) << name;
        }
    }
    // Node 7 of p90: pos 0.9 x 2 = 1.8 between members 1 and 2
    const scalar v1 = std::sqrt(0.3*7 + 1);
    const scalar v2 = std::sqrt(0.3*7 + 2);
    EXPECT_DOUBLE_EQ
    (
        terrainRaster(out/"maxHeight_p90.tif").values()[7], v1 + 0.8*(v2 - v1)
    );
}


TEST(ensembleMaps, MapNamesUseTheShortestExactNumbers)
{
    EXPECT_EQ(ensembleMaps::numberName(0.1), "0.1");
    EXPECT_EQ(ensembleMaps::numberName(1), "1");
    EXPECT_EQ(ensembleMaps::numberName(2.5), "2.5");
    EXPECT_EQ(ensembleMaps::numberName(97.5), "97.5");
    EXPECT_EQ(ensembleMaps::numberName(1e6), "1e+06");

    // Without maps: p50 of each field only, reached above 0.1 m
    const ensembleMaps defaults(mapsOf("members 3;"));
    EXPECT_EQ(defaults.reachHeight(), 0.1);
    EXPECT_EQ
    (
        defaults.mapNames(),
        wordList({"maxHeight_p50", "maxSpeed_p50", "maxIntensity_p50",
            "maxDischarge_p50"})
    );
    EXPECT_EQ
    (
        mapsOf("maps { percentiles (97.5); maxSpeed (0.1 2.5); }").mapNames(),
        wordList({"maxHeight_p50", "maxHeight_p97.5", "maxSpeed_p50",
            "maxSpeed_p97.5", "P_maxSpeed_gt_0.1", "P_maxSpeed_gt_2.5",
            "maxIntensity_p50", "maxIntensity_p97.5", "maxDischarge_p50",
            "maxDischarge_p97.5"})
    );
}


TEST(ensembleMaps, MisspeltMapsKeywordsAreWarnedAbout)
{
    // Every keyword read is declared: only reachHieght is unknown
    mapsOf
    (
        "maps { reachHieght 0.2; percentiles (10); maxHeight (1);"
        " maxSpeed (1); maxIntensity (1); maxDischarge (1);"
        " classProbability 0.5; intensityClasses { low { maxHeight 1;"
        " maxSpeed 1; maxIntensity 1; maxDischarge 1; } } }"
    );
    EXPECT_EQ(knownKeywords::warnUnknown(scratchDir("ensembleMapsCase")), 1);
}


TEST(ensembleMaps, MembersOnAnotherGridOrWithoutARasterAreRefused)
{
    const fileName base(scratchDir("ensembleMapsCase"));
    const gridShape g{3, 2};
    const struct
    {
        const char* name;
        gridShape other;
        std::string expected;
    } cases[] =
    {
        {"size", {4, 2}, "differ: nx x ny = 4 x 2 against 3 x 2"},
        {"spacing", {3, 2, 1, 2}, "differ: dx, dy = 1, 2 against 1, 1"},
        {
            "corner", {3, 2, 1, 1, vector2D(1000, 2000.5)},
            "differ: lower-left corner (999.5 2000) against (999.5 1999.5)"
        },
    };
    for (const auto& c : cases)
    {
        rmDir(base, true);
        const fileNameList members(memberDirs(base, 2));
        writeMember(members[0], g, {});
        writeMember(members[1], c.other, {});
        const std::string text =
            foamIOErrorText([&]{ writeMaps("", members, base/"maps"); });
        EXPECT_NE(text.find(c.expected), std::string::npos)
            << c.name << ": " << text;
        EXPECT_NE(text.find(members[1]/"maxHeight.asc"), std::string::npos)
            << text;
        EXPECT_NE(text.find(members[0]/"maxHeight.asc"), std::string::npos)
            << text;
    }

    rmDir(base, true);
    const fileNameList members(memberDirs(base, 2));
    writeMember(members[0], g, {});
    writeMember(members[1], g, {});
    rm(members[1]/"maxDischarge.asc");
    const std::string text =
        foamIOErrorText([&]{ writeMaps("", members, base/"maps"); });
    EXPECT_NE
    (
        text.find("the member raster \"" + members[1]/"maxDischarge.asc"
            + "\" is missing"),
        std::string::npos
    ) << text;
}


TEST(ensembleMaps, BadMapsInputIsRefusedNamingKeywordAndAllowedValues)
{
    const std::string fields = "(maxHeight maxSpeed maxIntensity maxDischarge)";
    const std::vector<std::pair<std::string, std::string>> cases =
    {
        {"maps 3;", "maps is not a dictionary; allowed: maps {"},
        {
            "maps { reachHeight 0; }",
            "reachHeight = 0 is invalid; allowed: reachHeight > 0 [m]"
        },
        {
            "maps { percentiles (50 10); }",
            "percentiles holds 10 after 50; allowed: percentiles in (0, 100)"
            " in increasing order"
        },
        {
            "maps { percentiles (0 50); }",
            "percentiles holds 0; allowed: percentiles in (0, 100)"
        },
        {
            "maps { percentiles (100); }",
            "percentiles holds 100; allowed: percentiles in (0, 100)"
        },
        {
            "maps { maxHeight (1 0.5); }",
            "maxHeight holds 0.5 after 1; allowed: thresholds >= 0 in"
            " increasing order"
        },
        {
            "maps { maxSpeed (-1); }",
            "maxSpeed holds -1; allowed: thresholds >= 0 in increasing order"
        },
        {
            "maps { maxDischarge (1 1); }",
            "maxDischarge holds 1 after 1; allowed: thresholds >= 0"
        },
        {
            "maps { classProbability 0; }",
            "classProbability = 0 is invalid; allowed: 0 < classProbability"
            " <= 1"
        },
        {
            "maps { classProbability 1.5; }",
            "classProbability = 1.5 is invalid; allowed: 0 < classProbability"
            " <= 1"
        },
        {
            "maps { intensityClasses { low { maxDepth 0.1; } } }",
            "class low: unknown field maxDepth; allowed: " + fields
        },
        {
            "maps { intensityClasses { low { } } }",
            "class low has no field; allowed: low { <field> <threshold>;"
            " ... } with fields " + fields
        },
        {
            "maps { intensityClasses { low 0.1; } }",
            "class low is not a dictionary; allowed: intensityClasses {"
            " <class> { <field> <threshold>; ... } ... } with fields " + fields
        },
        {
            "maps { intensityClasses { low { maxHeight -1; } } }",
            "class low: maxHeight = -1 is invalid; allowed: a threshold >= 0"
        },
        {
            "maps { intensityClasses { low { maxHeight 0.5; maxSpeed 2; }"
            " high { maxHeight 1; maxSpeed 1; } } }",
            "class high: maxSpeed 1 is lower than class low's 2; allowed:"
            " classes in increasing order"
        },
        {
            "maps { intensityClasses { } }",
            "intensityClasses has 0 classes; allowed: 1 to 255 classes"
        },
    };
    for (const auto& c : cases)
    {
        const std::string text = refusal(c.first);
        EXPECT_NE(text.find(c.second), std::string::npos)
            << c.first << "\n" << text;
        EXPECT_NE(text.find("system/ensembleDict"), std::string::npos)
            << c.first << "\n" << text;
    }

    // The numbers as written, also when the streams write 17 digits
    {
        const exactPrecision digits;
        const std::string text = refusal("maps { maxHeight (1 0.2); }");
        EXPECT_NE(text.find("maxHeight holds 0.2 after 1;"), std::string::npos)
            << text;
    }

    // Accepted: equal thresholds in successive classes, a field given in a
    // later class only
    EXPECT_EQ
    (
        refusal
        (
            "maps { intensityClasses { low { maxHeight 0.5; }"
            " high { maxHeight 0.5; maxSpeed 1; } } }"
        ),
        ""
    );
}


// ************************************************************************* //
