/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    BinghamRheology against its closed forms (doc/dampmFoam-discretisation.md
    sections 6, 7 and 13.5):
    - purely viscous (shearModulus 0), the shear stress at shear rate
      gammaDot is mu gammaDot + tauY (1 - exp(-m gammaDot)) (Papanastasiou)
      or min(mu + tauY/gammaDot, muMax) gammaDot (bi-viscous); the largest
      viscosity mu + m tauY or muMax;
    - without a yield stress it is the Newtonian rheology, bit for bit;
    - with a yield stress and a modulus it is elasto-viscoplastic
      (BinghamElastoViscoplasticTest.C);
    - basalShear: s = tauY a and the Newtonian drag; with the implicit
      update (resistanceUpdate) a layer on a slope theta stays exactly at
      rest up to its yield thickness h_y = tauY/(rho g sin cos), and above
      it reaches v = kappa h (rho g h sin cos - tauY)/(3 mu).

\*---------------------------------------------------------------------------*/

#include "rheologyModel.H"
#include "columnArrays.H"
#include "mathematicalConstants.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

//- The shear stress sigma_xy of a column in simple shear at gammaDot
double shearStress(const rheologyModel& rheology, const double gammaDot)
{
    columnArrays col({1}, {1}, {1});
    col.setGradient({0, gammaDot, 0, 0});
    rheology.stress(col.view(), 0.01);
    return col.sigma[1][0];
}

} // End anonymous namespace


TEST(BinghamRheology, ViscousStressFollowsTheRegularisedLaws)
{
    const double mu = 50, tauY = 2000, m = 100, muMax = 1e4;
    const autoPtr<rheologyModel> papanastasiou
    (
        rheologyModel::New(modelDict("rheology", "Bingham",
            "mu 50; tauY 2000; shearModulus 0;"))
    );
    const autoPtr<rheologyModel> biViscous
    (
        rheologyModel::New(modelDict("rheology", "Bingham",
            "mu 50; tauY 2000; regularisation biViscous; muMax 1e4;"
            " shearModulus 0;"))
    );
    EXPECT_EQ(papanastasiou->maxViscosity(), mu + m*tauY);
    EXPECT_EQ(biViscous->maxViscosity(), muMax);

    constexpr double tol = 1e-13; // expm1 and a few products
    for (const double gammaDot : {1e-10, 1e-3, 0.1, 10.0})
    {
        const double tauP = mu*gammaDot - tauY*std::expm1(-m*gammaDot);
        EXPECT_NEAR(shearStress(papanastasiou(), gammaDot), tauP, tol*tauP)
            << gammaDot;
        const double tauB = std::min(mu + tauY/gammaDot, muMax)*gammaDot;
        EXPECT_NEAR(shearStress(biViscous(), gammaDot), tauB, tol*tauB)
            << gammaDot;
    }
}


TEST(BinghamRheology, WithoutYieldStressItIsTheNewtonianRheology)
{
    const autoPtr<rheologyModel> bingham
    (
        rheologyModel::New(modelDict("rheology", "Bingham", "mu 7; tauY 0;"))
    );
    const autoPtr<rheologyModel> newtonian
    (
        rheologyModel::New(modelDict("rheology", "Newtonian", "mu 7;"))
    );
    EXPECT_FALSE(bingham->defaultShearModulus());
    EXPECT_EQ(bingham->shearModulus(), 0);

    columnArrays a({1, 0.3}, {1, 1}, {1, 0.8}), b(a);
    a.setGradient({0.3, 1.2, -0.4, -0.7});
    b.setGradient({0.3, 1.2, -0.4, -0.7});
    bingham->stress(a.view(), 0.01);
    newtonian->stress(b.view(), 0.01);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_EQ(a.sigma[k], b.sigma[k]) << k;
    }
}


TEST(BinghamRheology, BasalYieldHoldsALayerUpToItsYieldThickness)
{
    const double mu = 50, tauY = 2000, rho = 1800;
    const double theta = 25*constant::mathematical::pi/180;
    const double kappa = sqr(std::cos(theta));
    const double sinCos = std::sin(theta)*std::cos(theta);
    const double hy = tauY/(rho*9.81*sinCos);
    const autoPtr<rheologyModel> rheology
    (
        rheologyModel::New(modelDict("rheology", "Bingham",
            "mu 50; tauY 2000; basalShear true; shearModulus 0;"))
    );

    for (const double ratio : {0.999, 1.2})
    {
        const double h = ratio*hy;
        columnArrays col({h}, {1}, {kappa}, rho);
        rheology->addResistance(col.view());
        EXPECT_NEAR(col.s[0], tauY, 1e-15*tauY);
        EXPECT_NEAR(col.k1[0], 3*mu/(kappa*h), 1e-15*mu/h);

        loneNode node;
        node.m = col.m[0];
        node.S = col.s[0];
        node.K1 = col.k1[0];
        node.F[0] = col.m[0]*col.g*kappa*std::tan(theta);
        // 200 s: 160 relaxation times m/K1 above the yield thickness
        for (int n = 0; n < 20000; ++n)
        {
            node.step(1e-2);
            if (ratio < 1)
            {
                ASSERT_EQ(node.P[0], 0) << n;
            }
        }
        if (ratio > 1)
        {
            const double v = kappa*h*(rho*9.81*h*sinCos - tauY)/(3*mu);
            constexpr double tol = 1e-10; // converged to round-off
            EXPECT_NEAR(node.speed(), v, tol*v);
        }
    }
}


// ************************************************************************* //
