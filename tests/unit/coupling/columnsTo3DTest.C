/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    columnsTo3D: random columns (sheared, rotated footprints, depths from
    1 mm to 3 m, random velocities) over a curved sloping ground keep mass,
    volume, horizontal momentum and its kinetic energy to round-off, in
    total and column by column; every particle lies inside its column's
    footprint and between the ground and the column's top, moves along the
    bed and thins with the layer (w = u . grad G - z' div u, or the bed
    term alone) and starts at the hydrostatic pressure with the
    material's J; the Bagnold profile keeps the depth average; columns
    outside the region are counted with their mass, and those at its sides
    keep their particles inside. The merge joins the columns smaller than
    the spacing per cell, keeping mass, volume, area, momentum and the
    centre of mass to round-off, losing exactly the kinetic energy of the
    velocities about each cell's mean, and copies the others bit for bit.

\*---------------------------------------------------------------------------*/

#include "columnsTo3D.H"
#include "depthAveragedParticles.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

// Sums of up to ~1e4 terms of one sign
constexpr double roundOff = 1e-12;

const double rho = 1000, g = 9.81;

// A curved sloping ground and its exact gradient
double ground(const double x, const double y)
{
    return 5 + 0.3*x - 0.2*y + 0.5*std::sin(0.7*x);
}

double groundDx(const double x, const double)
{
    return 0.3 + 0.35*std::cos(0.7*x);
}

const double groundDy = -0.2;

// The ground as the conversion takes it
double groundWithGradient(const double x, const double y, vector2D& grad)
{
    grad = vector2D(groundDx(x, y), groundDy);
    return ground(x, y);
}

const boundBox region(point(0, 0, -10), point(20, 10, 30));
const vector spacing(0.1, 0.1, 0.1);

autoPtr<materialModel> water()
{
    dictionary dict;
    dict.add("material", word("Newtonian"));
    dictionary coeffs;
    coeffs.add("rho", rho);
    coeffs.add("mu", 0.0);
    coeffs.add("c", 50.0);
    dict.add("NewtonianCoeffs", coeffs);
    return materialModel::New(dict);
}

// The conversion of the tests: uniform profile, continuity's w
columnsTo3D uniformConversion(const materialModel& mat)
{
    return columnsTo3D
    (
        region, spacing, mat, g, columnsTo3D::profileType::uniform,
        groundWithGradient
    );
}

// The 3D fields the conversion fills, as mpm3dFlow has them
particleArrays fields3D()
{
    particleArrays p;
    p.addField("gradU", particleArrays::fieldKind::tensor);
    p.addField("sigma", particleArrays::fieldKind::symmTensor);
    p.addField("p", particleArrays::fieldKind::scalar);
    p.addField("J", particleArrays::fieldKind::scalar, 1);
    return p;
}

// Where fields3D keeps the stress state
mpm3dFlow::stressFields stress3D()
{
    const particleArrays p = fields3D();
    return {p.field("sigma").first, p.field("p").first, p.field("J").first};
}

