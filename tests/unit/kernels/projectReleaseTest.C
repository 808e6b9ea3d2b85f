/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The projected release (projectRelease, doc/dampmFoam-discretisation.md
    section 3.4), for every shape function and 1 to 3 columns per cell and
    axis: the volume is kept to round-off, the thin tail's share included;
    a release that fills the domain is unchanged; a symmetric release stays
    symmetric; the spill stays within one cell of the release; and the edge
    column of a 1 m step gets the projected depth 0.62109375 m of the
    B-spline (2 columns per cell), which the pressure force sees there.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "depthAveragedKernels.H"
#include "shapeKernels.H"
#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <map>
#include <random>

using namespace Foam;

namespace
{

// Sums of a few thousand columns and of 9 nodes each: round-off
constexpr double volumeTol = 1e-13;     // relative
constexpr double exactTol = 1e-13;      // [m], depths of about 1 m

gridGeometry makeGrid()
{
    return uniformGrid(2, {-3, 1, 0}, {0.25, 0.2, 1}, {48, 40, 1});
}

struct release
{
    std::vector<double> x, y, h;
    double volume(const double a) const
    {
        double v = 0;
        for (const double hk : h)
        {
            v += hk*a;
        }
        return v;
    }
};

// The seed lattice of g (n per cell and axis) where height(x, y) > 0
release sample
(
    const gridGeometry& g,
    const int n,
    const std::function<double(double, double)>& height
)
{
    release r;
    for (int j = 0; j < g.nCells[1]*n; ++j)
    {
        const double y = g.origin[1] + (j + 0.5)*g.dx[1]/n;
        for (int i = 0; i < g.nCells[0]*n; ++i)
        {
            const double x = g.origin[0] + (i + 0.5)*g.dx[0]/n;
            const double h = height(x, y);
            if (h > 0)
            {
                r.x.push_back(x);
                r.y.push_back(y);
                r.h.push_back(h);
            }
        }
    }
    return r;
}

template<class Kernel>
std::vector<double> areas(const gridGeometry& g, const Kernel& k, const int n)
{
    std::vector<double> A(g.nNodes(), 0.0);
    nodalAreas(g, k, n, A.data());
    return A;
}

GIMPKernel gimp(const int n)
{
    return GIMPKernel(0.5/n);
}

// An irregular release with random thickness: the volume is kept
template<class Kernel>
void checkVolume(const Kernel& k, const int n)
{
    const gridGeometry g = makeGrid();
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0.5, 2);
    release r = sample
    (
        g, n,
        [&](const double x, const double y)
        {
            // A disc and a strip touching the domain's side x = -3
            const bool in =
                (x - 2)*(x - 2) + (y - 4)*(y - 4) < 4 || (y > 6 && y < 7.3);
            return in ? u(gen) : 0.0;
        }
    );
    const double a = g.dx[0]*g.dx[1]/(n*n);
    const double before = r.volume(a);
    const std::vector<double> A = areas(g, k, n);
    const double moved = projectRelease(g, k, n, A.data(), 1e-4, r.x, r.y, r.h);
    EXPECT_NEAR(r.volume(a), before, volumeTol*before)
        << "n = " << n << ", " << moved << " m^3 of thin tail moved";
    for (size_t l = 0; l < r.h.size(); ++l)
    {
        EXPECT_GT(r.h[l], 0);
    }
}

// A uniform layer filling the domain: every column as it was
template<class Kernel>
void checkUniform(const Kernel& k, const int n)
{
    const gridGeometry g = makeGrid();
    release r = sample(g, n, [](double, double) { return 1.25; });
    const size_t count = r.x.size();
    const std::vector<double> A = areas(g, k, n);
    projectRelease(g, k, n, A.data(), 1e-4, r.x, r.y, r.h);
    ASSERT_EQ(r.x.size(), count);
    for (size_t l = 0; l < count; ++l)
    {
        EXPECT_NEAR(r.h[l], 1.25, exactTol);
    }
}

