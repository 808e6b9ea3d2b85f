/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    viscoplasticFluid (Newtonian, Bingham, HerschelBulkley) against its
    closed forms (materialModelTest.C checks the coefficients' ranges):
    - Tait's pressure rho c^2/gamma (J^-gamma - 1), cut at pMin, and the
      rest volume restJ its inverse; J^-gamma by squaring for a whole
      exponent up to 16 (within gamma/2 + 1 epsilons of std::pow: the
      squarings' bound and pow's own error), std::pow's
      for any other;
    - Newtonian: sigma = 2 mu dev(D) - p(J) I, with no stress memory;
    - HerschelBulkley, purely viscous: the shear stress
      k gammaDot^n + tauY (1 - exp(-m gammaDot));
    - Bingham's default Maxwell modulus rho c^2/4 with its wave speed
      c sqrt(1 + 4 G/(3 rho c^2)), and the Maxwell element relaxing
      exactly: sigma_xy(t) = mu_eff gammaDot (1 - exp(-G t/mu_eff)) at any
      step;
    - maxJ, the J where the stiffest mode of a particle alone on its
      nodes reaches the explicit step's limit, with G and without;
    - the update of many particles (in blocks, with strain, spin and
      volumetric smoothing's divergence) against the same update written
      with 3 x 3 tensors, Bingham and Newtonian.

\*---------------------------------------------------------------------------*/

#include "sameBits.H"
#include "testCase.H"
#include "materialState.H"
#include "viscoplasticFluid.H"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

using namespace Foam;

namespace
{

typedef materialState::tensor3 tensor3;

//- Water-like: rho 1000, c 20, gamma 7
const std::string tait("rho 1000; c 20; gamma 7;");

constexpr double rho = 1000, c = 20, gamma = 7;

double taitPressure(const double J)
{
    return rho*c*c/gamma*(std::pow(J, -gamma) - 1);
}

} // End anonymous namespace


TEST(viscoplasticFluid, TaitPressureCutAtPMinAndItsRestVolume)
{
    autoPtr<materialModel> water
    (
        materialModel::New(materialDict("Newtonian", tait + " mu 0;"))
    );
    autoPtr<materialModel> pulling
    (
        materialModel::New
        (
            materialDict("Newtonian", tait + " mu 0; pMin -1e4;")
        )
    );
    // J^-gamma within gamma/2 epsilons (squaring): the pressure within
    // rho c^2 J^-gamma epsilon, 1.1e-10 Pa at J = 0.97 (tol scale: 2e-10)
    constexpr double tol = 5e-13;
    const double Js[4] = {0.97, 0.999, 1.0, 1.02};
    materialState a(*water, 4), b(*pulling, 4);
    for (int i = 0; i < 4; ++i)
    {
        a.setJ(i, Js[i]);
        b.setJ(i, Js[i]);
    }
    a.update(*water, 1e-3);
    b.update(*pulling, 1e-3);
    for (int i = 0; i < 4; ++i)
    {
        const double p = taitPressure(Js[i]);
        const double scale = rho*c*c*1e-3;
        EXPECT_NEAR(a.p(i), std::max(p, 0.0), tol*scale) << Js[i];
        EXPECT_NEAR(b.p(i), std::max(p, -1e4), tol*scale) << Js[i];
        EXPECT_NEAR(a.stress(i)(1, 1), -a.p(i), tol*scale) << Js[i];
        EXPECT_EQ(a.stress(i)(0, 1), 0);
        if (p >= 0)
        {
            EXPECT_NEAR(taitPressure(water->restJ(p)), p, tol*scale);
        }
    }
    EXPECT_EQ(water->waveSpeed(), c);
}


TEST(viscoplasticFluid, WholeTaitExponentsTakePowersBySquaring)
{
    // J^n by any chain of products is within (n - 1)/2 epsilon of the
    // exact power (first order), its inverse within n/2: gamma/2 + 1
    // epsilons hold it with std::pow's own error of about half a unit
    const double eps = std::numeric_limits<double>::epsilon();
    std::vector<double> exponents{7.5, 17};
    for (int n = 1; n <= 16; ++n)
    {
        exponents.push_back(n);
    }
    for (const double g : exponents)
    {
        autoPtr<materialModel> m
        (
            materialModel::New
            (
                materialDict
                (
                    "Newtonian",
                    "rho 1000; c 20; gamma " + std::to_string(g) + "; mu 0;"
                )
            )
        );
        const auto& fluid =
            dynamic_cast<const materialModels::viscoplasticFluid&>(*m);
        const bool whole = g == std::round(g) && g <= 16;
        double worst = 0;
        for (int k = 0; k <= 400; ++k)
        {
            // Off a regular grid (k^2 term), so that few J are short
            // binary fractions whose powers round alike either way
            const double J = 0.9 + 0.2*k/400 + 1e-7*k*k;
            const double viaPow = std::pow(J, -g);
            const double power = fluid.inversePower(J);
            if (whole)
            {
                EXPECT_NEAR(power, viaPow, (g/2 + 1)*eps*viaPow)
                    << g << " " << J;
                worst = std::max(worst, std::abs(power/viaPow - 1)/eps);
            }
            else
            {
                EXPECT_EQ(power, viaPow) << g << " " << J;
            }
        }
        // Squaring taken: from gamma 3 on, 401 powers all the same to the
        // bit as std::pow's would be std::pow itself
        if (whole && g >= 3)
        {
            EXPECT_GT(worst, 0) << g;
        }
    }
}


TEST(viscoplasticFluid, NewtonianStressIsTwiceMuTimesTheDeviatoricRate)
{
    const double mu = 0.5;
    autoPtr<materialModel> fluid
    (
        materialModel::New(materialDict("Newtonian", tait + " mu 0.5;"))
    );
    EXPECT_EQ(fluid->explicitViscosity(), mu);

    materialState state(*fluid, 1);
    tensor3 L;
    L << 0.3, 1.2, 0,
         -0.4, -0.7, 0.2,
         0.1, 0, 0.6;
    state.setGradient(0, L);
    state.setJ(0, 0.99);
    state.setStress(0, 1e3*tensor3::Ones());
    state.update(*fluid, 1e-3);

    const tensor3 D = 0.5*(L + L.transpose());
    const tensor3 expected =
        2*mu*materialParticles::dev(D)
      - taitPressure(0.99)*tensor3::Identity();
    constexpr double tol = 1e-13; // relative to the pressure
    EXPECT_LT
    (
        (state.stress(0) - expected).cwiseAbs().maxCoeff(),
        tol*taitPressure(0.99)
    );
}


TEST(viscoplasticFluid, HerschelBulkleyShearStress)
{
    const double kHB = 20, n = 0.6, tauY = 300, m = 50;
    autoPtr<materialModel> mud
    (
        materialModel::New
        (
            materialDict("HerschelBulkley", tait
              + " k 20; n 0.6; tauY 300; m 50; shearModulus 0;")
        )
    );
    constexpr double tol = 1e-13; // pow, expm1 and a few products
    for (const double gammaDot : {0.05, 1.0, 30.0})
    {
        materialState state(*mud, 1);
        tensor3 L = tensor3::Zero();
        L(0, 2) = gammaDot;
        state.setGradient(0, L);
        state.update(*mud, 1e-3);
        const double tau =
            kHB*std::pow(gammaDot, n) - tauY*std::expm1(-m*gammaDot);
        EXPECT_NEAR(state.stress(0)(0, 2), tau, tol*tau) << gammaDot;
    }
}


TEST(viscoplasticFluid, BinghamMaxwellStressRelaxesExactlyAtAnyStep)
{
    const double mu = 10, tauY = 200, m = 100;
    const double G = 0.25*rho*c*c;
    autoPtr<materialModel> mud
    (
        materialModel::New
        (
            materialDict("Bingham", tait + " mu 10; tauY 200;")
        )
    );
    EXPECT_EQ(mud->explicitViscosity(), 0);
    EXPECT_NEAR(mud->waveSpeed(), c*std::sqrt(1 + 4*G/(3*rho*c*c)), 1e-14*c);

    const double gammaDot = 0.5, t = 1e-3;
    const double muEff = mu - tauY*std::expm1(-m*gammaDot)/gammaDot;
    const double steady = muEff*gammaDot;
    const double expected = steady*(1 - std::exp(-G*t/muEff));
    constexpr double tol = 1e-12; // round-off over up to 400 steps
    for (const int nSteps : {1, 13, 400})
    {
        materialState state(*mud, 1);
        tensor3 L = tensor3::Zero();
        // Pure shear, no spin
        L(0, 1) = L(1, 0) = gammaDot/2;
        state.setGradient(0, L);
        for (int s = 0; s < nSteps; ++s)
        {
            state.update(*mud, t/nSteps);
        }
        EXPECT_NEAR(state.stress(0)(0, 1), expected, tol*steady) << nSteps;
        EXPECT_EQ(state.p(0), 0);
    }
    // Well short of the steady stress: the test sees the relaxation
    EXPECT_LT(expected, 0.9*steady);
}


TEST(viscoplasticFluid, MaxJIsWhereALoneParticlesModeReachesTheStepsLimit)
{
    const auto fluid = [](const std::string& type, const std::string& coeffs)
    {
        return materialModel::New(materialDict(type, tait + coeffs));
    };
    const double h = 0.04;

    // Maxwell: (J/rho) 2G 6/h^2 dt^2 = 4, at the step maxCo h/waveSpeed
    // 16/(9 maxCo^2) with the default G = rho c^2/4
    autoPtr<materialModel> mud(fluid("Bingham", " mu 10; tauY 200;"));
    for (const double maxCo : {0.4, 0.8})
    {
        const double dt = maxCo*h/mud->waveSpeed();
        EXPECT_NEAR
        (
            mud->maxJ(dt, h, 6), 16/(9*maxCo*maxCo), 1e-13*mud->maxJ(dt, h, 6)
        ) << maxCo;
    }
    const double G = 1e4, dt = 1e-3;
    EXPECT_NEAR
    (
        fluid("Bingham", " mu 10; tauY 200; shearModulus 1e4;")
            ->maxJ(dt, h, 6),
        rho*h*h/(3*G*dt*dt), 1e-13*rho*h*h/(3*G*dt*dt)
    );
    // Viscous, no G: the decay rate (J/rho) 2 mu 6/h^2 = 2/dt
    const double mu = 1e-3;
    EXPECT_NEAR
    (
        fluid("Newtonian", " mu 1e-3;")->maxJ(dt, h, 6),
        rho*h*h/(6*mu*dt), 1e-13*rho*h*h/(6*mu*dt)
    );
    // A step too long for a lone particle even at rest volume: J not
    // pushed below 1 (that would be pressure, not a bound)
    EXPECT_EQ(mud->maxJ(1, h, 6), 1);
    // GIMP with 4 particles per cell and axis (lp = 1/8): a = 2/lp +
    // 1/(1 - lp) instead of 6 (at maxCo 0.4); the hat's unbounded
    // stiffness leaves 1
    const double dt4 = 0.4*h/mud->waveSpeed(), a = 16 + 8.0/7;
    EXPECT_NEAR(mud->maxJ(dt4, h, a), 16/(9*0.16)*6/a, 1e-13);
    const double hat = std::numeric_limits<double>::infinity();
    EXPECT_EQ(mud->maxJ(dt4, h, hat), 1);
    // Nothing stiffens with J without viscosity or G
    EXPECT_GE(fluid("Newtonian", " mu 0;")->maxJ(dt, h, 6), VGREAT);
}


TEST(viscoplasticFluid, UpdateOfManyParticlesIsTheTensorFormula)
{
    // 1,000 particles (whole blocks and a part block) with random velocity
    // gradients (strain and spin), divergences, stresses and volume
    // ratios, against the update written with 3 x 3 tensors:
    //     D = dev(sym L), s = 2 mu D,
    //     s += (dev(s_n + dt (W s_n - s_n W)) - s) exp(-G dt/mu),
    //     sigma = s - p(J) I
    for (const std::string law : {"Bingham", "Newtonian"})
    {
        const std::string coeffs =
            law == "Bingham" ? " mu 10; tauY 200; m 100;" : " mu 10;";
        autoPtr<materialModel> model
        (
            materialModel::New(materialDict(law, tait + coeffs))
        );
        const auto& fluid =
            dynamic_cast<const materialModels::viscoplasticFluid&>(*model);
        const double G = law == "Bingham" ? 0.25*rho*c*c : 0;
        const label n = 1000;
        materialState state(*model, n);
        std::vector<tensor3> L0(n), s0(n);
        std::vector<double> J0(n);
        std::mt19937 gen(7);
        std::uniform_real_distribution<double> uniform(-1, 1);
        for (label i = 0; i < n; ++i)
        {
            for (int k = 0; k < 9; ++k)
            {
                L0[i](k/3, k%3) = 20*uniform(gen);
            }
            tensor3 s;
            for (int k = 0; k < 9; ++k)
            {
                s(k/3, k%3) = 1e4*uniform(gen);
            }
            s0[i] = 0.5*(s + s.transpose());
            J0[i] = 1 + 0.01*uniform(gen);
            state.setGradient(i, L0[i]);
            state.setDiv(i, L0[i].trace() + uniform(gen));
            state.setJ(i, J0[i]);
            state.setStress(i, s0[i]);
        }
        const double dt = 1e-3;
        state.update(*model, dt);

        // The tensor formula with materialParticles' helpers (the strain
        // rate with the divergence set above as its trace)
        const materialParticles view = state.view();
        double worst = 0;
        for (label i = 0; i < n; ++i)
        {
            const tensor3& l = L0[i];
            const tensor3 D =
                materialParticles::dev(view.strainRate(i, l));
            const double mu =
                (*fluid.viscosityLaw())(std::sqrt(2*D.squaredNorm()));
            tensor3 s = 2*mu*D;
            if (G > 0 && mu > 0)
            {
                const tensor3 rotated =
                    materialParticles::rotate(s0[i], l, dt);
                s += (materialParticles::dev(rotated) - s)*std::exp(-G*dt/mu);
            }
            s.diagonal().array() -= fluid.pressure(J0[i]);
            const double scale = s.cwiseAbs().maxCoeff();
            worst = std::max
            (
                worst,
                (state.stress(i) - s).cwiseAbs().maxCoeff()/scale
            );
            EXPECT_NEAR(state.p(i), -s.trace()/3, 1e-13*scale)
                << law << ' ' << i;
        }
        // Round-off of a few dozen operations, relative to each particle's
        // largest stress component (40 Pa to 1e4 Pa here)
        EXPECT_LT(worst, 1e-13) << law;
    }
}


namespace
{

//- The Maxwell decay exp(-G dt/mu) of particle i of a state whose gradient
//  is L (0: none, the particle keeps no stress memory)
double maxwellDecay
(
    materialState& state,
    const materialModel& model,
    const label i,
    const tensor3& L,
    const double G,
    const double dt
)
{
    const auto& fluid =
        dynamic_cast<const materialModels::viscoplasticFluid&>(model);
    const tensor3 D =
        materialParticles::dev(state.view().strainRate(i, L));
    const double mu =
        (*fluid.viscosityLaw())(std::sqrt(2*D.squaredNorm()));
    return G > 0 && mu > 0 ? std::exp(-G*dt/mu) : 0;
}


//- The same bits in every component
bool sameBits(const tensor3& a, const tensor3& b)
{
    bool same = true;
    for (int k = 0; k < 9; ++k)
    {
        same = same && Foam::sameBits(a.data()[k], b.data()[k]);
    }
    return same;
}

} // End anonymous namespace


TEST(viscoplasticFluid, ParticlesUpdatedTogetherAsEachAlone)
{
    // The update takes four particles at a time in vector lanes and the
    // rest of a block one by one: 1,003 particles (15 whole blocks, ten
    // groups of four and three alone) updated together give, bit for bit,
    // the stress and pressure of each updated on its own. A Maxwell fluid
    // at two steps (at 0.5 s the flowing particles' decay underflows to 0,
    // the plugs' does not: both kinds in most groups of four) and a purely
    // viscous one
    const std::string bingham(" mu 10; tauY 200; m 100;");
    for (const std::string& coeffs : {bingham, bingham + " shearModulus 0;"})
    {
        autoPtr<materialModel> model
        (
            materialModel::New(materialDict("Bingham", tait + coeffs))
        );
        const double G = coeffs == bingham ? 0.25*rho*c*c : 0;
        for (const double dt : {1e-3, 0.5})
        {
            const label n = 1003;
            materialState all(*model, n);
            std::vector<std::unique_ptr<materialState>> alone;
            std::mt19937 gen(11);
            std::uniform_real_distribution<double> uniform(-1, 1);
            label withoutDecay = 0;
            for (label i = 0; i < n; ++i)
            {
                // Strain rates from plug (1e-4 s^-1) to flowing (20 s^-1)
                const double rate = std::pow(10.0, -4 + 5.3*(i%7)/6);
                tensor3 L, s;
                for (int k = 0; k < 9; ++k)
                {
                    L(k/3, k%3) = rate*uniform(gen);
                    s(k/3, k%3) = 1e4*uniform(gen);
                }
                s = 0.5*(s + s.transpose());
                const double J = 1 + 0.01*uniform(gen);
                alone.emplace_back(new materialState(*model, 1));
                for (materialState* state : {&all, alone.back().get()})
                {
                    const label j = state == &all ? i : 0;
                    state->setGradient(j, L);
                    state->setJ(j, J);
                    state->setStress(j, s);
                }
                withoutDecay += maxwellDecay(all, *model, i, L, G, dt) == 0;
            }
            if (G == 0)
            {
                EXPECT_EQ(withoutDecay, n);
            }
            else if (dt < 0.1)
            {
                EXPECT_EQ(withoutDecay, 0);
            }
            else
            {
                EXPECT_GT(withoutDecay, n/7);
                EXPECT_LT(withoutDecay, n - n/7);
            }
            all.update(*model, dt);
            label differ = 0;
            for (label i = 0; i < n; ++i)
            {
                alone[i]->update(*model, dt);
                differ +=
                    !sameBits(all.stress(i), alone[i]->stress(0))
                 || !sameBits(all.p(i), alone[i]->p(0));
            }
            EXPECT_EQ(differ, 0) << coeffs << " dt " << dt;
        }
    }
}


TEST(viscoplasticFluid, NoDecayTrapsNoMatterTheStressItForgets)
{
    // With FOAM_SIGFPE's traps on, eight flowing particles (two groups of
    // four) whose Maxwell decay underflows to 0 forget their last stress,
    // even an infinite shear stress: the update traps nowhere and gives the
    // viscous stress, as the same particles with no stress before
    autoPtr<materialModel> model
    (
        materialModel::New
        (
            materialDict("Bingham", tait + " mu 10; tauY 200; m 100;")
        )
    );
    const double G = 0.25*rho*c*c, dt = 0.5;
    const label n = 8;
    materialState stressed(*model, n), unstressed(*model, n);
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> uniform(0.5, 1);
    for (label i = 0; i < n; ++i)
    {
        tensor3 L;
        for (int k = 0; k < 9; ++k)
        {
            L(k/3, k%3) = (k%2 ? 20 : -20)*uniform(gen);
        }
        tensor3 s = tensor3::Zero();
        s(0, 1) = s(1, 0) = i == 5
          ? std::numeric_limits<double>::infinity() : 1e300;
        for (materialState* state : {&stressed, &unstressed})
        {
            state->setGradient(i, L);
        }
        stressed.setStress(i, s);
        ASSERT_EQ(maxwellDecay(stressed, *model, i, L, G, dt), 0) << i;
    }
    {
        const solverFpTraps traps;
        stressed.update(*model, dt);
        unstressed.update(*model, dt);
    }
    for (label i = 0; i < n; ++i)
    {
        EXPECT_TRUE(sameBits(stressed.stress(i), unstressed.stress(i))) << i;
    }
}


TEST(viscoplasticFluid, ParticleTurnedInsideOutStopsTheRunWithAMessage)
{
    // A particle whose volume ratio went through zero in a step (J = -0,
    // or a large negative J: seen in a fragment whose J had grown without
    // bound, before maxJ) has no pressure: the update stops with a
    // FatalError naming it and the cure, not a floating-point signal or a
    // pressure of 1/0. Among 200 particles (four blocks), the others valid
    autoPtr<materialModel> fluid
    (
        materialModel::New
        (
            materialDict("Bingham", tait + " mu 50; tauY 2000;")
        )
    );
    for (const double J : {-0.0, 0.0, -57076.0, 1e-40})
    {
        materialState state(*fluid, 200);
        for (label i = 0; i < 200; ++i)
        {
            state.setJ(i, 0.99);
        }
        state.setJ(137, J);
        std::string message;
        try
        {
            state.update(*fluid, 1e-3);
        }
        catch (const Foam::error& err)
        {
            message = err.message();
        }
        EXPECT_NE(message.find("particle 137"), std::string::npos) << J;
        EXPECT_NE(message.find("lower maxCo"), std::string::npos) << J;
    }

    // At the smallest J taken, the pressure is finite
    materialState state(*fluid, 1);
    state.setJ(0, 2e-30);
    state.update(*fluid, 1e-3);
    EXPECT_TRUE(std::isfinite(state.p(0)));
    EXPECT_GT(state.p(0), 1e200);
}


// ************************************************************************* //
