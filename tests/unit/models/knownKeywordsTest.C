/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    knownKeywords: the edit distance behind "did you mean", the nearest
    keyword, and the warnings: one per undeclared keyword of a declared
    dictionary of the case, with the keywords of all its readers, none for
    other cases' dictionaries or dictionaries built in code.

\*---------------------------------------------------------------------------*/

#include "knownKeywords.H"
#include "IStringStream.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

dictionary named(const char* text, const fileName& name)
{
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = name;
    return dict;
}

} // End anonymous namespace


TEST(knownKeywords, DistanceCountsEditsSwapsAndIgnoresCase)
{
    auto d = [](const char* a, const char* b)
    {
        return knownKeywords::distance(a, b);
    };
    EXPECT_EQ(d("particlesPerCell", "particlesPerCell"), 0);
    EXPECT_EQ(d("particlesPerCel", "particlesPerCell"), 1);
    EXPECT_EQ(d("flipRatoi", "flipRatio"), 1);
    EXPECT_EQ(d("ParticlesPERcell", "particlesPerCell"), 0);
    EXPECT_EQ(d("pa", "pA"), 0);
    EXPECT_EQ(d("kitten", "sitting"), 3);
    EXPECT_EQ(d("", "rho"), 3);
}


TEST(knownKeywords, NearestIsWithinAQuarterOfTheLetters)
{
    const wordList allowed({"particlesPerCell", "flipRatio", "damping", "mu"});
    EXPECT_EQ
    (
        knownKeywords::nearest("particlesPerCel", allowed),
        "particlesPerCell"
    );
    EXPECT_EQ(knownKeywords::nearest("flipRatoi", allowed), "flipRatio");
    EXPECT_EQ(knownKeywords::nearest("dampng", allowed), "damping");
    // Nothing near
    EXPECT_EQ(knownKeywords::nearest("colour", allowed), word::null);
    EXPECT_EQ(knownKeywords::nearest("viscosity", allowed), word::null);
}


TEST(knownKeywords, WarnsOnceForEachUndeclaredKeywordOfTheCase)
{
    const fileName caseDir("/cases/test");
    dictionary top = named
    (
        "rho 1; particlesPerCel 2; CoulombCoeffs { phi 20; pa 1; }",
        caseDir/"constant"/"dampmProperties"
    );
    top.subDict("CoulombCoeffs").name() = top.name() + ".CoulombCoeffs";
    // Two readers of the top level, a base and a model of the coefficients
    knownKeywords::add(top, {"rho", "particlesPerCell"});
    knownKeywords::addSelector(top, "bedFriction", {"Coulomb", "Voellmy"});
    knownKeywords::add(top.subDict("CoulombCoeffs"), {"phi"});
    knownKeywords::add(top.subDict("CoulombCoeffs"), {"pA"});

    // Another case's dictionary, read in part, and one built in code
    const dictionary other = named
    (
        "topography flat; rho 1;", "/cases/other/constant/dampmProperties"
    );
    knownKeywords::add(other, {"topography"});
    dictionary built;
    built.add("mu", 1.0);
    built.add("nu", 1.0);
    knownKeywords::add(built, {"mu"});

    EXPECT_EQ(knownKeywords::warnUnknown(caseDir), 2);
    // Forgotten once warned
    EXPECT_EQ(knownKeywords::warnUnknown(caseDir), 0);
}


// ************************************************************************* //
