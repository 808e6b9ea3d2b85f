/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Bare transport (bareTransport) on the layer of the throughput benchmarks
    (0.2 m cells, 2 x 2 columns per cell, quadratic B-splines, a 1 m layer
    filling the grid), 40 steps; each test prints the particle-updates per
    second against which benchmarks/effectsCost sets dampmFoam's
    frictionless flat case.
    - advect: a uniform flow must be carried exactly: velocity, zero
      velocity gradient and displacement to round-off.
    - shallowWater: the layer filling the grid is a lake at rest and stays
      at rest to round-off (timed); a block of half the grid's side in its
      middle collapses at its edges: its outermost columns move outwards,
      those more than a quarter of its side from every edge under 5 % of
      the fastest, the flow is symmetric about the block's mid-line and its
      diagonal (to round-off: the sums run in other orders), the mass is
      constant and no column is faster than the dry-bed front's
      2 sqrt(g h0) (Ritter).
    Size: DAMPM_BENCHMARK_CELLS cells per axis (default 250: 2.5e5
    columns); timed steps: DAMPM_BENCHMARK_STEPS (default 40); threads:
    OMP_NUM_THREADS.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
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

// Uniform velocity of advect [m/s]: the columns move 1.2 cm over the run
const double a[2] = {0.3, -0.2};

// Sums over 9 nodes of values O(1) m/s (velocities) or O(1)/0.2 m
// (gradients)
constexpr double exactTol = 1e-12;

// Mean of up to 1e6 positions O(50) m: round-off at most n eps 50 = 5e-9 m
// (a step too many or too few would be 3e-4 m)
constexpr double positionTol = 1e-8;

// Mirror images: velocities O(1) m/s, positions O(50) m, summed in other
// orders over 40 steps
constexpr double mirrorVelocityTol = 1e-10;
constexpr double mirrorPositionTol = 1e-10;

const double rho = 1300, gravity = 9.81, h0 = 1;
const int nPer = 2;
const int nSteps = 40;
const double dt = 1e-3;

int benchmarkCells()
{
    const char* env = std::getenv("DAMPM_BENCHMARK_CELLS");
    return env ? std::atoi(env) : 250;
}

gridGeometry benchmarkGrid(const int nCells)
{
    return uniformGrid(2, {0, 0, 0}, {0.2, 0.2, 1}, {nCells, nCells, 1});
}

// The release of the benchmarks: the h0 layer on the seed lattice (nPer
// per cell and axis), storage in lattice order as dampmFoam seeds them,
// moving at u; lattice points first to last - 1 on each axis (default: the
// whole grid). The lattice index goes to the field id if there is one.
void seedLayer
(
    const gridGeometry& g,
    particleArrays& p,
    const double u[2],
    label first = 0,
    label last = -1
)
{
    if (last < 0)
    {
        last = g.nCells[0]*nPer;
    }
    const label nSide = last - first;
    const label id = p.found("id") ? p.field("id").first : -1;
    const label start = p.append(nSide*nSide);
    const double seedArea = g.dx[0]*g.dx[1]/(nPer*nPer);
    for (label j = 0; j < nSide; ++j)
    {
        for (label i = 0; i < nSide; ++i)
        {
            const label k = start + i + nSide*j;
            const double spacing = g.dx[0]/nPer;
            p.component(particleArrays::X)[k] = (first + i + 0.5)*spacing;
            p.component(particleArrays::Y)[k] = (first + j + 0.5)*spacing;
            p.component(particleArrays::UX)[k] = u[0];
            p.component(particleArrays::UY)[k] = u[1];
            p.component(particleArrays::VOL)[k] = h0*seedArea;
            p.component(particleArrays::M)[k] = rho*h0*seedArea;
            if (id >= 0)
            {
                p.component(id)[k] = i + nSide*j;
            }
        }
    }
}

// Steps of a timed run: DAMPM_BENCHMARK_STEPS (default nSteps)
int timedSteps()
{
    const char* env = std::getenv("DAMPM_BENCHMARK_STEPS");
    return env ? std::max(std::atoi(env), 2) : nSteps;
}

// Times timedSteps() - 1 calls of step after a first (which touches the
// node arrays) and prints the rate
template<class Step>
void timeSteps(const char* name, const label nColumns, Step&& step)
{
    const int n = timedSteps();
    step();
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    for (int s = 1; s < n; ++s)
    {
        step();
    }
    const double seconds =
        std::chrono::duration<double>(clock::now() - start).count();
    int nThreads = 1;
    #ifdef _OPENMP
    nThreads = omp_get_max_threads();
    #endif
    std::cout
        << "bare transport " << name << ": " << nColumns << " columns, "
        << n - 1 << " steps, " << nThreads << " threads: " << seconds
        << " s, Particle-updates per second: "
        << double(nColumns)*(n - 1)/seconds << std::endl;
}

} // End anonymous namespace


