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
    keep their particles inside.

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

} // End anonymous namespace


TEST(columnsTo3D, ConservesOnRandomColumnsOverSlopingGround)
{
    const autoPtr<materialModel> mat = water();
    const columnsTo3D conversion
    (
        region, spacing, *mat, g, columnsTo3D::profileType::uniform,
        groundWithGradient
    );
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
    const columnsTo3D conversion
    (
        region, spacing, *mat, g, columnsTo3D::profileType::uniform,
        groundWithGradient
    );
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
    const columnsTo3D conversion
    (
        region, spacing, *mat, g, columnsTo3D::profileType::uniform,
        groundWithGradient
    );
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


// ************************************************************************* //
