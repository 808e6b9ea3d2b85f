/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The elasto-viscoplastic in-plane stress of the Bingham rheology with a
    yield stress and a modulus G (Saramito, 2007, n = 1; the default), one
    column, against its closed forms (doc/dampmFoam-discretisation.md,
    section 7), |sigma| = sqrt(sigma:sigma/2):
    - a plug holds a stress below yield for ever, where the regularised
      law it replaces relaxed it and crept;
    - loading below yield is elastic, 2 G D dt per step, and so is
      unloading from the yield surface;
    - steady shear gives the Bingham stress tauY + mu gammaDot exactly at
      any step, and without viscosity the yield stress itself;
    - the plug sets no viscous step (the elastic one holds), while the
      purely viscous stress (shearModulus 0) keeps its regularised limit;
    - columns thinner than hMin carry no stress;
    - many columns (thin and thick, below and above yield, 1 and 2
      threads) get what the one-column form, branch by branch, gives, bit
      for bit.

\*---------------------------------------------------------------------------*/

#include "rheologyModel.H"
#include "IStringStream.H"
#include "columnArrays.H"
#include "sameBits.H"
#include "threadCount.H"
#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

//- The rheology of BinghamCoeffs { coeffs }
autoPtr<rheologyModel> bingham(const std::string& coeffs)
{
    IStringStream is("rheology Bingham; BinghamCoeffs { " + coeffs + " }");
    return rheologyModel::New(dictionary(is));
}


//- One column of height h with a velocity gradient (row-major du/dx
//  du/dy dv/dx dv/dy) and a stress (xx xy yy)
struct column
{
    double m = 1000, h = 1, a = 1, kappa = 1;
    double C[4] = {0, 0, 0, 0};
    double sigma[3] = {0, 0, 0};
    double s = 0, k1 = 0, k2 = 0;

    shallowParticles view()
    {
        shallowParticles p;
        p.n = 1;
        p.m = &m;
        p.h = &h;
        p.a = &a;
        p.kappa = &kappa;
        for (int k = 0; k < 4; ++k)
        {
            p.C[k] = &C[k];
        }
        for (int k = 0; k < 3; ++k)
        {
            p.sigma[k] = &sigma[k];
        }
        p.s = &s;
        p.k1 = &k1;
        p.k2 = &k2;
        return p;
    }

    //- Pure shear at the rate gammaDot (D_xy = gammaDot/2, no spin)
    void shear(const double gammaDot)
    {
        C[0] = C[3] = 0;
        C[1] = C[2] = 0.5*gammaDot;
    }

    //- |sigma| = sqrt(sigma:sigma/2)
    double magnitude() const
    {
        return std::sqrt
        (
            0.5*(sqr(sigma[0]) + 2*sqr(sigma[1]) + sqr(sigma[2]))
        );
    }
};

constexpr double mu = 50, tauY = 2000, G = 19600;

} // End anonymous namespace


TEST(BinghamElastoViscoplastic, PlugHoldsAStressBelowYieldWithoutCreep)
{
    autoPtr<rheologyModel> evp(bingham("mu 50; tauY 2000;"));
    ASSERT_TRUE(evp->defaultShearModulus());
    evp->setDefaultShearModulus(G);

    // A stretched, sheared plug at rest, 0.9 tauY: no rate, no relaxation,
    // over 1000 s of steps of 0.1 s
    column c;
    c.sigma[0] = 1200;
    c.sigma[1] = 900;
    c.sigma[2] = -700;
    ASSERT_LT(c.magnitude(), tauY);
    const column held(c);
    for (int n = 0; n < 10000; ++n)
    {
        evp->stress(c.view(), 0.1);
    }
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_EQ(c.sigma[k], held.sigma[k]) << k;
    }
}


