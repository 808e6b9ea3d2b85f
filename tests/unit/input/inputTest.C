/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Reading input: fpTrapsHeld::readFinite refuses nan, inf and 1e400 with
    the traps of FOAM_SIGFPE on (no signal) and restores them;
    strictIOdictionary::read refuses a keyword given twice (also in a
    sub-dictionary), naming it and the line, accepts #overwrite and
    #inputMode merge, and leaves OpenFOAM's default (merge) afterwards.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "fpTrapsHeld.H"
#include "strictIOdictionary.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include <fstream>
#include <gtest/gtest.h>
#include <cfenv>

using namespace Foam;

namespace
{

//- The message and line of the IOerror thrown reading text ("" if none)
std::string readError(const std::string& text, dictionary& dict)
{
    // From a file, as the solvers read them (its line numbers)
    const fileName dir(scratchDir("inputTest"));
    mkDir(dir);
    std::ofstream(dir/"dict") << text;
    try
    {
        IFstream is(dir/"dict");
        strictIOdictionary::read(is, dict);
    }
    catch (const IOerror& err)
    {
        return err.message() + " at line "
            + std::to_string(err.ioStartLineNumber());
    }
    return "";
}

} // End anonymous namespace


TEST(fpTrapsHeld, ReadFiniteRefusesNonFiniteTextWithoutSignal)
{
    const int traps = fegetexcept();
    const int foamTraps = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;
    feenableexcept(foamTraps);
    scalar x = -1;
    const bool nan = fpTrapsHeld::readFinite("nan", x);
    const bool inf = fpTrapsHeld::readFinite("-inf", x);
    const bool huge = fpTrapsHeld::readFinite("1e400", x);
    const bool word = fpTrapsHeld::readFinite("abc", x);
    const bool trailing = fpTrapsHeld::readFinite("2 m", x);
    const bool empty = fpTrapsHeld::readFinite("", x);
    const bool tiny = fpTrapsHeld::readFinite("1e-400", x);
    const scalar tinyValue = x;
    const bool plain = fpTrapsHeld::readFinite(" 2.5e3 ", x);
    const int trapsAfter = fegetexcept();
    fedisableexcept(FE_ALL_EXCEPT);
    feenableexcept(traps);

    EXPECT_FALSE(nan);
    EXPECT_FALSE(inf);
    EXPECT_FALSE(huge);
    EXPECT_FALSE(word);
    EXPECT_FALSE(trailing);
    EXPECT_FALSE(empty);
    EXPECT_TRUE(tiny);
    EXPECT_EQ(tinyValue, 0);
    EXPECT_TRUE(plain);
    EXPECT_EQ(x, 2500);
    EXPECT_EQ(trapsAfter, foamTraps);
}


TEST(strictIOdictionary, DuplicateKeywordRefusedWithLine)
{
    dictionary d;
    const std::string twice
    (
        readError("a 1;\nb\n{\n    c 2;\n    c 3;\n}\n", d)
    );
    EXPECT_NE(twice.find("duplicate keyword \"c\""), std::string::npos)
        << twice;
    EXPECT_NE(twice.find("allowed: distinct names"), std::string::npos);
    EXPECT_NE(twice.find("at line 5"), std::string::npos) << twice;
    EXPECT_EQ(entry::globalInputMode, entry::inputMode::MERGE);

    dictionary top;
    EXPECT_NE
    (
        readError("wall { a 1; }\nwall { b 2; }\n", top).find
        (
            "duplicate keyword \"wall\""
        ),
        std::string::npos
    );
}


TEST(strictIOdictionary, OverwriteAndMergeOnPurposeAccepted)
{
    dictionary d;
    EXPECT_EQ(readError("a 1;\n#overwrite a 2;\nb 1;\n", d), "");
    EXPECT_EQ(d.get<label>("a"), 2);

    dictionary m;
    EXPECT_EQ(readError("#inputMode merge\na 1;\na 3;\n", m), "");
    EXPECT_EQ(m.get<label>("a"), 3);
    EXPECT_EQ(entry::globalInputMode, entry::inputMode::MERGE);

    // An entry inherited with $name overridden (OpenFOAM's usual pattern);
    // the override itself written twice is refused
    dictionary inherit;
    EXPECT_EQ
    (
        readError("base { a 1; b 2; }\nderived\n{\n    $base;\n    b 3;\n}\n",
            inherit),
        ""
    );
    EXPECT_EQ(inherit.subDict("derived").get<label>("b"), 3);
    EXPECT_EQ(inherit.subDict("derived").get<label>("a"), 1);
    dictionary twice;
    const std::string message
    (
        readError("base { b 2; }\nderived { $base; b 3; b 4; }\n", twice)
    );
    EXPECT_NE(message.find("duplicate keyword \"b\" in derived"),
        std::string::npos) << message;

    // A plain dictionary read afterwards merges, as OpenFOAM's default
    IStringStream is("a 1;\na 4;\n");
    const dictionary plain(is);
    EXPECT_EQ(plain.get<label>("a"), 4);
}


// ************************************************************************* //