// Random columns with dampmFoam's fields; centres in [x0, x1] x [y0, y1]
depthAveragedParticles randomColumns
(
    const label n,
    const double x0, const double x1,
    const double y0, const double y1,
    const unsigned seed
)
{
    depthAveragedParticles set;
    particleArrays& c = set.p;
    const label A = set.f.A();
    const label F = set.f.F();
    const label C = set.f.gradU();
    c.append(n);
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (label i = 0; i < n; ++i)
    {
        const double h = std::pow(10, -3 + 3.5*u(gen));     // 1 mm .. 3 m
        const double Fxx = 0.05 + 0.2*u(gen), Fyy = 0.05 + 0.2*u(gen);
        const double shear = 0.5*(u(gen) - 0.5), angle = 6.3*u(gen);
        // F = R(angle) [Fxx shear*Fxx; 0 Fyy]
        const double cs = std::cos(angle), sn = std::sin(angle);
        const double f[4] = {Fxx, shear*Fxx, 0, Fyy};
        c.component(F)[i] = cs*f[0] - sn*f[2];
        c.component(F + 1)[i] = cs*f[1] - sn*f[3];
        c.component(F + 2)[i] = sn*f[0] + cs*f[2];
        c.component(F + 3)[i] = sn*f[1] + cs*f[3];
        // The area from the projected depth differs from |det F|
        const double area = (0.5 + u(gen))*Fxx*Fyy;
        c.component(A)[i] = area;
        c.component(particleArrays::VOL)[i] = area*h;
        c.component(particleArrays::M)[i] = rho*area*h;
        c.component(particleArrays::X)[i] = x0 + (x1 - x0)*u(gen);
        c.component(particleArrays::Y)[i] = y0 + (y1 - y0)*u(gen);
        c.component(particleArrays::UX)[i] = 20*(u(gen) - 0.5);
        c.component(particleArrays::UY)[i] = 20*(u(gen) - 0.5);
        // A stretching or converging layer, div u in [-2, 2] 1/s
        c.component(C)[i] = 2*(u(gen) - 0.5);
        c.component(C + 1)[i] = u(gen) - 0.5;
        c.component(C + 2)[i] = u(gen) - 0.5;
        c.component(C + 3)[i] = 2*(u(gen) - 0.5);
    }
    return set;
}

// One column of c as its own set
depthAveragedParticles oneColumn(const depthAveragedParticles& c, const label i)
{
    depthAveragedParticles one(c);
    std::vector<char> remove(c.p.size(), 1);
    remove[i] = 0;
    one.p.removeFlagged(remove);
    return one;
}

double rel(const double a, const double b)
{
    return std::abs(a - b)/std::max(std::abs(b), 1e-300);
}

// Square columns of edge e tiling [x0, x0 + nx e] x [y0, y0 + ny e]
// (axis-aligned, as a run-out's split columns), with randomColumns'
// depths, velocities and velocity gradients
depthAveragedParticles tiledColumns
(
    const label nx,
    const label ny,
    const double e,
    const double x0,
    const double y0,
    const unsigned seed
)
{
    depthAveragedParticles set = randomColumns(nx*ny, x0, x0, y0, y0, seed);
    particleArrays& c = set.p;
    const label A = set.f.A();
    const label F = set.f.F();
    for (label i = 0; i < nx*ny; ++i)
    {
        const double h =
            c.component(particleArrays::VOL)[i]/c.component(A)[i];
        c.component(F)[i] = e;
        c.component(F + 1)[i] = 0;
        c.component(F + 2)[i] = 0;
        c.component(F + 3)[i] = e;
        c.component(A)[i] = e*e;
        c.component(particleArrays::VOL)[i] = e*e*h;
        c.component(particleArrays::M)[i] = rho*e*e*h;
        c.component(particleArrays::X)[i] = x0 + (i % nx + 0.5)*e;
        c.component(particleArrays::Y)[i] = y0 + (i/nx + 0.5)*e;
    }
    return set;
}

// Mass, its moments (x, y), volume, area and momentum of columns
struct columnSums
{
    double m = 0, mx = 0, my = 0, V = 0, A = 0, px = 0, py = 0;

    explicit columnSums(const runOutFields& c)
    {
        for (label i = 0; i < c.n; ++i)
        {
            m += c.m[i];
            mx += c.m[i]*c.x[i];
            my += c.m[i]*c.y[i];
            V += c.V[i];
            A += c.A[i];
            px += c.m[i]*c.ux[i];
            py += c.m[i]*c.uy[i];
        }
    }
};

} // End anonymous namespace