// A square release centred on a node of the square-celled grid: the result
// is symmetric in x and y and under their exchange, and no column lies more
// than one cell (Euclidean, in cells) beyond the release
template<class Kernel>
void checkSymmetryAndSpill(const Kernel& k, const int n)
{
    gridGeometry g = makeGrid();
    g.dx[1] = g.dx[0];
    g.nCells[1] = g.nCells[0];
    g.finalise();
    const double cx = g.origin[0] + 24*g.dx[0], cy = g.origin[1] + 24*g.dx[1];
    const double half = 2.0;
    release r = sample
    (
        g, n,
        [&](const double x, const double y)
        {
            return std::abs(x - cx) < half && std::abs(y - cy) < half ? 1 : 0;
        }
    );
    const std::vector<double> A = areas(g, k, n);
    projectRelease(g, k, n, A.data(), 1e-4, r.x, r.y, r.h);

    // Depth at each column's mirror images (a lattice point: the lattice
    // is symmetric about the centre node)
    std::map<std::pair<long, long>, double> depth;
    const auto key = [&](const double x, const double y)
    {
        return std::make_pair
        (
            std::lround((x - cx)*2*n/g.dx[0]), std::lround((y - cy)*2*n/g.dx[1])
        );
    };
    for (size_t l = 0; l < r.x.size(); ++l)
    {
        depth[key(r.x[l], r.y[l])] = r.h[l];
    }
    for (const auto& kv : depth)
    {
        const long i = kv.first.first, j = kv.first.second;
        for (const auto& m : {std::make_pair(-i, j), std::make_pair(i, -j),
                              std::make_pair(j, i)})
        {
            const auto it = depth.find(m);
            ASSERT_TRUE(it != depth.end()) << "no mirror of (" << i << ' '
                << j << ") at (" << m.first << ' ' << m.second << ')';
            EXPECT_NEAR(it->second, kv.second, exactTol);
        }
    }
    for (size_t l = 0; l < r.x.size(); ++l)
    {
        // Distance in cells beyond the release's outermost columns
        const double ex = std::max(0.0, std::abs(r.x[l] - cx) - half)/g.dx[0];
        const double ey = std::max(0.0, std::abs(r.y[l] - cy) - half)/g.dx[1];
        EXPECT_LE(std::hypot(ex, ey), 1 + 0.5/n + 1e-12);
    }
}

} // End anonymous namespace


TEST(projectRelease, VolumeIsKeptToRoundOff)
{
    for (int n = 1; n <= 3; ++n)
    {
        checkVolume(quadraticBSplineKernel(), n);
        checkVolume(gimp(n), n);
        checkVolume(linearKernel(), n);
    }
}


TEST(projectRelease, ReleaseFillingTheDomainIsUnchanged)
{
    for (int n = 1; n <= 3; ++n)
    {
        checkUniform(quadraticBSplineKernel(), n);
        checkUniform(gimp(n), n);
        checkUniform(linearKernel(), n);
    }
}


TEST(projectRelease, SymmetricReleaseStaysSymmetricWithinOneCell)
{
    for (int n = 1; n <= 3; ++n)
    {
        checkSymmetryAndSpill(quadraticBSplineKernel(), n);
        checkSymmetryAndSpill(gimp(n), n);
    }
}


TEST(projectRelease, EdgeColumnOfAStepGetsTheProjectedDepth)
{
    // A 1 m step at x = 0 across the whole width (-3 <= x < 0), 2 columns
    // per cell: the edge column at x = -dx/4 sees the nodes at -dx, 0, dx
    // with depths 63/64, 1/2, 1/64 m and weights 9/32, 11/16, 1/32
    const gridGeometry g = makeGrid();
    const int n = 2;
    release r = sample(g, n, [](double x, double) { return x < 0 ? 1 : 0; });
    const quadraticBSplineKernel k;
    const std::vector<double> A = areas(g, k, n);
    projectRelease(g, k, n, A.data(), 1e-4, r.x, r.y, r.h);
    const double edge = -0.25*g.dx[0];
    const double expected =
        9.0/32*63.0/64 + 11.0/16*0.5 + 1.0/32*1.0/64;
    int found = 0;
    for (size_t l = 0; l < r.x.size(); ++l)
    {
        if (std::abs(r.x[l] - edge) < 1e-12)
        {
            EXPECT_NEAR(r.h[l], expected, exactTol);
            ++found;
        }
    }
    EXPECT_EQ(found, 2*g.nCells[1]);
}


// ************************************************************************* //
