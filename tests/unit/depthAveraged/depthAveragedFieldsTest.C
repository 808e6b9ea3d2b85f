/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    depthAveragedFields: the fields written to the cloud keep their names
    (a restart and depthToParticles3D read them by these), the internal
    ones are not written, and the hand-over view runOut reads the columns
    of its fields.

\*---------------------------------------------------------------------------*/

#include "depthAveragedFields.H"
#include "particleCloudIO.H"
#include <gtest/gtest.h>

using namespace Foam;


TEST(depthAveragedFields, CloudFieldNamesAreThoseOfWrittenRuns)
{
    particleArrays p;
    const depthAveragedFields f(p);
    const wordList written(particleCloudIO::fieldNames(p));
    for (const word name : {"h", "A", "F", "gradU", "sigma", "Zb"})
    {
        EXPECT_TRUE(written.found(name)) << name;
    }
    for (const word name : {"gradZeta", "gradZ", "kappa", "basal"})
    {
        EXPECT_FALSE(written.found(name)) << name;
        EXPECT_TRUE(p.found(name)) << name;
    }
    EXPECT_EQ(p.field("h").first, f.h());
    EXPECT_EQ(p.field("A").first, f.A());
    EXPECT_EQ(p.field("F").first, f.F());
    EXPECT_EQ(p.field("gradU").first, f.gradU());
    EXPECT_EQ(p.field("sigma").first, f.sigma());
    EXPECT_EQ(p.field("Zb").first, f.Zb());
    EXPECT_EQ(p.field("kappa").initialValue, 1.0);
}


TEST(depthAveragedFields, RunOutViewReadsTheColumnsOfItsFields)
{
    particleArrays p;
    const depthAveragedFields f(p);
    p.append(3);
    for (label c = 0; c < p.nComponentArrays(); ++c)
    {
        for (label i = 0; i < 3; ++i)
        {
            p.component(c)[i] = 100*c + i;
        }
    }
    const runOutFields v = f.runOut(p);
    EXPECT_EQ(v.n, 3);
    for (label i = 0; i < 3; ++i)
    {
        EXPECT_EQ(v.x[i], p.component(particleArrays::X)[i]);
        EXPECT_EQ(v.y[i], p.component(particleArrays::Y)[i]);
        EXPECT_EQ(v.ux[i], p.component(particleArrays::UX)[i]);
        EXPECT_EQ(v.uy[i], p.component(particleArrays::UY)[i]);
        EXPECT_EQ(v.m[i], p.component(particleArrays::M)[i]);
        EXPECT_EQ(v.V[i], p.component(particleArrays::VOL)[i]);
        EXPECT_EQ(v.A[i], p.component(p.field("A").first)[i]);
        for (int k = 0; k < 4; ++k)
        {
            EXPECT_EQ(v.F[k][i], p.component(p.field("F").first + k)[i]);
            EXPECT_EQ
            (
                v.gradU[k][i], p.component(p.field("gradU").first + k)[i]
            );
        }
    }
}


// ************************************************************************* //
