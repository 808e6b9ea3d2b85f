/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The library's code generation (src/dampm/Make/codeGeneration, with which
    the tests are compiled too) must build vectors whose upper lanes are
    zero as written. Debian 12's GCC 12.2 with AVX-512 (AVX512VL) makes
    {1, 1, 0, 0} by broadcasting 1 to all four lanes: this fails when the
    code generation lets it use AVX-512 on a machine that has it.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <vector>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(codeGeneration, ConstantWithZeroUpperHalfIsBuiltAsWritten)
{
    const std::vector<double> v({1, 1, 0, 0});
    EXPECT_EQ(v[0], 1);
    EXPECT_EQ(v[1], 1);
    EXPECT_EQ(v[2], 0);
    EXPECT_EQ(v[3], 0);
}


// ************************************************************************* //
