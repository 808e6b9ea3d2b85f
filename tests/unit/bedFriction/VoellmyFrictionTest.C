/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    VoellmyFriction against its closed forms (doc/dampmFoam-discretisation.md
    sections 6, 11 and 13.4), with the slope correction (kappa =
    cos^2(theta), H = h cos(theta) slope-normal, U = |v|/cos(theta) along
    the slope):
    - the resistance of a column at horizontal speed |v| is
      (tan(phi) (rho g kappa h + pA) + rho g U^2/xi) a: the Coulomb part in
      s, the turbulent drag in k2;
    - with the implicit update at a node (resistanceUpdate), a column on a
      plane approaches the terminal speed along the slope
      U = sqrt(xi H (sin(theta) - cos(theta) tan(phi))) from below and from
      above without overshooting, to the same value at any step; from rest
      it follows u(t) = u_inf tanh(A t/u_inf) to first order in the step.

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

//- Slope, friction angle [deg], turbulence coefficient [m/s^2], vertical
//  height [m]
constexpr double theta = 35, phi = 20, xi = 500, h = 2;

//- The column at a lone node: mass, driving force along x and the
//  Voellmy coefficients of the model
loneNode voellmyColumn()
{
    const double kappa = sqr(std::cos(theta*deg));
    columnArrays col({h}, {1}, {kappa}, 2000);
    bedFrictionModel::New
    (
        modelDict("bedFriction", "Voellmy", "phi 20; xi 500;")
    )->addResistance(col.view());

    loneNode node;
    node.m = col.m[0];
    node.S = col.s[0];
    node.K2 = col.k2[0];
    node.F[0] = col.m[0]*col.g*kappa*std::tan(theta*deg);
    return node;
}


//- The closed-form terminal speed along the slope [m/s]
double terminalSpeed()
{
    const double H = h*std::cos(theta*deg);
    return std::sqrt
    (
        xi*H*(std::sin(theta*deg) - std::cos(theta*deg)*std::tan(phi*deg))
    );
}

} // End anonymous namespace


TEST(VoellmyFriction, ResistanceIsCoulombPlusTheTurbulentDragAlongTheBed)
{
    const double tanPhi = std::tan(25*deg), pA = 80, xiV = 400;
    columnArrays cols
    (
        {0.5, 2, 3.7},
        {0.25, 1, 0.04},
        {1, sqr(std::cos(20*deg)), sqr(std::cos(40*deg))},
        1900
    );
    bedFrictionModel::New
    (
        modelDict("bedFriction", "Voellmy", "phi 25; xi 400; pA 80;")
    )->addResistance(cols.view());

    constexpr double tol = 1e-14; // round-off of a few products
    const double v = 3; // horizontal speed [m/s]
    for (int i = 0; i < 3; ++i)
    {
        const double U2 = v*v/cols.kappa[i];
        const double expected =
            (
                tanPhi*(cols.rho*cols.g*cols.kappa[i]*cols.h[i] + pA)
              + cols.rho*cols.g*U2/xiV
            )*cols.a[i];
        const double resistance = cols.s[i] + cols.k2[i]*v*v;
        EXPECT_NEAR(resistance, expected, tol*expected) << i;
        EXPECT_EQ(cols.k1[i], 0);
    }
}


TEST(VoellmyFriction, ColumnReachesTheTerminalSpeedWhateverTheStep)
{
    const double U = terminalSpeed();
    const double cosTheta = std::cos(theta*deg);
    constexpr double tol = 1e-12; // round-off of the fixed point

    for (const double dt : {1e-2, 1e-1, 1.0})
    {
        for (const double start : {0.0, 2.0})
        {
            loneNode node = voellmyColumn();
            node.P[0] = node.m*start*U*cosTheta;
            double before = node.speed();
            for (int n = 0; n < 100000 && n*dt < 200; ++n)
            {
                node.step(dt);
                const double u = node.speed()/cosTheta;
                // Monotone, and never past the terminal speed
                if (start < 1)
                {
                    ASSERT_LE(u, U*(1 + tol)) << dt << " " << n;
                    ASSERT_GE(node.speed(), before) << dt << " " << n;
                }
                else
                {
                    ASSERT_GE(u, U*(1 - tol)) << dt << " " << n;
                    ASSERT_LE(node.speed(), before) << dt << " " << n;
                }
                before = node.speed();
            }
            EXPECT_NEAR(node.speed()/cosTheta, U, tol*U)
                << "dt " << dt << ", start " << start << " U";
            EXPECT_EQ(node.P[1], 0);
        }
    }
}


TEST(VoellmyFriction, FromRestFollowsTheTanhLawToFirstOrderInTheStep)
{
    // Horizontal frame: u_inf = U cos(theta), A = g kappa (tan - tan)
    const double kappa = sqr(std::cos(theta*deg));
    const double uInf = terminalSpeed()*std::cos(theta*deg);
    const double A = 9.81*kappa*(std::tan(theta*deg) - std::tan(phi*deg));
    const double t = uInf/A;
    const double exact = uInf*std::tanh(1.0);

    double error[2];
    const double dts[2] = {2e-2*t, 1e-2*t};
    for (int k = 0; k < 2; ++k)
    {
        loneNode node = voellmyColumn();
        const int nSteps = int(std::round(t/dts[k]));
        for (int n = 0; n < nSteps; ++n)
        {
            node.step(dts[k]);
        }
        error[k] = node.speed() - exact;
    }
    // Backward Euler on the drag: an error of O(dt/t), first order
    constexpr double tol = 1e-2;
    EXPECT_LT(std::abs(error[1]), tol*exact);
    EXPECT_NEAR(error[0]/error[1], 2, 0.1);
}


// ************************************************************************* //