TEST(BinghamElastoViscoplastic, LoadingBelowYieldIsElasticAndSoIsUnloading)
{
    autoPtr<rheologyModel> evp(bingham("mu 50; tauY 2000; shearModulus 19600;"));
    constexpr double tol = 1e-12;   // round-off of a few products

    // Stretching at 0.01/s for 0.5 s in steps of 0.05 s: 2 G D t = 196 Pa
    column c;
    c.C[0] = 0.01;
    for (int n = 0; n < 10; ++n)
    {
        evp->stress(c.view(), 0.05);
    }
    EXPECT_NEAR(c.sigma[0], 2*G*0.01*0.5, tol*G);
    EXPECT_EQ(c.sigma[1], 0);
    EXPECT_EQ(c.sigma[2], 0);

    // Sheared beyond the yield surface (trial 3920 Pa), then unloaded by a
    // shear of 0.05: the stress falls by G times it, elastically
    c.C[0] = 0;
    c.shear(2);
    evp->stress(c.view(), 0.1);
    const column yielded(c);
    EXPECT_GT(c.magnitude(), tauY);
    EXPECT_LT(c.magnitude(), 1.1*tauY);
    c.shear(-0.5);
    evp->stress(c.view(), 0.1);
    EXPECT_LT(c.magnitude(), tauY);
    EXPECT_NEAR(c.sigma[1], yielded.sigma[1] - G*0.5*0.1, tol*G);
    EXPECT_EQ(c.sigma[0], yielded.sigma[0]);
}


TEST(BinghamElastoViscoplastic, SteadyShearIsBinghamAtAnyStep)
{
    autoPtr<rheologyModel> evp(bingham("mu 50; tauY 2000; shearModulus 19600;"));
    autoPtr<rheologyModel> plastic(bingham("mu 0; tauY 2000; shearModulus 19600;"));
    constexpr double tol = 1e-12;   // the fixed point to round-off

    for (const double gammaDot : {1e-3, 0.1, 10.0})
    {
        for (const double dt : {1e-4, 1e-2, 1.0})
        {
            // From the yield stress: the excess over it approaches mu
            // gammaDot by the factor mu/(mu + G dt) per step, 0.96 at
            // the smallest step, 2000 steps are plenty
            column c, p;
            c.sigma[1] = p.sigma[1] = tauY;
            c.shear(gammaDot);
            p.shear(gammaDot);
            for (int n = 0; n < 2000; ++n)
            {
                evp->stress(c.view(), dt);
                plastic->stress(p.view(), dt);
            }
            const double bingham = tauY + mu*gammaDot;
            EXPECT_NEAR(c.sigma[1], bingham, tol*bingham)
                << gammaDot << " " << dt;
            EXPECT_NEAR(p.sigma[1], tauY, tol*tauY)
                << gammaDot << " " << dt;
        }
    }
}


TEST(BinghamElastoViscoplastic, ElasticPlugSetsTheStepNotTheRegularisation)
{
    autoPtr<rheologyModel> evp(bingham("mu 50; tauY 2000;"));
    evp->setDefaultShearModulus(G);
    EXPECT_EQ(evp->shearModulus(), G);
    EXPECT_EQ(evp->maxViscosity(), VGREAT);

    // Purely viscous: the regularised plug mu + m tauY sets the step
    autoPtr<rheologyModel> viscous
    (
        bingham("mu 50; tauY 2000; m 100; shearModulus 0;")
    );
    EXPECT_EQ(viscous->maxViscosity(), mu + 100*tauY);

    // Without a yield stress there is no plug: the Maxwell fluid of mu
    autoPtr<rheologyModel> noYield
    (
        bingham("mu 50; tauY 0; shearModulus 19600;")
    );
    EXPECT_EQ(noYield->maxViscosity(), mu);
}


TEST(BinghamElastoViscoplastic, ThinColumnsCarryNoStress)
{
    autoPtr<rheologyModel> evp(bingham("mu 50; tauY 2000; shearModulus 19600;"));
    column c;
    c.h = 0.5e-4;                   // below the default hMin 1e-4 m
    c.sigma[0] = c.sigma[1] = c.sigma[2] = 100;
    c.shear(1);
    evp->stress(c.view(), 0.01);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_EQ(c.sigma[k], 0) << k;
    }
}


