/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    linearElastic against Hooke's law, with the moduli from E and nu
    (lambda = E nu/((1 + nu)(1 - 2 nu)), G = E/(2 (1 + nu))):
    - uniaxial strain eps along each axis: sigma_aa = (lambda + 2 G) eps,
      the others lambda eps, p = -K eps, increments adding step by step;
    - pure shear gamma in each plane: sigma_ab = G gamma, nothing else;
    - the volumetric rate of volumetric smoothing (div) sets the pressure,
      K div dt, instead of tr(L);
    - the P-wave speed sqrt((lambda + 2 G)/rho) and the rest volume
      J = exp(-p/K).

\*---------------------------------------------------------------------------*/

#include "materialState.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

constexpr double E = 2e7, nu = 0.3, rho = 2000;
const double lambda = E*nu/((1 + nu)*(1 - 2*nu));
const double G = E/(2*(1 + nu));

autoPtr<materialModel> solid()
{
    return materialModel::New
    (
        materialDict("linearElastic", "rho 2000; E 2e7; nu 0.3;")
    );
}

//- Round-off of a few products, relative to the stress
constexpr double tol = 1e-13;

} // End anonymous namespace


TEST(linearElastic, UniaxialStrainGivesHookesStresses)
{
    autoPtr<materialModel> model(solid());
    const double rate = 1e-3, dt = 0.1, eps = rate*dt;
    for (int a = 0; a < 3; ++a)
    {
        materialState state(*model, 1);
        materialState::tensor3 L = materialState::tensor3::Zero();
        L(a, a) = rate;
        state.setGradient(0, L);
        for (int n = 1; n <= 3; ++n)
        {
            state.update(*model, dt);
            const materialState::tensor3 s = state.stress(0);
            const double scale = n*(lambda + 2*G)*eps;
            for (int b = 0; b < 3; ++b)
            {
                for (int c = 0; c < 3; ++c)
                {
                    const double expected =
                        b != c ? 0 : n*eps*(b == a ? lambda + 2*G : lambda);
                    EXPECT_NEAR(s(b, c), expected, tol*scale)
                        << "axis " << a << ", step " << n;
                }
            }
            const double K = lambda + 2*G/3;
            EXPECT_NEAR(state.p(0), -n*K*eps, tol*scale);
        }
    }
}


TEST(linearElastic, PureShearGivesGTimesTheShearStrain)
{
    autoPtr<materialModel> model(solid());
    const double gammaDot = 4e-3, dt = 0.05;
    const int planes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (const auto& ab : planes)
    {
        materialState state(*model, 1);
        materialState::tensor3 L = materialState::tensor3::Zero();
        L(ab[0], ab[1]) = L(ab[1], ab[0]) = gammaDot/2;
        state.setGradient(0, L);
        state.update(*model, dt);
        const materialState::tensor3 s = state.stress(0);
        const double expected = G*gammaDot*dt;
        for (int b = 0; b < 3; ++b)
        {
            for (int c = 0; c < 3; ++c)
            {
                const bool shear =
                    (b == ab[0] && c == ab[1]) || (b == ab[1] && c == ab[0]);
                EXPECT_NEAR(s(b, c), shear ? expected : 0, tol*expected)
                    << ab[0] << ab[1] << " " << b << c;
            }
        }
        EXPECT_EQ(state.p(0), 0);
    }
}


TEST(linearElastic, SmoothedVolumeRateSetsThePressure)
{
    autoPtr<materialModel> model(solid());
    materialState state(*model, 1);
    const double div = -2e-3, dt = 0.1;
    state.setDiv(0, div);
    state.update(*model, dt);
    const double K = lambda + 2*G/3;
    const materialState::tensor3 s = state.stress(0);
    EXPECT_NEAR(state.p(0), -K*div*dt, tol*K*std::abs(div)*dt);
    EXPECT_NEAR(s(0, 0), K*div*dt, tol*K*std::abs(div)*dt);
    EXPECT_NEAR(s(0, 0), s(2, 2), tol*K*std::abs(div)*dt);
    EXPECT_EQ(s(0, 1), 0);
}


TEST(linearElastic, WaveSpeedAndRestVolume)
{
    const autoPtr<materialModel> model(solid());
    const double K = lambda + 2*G/3;
    EXPECT_NEAR(model->waveSpeed(), std::sqrt((lambda + 2*G)/rho), tol);
    EXPECT_NEAR(model->restJ(1e5), std::exp(-1e5/K), tol);
}


// ************************************************************************* //
