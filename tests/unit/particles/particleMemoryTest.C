/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    particleMemory: the seed positions of a box counted without a loop, the
    bytes of a particle from its columns, a request beyond the memory or
    beyond 32-bit labels refused with the numbers before anything is
    allocated, the room reserved for what fits, and a failed allocation
    ending as a FatalError.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "particleMemory.H"
#include "testCase.H"
#include <gtest/gtest.h>
#include <cmath>
#include <new>
#include <random>

using namespace Foam;

namespace
{

gridGeometry grid3D()
{
    return uniformGrid(3, {-1, 2, 0.5}, {0.5, 0.25, 1}, {7, 5, 3});
}


//- Where the failed allocation's pointer goes, so that it is not elided
void* volatile allocated = nullptr;

} // End anonymous namespace


TEST(particleMemory, SeedsInBoxCountsTheGridPositionsInside)
{
    const gridGeometry g = grid3D();
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-0.3, 1.3);
    for (const label n : {1, 2, 3})
    {
        for (int trial = 0; trial < 50; ++trial)
        {
            // Boxes inside, across and outside the grid
            point lo, hi;
            for (int d = 0; d < 3; ++d)
            {
                const double a = g.origin[d] + u(gen)*g.nCells[d]*g.dx[d];
                const double b = g.origin[d] + u(gen)*g.nCells[d]*g.dx[d];
                lo[d] = min(a, b);
                hi[d] = max(a, b);
            }
            const boundBox box(lo, hi);
            label inside = 0;
            for (label k = 0; k < g.nCells[2]*n; ++k)
            {
                for (label j = 0; j < g.nCells[1]*n; ++j)
                {
                    for (label i = 0; i < g.nCells[0]*n; ++i)
                    {
                        const point x
                        (
                            g.origin[0] + (i + 0.5)*g.dx[0]/n,
                            g.origin[1] + (j + 0.5)*g.dx[1]/n,
                            g.origin[2] + (k + 0.5)*g.dx[2]/n
                        );
                        inside += box.contains(x);
                    }
                }
            }
            EXPECT_EQ(particleMemory::seedsInBox(g, n, box), inside)
                << "box (" << lo.x() << ' ' << lo.y() << ' ' << lo.z()
                << ") to (" << hi.x() << ' ' << hi.y() << ' ' << hi.z()
                << "), " << n << " per cell";
        }
    }
}


TEST(particleMemory, BytesPerParticleCountEveryColumn)
{
    particleArrays p;
    const double standard = particleMemory::bytesPerParticle(p);
    p.addField("sigma", particleArrays::fieldKind::symmTensor);
    p.addField("work", particleArrays::fieldKind::internal, 0, 5);
    EXPECT_EQ(p.nComponentArrays(), 8 + 6 + 5);
    EXPECT_EQ(particleMemory::bytesPerParticle(p) - standard, 1.125*11*8);
    // The columns and the sort's scratch column with the room kept around
    // them (an eighth), the cell and order labels and the solvers' work
    // arrays
    EXPECT_EQ
    (
        particleMemory::bytesPerParticle(p),
        1.125*8*(19 + 1) + 2*sizeof(label) + particleMemory::workBytes
    );
}


TEST(particleMemory, RequestBeyondLabelsIsRefusedWithTheCount)
{
    particleArrays p;
    const std::string msg = foamErrorMessage
    (
        [&]{ particleMemory::reserve(p, 3e9, "the test's region"); }
    );
    EXPECT_NE(msg.find("3e+09 particles requested by the test's region"),
        std::string::npos) << msg;
    EXPECT_NE(msg.find("2147483647 in all, 32-bit labels"), std::string::npos)
        << msg;
    EXPECT_EQ(p.size(), 0);
}


TEST(particleMemory, RequestBeyondTheMemoryIsRefusedBeforeAllocating)
{
    const double free = particleMemory::available();
    ASSERT_TRUE(free > 0 && std::isfinite(free))
        << "no MemAvailable in /proc/meminfo";
    const gridGeometry g = grid3D();
    particleArrays p;
    // Ten times the memory, within 32-bit labels (columns added)
    while (10*free/particleMemory::bytesPerParticle(p) > 2e9)
    {
        p.addField
        (
            "pad" + std::to_string(p.nComponentArrays()),
            particleArrays::fieldKind::internal,
            0,
            100
        );
    }
    const double n = std::ceil(10*free/particleMemory::bytesPerParticle(p));
    const std::string msg = foamErrorMessage
    (
        [&]{ particleMemory::reserve(p, n, "the test's release", g, 8); }
    );
    for
    (
        const std::string& words
      : {
            std::string("particles requested by the test's release"),
            std::string("particlesPerCell 8 (512 per cell) and the mesh of"
                " 7 x 5 x 3 cells"),
            std::string("bytes needed"),
            std::string("bytes available (MemAvailable"),
            std::string("Allowed: at most")
        }
    )
    {
        EXPECT_NE(msg.find(words), std::string::npos) << words << ": " << msg;
    }
    EXPECT_EQ(p.size(), 0);
}


TEST(particleMemory, WhatFitsIsReservedAtOnce)
{
    particleArrays p;
    p.append(10);
    particleMemory::reserve(p, 5000, "the test");
    const double* x = p.component(particleArrays::X);
    const double* m = p.component(particleArrays::M);
    p.append(5000);
    // No reallocation: the arrays held the room
    EXPECT_EQ(p.component(particleArrays::X), x);
    EXPECT_EQ(p.component(particleArrays::M), m);
    EXPECT_EQ(p.size(), 5010);
}


TEST(particleMemory, FailedAllocationIsAFatalError)
{
    EXPECT_EXIT
    (
        {
            Foam::FatalError.dontThrowExceptions();
            particleMemory::exitOnOutOfMemory();
            allocated = ::operator new(std::size_t(1) << 62);
        },
        ::testing::ExitedWithCode(1),
        "out of memory: an allocation failed"
    );
}


// ************************************************************************* //