TEST(bareTransportBenchmark, AdvectCarriesAUniformFlowExactly)
{
    const int nCells = benchmarkCells();
    ASSERT_GT(nCells, 2);
    const gridGeometry g = benchmarkGrid(nCells);
    particleArrays p;
    const label gradU =
        p.addField("gradU", particleArrays::fieldKind::tensor2D);
    seedLayer(g, p, a);

    double mean0[2] = {0, 0};
    for (label k = 0; k < p.size(); ++k)
    {
        mean0[0] += p.component(particleArrays::X)[k]/p.size();
        mean0[1] += p.component(particleArrays::Y)[k]/p.size();
    }

    const double seedArea = g.dx[0]*g.dx[1]/(nPer*nPer);
    bareTransport transport(g, 1e-12*rho*seedArea);
    timeSteps("advect", p.size(), [&]{ transport.advect(p, gradU, dt); });

    double err = 0, mean[2] = {0, 0};
    for (label k = 0; k < p.size(); ++k)
    {
        err = std::max(err, std::abs(p.component(particleArrays::UX)[k] - a[0]));
        err = std::max(err, std::abs(p.component(particleArrays::UY)[k] - a[1]));
        for (int c = 0; c < 4; ++c)
        {
            err = std::max(err, std::abs(p.component(gradU + c)[k]));
        }
        mean[0] += p.component(particleArrays::X)[k]/p.size();
        mean[1] += p.component(particleArrays::Y)[k]/p.size();
    }
    EXPECT_LT(err, exactTol);
    for (int d = 0; d < 2; ++d)
    {
        EXPECT_NEAR(mean[d] - mean0[d], timedSteps()*dt*a[d], positionTol);
    }
}


TEST(bareTransportBenchmark, ShallowWaterKeepsALakeAtRestAndABlockCollapsesSymmetrically)
{
    const int nCells = benchmarkCells();
    ASSERT_GT(nCells, 8);
    const gridGeometry g = benchmarkGrid(nCells);
    const double seedArea = g.dx[0]*g.dx[1]/(nPer*nPer);
    const double massTol = 1e-12*rho*seedArea;
    const double atRest[2] = {0, 0};
    auto fastest = [](const particleArrays& p)
    {
        double v = 0;
        for (label k = 0; k < p.size(); ++k)
        {
            v = std::max
            (
                v,
                std::hypot
                (
                    p.component(particleArrays::UX)[k],
                    p.component(particleArrays::UY)[k]
                )
            );
        }
        return v;
    };

    // Timed: the benchmark layer fills the grid, whose nodal areas are
    // those of the seed lattice, so its height is uniform up to the edges
    // and it stays at rest (dampmFoam's frictionless flat case likewise)
    {
        particleArrays p;
        seedLayer(g, p, atRest);
        bareTransport transport(g, massTol, p, nPer, rho, gravity);
        timeSteps
        (
            "shallowWater", p.size(), [&]{ transport.shallowWater(p, dt); }
        );
        EXPECT_LT(fastest(p), exactTol);
    }

    // A block of half the grid's side in its middle collapses at its edges
    const label nSide = nCells*nPer;
    const label first = nSide/4, last = nSide - nSide/4;
    const label nBlock = last - first;
    particleArrays p;
    const label id = p.addField("id", particleArrays::fieldKind::internal);
    seedLayer(g, p, atRest, first, last);
    const double side = nBlock*g.dx[0]/nPer;
    const double mass0 = rho*h0*side*side;
    bareTransport transport(g, massTol, p, nPer, rho, gravity);
    for (int s = 0; s < nSteps; ++s)
    {
        transport.shallowWater(p, dt);
    }

    // Columns by their lattice index (re-binning reorders them)
    const double* x = p.component(particleArrays::X);
    const double* y = p.component(particleArrays::Y);
    const double* ux = p.component(particleArrays::UX);
    const double* uy = p.component(particleArrays::UY);
    const double lo = first*g.dx[0]/nPer, hi = last*g.dx[0]/nPer;
    const double L = lo + hi;
    std::vector<label> at(p.size(), -1);
    double mass = 0, interior = 0;
    for (label k = 0; k < p.size(); ++k)
    {
        mass += p.component(particleArrays::M)[k];
        at[label(p.component(id)[k])] = k;
        const double edge = std::min({x[k] - lo, y[k] - lo, hi - x[k], hi - y[k]});
        if (edge > 0.25*side)
        {
            interior = std::max(interior, std::hypot(ux[k], uy[k]));
        }
    }
    EXPECT_NEAR(mass, mass0, 1e-12*mass0);
    const double vMax = fastest(p);
    EXPECT_GT(vMax, 0.1);
    EXPECT_LE(vMax, 2*std::sqrt(gravity*h0));
    // Measured 2.5 % at 40 cells: the B-splines spread the edge's
    // rarefaction over some 4 cells, with a small overshoot behind it
    EXPECT_LT(interior, 0.05*vMax);

    // The outermost columns move outwards
    for (label j = 0; j < nBlock; ++j)
    {
        EXPECT_LT(ux[at[nBlock*j]], -0.1*vMax);
        EXPECT_GT(ux[at[nBlock - 1 + nBlock*j]], 0.1*vMax);
    }

    // Mirror images about x = L/2 and about the diagonal
    double mirrorU = 0, mirrorX = 0;
    for (label j = 0; j < nBlock; ++j)
    {
        for (label i = 0; i < nBlock; ++i)
        {
            const label k = at[i + nBlock*j];
            const label kx = at[nBlock - 1 - i + nBlock*j];
            const label kd = at[j + nBlock*i];
            ASSERT_TRUE(k >= 0 && kx >= 0 && kd >= 0);
            mirrorU = std::max
            ({
                mirrorU, std::abs(ux[k] + ux[kx]), std::abs(uy[k] - uy[kx]),
                std::abs(ux[k] - uy[kd]), std::abs(uy[k] - ux[kd])
            });
            mirrorX = std::max
            ({
                mirrorX, std::abs(x[k] + x[kx] - L), std::abs(y[k] - y[kx]),
                std::abs(x[k] - y[kd]), std::abs(y[k] - x[kd])
            });
        }
    }
    EXPECT_LT(mirrorU, mirrorVelocityTol);
    EXPECT_LT(mirrorX, mirrorPositionTol);
}


// ************************************************************************* //