TEST(columnsTo3D, ConservesOnRandomColumnsOverSlopingGround)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion = uniformConversion(*mat);
    const depthAveragedParticles columns = randomColumns(3000, 1, 19, 1, 9, 7);
    particleArrays p = fields3D();
    const columnsTo3D::totals t =
        conversion.convert(columns.runOut(), p, stress3D());

    EXPECT_EQ(t.columns, 3000);
    EXPECT_EQ(t.unconvertedColumns, 0);
    EXPECT_EQ(t.particles, p.size());
    EXPECT_GT(p.size(), 3000);
    EXPECT_LT(rel(t.mass3D, t.massDA), roundOff);
    EXPECT_LT(rel(t.volume3D, t.volumeDA), roundOff);
    EXPECT_LT(t.maxColumnMassError, roundOff);
    EXPECT_LT(t.maxColumnVolumeError, roundOff);
    const double pScale = std::abs(t.momentumDA[0]) + std::abs(t.momentumDA[1]);
    EXPECT_LT(std::abs(t.momentum3D[0] - t.momentumDA[0]), roundOff*pScale);
    EXPECT_LT(std::abs(t.momentum3D[1] - t.momentumDA[1]), roundOff*pScale);
    EXPECT_LT(rel(t.kineticEnergy3D, t.kineticEnergyDA), roundOff);
    EXPECT_GT(t.kineticEnergyVertical, 0);

    // The totals are the particles' own
    double m = 0, px = 0;
    for (label i = 0; i < p.size(); ++i)
    {
        m += p.component(particleArrays::M)[i];
        px += p.component(particleArrays::M)[i]*p.component(particleArrays::UX)[i];
    }
    EXPECT_LT(rel(m, t.massDA), roundOff);
    EXPECT_LT(std::abs(px - t.momentumDA[0]), roundOff*pScale);
}


TEST(columnsTo3D, ParticlesInsideTheirColumnOnTheGroundHydrostatic)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion = uniformConversion(*mat);
    const depthAveragedParticles columns = randomColumns(300, 1, 19, 1, 9, 11);
    const label A = columns.f.A();
    const label F = columns.f.F();
    const label sigma = stress3D().sigma;
    const label pF = stress3D().p;
    const label JF = stress3D().J;

    for (label c = 0; c < columns.p.size(); ++c)
    {
        particleArrays p = fields3D();
        conversion.convert(oneColumn(columns, c).runOut(), p, stress3D());
        ASSERT_GT(p.size(), 0);

        // The footprint F scaled to the area A
        const double* Fc[4] =
        {
            columns.p.component(F), columns.p.component(F + 1),
            columns.p.component(F + 2), columns.p.component(F + 3)
        };
        const double f00 = Fc[0][c], f01 = Fc[1][c];
        const double f10 = Fc[2][c], f11 = Fc[3][c];
        const double det = f00*f11 - f01*f10;
        const double area = columns.p.component(A)[c];
        const double s = std::sqrt(area/std::abs(det));
        const double h = columns.p.component(particleArrays::VOL)[c]/area;
        const double xc = columns.p.component(particleArrays::X)[c];
        const double yc = columns.p.component(particleArrays::Y)[c];
        const double uc = columns.p.component(particleArrays::UX)[c];
        const double vc = columns.p.component(particleArrays::UY)[c];
        const double V0 = columns.p.component(particleArrays::VOL)[c]/p.size();
        const label gradU = columns.f.gradU();
        const double divU =
            columns.p.component(gradU)[c] + columns.p.component(gradU + 3)[c];

        for (label i = 0; i < p.size(); ++i)
        {
            const double x = p.component(particleArrays::X)[i];
            const double y = p.component(particleArrays::Y)[i];
            const double z = p.component(particleArrays::Z)[i];
            // Footprint coordinates: inside means |a|, |b| <= 1/2
            const double dx = (x - xc)/s, dy = (y - yc)/s;
            const double a = (f11*dx - f01*dy)/det;
            const double b = (-f10*dx + f00*dy)/det;
            EXPECT_LE(std::abs(a), 0.5 + 1e-12);
            EXPECT_LE(std::abs(b), 0.5 + 1e-12);

            const double G = ground(x, y);
            EXPECT_GT(z, G);
            EXPECT_LT(z, G + h);

            EXPECT_DOUBLE_EQ(p.component(particleArrays::UX)[i], uc);
            EXPECT_DOUBLE_EQ(p.component(particleArrays::UY)[i], vc);
            // Continuity: along the bed, and the layer's thinning
            const double w = uc*groundDx(x, y) + vc*groundDy - (z - G)*divU;
            EXPECT_NEAR
            (
                p.component(particleArrays::UZ)[i], w, roundOff*(1 + std::abs(w))
            );

            const double pressure = rho*g*(G + h - z);
            EXPECT_NEAR(p.component(pF)[i], pressure, 1e-9*(1 + pressure));
            EXPECT_DOUBLE_EQ(p.component(sigma)[i], -p.component(pF)[i]);
            EXPECT_DOUBLE_EQ(p.component(sigma + 5)[i], -p.component(pF)[i]);
            EXPECT_EQ(p.component(sigma + 1)[i], 0);
            const double J = mat->restJ(p.component(pF)[i]);
            EXPECT_DOUBLE_EQ(p.component(JF)[i], J);
            EXPECT_LT(J, 1 + 1e-15);
            EXPECT_NEAR(p.component(particleArrays::VOL)[i], J*V0, 1e-14*V0);
        }
    }
}


