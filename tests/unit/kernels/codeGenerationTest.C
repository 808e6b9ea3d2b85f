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
    zero as written. Debian 12's GCC 12.2 with AVX-512 (-mavx512f, or
    -march=native on a CPU that has it) makes {1, 1, 0, 0} by broadcasting
    1 to all four lanes:
    - the code generation leaves AVX-512 out where GCC 12 would use it (on
      this project's AVX-512 test machines the check that fails first);
    - a constant with a zero upper half is built as written (fails on an
      AVX-512 machine with GCC 12.2 when AVX-512 is let in).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <vector>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(codeGeneration, NoAVX512WithGcc12)
{
#if defined(__AVX512F__) && defined(__GNUC__) && !defined(__clang__) \
 && __GNUC__ == 12
    FAIL()
        << "compiled with AVX-512 by GCC 12, which miscompiles it: "
        << "src/dampm/Make/codeGeneration must keep -mno-avx512f";
#endif
}


TEST(codeGeneration, ConstantWithZeroUpperHalfIsBuiltAsWritten)
{
    // As the structures' tests build their expected values: read back
    // through a volatile copy, GCC builds the constant right and the check
    // no longer shows the fault
    const std::vector<double> v({1, 1, 0, 0});
    EXPECT_EQ(v[0], 1);
    EXPECT_EQ(v[1], 1);
    EXPECT_EQ(v[2], 0);
    EXPECT_EQ(v[3], 0);
}


// ************************************************************************* //
