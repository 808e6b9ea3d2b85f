/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    DruckerPrager's return map against its closed forms: cone
    f = alpha I1 + sqrt(J2) - k, alpha = tan(phi)/sqrt(9 + 12 tan^2(phi)),
    k = 3 c/sqrt(9 + 12 tan^2(phi)), potential alpha_psi I1 + sqrt(J2);
    trial stresses are set as the old stress with no strain rate, so that
    the trial is exactly that stress:
    - inside the cone the update is linearElastic's, bit for bit, and the
      plastic strain stays zero;
    - outside, the stress returns onto the cone (consistency, f = 0) along
      the potential's gradient: dLambda = f/(9 K alpha alpha_psi + G),
      I1 - 9 K alpha_psi dLambda, sqrt(J2) - G dLambda, the deviator's
      direction kept; the plastic strain C^-1 (sigma_trial - sigma) has the
      equivalent shear strain sqrt(2 e:e) = dLambda (the plasticStrain
      increment) and the volume change 3 alpha_psi dLambda (none for
      psi = 0);
    - beyond the apex (tension), the stress returns to the apex
      k/(3 alpha) I with no deviator; the whole trial deviator is plastic,
      so plasticStrain grows by its equivalent shear strain sqrt(J2)/G, the
      apex return's own, not the cone's multiplier (which overshoots the
      apex); cohesionless material ends unstressed.

\*---------------------------------------------------------------------------*/

#include "materialState.H"
#include "mathematicalConstants.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

typedef materialState::tensor3 tensor3;

constexpr double E = 1e7, nu = 0.3, phi = 30, cohesion = 1000;
const double G = E/(2*(1 + nu));
const double K = E/(3*(1 - 2*nu));

//- alpha of the cone of friction (or dilatancy) angle a [deg]
double coneAlpha(const double a)
{
    const double t = std::tan(a*constant::mathematical::pi/180);
    return t/std::sqrt(9 + 12*t*t);
}

const double alpha = coneAlpha(phi);
const double k = 3*cohesion*coneAlpha(phi)
   /std::tan(phi*constant::mathematical::pi/180);

//- The model with dilatancy angle psi [deg] and cohesion c [Pa]
autoPtr<materialModel> granular(const double psi, const double c = cohesion)
{
    return materialModel::New
    (
        materialDict
        (
            "DruckerPrager",
            "rho 2000; E 1e7; nu 0.3; frictionAngle 30; dilatancyAngle "
          + std::to_string(psi) + "; cohesion " + std::to_string(c) + ";"
        )
    );
}

double sqrtJ2(const tensor3& s)
{
    return std::sqrt(0.5*materialParticles::dev(s).squaredNorm());
}

//- The stress one update makes of a trial stress, and the plastic strain
//  it adds
tensor3 returned(materialModel& model, const tensor3& trial, double& epsP)
{
    materialState state(model, 1);
    state.setStress(0, trial);
    state.update(model, 1e-3);
    epsP = state.field("plasticStrain")[0];
    return state.stress(0);
}

//- A deviator with every component
tensor3 deviator(const double scale)
{
    tensor3 s;
    s << 2, 9, 0,
         9, -0.5, 3,
         0, 3, -1.5;
    return scale*s;
}

} // End anonymous namespace


TEST(DruckerPrager, InsideTheConeItIsLinearElastic)
{
    autoPtr<materialModel> model(granular(0));
    autoPtr<materialModel> elastic
    (
        materialModel::New
        (
            materialDict("linearElastic", "rho 2000; E 1e7; nu 0.3;")
        )
    );
    materialState a(*model, 1), b(*elastic, 1);
    tensor3 L;
    L << 1e-3, 2e-3, 0,
         0, -1e-3, 0,
         0, 5e-4, 0;
    for (materialState* s : {&a, &b})
    {
        s->setStress(0, -1e4*tensor3::Identity());
        s->setGradient(0, L);
    }
    a.update(*model, 0.1);
    b.update(*elastic, 0.1);
    const tensor3 s = a.stress(0);
    EXPECT_LT(alpha*s.trace() + sqrtJ2(s) - k, 0);
    EXPECT_EQ(s, b.stress(0));
    EXPECT_EQ(a.field("plasticStrain")[0], 0);
}


TEST(DruckerPrager, TrialOutsideTheConeReturnsOntoItAlongThePotential)
{
    const tensor3 trial = -1e4*tensor3::Identity() + deviator(1000);
    const double I1 = trial.trace(), q = sqrtJ2(trial);
    const double f = alpha*I1 + q - k;
    ASSERT_GT(f, 0.1*q);

    for (const double psi : {0.0, 10.0})
    {
        autoPtr<materialModel> model(granular(psi));
        const double alphaPsi = coneAlpha(psi);
        const double dLambda = f/(9*K*alpha*alphaPsi + G);
        double epsP = 0;
        const tensor3 s = returned(*model, trial, epsP);

        // The closed form, to round-off
        const tensor3 dev0 = materialParticles::dev(trial);
        const tensor3 expected =
            ((I1 - 9*K*alphaPsi*dLambda)/3)*tensor3::Identity()
          + (1 - G*dLambda/q)*dev0;
        constexpr double tol = 1e-12; // relative to the trial stress
        EXPECT_LT((s - expected).cwiseAbs().maxCoeff(), tol*std::abs(I1))
            << "psi " << psi;
        EXPECT_NEAR(alpha*s.trace() + sqrtJ2(s) - k, 0, tol*std::abs(I1))
            << "psi " << psi;

        // Plastic strain: C^-1 of the stress taken
        const tensor3 e = materialParticles::dev(trial - s)/(2*G);
        const double volume = (trial - s).trace()/(3*K);
        EXPECT_NEAR(std::sqrt(2*e.squaredNorm()), dLambda, tol*dLambda);
        EXPECT_NEAR(volume, 3*alphaPsi*dLambda, tol*dLambda);
        EXPECT_NEAR(epsP, dLambda, tol*dLambda) << "psi " << psi;
    }
}


TEST(DruckerPrager, TrialBeyondTheApexReturnsToTheApex)
{
    const tensor3 trial = 3000*tensor3::Identity() + deviator(50);
    const double q = sqrtJ2(trial);
    constexpr double tol = 1e-12; // relative to the apex stress

    for (const double psi : {0.0, 10.0, 30.0})
    {
        autoPtr<materialModel> model(granular(psi));
        double epsP = 0;
        const tensor3 s = returned(*model, trial, epsP);
        const tensor3 apex = k/(3*alpha)*tensor3::Identity();
        EXPECT_LT((s - apex).cwiseAbs().maxCoeff(), tol*apex(0, 0))
            << "psi " << psi;

        // The whole trial deviator is plastic strain: sqrt(2 e:e) with
        // e = dev(trial)/(2 G); less than the cone's multiplier
        const double coneMultiplier =
            (alpha*trial.trace() + q - k)
           /(9*K*alpha*coneAlpha(psi) + G);
        EXPECT_NEAR(epsP, q/G, tol*q/G) << "psi " << psi;
        EXPECT_GT(coneMultiplier, 1.2*q/G) << "psi " << psi;
    }

    // Cohesionless: no tension at all
    autoPtr<materialModel> sand(granular(0, 0));
    double epsP = 0;
    EXPECT_EQ(returned(*sand, trial, epsP), tensor3::Zero());
    EXPECT_NEAR(epsP, q/G, tol*q/G);
}


// ************************************************************************* //
