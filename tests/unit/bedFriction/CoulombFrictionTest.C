/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    CoulombFriction against its closed forms (doc/dampmFoam-discretisation.md
    sections 6 and 13.3):
    - the resistance of a column is tan(phi) times its bed-normal load,
      s = tan(phi) (rho g kappa h + pA) a, added to what is there;
    - with the implicit update at a node (resistanceUpdate), a column
      sliding on a slope gentler than phi decelerates at
      g kappa (tan(phi) - tan(theta)), stops exactly at the first step at
      or after t* = u0/(g kappa (tan(phi) - tan(theta))), never reverses
      and stays exactly at rest; one step longer than the whole stop stops
      it without reversing; on a steeper slope it accelerates from rest at
      g kappa (tan(theta) - tan(phi)).

\*---------------------------------------------------------------------------*/

#include "bedFrictionModel.H"
#include "columnArrays.H"
#include "mathematicalConstants.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

const double deg = constant::mathematical::pi/180;

//- A column of 1 m on 1 m^2 on a slope theta (slope correction on:
//  kappa = cos^2(theta)) at a lone node, with the Coulomb resistance of
//  friction angle phi and the driving force of the slope, m g kappa
//  tan(theta) along x (the gradient-form force of a uniform layer)
loneNode slidingColumn(const double theta, const double phi)
{
    const double kappa = sqr(std::cos(theta*deg));
    columnArrays col({1}, {1}, {kappa}, 1900);
    bedFrictionModel::New
    (
        modelDict("bedFriction", "Coulomb", "phi " + std::to_string(phi) + ";")
    )->addResistance(col.view());

    loneNode node;
    node.m = col.m[0];
    node.S = col.s[0];
    node.F[0] = col.m[0]*col.g*kappa*std::tan(theta*deg);
    return node;
}

} // End anonymous namespace


TEST(CoulombFriction, ResistanceIsTanPhiTimesTheBedNormalLoad)
{
    const double tanPhi = std::tan(30*deg), pA = 150;
    columnArrays cols
    (
        {0.5, 2, 3.7},
        {0.25, 1, 0.04},
        {1, sqr(std::cos(20*deg)), sqr(std::cos(40*deg))},
        1900
    );
    cols.s = {7, 0, -1};
    const autoPtr<bedFrictionModel> friction
    (
        bedFrictionModel::New(modelDict("bedFriction", "Coulomb",
            "phi 30; pA 150;"))
    );
    EXPECT_TRUE(friction->active());
    friction->addResistance(cols.view());

    constexpr double tol = 1e-14; // round-off of a few products
    const double before[3] = {7, 0, -1};
    for (int i = 0; i < 3; ++i)
    {
        const double sigmaN = cols.rho*cols.g*cols.kappa[i]*cols.h[i] + pA;
        const double expected = before[i] + tanPhi*sigmaN*cols.a[i];
        EXPECT_NEAR(cols.s[i], expected, tol*std::abs(expected)) << i;
        EXPECT_EQ(cols.k1[i], 0);
        EXPECT_EQ(cols.k2[i], 0);
    }
}


TEST(CoulombFriction, SlidingColumnStopsAtTheAnalyticTimeAndStaysAtRest)
{
    const double theta = 20, phi = 30, u0 = 5, dt = 1e-3;
    loneNode node = slidingColumn(theta, phi);
    const double kappa = sqr(std::cos(theta*deg));
    const double decel =
        9.81*kappa*(std::tan(phi*deg) - std::tan(theta*deg));
    const double tStop = u0/decel;

    // Along (0.6, 0.8): the direction is kept
    const double e[2] = {0.6, 0.8};
    const double F = node.F[0];
    node.F[0] = F*e[0];
    node.F[1] = F*e[1];
    node.P[0] = node.m*u0*e[0];
    node.P[1] = node.m*u0*e[1];

    constexpr double tol = 1e-11; // round-off summed over 1e3 steps
    double stoppedAt = -1;
    const int nSteps = int(2*tStop/dt);
    for (int n = 1; n <= nSteps; ++n)
    {
        node.step(dt);
        const double u = node.speed();
        if (stoppedAt < 0)
        {
            EXPECT_NEAR(u, std::max(u0 - n*dt*decel, 0.0), tol*u0) << n;
            if (u == 0)
            {
                stoppedAt = n*dt;
            }
        }
        else
        {
            // Exactly at rest, every step after
            ASSERT_EQ(node.P[0], 0) << n;
            ASSERT_EQ(node.P[1], 0) << n;
        }
        // Never reversed: the momentum stays along e
        ASSERT_GE(node.P[0], 0) << n;
        ASSERT_GE(node.P[1], 0) << n;
        EXPECT_NEAR(node.P[0]*e[1], node.P[1]*e[0], tol*node.m*u0) << n;
    }
    // The first step at or after t* (1e-9 dt: the margin of the stick test)
    EXPECT_GE(stoppedAt, tStop - 1e-9*dt);
    EXPECT_LT(stoppedAt, tStop + dt);
}


TEST(CoulombFriction, StepLongerThanTheStopStopsWithoutReversing)
{
    const double theta = 10, phi = 35, u0 = 2;
    loneNode node = slidingColumn(theta, phi);
    const double decel =
        9.81*sqr(std::cos(theta*deg))
       *(std::tan(phi*deg) - std::tan(theta*deg));
    node.P[0] = node.m*u0;
    node.step(10*u0/decel);
    EXPECT_EQ(node.P[0], 0);
    EXPECT_EQ(node.P[1], 0);
    for (int n = 0; n < 1000; ++n)
    {
        node.step(1e-2);
        ASSERT_EQ(node.P[0], 0) << n;
    }
}


TEST(CoulombFriction, SteeperThanPhiAcceleratesAtTheNetSlopeAcceleration)
{
    const double theta = 35, phi = 30, dt = 1e-3;
    loneNode node = slidingColumn(theta, phi);
    const double accel =
        9.81*sqr(std::cos(theta*deg))
       *(std::tan(theta*deg) - std::tan(phi*deg));
    constexpr double tol = 1e-11; // round-off summed over 1e3 steps
    for (int n = 1; n <= 1000; ++n)
    {
        node.step(dt);
        ASSERT_NEAR(node.speed(), n*dt*accel, tol*accel) << n;
    }
}


// ************************************************************************* //
