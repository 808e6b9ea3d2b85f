/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The shared P2G and G2P transfers, for every shape function in 2D and 3D:
    a uniform and a linear velocity field pass P2G then G2P unchanged (the
    linear one with the affine transfer), P2G conserves mass and momentum to
    round-off, and one and two threads give bit-identical node sums.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "particleTransfers.H"
#include "shapeKernels.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <random>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;

namespace
{

// Exactness of the transfers: round-off of sums over 9-27 nodes and over
// a few hundred particles per node
constexpr double exactTol = 1e-12;
constexpr double conservationTol = 1e-13;  // relative

gridGeometry makeGrid(const int dim)
{
    return uniformGrid
    (
        dim, {10, -5, 2}, {0.4, 0.5, 0.25},
        dim == 2
      ? std::array<gridGeometry::index, 3>{40, 30, 1}
      : std::array<gridGeometry::index, 3>{14, 11, 9}
    );
}

// Random particles (4 per cell on average) with random masses
particleArrays makeParticles(const gridGeometry& g, const int dim)
{
    particleArrays p;
    p.addField("gradU", particleArrays::fieldKind::tensor);
    const label n = 4*g.nCellsTotal();
    p.append(n);
    std::mt19937 gen(99);
    std::uniform_real_distribution<double> u(0, 1);
    for (label i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            p.component(particleArrays::X + d)[i] =
                d < dim ? g.origin[d] + u(gen)*(g.upper(d) - g.origin[d]) : 0;
        }
        p.component(particleArrays::M)[i] = 0.5 + u(gen);
    }
    p.sortByCell(g, scatterSchedule(g));
    return p;
}

// P2G of a particleArrays sorted by cell; gradU -1 for PIC
template<int Dim, class Kernel>
void particlesToGrid
(
    const gridGeometry& g,
    const scatterSchedule& schedule,
    const Kernel& kernel,
    particleArrays& p,
    const label gradU,
    double* mass,
    double* const mom[Dim]
)
{
    particlesToGridMomentum<Dim>
    (
        g, schedule, kernel, p.stencilNodes(g), p.binStart().data(),
        affineArraysOf<Dim>(p, gradU), mass, mom
    );
}

// Linear field v = a + B x, B[a][b] = dv_a/dx_b
const double A[3] = {1.5, -0.75, 0.3};
const double B[3][3] = {{0.2, -0.7, 0.4}, {1.1, 0.05, -0.3}, {-0.6, 0.9, 0.25}};

template<int Dim>
struct nodeArrays
{
    std::vector<double> mass;
    std::vector<double> mom[Dim];
    std::vector<double> vel[Dim];
    double* momPtr[Dim];
    double* velPtr[Dim];

    explicit nodeArrays(const gridGeometry& g)
    :
        mass(g.nNodes())
    {
        for (int d = 0; d < Dim; ++d)
        {
            mom[d].resize(g.nNodes());
            vel[d].resize(g.nNodes());
            momPtr[d] = mom[d].data();
            velPtr[d] = vel[d].data();
        }
    }
};


template<int Dim, class Kernel>
void checkLinearFieldRoundTrip(const Kernel& kernel, const bool linear)
{
    const gridGeometry g = makeGrid(Dim);
    const scatterSchedule schedule(g);
    particleArrays p = makeParticles(g, Dim);
    const label gradU = p.field("gradU").first;

    for (label i = 0; i < p.size(); ++i)
    {
        for (int a = 0; a < Dim; ++a)
        {
            double v = A[a];
            for (int b = 0; b < Dim; ++b)
            {
                const double s = linear ? B[a][b] : 0;
                v += s*p.component(particleArrays::X + b)[i];
                p.component(gradU + a*Dim + b)[i] = s;
            }
            p.component(particleArrays::UX + a)[i] = v;
        }
    }

    nodeArrays<Dim> n(g);
    particlesToGrid<Dim>
    (
        g, schedule, kernel, p, linear ? gradU : -1, n.mass.data(), n.momPtr
    );
    nodeVelocity<Dim>(g.nNodes(), n.mass.data(), n.momPtr, n.velPtr, 1e-14);

    // Node velocities equal the field at every node with mass
    for (label nodei = 0; nodei < g.nNodes(); ++nodei)
    {
        if (n.mass[nodei] < 1e-8)
        {
            continue;
        }
        gridGeometry::index ijk[3];
        g.nodeIJK(nodei, ijk);
        for (int a = 0; a < Dim; ++a)
        {
            double v = A[a];
            for (int b = 0; b < Dim; ++b)
            {
                v += (linear ? B[a][b] : 0)*g.nodeCoord(b, ijk[b]);
            }
            ASSERT_NEAR(n.vel[a][nodei], v, exactTol) << "node " << nodei;
        }
    }

    // Scramble the particle state, then recover it from the grid
    std::vector<std::vector<double>> before(Dim);
    for (int a = 0; a < Dim; ++a)
    {
        double* u = p.component(particleArrays::UX + a);
        before[a].assign(u, u + p.size());
        std::fill(u, u + p.size(), 1e3);
    }
    gridToParticlesVelocity<Dim>(g, kernel, p, gradU, n.velPtr);

    for (label i = 0; i < p.size(); ++i)
    {
        for (int a = 0; a < Dim; ++a)
        {
            ASSERT_NEAR(p.component(particleArrays::UX + a)[i], before[a][i],
                exactTol);
            for (int b = 0; b < Dim; ++b)
            {
                ASSERT_NEAR(p.component(gradU + a*Dim + b)[i],
                    linear ? B[a][b] : 0, 1e-10);
            }
        }
    }
}