// The columns' loop runs every column through the same operations (a
// vector loop): each column's stress is the one-column form's, branch by
// branch (spun old stress plus 2 G D dt; at or below yield kept, above it
// scaled to tauY plus the kept share of the excess; thin: zero), bit for
// bit, with and without viscosity, some columns at the yield stress
// exactly, on 1 and 2 threads
TEST(BinghamElastoViscoplastic, ManyColumnsAreTheOneColumnFormBitForBit)
{
    const double dt = 0.003;
    for (const double viscosity : {mu, 0.0})
    {
        autoPtr<rheologyModel> evp
        (
            bingham
            (
                "mu " + std::to_string(viscosity)
              + "; tauY 2000; shearModulus 19600;"
            )
        );
        constexpr int n = 10007;
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<double> h(n), ones(n, 1.0);
        for (int i = 0; i < n; ++i)
        {
            h[i] = i % 5 == 0 ? 0.5e-4 : 0.2 + u(rng);
        }
        columnArrays cols(h, ones, ones);
        for (int i = 0; i < n; ++i)
        {
            for (int k = 0; k < 4; ++k)
            {
                cols.C[k][i] = i % 7 == 0 ? 0 : 3*u(rng);
            }
            for (int k = 0; k < 3; ++k)
            {
                cols.sigma[k][i] = i % 7 == 0 ? 0 : 1.5*tauY*u(rng);
            }
            // At the yield stress exactly: |sigma| = |sigma_xy| = tauY
            if (i % 11 == 3)
            {
                for (int k = 0; k < 4; ++k)
                {
                    cols.C[k][i] = 0;
                }
                cols.sigma[0][i] = cols.sigma[2][i] = 0;
                cols.sigma[1][i] = tauY;
            }
        }

        // The one-column form
        const double keep =
            viscosity > 0 ? viscosity/(viscosity + G*dt) : 0;
        const double Gdt = G*dt;
        std::vector<double> expected[3];
        int nYield = 0, nBelow = 0;
        for (int i = 0; i < n; ++i)
        {
            double sxx = 0, sxy = 0, syy = 0;
            if (cols.h[i] >= cols.hMin)
            {
                const double wdt = 0.5*(cols.C[2][i] - cols.C[1][i])*dt;
                const double a = cols.sigma[0][i];
                const double b = cols.sigma[1][i];
                const double c = cols.sigma[2][i];
                sxx = (a - 2*wdt*b) + 2*Gdt*cols.C[0][i];
                sxy = (b + wdt*(a - c)) + Gdt*(cols.C[1][i] + cols.C[2][i]);
                syy = (c + 2*wdt*b) + 2*Gdt*cols.C[3][i];
                const double tau =
                    std::sqrt(0.5*(sxx*sxx + 2*sxy*sxy + syy*syy));
                if (tau > tauY)
                {
                    const double scale = (tauY + (tau - tauY)*keep)/tau;
                    sxx *= scale;
                    sxy *= scale;
                    syy *= scale;
                    ++nYield;
                }
                else
                {
                    ++nBelow;
                }
            }
            expected[0].push_back(sxx);
            expected[1].push_back(sxy);
            expected[2].push_back(syy);
        }
        EXPECT_GT(nYield, n/5);
        EXPECT_GT(nBelow, n/5);

        for (const int threads : {1, 2})
        {
            columnArrays run(cols);
            {
                const threadCount guard(threads);
                evp->stress(run.view(), dt);
            }
            int differing = 0;
            for (int i = 0; i < n; ++i)
            {
                for (int k = 0; k < 3; ++k)
                {
                    differing += !sameBits(run.sigma[k][i], expected[k][i]);
                }
            }
            EXPECT_EQ(differing, 0)
                << "mu " << viscosity << ", " << threads << " threads";
        }
    }
}


// ************************************************************************* //
