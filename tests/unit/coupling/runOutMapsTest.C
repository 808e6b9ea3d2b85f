/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    runOutMaps' projection of 3D particles onto the run-out grid
    (scatterBand): 20,000 random particles, some beyond the grid's sides,
    give each node the sums of a plain bilinear reference (w m, w m ux,
    w m uy, w V in particle order) bit for bit, and the same bits and box
    of nodes whatever bands of rows share the work (1 to 9, as threads do);
    the mass projected is that of the particles on the grid, to round-off.

\*---------------------------------------------------------------------------*/

#include "runOutMaps.H"
#include "skewedAllocator.H"
#include "uniformGrid.H"
#include <gtest/gtest.h>
#include <cstring>
#include <random>

using namespace Foam;

namespace
{

constexpr int nSums = runOutMaps::nSums;

//- Node sums, aligned as runOutMaps' (a corner's four lanes are one
//  aligned vector)
typedef std::vector<double, skewedAllocator<double>> nodeSums;

//- The projection of particles p onto g in bands of rows cut at cuts
//  (ascending, within [0, nCells[1] + 1]); box [lo, hi) of nodes
nodeSums projected
(
    const gridGeometry& g,
    const particleArrays& p,
    const std::vector<int32_t>& cuts,
    int32_t lo[2],
    int32_t hi[2]
)
{
    nodeSums sums(nSums*g.nNodes(), 0.0);
    lo[0] = lo[1] = std::numeric_limits<int32_t>::max();
    hi[0] = hi[1] = std::numeric_limits<int32_t>::min();
    for (size_t b = 0; b + 1 < cuts.size(); ++b)
    {
        const int32_t rows[2] = {cuts[b], cuts[b + 1]};
        int32_t bandLo[2] = {lo[0], lo[1]}, bandHi[2] = {hi[0], hi[1]};
        runOutMaps::scatterBand(g, p, rows, sums.data(), bandLo, bandHi);
        for (int d = 0; d < 2; ++d)
        {
            lo[d] = std::min(lo[d], bandLo[d]);
            hi[d] = std::max(hi[d], bandHi[d]);
        }
    }
    return sums;
}

} // End anonymous namespace


TEST(runOutMaps, ProjectionIsBilinearAndTheSameInAnyBands)
{
    const gridGeometry g
    (
        uniformGrid(2, {10, -5, 0}, {0.4, 0.5, 1}, {24, 20, 1})
    );
    std::mt19937 gen(41);
    std::uniform_real_distribution<double> u(0, 1), v(-1, 1);
    particleArrays p;
    const label n = 20000;
    p.append(n);
    double onGridMass = 0;
    for (label i = 0; i < n; ++i)
    {
        // 5 % beyond each side
        for (int d = 0; d < 2; ++d)
        {
            const double span = g.upper(d) - g.origin[d];
            p.component(particleArrays::X + d)[i] =
                g.origin[d] + (1.1*u(gen) - 0.05)*span;
            p.component(particleArrays::UX + d)[i] = v(gen);
        }
        p.component(particleArrays::Z)[i] = v(gen);
        p.component(particleArrays::M)[i] = 0.5 + u(gen);
        p.component(particleArrays::VOL)[i] = 0.1 + u(gen);
    }

    // The reference: each particle's four corners in particle order
    const double* x = p.component(particleArrays::X);
    const double* y = p.component(particleArrays::Y);
    const double* m = p.component(particleArrays::M);
    const double* V = p.component(particleArrays::VOL);
    std::vector<double> ref(nSums*g.nNodes(), 0.0);
    int32_t refLo[2] = {1 << 30, 1 << 30}, refHi[2] = {-1, -1};
    for (label i = 0; i < n; ++i)
    {
        const double xi = g.local(0, x[i]), eta = g.local(1, y[i]);
        if (!(xi >= 0 && xi <= g.nCells[0] && eta >= 0 && eta <= g.nCells[1]))
        {
            continue;
        }
        onGridMass += m[i];
        const int32_t ci = std::min(int32_t(xi), g.nCells[0] - 1);
        const int32_t cj = std::min(int32_t(eta), g.nCells[1] - 1);
        const double fx = xi - ci, fy = eta - cj;
        const double w[4] =
            {(1 - fx)*(1 - fy), fx*(1 - fy), (1 - fx)*fy, fx*fy};
        for (int c = 0; c < 4; ++c)
        {
            double* s =
                ref.data()
              + nSums*g.nodeIndex(ci + (c & 1), cj + (c >> 1), 0);
            const double wm = w[c]*m[i];
            s[0] += wm;
            s[1] += wm*p.component(particleArrays::UX)[i];
            s[2] += wm*p.component(particleArrays::UY)[i];
            s[3] += w[c]*V[i];
        }
        refLo[0] = std::min(refLo[0], ci);
        refLo[1] = std::min(refLo[1], cj);
        refHi[0] = std::max(refHi[0], ci + 2);
        refHi[1] = std::max(refHi[1], cj + 2);
    }

    // One band, then random cuts into up to nine
    const int32_t nRows = g.nCells[1] + 1;
    std::vector<std::vector<int32_t>> splits = {{0, nRows}};
    std::uniform_int_distribution<int32_t> row(1, nRows - 1);
    for (int nBands = 2; nBands <= 9; ++nBands)
    {
        std::vector<int32_t> cuts = {0, nRows};
        while (int(cuts.size()) < nBands + 1)
        {
            const int32_t r = row(gen);
            if (std::find(cuts.begin(), cuts.end(), r) == cuts.end())
            {
                cuts.push_back(r);
            }
        }
        std::sort(cuts.begin(), cuts.end());
        splits.push_back(cuts);
    }
    for (const std::vector<int32_t>& cuts : splits)
    {
        int32_t lo[2], hi[2];
        const nodeSums sums = projected(g, p, cuts, lo, hi);
        EXPECT_EQ
        (
            std::memcmp(sums.data(), ref.data(), sums.size()*sizeof(double)),
            0
        ) << cuts.size() - 1 << " bands";
        for (int d = 0; d < 2; ++d)
        {
            EXPECT_EQ(lo[d], refLo[d]);
            EXPECT_EQ(hi[d], refHi[d]);
        }
    }

    // Bilinear weights sum to one: the particles' mass on the grid
    int32_t lo[2], hi[2];
    const nodeSums sums = projected(g, p, {0, nRows}, lo, hi);
    double mass = 0;
    for (label k = 0; k < g.nNodes(); ++k)
    {
        mass += sums[nSums*k];
    }
    EXPECT_GT(onGridMass, 0.8*n*0.5);
    EXPECT_NEAR(mass, onGridMass, 1e-12*onGridMass);
}


// ************************************************************************* //