template<int Dim, class Kernel>
void checkConservation(const Kernel& kernel)
{
    const gridGeometry g = makeGrid(Dim);
    const scatterSchedule schedule(g);
    particleArrays p = makeParticles(g, Dim);
    const label gradU = p.field("gradU").first;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-3, 3);
    double mP = 0, momP[Dim] = {};
    for (label i = 0; i < p.size(); ++i)
    {
        const double m = p.component(particleArrays::M)[i];
        mP += m;
        for (int a = 0; a < Dim; ++a)
        {
            const double v = u(gen);
            p.component(particleArrays::UX + a)[i] = v;
            momP[a] += m*v;
            for (int b = 0; b < Dim; ++b)
            {
                p.component(gradU + a*Dim + b)[i] = u(gen);
            }
        }
    }
    nodeArrays<Dim> n(g);
    particlesToGrid<Dim>
    (
        g, schedule, kernel, p, gradU, n.mass.data(), n.momPtr
    );
    double mG = 0, momG[Dim] = {};
    for (label nodei = 0; nodei < g.nNodes(); ++nodei)
    {
        mG += n.mass[nodei];
        for (int a = 0; a < Dim; ++a)
        {
            momG[a] += n.mom[a][nodei];
        }
    }
    EXPECT_NEAR(mG, mP, conservationTol*mP);
    for (int a = 0; a < Dim; ++a)
    {
        EXPECT_NEAR(momG[a], momP[a], conservationTol*3*mP);
    }
}


template<int Dim, class Kernel>
void checkThreadIndependence(const Kernel& kernel)
{
#ifdef _OPENMP
    const gridGeometry g = makeGrid(Dim);
    const scatterSchedule schedule(g);
    particleArrays p = makeParticles(g, Dim);
    std::mt19937 gen(8);
    std::uniform_real_distribution<double> u(-3, 3);
    for (label i = 0; i < p.size(); ++i)
    {
        for (int a = 0; a < Dim; ++a)
        {
            p.component(particleArrays::UX + a)[i] = u(gen);
        }
    }
    const int maxThreads = omp_get_max_threads();
    nodeArrays<Dim> one(g), two(g);
    omp_set_num_threads(1);
    particlesToGrid<Dim>
    (
        g, schedule, kernel, p, -1, one.mass.data(), one.momPtr
    );
    omp_set_num_threads(2);
    particlesToGrid<Dim>
    (
        g, schedule, kernel, p, -1, two.mass.data(), two.momPtr
    );
    omp_set_num_threads(maxThreads);
    // Bit for bit, not within a tolerance
    EXPECT_TRUE(one.mass == two.mass);
    for (int a = 0; a < Dim; ++a)
    {
        EXPECT_TRUE(one.mom[a] == two.mom[a]);
    }
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}

GIMPKernel gimp()
{
    return GIMPKernel(0.25);
}

} // End anonymous namespace


TEST(transfers, UniformVelocityIsReturnedExactlyByPIC)
{
    checkLinearFieldRoundTrip<2>(linearKernel(), false);
    checkLinearFieldRoundTrip<3>(linearKernel(), false);
    checkLinearFieldRoundTrip<2>(gimp(), false);
    checkLinearFieldRoundTrip<3>(quadraticBSplineKernel(), false);
}


TEST(transfers, LinearVelocityIsReturnedExactlyByAffineTransfer)
{
    checkLinearFieldRoundTrip<2>(linearKernel(), true);
    checkLinearFieldRoundTrip<3>(linearKernel(), true);
    checkLinearFieldRoundTrip<2>(gimp(), true);
    checkLinearFieldRoundTrip<3>(gimp(), true);
    checkLinearFieldRoundTrip<2>(quadraticBSplineKernel(), true);
    checkLinearFieldRoundTrip<3>(quadraticBSplineKernel(), true);
}


TEST(transfers, ParticlesToGridConservesMassAndMomentum)
{
    checkConservation<2>(linearKernel());
    checkConservation<3>(linearKernel());
    checkConservation<2>(gimp());
    checkConservation<3>(gimp());
    checkConservation<2>(quadraticBSplineKernel());
    checkConservation<3>(quadraticBSplineKernel());
}


