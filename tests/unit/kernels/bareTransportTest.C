/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Bare transport (bareTransport): the library's P2G of mass and momentum
    and G2P of velocity and position, no physics, on the layer of the
    throughput benchmarks (0.2 m cells, 2 x 2 columns per cell, quadratic
    B-splines). A uniform flow must be carried exactly: velocity, zero
    velocity gradient and displacement to round-off;
    the benchmark prints the particle-updates per second against which
    benchmarks/effectsCost sets dampmFoam's frictionless flat case.
    Size: DAMPM_BENCHMARK_CELLS cells per axis (default 250: 2.5e5
    columns); threads: OMP_NUM_THREADS.

\*---------------------------------------------------------------------------*/

#include "bareTransport.H"
#include <gtest/gtest.h>
#include <chrono>
#include <cstdlib>
#include <iostream>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;

namespace
{

// Uniform velocity [m/s]: the columns move 1.2 cm over the run, all inside
const double a[2] = {0.3, -0.2};

// Sums over 9 nodes of values O(1) m/s (velocities) or O(1)/0.2 m
// (gradients)
constexpr double exactTol = 1e-12;

// Mean of up to 1e6 positions O(50) m: round-off at most n eps 50 = 5e-9 m
// (a step too many or too few would be 3e-4 m)
constexpr double positionTol = 1e-8;

} // End anonymous namespace


TEST(bareTransportBenchmark, UniformFlowIsCarriedExactlyAndTheRateIsReported)
{
    const char* env = std::getenv("DAMPM_BENCHMARK_CELLS");
    const int nCells = env ? std::atoi(env) : 250;
    ASSERT_GT(nCells, 2);
    const int nPer = 2;
    const int nSteps = 40;
    const double dt = 1e-3;

    gridGeometry g;
    g.dim = 2;
    g.dx[0] = g.dx[1] = 0.2;
    g.nCells[0] = g.nCells[1] = nCells;
    g.finalise();

    // The release of the benchmarks: a 1 m layer, columns on the seed
    // lattice, storage in lattice order as dampmFoam seeds them
    particleArrays p;
    const label gradU =
        p.addField("gradU", particleArrays::fieldKind::tensor2D);
    const label nSide = nCells*nPer;
    p.append(nSide*nSide);
    const double seedArea = g.dx[0]*g.dx[1]/(nPer*nPer);
    for (label j = 0; j < nSide; ++j)
    {
        for (label i = 0; i < nSide; ++i)
        {
            const label k = i + nSide*j;
            const double x = (i + 0.5)*g.dx[0]/nPer;
            const double y = (j + 0.5)*g.dx[1]/nPer;
            p.column(particleArrays::X)[k] = x;
            p.column(particleArrays::Y)[k] = y;
            p.column(particleArrays::UX)[k] = a[0];
            p.column(particleArrays::UY)[k] = a[1];
            p.column(particleArrays::VOL)[k] = seedArea;
            p.column(particleArrays::M)[k] = 1300*seedArea;
        }
    }
    double mean0[2] = {0, 0};
    for (label k = 0; k < p.size(); ++k)
    {
        mean0[0] += p.column(particleArrays::X)[k]/p.size();
        mean0[1] += p.column(particleArrays::Y)[k]/p.size();
    }

    bareTransport transport(g, 1e-12*1300*seedArea);
    transport.step(p, gradU, dt);   // first touch of the node arrays

    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    for (int s = 1; s < nSteps; ++s)
    {
        transport.step(p, gradU, dt);
    }
    const double seconds =
        std::chrono::duration<double>(clock::now() - start).count();
    const double rate = double(p.size())*(nSteps - 1)/seconds;

    int nThreads = 1;
    #ifdef _OPENMP
    nThreads = omp_get_max_threads();
    #endif
    std::cout
        << "bare transport: " << p.size() << " columns, " << nSteps - 1
        << " steps, " << nThreads << " threads: " << seconds << " s, "
        << "Particle-updates per second: " << rate << std::endl;

    double err = 0, mean[2] = {0, 0};
    for (label k = 0; k < p.size(); ++k)
    {
        err = std::max(err, std::abs(p.column(particleArrays::UX)[k] - a[0]));
        err = std::max(err, std::abs(p.column(particleArrays::UY)[k] - a[1]));
        for (int c = 0; c < 4; ++c)
        {
            err = std::max(err, std::abs(p.column(gradU + c)[k]));
        }
        mean[0] += p.column(particleArrays::X)[k]/p.size();
        mean[1] += p.column(particleArrays::Y)[k]/p.size();
    }
    EXPECT_LT(err, exactTol);
    for (int d = 0; d < 2; ++d)
    {
        EXPECT_NEAR(mean[d] - mean0[d], nSteps*dt*a[d], positionTol);
    }
}


// ************************************************************************* //