TEST(columnsTo3D, BedVerticalVelocityFollowsTheGroundOnly)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion
    (
        region, spacing, *mat, g, columnsTo3D::profileType::uniform,
        groundWithGradient,
        columnsTo3D::verticalType::bed
    );
    const depthAveragedParticles columns = randomColumns(50, 1, 19, 1, 9, 19);
    particleArrays p = fields3D();
    const columnsTo3D::totals t =
        conversion.convert(columns.runOut(), p, stress3D());
    for (label i = 0; i < p.size(); ++i)
    {
        const double x = p.component(particleArrays::X)[i];
        const double y = p.component(particleArrays::Y)[i];
        const double w = p.component(particleArrays::UX)[i]*groundDx(x, y)
          + p.component(particleArrays::UY)[i]*groundDy;
        EXPECT_NEAR
        (
            p.component(particleArrays::UZ)[i], w, roundOff*(1 + std::abs(w))
        );
    }
    EXPECT_DOUBLE_EQ(t.kineticEnergyVertical, t.kineticEnergyBed);
}


TEST(columnsTo3D, BagnoldProfileKeepsTheDepthAverage)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion
    (
        region, spacing, *mat, g, columnsTo3D::profileType::Bagnold,
        groundWithGradient
    );
    const depthAveragedParticles columns = randomColumns(500, 1, 19, 1, 9, 13);
    particleArrays p = fields3D();
    const columnsTo3D::totals t =
        conversion.convert(columns.runOut(), p, stress3D());

    const double pScale = std::abs(t.momentumDA[0]) + std::abs(t.momentumDA[1]);
    EXPECT_LT(std::abs(t.momentum3D[0] - t.momentumDA[0]), roundOff*pScale);
    EXPECT_LT(std::abs(t.momentum3D[1] - t.momentumDA[1]), roundOff*pScale);
    // A sheared profile carries more energy than the plug of the same mean
    EXPECT_GT(t.kineticEnergy3D, 1.01*t.kineticEnergyDA);
}