TEST(transfers, OneAndTwoThreadsGiveIdenticalNodeSums)
{
    checkThreadIndependence<2>(linearKernel());
    checkThreadIndependence<3>(quadraticBSplineKernel());
    checkThreadIndependence<2>(gimp());
}


TEST(transfers, ScatterTakesEveryParticleOnceOnAnyNumberOfThreads)
{
#ifdef _OPENMP
    // The threads take runs of a colour's tiles as they come free: every
    // particle once, also with more runs than tiles (many threads) and with
    // the particles in part of the grid only (empty tiles)
    const int maxThreads = omp_get_max_threads();
    for (const int dim : {2, 3})
    {
        // Many tiles of each colour
        const gridGeometry g = uniformGrid
        (
            dim, {10, -5, 2}, {0.4, 0.5, 0.25},
            dim == 2
          ? std::array<gridGeometry::index, 3>{200, 150, 1}
          : std::array<gridGeometry::index, 3>{40, 30, 20}
        );
        const scatterSchedule schedule(g);
        particleArrays p = makeParticles(g, dim);
        const double xMid = 0.5*(g.origin[0] + g.upper(0));
        std::vector<char> right(p.size(), 0);
        for (label i = 0; i < p.size(); ++i)
        {
            right[i] = p.component(particleArrays::X)[i] > xMid;
        }
        p.removeFlagged(right);
        p.sortByCell(g, schedule);
        for (const int nThreads : {1, 2, 3, 16})
        {
            omp_set_num_threads(nThreads);
            std::vector<int> visits(p.size(), 0);
            schedule.scatterRanges
            (
                g,
                p.stencilNodes(g),
                p.binStart().data(),
                [&](const label first, const label last)
                {
                    for (label i = first; i < last; ++i)
                    {
                        #pragma omp atomic
                        ++visits[i];
                    }
                }
            );
            EXPECT_EQ
            (
                std::count(visits.begin(), visits.end(), 1), p.size()
            ) << dim << "D, " << nThreads << " threads";
        }
    }
    omp_set_num_threads(maxThreads);
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}


TEST(transfers, StaleBinningWithinTheScheduleReachStaysRaceFreeAndConservative)
{
#ifdef _OPENMP
    // Particles binned, then moved by up to maxStale cells (2 in 2D, 1 in
    // 3D) without re-binning: the schedule's tiles keep the scatter
    // race-free
    for (const int dim : {2, 3})
    {
        const gridGeometry g = makeGrid(dim);
        const scatterSchedule schedule(g);
        ASSERT_GE(schedule.maxStale(), 1);
        particleArrays p = makeParticles(g, dim);
        std::mt19937 gen(21);
        const double reach = schedule.maxStale() - 0.01;
        std::uniform_real_distribution<double> u(-reach, reach);
        double mP = 0;
        for (label i = 0; i < p.size(); ++i)
        {
            for (int d = 0; d < dim; ++d)
            {
                double& x = p.component(particleArrays::X + d)[i];
                x = std::min(std::max(x + u(gen)*g.dx[d], g.origin[d]),
                    g.upper(d));
                p.component(particleArrays::UX + d)[i] = u(gen);
            }
            mP += p.component(particleArrays::M)[i];
        }
        ASSERT_FALSE(p.sortByCell(g, schedule));
        const int maxThreads = omp_get_max_threads();
        std::vector<double> m1(g.nNodes()), m2(g.nNodes());
        std::vector<double> q1[3], q2[3];
        double* mom1[3];
        double* mom2[3];
        for (int d = 0; d < 3; ++d)
        {
            q1[d].resize(g.nNodes());
            q2[d].resize(g.nNodes());
            mom1[d] = q1[d].data();
            mom2[d] = q2[d].data();
        }
        omp_set_num_threads(1);
        dim == 2
          ? particlesToGrid<2>(g, schedule, quadraticBSplineKernel(),
                p, -1, m1.data(), mom1)
          : particlesToGrid<3>(g, schedule, quadraticBSplineKernel(),
                p, -1, m1.data(), mom1);
        omp_set_num_threads(2);
        dim == 2
          ? particlesToGrid<2>(g, schedule, quadraticBSplineKernel(),
                p, -1, m2.data(), mom2)
          : particlesToGrid<3>(g, schedule, quadraticBSplineKernel(),
                p, -1, m2.data(), mom2);
        omp_set_num_threads(maxThreads);
        EXPECT_TRUE(m1 == m2);
        for (int d = 0; d < dim; ++d)
        {
            EXPECT_TRUE(q1[d] == q2[d]);
        }
        double mG = 0;
        for (const double m : m1)
        {
            mG += m;
        }
        EXPECT_NEAR(mG, mP, conservationTol*mP);
    }
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}


// ************************************************************************* //
