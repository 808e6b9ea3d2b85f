/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    NewtonianRheology against its closed forms (doc/dampmFoam-discretisation.md
    section 7):
    - purely viscous (the default): sigma = 2 mu D, D the symmetric part of
      the velocity gradient, whatever the old stress; zero below hMin;
    - with shearModulus G, the Maxwell element under a constant D from an
      unstressed column: sigma(t) = 2 mu D (1 - exp(-G t/mu)), and from a
      stress sigma0 without strain rate sigma0 exp(-G t/mu), exactly at any
      step;
    - a spin turns the old stress (Jaumann rate): a stress held (mu/G much
      longer than the run) under a steady spin w follows the rotation by
      w t to first order in w dt;
    - basalShear: the drag of the parabolic profile, k1 |v| = 3 mu U/H a
      with U = |v|/cos(theta) and H = max(h, hMin) cos(theta); none without.

\*---------------------------------------------------------------------------*/

#include "rheologyModel.H"
#include "columnArrays.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

TEST(NewtonianRheology, ViscousStressIsTwiceMuTimesTheStrainRate)
{
    const double mu = 50;
    const autoPtr<rheologyModel> rheology
    (
        rheologyModel::New(modelDict("rheology", "Newtonian", "mu 50;"))
    );
    EXPECT_TRUE(rheology->active());
    EXPECT_EQ(rheology->shearModulus(), 0);
    EXPECT_FALSE(rheology->defaultShearModulus());
    EXPECT_EQ(rheology->maxViscosity(), mu);

    // The second column is thinner than hMin: no stress
    columnArrays cols({1, 0.5e-4}, {1, 1}, {1, 1});
    const double L[4] = {0.3, 1.2, -0.4, -0.7};
    cols.setGradient({L[0], L[1], L[2], L[3]});
    cols.sigma[0] = {123, 123};
    rheology->stress(cols.view(), 0.01);

    constexpr double tol = 1e-15; // one product
    EXPECT_NEAR(cols.sigma[0][0], 2*mu*L[0], tol*mu);
    EXPECT_NEAR(cols.sigma[1][0], mu*(L[1] + L[2]), tol*mu);
    EXPECT_NEAR(cols.sigma[2][0], 2*mu*L[3], tol*mu);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_EQ(cols.sigma[k][1], 0) << k;
    }
}


TEST(NewtonianRheology, MaxwellStressRelaxesExactlyAtAnyStep)
{
    const double mu = 100, G = 500, t = 0.3;
    const autoPtr<rheologyModel> rheology
    (
        rheologyModel::New
        (
            modelDict("rheology", "Newtonian", "mu 100; shearModulus 500;")
        )
    );
    EXPECT_EQ(rheology->shearModulus(), G);

    // Pure shear and extension (no spin)
    const double D[3] = {0.2, 0.15, -0.1};
    const double decay = std::exp(-G*t/mu);
    constexpr double tol = 1e-13; // round-off over up to 300 steps
    for (const int nSteps : {1, 7, 300})
    {
        columnArrays cols({1}, {1}, {1});
        cols.setGradient({D[0], D[1], D[1], D[2]});
        for (int n = 0; n < nSteps; ++n)
        {
            rheology->stress(cols.view(), t/nSteps);
        }
        EXPECT_NEAR(cols.sigma[0][0], 2*mu*D[0]*(1 - decay), tol*mu)
            << nSteps;
        EXPECT_NEAR(cols.sigma[1][0], 2*mu*D[1]*(1 - decay), tol*mu)
            << nSteps;
        EXPECT_NEAR(cols.sigma[2][0], 2*mu*D[2]*(1 - decay), tol*mu)
            << nSteps;

        // Without strain rate a stress relaxes to zero
        cols.setGradient({0, 0, 0, 0});
        cols.sigma[0] = {1000};
        cols.sigma[1] = {-300};
        cols.sigma[2] = {0};
        for (int n = 0; n < nSteps; ++n)
        {
            rheology->stress(cols.view(), t/nSteps);
        }
        EXPECT_NEAR(cols.sigma[0][0], 1000*decay, tol*1000) << nSteps;
        EXPECT_NEAR(cols.sigma[1][0], -300*decay, tol*1000) << nSteps;
        EXPECT_EQ(cols.sigma[2][0], 0) << nSteps;
    }
}


TEST(NewtonianRheology, SpinTurnsTheStressWithTheJaumannRate)
{
    // mu/G = 1e12 s: the stress is held; the spin w turns it by w t
    const autoPtr<rheologyModel> rheology
    (
        rheologyModel::New
        (
            modelDict("rheology", "Newtonian", "mu 1e12; shearModulus 1;")
        )
    );
    const double w = 2, t = 0.25, a = 1000, c = -400;
    double error[2];
    const int nSteps[2] = {1000, 2000};
    for (int k = 0; k < 2; ++k)
    {
        columnArrays cols({1}, {1}, {1});
        // dv/dx - du/dy = 2 w
        cols.setGradient({0, -w, w, 0});
        cols.sigma[0] = {a};
        cols.sigma[2] = {c};
        for (int n = 0; n < nSteps[k]; ++n)
        {
            rheology->stress(cols.view(), t/nSteps[k]);
        }
        // R diag(a, c) R^T, R the rotation by w t
        const double cs = std::cos(w*t), sn = std::sin(w*t);
        const double exact[3] =
            {a*cs*cs + c*sn*sn, (a - c)*sn*cs, a*sn*sn + c*cs*cs};
        error[k] = 0;
        for (int i = 0; i < 3; ++i)
        {
            error[k] =
                std::max(error[k], std::abs(cols.sigma[i][0] - exact[i]));
        }
    }
    // First order: about w^2 t dt (a - c)
    constexpr double tol = 1e-3;
    EXPECT_LT(error[1], tol*(a - c));
    EXPECT_NEAR(error[0]/error[1], 2, 0.1);
}


TEST(NewtonianRheology, BasalShearIsTheDragOfTheParabolicProfile)
{
    const double mu = 30, hMin = 1e-4;
    const double kappa[3] = {1, 0.75, 0.5};
    const double h[3] = {0.8, 2.5, 0.5e-4};
    const double a[3] = {1, 0.3, 2};
    const double v = 1.7; // horizontal speed [m/s]

    const autoPtr<rheologyModel> off
    (
        rheologyModel::New(modelDict("rheology", "Newtonian", "mu 30;"))
    );
    const autoPtr<rheologyModel> on
    (
        rheologyModel::New
        (
            modelDict("rheology", "Newtonian", "mu 30; basalShear true;")
        )
    );
    EXPECT_EQ(off->basalTerms(), 0u);
    EXPECT_EQ(on->basalTerms(), unsigned(basalTerm::k1));

    columnArrays cols({h[0], h[1], h[2]}, {a[0], a[1], a[2]},
        {kappa[0], kappa[1], kappa[2]});
    off->addResistance(cols.view());
    EXPECT_EQ(cols.k1, std::vector<double>(3, 0.0));
    on->addResistance(cols.view());

    constexpr double tol = 1e-14; // a few products
    for (int i = 0; i < 3; ++i)
    {
        const double U = v/std::sqrt(kappa[i]);
        const double H = std::max(h[i], hMin)*std::sqrt(kappa[i]);
        const double expected = 3*mu*U/H*a[i];
        EXPECT_NEAR(cols.k1[i]*v, expected, tol*expected) << i;
        EXPECT_EQ(cols.s[i], 0);
        EXPECT_EQ(cols.k2[i], 0);
    }
}


// ************************************************************************* //