TEST(columnsTo3D, CountsColumnsOutsideAndKeepsSideParticlesInside)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion = uniformConversion(*mat);
    // Centres from x = -2 to 22: some outside the region [0, 20]
    const depthAveragedParticles columns = randomColumns(2000, -2, 22, 0, 10, 17);
    double massOutside = 0;
    label nOutside = 0;
    for (label i = 0; i < columns.p.size(); ++i)
    {
        const double x = columns.p.component(particleArrays::X)[i];
        if (x < 0 || x > 20)
        {
            ++nOutside;
            massOutside += columns.p.component(particleArrays::M)[i];
        }
    }
    particleArrays p = fields3D();
    std::vector<char> converted;
    const columnsTo3D::totals t =
        conversion.convert(columns.runOut(), p, stress3D(), &converted);

    ASSERT_GT(nOutside, 0);
    EXPECT_EQ(t.unconvertedColumns, nOutside);
    EXPECT_LT(rel(t.unconvertedMass, massOutside), roundOff);
    EXPECT_EQ(t.columns + t.unconvertedColumns, columns.p.size());
    label nConverted = 0;
    for (const char c : converted)
    {
        nConverted += c;
    }
    EXPECT_EQ(nConverted, t.columns);

    // Centres reach the sides y = 0 and 10: their particles stay inside
    for (label i = 0; i < p.size(); ++i)
    {
        for (int d = 0; d < 2; ++d)
        {
            const double x = p.component(particleArrays::X + d)[i];
            EXPECT_GT(x, region.min()[d]);
            EXPECT_LT(x, region.max()[d]);
        }
    }

    // A column taller than the region is not converted either
    depthAveragedParticles tall = oneColumn(columns, 0);
    tall.p.component(particleArrays::X)[0] = 10;
    tall.p.component(particleArrays::VOL)[0] *= 1e4;
    particleArrays q = fields3D();
    const columnsTo3D::totals tt =
        conversion.convert(tall.runOut(), q, stress3D());
    EXPECT_EQ(tt.columns, 0);
    EXPECT_EQ(tt.columnsAbove, 1);
    EXPECT_EQ(q.size(), 0);
}


TEST(columnsTo3D, MergeJoinsSmallColumnsPerCellKeepingTheirSums)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion = uniformConversion(*mat);
    // Columns of a quarter of a cell of the 0.1 m spacing: 4 per cell,
    // 40 x 20 cells from (2, 3)
    const depthAveragedParticles columns =
        tiledColumns(80, 40, 0.05, 2, 3, 23);
    const runOutFields source = columns.runOut();
    const columnsTo3D::mergedColumns merged = conversion.merge(source);
    const runOutFields view = merged.view();

    EXPECT_EQ(view.n, 800);
    EXPECT_EQ(merged.nMerged, 800);
    EXPECT_EQ(merged.nMergedSource, 3200);

    // Mass, volume, area, momentum and the centre of mass kept
    const columnSums before(source), after(view);
    EXPECT_LT(rel(after.m, before.m), roundOff);
    EXPECT_LT(rel(after.V, before.V), roundOff);
    EXPECT_LT(rel(after.A, before.A), roundOff);
    EXPECT_LT(rel(after.mx, before.mx), roundOff);
    EXPECT_LT(rel(after.my, before.my), roundOff);
    const double pScale = std::abs(before.px) + std::abs(before.py);
    EXPECT_LT(std::abs(after.px - before.px), roundOff*pScale);
    EXPECT_LT(std::abs(after.py - before.py), roundOff*pScale);

    // Cell by cell: the four columns of each, their sums, a square of
    // their area and the mass-weighted gradient; the kinetic energy lost
    // is that of the velocities about each cell's mean
    std::vector<label> count(view.n, 0);
    std::vector<double> mass(view.n, 0), spread(view.n, 0);
    for (label c = 0; c < source.n; ++c)
    {
        const label k = merged.into[c];
        ASSERT_GE(k, 0);
        ASSERT_LT(k, view.n);
        EXPECT_EQ(label((source.x[c] - 2)/0.1), label((view.x[k] - 2)/0.1));
        EXPECT_EQ(label((source.y[c] - 3)/0.1), label((view.y[k] - 3)/0.1));
        ++count[k];
        mass[k] += source.m[c];
        spread[k] += 0.5*source.m[c]
           *(sqr(source.ux[c] - view.ux[k]) + sqr(source.uy[c] - view.uy[k]));
    }
    const label C = columns.f.gradU();
    double lost = 0;
    for (label k = 0; k < view.n; ++k)
    {
        EXPECT_EQ(count[k], 4);
        EXPECT_LT(rel(view.m[k], mass[k]), roundOff);
        EXPECT_DOUBLE_EQ(view.F[0][k], 1);
        EXPECT_EQ(view.F[1][k], 0);
        EXPECT_LT(rel(view.A[k], 0.01), roundOff);
        lost += spread[k];
    }
    double mGradU = 0;
    for (label c = 0; c < source.n; ++c)
    {
        mGradU += source.m[c]*columns.p.component(C + 3)[c];
    }
    double mGradUMerged = 0;
    for (label k = 0; k < view.n; ++k)
    {
        mGradUMerged += view.m[k]*view.gradU[3][k];
    }
    EXPECT_NEAR(mGradUMerged, mGradU, roundOff*before.m);
    EXPECT_GT(lost, 0);
    EXPECT_LT
    (
        std::abs(merged.kineticEnergySource - merged.kineticEnergy - lost),
        1e-10*merged.kineticEnergySource
    );

    // Converted: one particle across per cell, at its centre of mass, the
    // mass, volume and momentum of the columns
    particleArrays p = fields3D();
    const columnsTo3D::totals t = conversion.convert(view, p, stress3D());
    label nLevels = 0;
    for (label k = 0; k < view.n; ++k)
    {
        nLevels += std::max(1L, std::lround(view.V[k]/view.A[k]/0.1));
    }
    EXPECT_EQ(t.particles, nLevels);
    EXPECT_LT(rel(t.mass3D, before.m), roundOff);
    EXPECT_LT(rel(t.volume3D, before.V), roundOff);
    EXPECT_LT(std::abs(t.momentum3D[0] - before.px), roundOff*pScale);
    double px = 0, mx = 0;
    for (label i = 0; i < p.size(); ++i)
    {
        const double m = p.component(particleArrays::M)[i];
        px += m*p.component(particleArrays::UX)[i];
        mx += m*p.component(particleArrays::X)[i];
    }
    EXPECT_LT(std::abs(px - before.px), roundOff*pScale);
    EXPECT_LT(rel(mx, before.mx), roundOff);
}


TEST(columnsTo3D, MergeBinsFromTheRegionCornerAtEachAxisSpacing)
{
    const autoPtr<materialModel> mat = water();
    // A region off the origin, cells of 0.1 x 0.2 m: 2 x 4 of the 0.05 m
    // columns each, 30 x 10 cells (binned from the origin, with the axes
    // swapped or with a row stride of the cells along y, they would not
    // come in eights from one cell)
    const boundBox shifted(point(-0.73, 0.31, -10), point(3.27, 4.31, 30));
    const columnsTo3D conversion
    (
        shifted, vector(0.1, 0.2, 0.1), *mat, g,
        columnsTo3D::profileType::uniform, groundWithGradient
    );
    const depthAveragedParticles columns =
        tiledColumns(60, 40, 0.05, -0.23, 1.31, 31);
    // Without a velocity gradient, as a run-out may hand over
    runOutFields source = columns.runOut();
    for (int k = 0; k < 4; ++k)
    {
        source.gradU[k] = nullptr;
    }
    const columnsTo3D::mergedColumns merged = conversion.merge(source);
    const runOutFields view = merged.view();

    EXPECT_EQ(view.n, 300);
    EXPECT_EQ(merged.nMergedSource, 2400);
    EXPECT_EQ(view.gradU[0], nullptr);
    std::vector<label> count(view.n, 0);
    for (label c = 0; c < source.n; ++c)
    {
        const label k = merged.into[c];
        ++count[k];
        EXPECT_EQ
        (
            label((source.x[c] + 0.73)/0.1), label((view.x[k] + 0.73)/0.1)
        );
        EXPECT_EQ
        (
            label((source.y[c] - 0.31)/0.2), label((view.y[k] - 0.31)/0.2)
        );
    }
    for (label k = 0; k < view.n; ++k)
    {
        EXPECT_EQ(count[k], 8);
    }
    particleArrays p = fields3D();
    const columnsTo3D::totals t = conversion.convert(view, p, stress3D());
    EXPECT_EQ(t.columns, 300);
    EXPECT_LT(rel(t.mass3D, columnSums(source).m), roundOff);
}


TEST(columnsTo3D, MergeKeepsLargeLoneAndOutsideColumnsAsTheyAre)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion = uniformConversion(*mat);
    // Random footprints of 0.05-0.25 m (some above the 0.1 m spacing),
    // centres from x = -2 to 22 (some outside the region)
    const depthAveragedParticles columns =
        randomColumns(3000, -2, 22, 0, 10, 29);
    const runOutFields source = columns.runOut();
    const columnsTo3D::mergedColumns merged = conversion.merge(source);
    const runOutFields view = merged.view();

    // The columns alone in their merged column are copied bit for bit;
    // those outside the region and those wider than the spacing are alone
    std::vector<label> count(view.n, 0);
    for (label c = 0; c < source.n; ++c)
    {
        ++count[merged.into[c]];
    }
    label nAlone = 0, nOutside = 0;
    for (label c = 0; c < source.n; ++c)
    {
        const label k = merged.into[c];
        const double x = source.x[c];
        const double edge = std::sqrt(source.A[c]);
        if (x < 0 || x > 20 || edge > 0.15)
        {
            EXPECT_EQ(count[k], 1) << "column " << c;
        }
        nOutside += x < 0 || x > 20;
        if (count[k] == 1)
        {
            ++nAlone;
            EXPECT_EQ(view.x[k], x);
            EXPECT_EQ(view.y[k], source.y[c]);
            EXPECT_EQ(view.ux[k], source.ux[c]);
            EXPECT_EQ(view.m[k], source.m[c]);
            EXPECT_EQ(view.V[k], source.V[c]);
            EXPECT_EQ(view.A[k], source.A[c]);
            for (int j = 0; j < 4; ++j)
            {
                EXPECT_EQ(view.F[j][k], source.F[j][c]);
                EXPECT_EQ(view.gradU[j][k], source.gradU[j][c]);
            }
        }
    }
    EXPECT_GT(nOutside, 0);
    EXPECT_GT(nAlone, nOutside);
    EXPECT_GT(merged.nMerged, 0);
    EXPECT_EQ(view.n, nAlone + merged.nMerged);
    EXPECT_EQ(source.n, nAlone + merged.nMergedSource);

    // Converted: the same columns outside, the same mass, volume and
    // momentum inside as without the merge, from fewer particles; the
    // flags per source column are those of their merged column
    particleArrays p = fields3D(), q = fields3D();
    std::vector<char> convertedMerged, converted;
    const columnsTo3D::totals t =
        conversion.convert(view, p, stress3D(), &convertedMerged);
    const columnsTo3D::totals t0 =
        conversion.convert(source, q, stress3D(), &converted);
    EXPECT_EQ(merged.perSource(convertedMerged), converted);
    EXPECT_EQ(t.unconvertedColumns, t0.unconvertedColumns);
    EXPECT_DOUBLE_EQ(t.unconvertedMass, t0.unconvertedMass);
    EXPECT_LT(rel(t.mass3D, t0.mass3D), roundOff);
    EXPECT_LT(rel(t.volume3D, t0.volume3D), roundOff);
    const double pScale =
        std::abs(t0.momentumDA[0]) + std::abs(t0.momentumDA[1]);
    EXPECT_LT(std::abs(t.momentum3D[0] - t0.momentum3D[0]), roundOff*pScale);
    EXPECT_LT(std::abs(t.momentum3D[1] - t0.momentum3D[1]), roundOff*pScale);
    EXPECT_LT(t.particles, t0.particles);
}


// ************************************************************************* //
