/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Ropes against closed forms: the sag of a taut rope under a point load
    at mid-span (geometrically non-linear truss), and a brake that slides
    at its threshold, dissipates threshold times its plastic elongation and
    stops at its maximum elongation.

\*---------------------------------------------------------------------------*/

#include "structureTestTools.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;
using namespace Foam::structureTest;

namespace
{

//- Sag of a rope of span 2 L, pretension T0, stiffness EA under P at
//  mid-span: P = 2 T sin(theta), T = T0 + EA (1/cos(theta) - 1), by Newton
double ropeSag(const double L, const double T0, const double EA, const double P)
{
    double theta = 0.1;
    for (label iter = 0; iter < 100; ++iter)
    {
        const double T = T0 + EA*(1/std::cos(theta) - 1);
        const double r = 2*T*std::sin(theta) - P;
        const double dT = EA*std::sin(theta)/sqr(std::cos(theta));
        const double dr = 2*dT*std::sin(theta) + 2*T*std::cos(theta);
        theta -= r/dr;
    }
    return L*std::tan(theta);
}

} // End anonymous namespace


TEST(ropeElements, TautRopeSagsAsClosedFormUnderMidSpanLoad)
{
    const double L = 5, T0 = 1e4, EA = 1e6, P = 5e3;
    flexibleStructure s
    (
        dictionaryOf
        (
            "type ropes;"
            "ropes { span { from (-5 0 0); to (5 0 0); EA 1e6;"
            "    linearDensity 1; pretension 1e4; segments 2; } }"
            "damping { massProportional 40; }"
        ),
        "."
    );
    scalar distance;
    const label mid = s.nodes().nearest(point::zero, distance);
    ASSERT_EQ(distance, 0);
    s.nodes().fExtZ[mid] = -P;
    relax(s, 1e-30, 20);

    const double exact = ropeSag(L, T0, EA, P);
    const double sag = -s.nodes().z[mid];
    std::cout
        << "    sag " << sag << " m, closed form " << exact << " m, in "
        << s.time() << " s" << std::endl;
    constexpr double tol = 1e-6;    // the static state, to the relaxation
    EXPECT_NEAR(sag, exact, tol*exact);

    // Each anchor takes half the load and the horizontal tension
    const double T = T0 + EA*(std::sqrt(L*L + exact*exact)/L - 1);
    const vector R = s.reaction("span");
    EXPECT_NEAR(R.z(), P, tol*P);
    EXPECT_NEAR(R.x(), 0, tol*P);
    EXPECT_NEAR(s.ropes().tension()[0], T, tol*T);
}


TEST(ropeElements, BrakeSlidesAtThresholdAndStopsAtMaxElongation)
{
    // A rope pulled along its axis at its mid node: the first segment
    // (with the brake) in tension, the second slack
    const double L = 1, EA = 1e6, Fb = 2e4, maxElongation = 0.3;
    flexibleStructure s
    (
        dictionaryOf
        (
            "type ropes;"
            "ropes { line { from (0 0 0); to (2 0 0); EA 1e6;"
            "    linearDensity 2; segments 2;"
            "    brake { threshold 2e4; maxElongation 0.3; } } }"
            "damping { massProportional 20; }"
        ),
        "."
    );
    scalar distance;
    const label mid = s.nodes().nearest(point(1, 0, 0), distance);
    const double dt = s.stableTimeStep();
    const double Fmax = 3e4;

    double maxSlidingTension = 0;
    label slidingSteps = 0;
    while (s.time() < 20)
    {
        // Ramp the load over 2 s, then hold it
        s.nodes().fExtX[mid] = Fmax*min(1.0, s.time()/2);
        const double before = s.ropes().plasticElongation()[0];
        s.step(dt);
        const double after = s.ropes().plasticElongation()[0];
        // Sliding through the step (the step that reaches the stop is
        // elastic beyond it)
        if (after > before && after < maxElongation)
        {
            ++slidingSteps;
            maxSlidingTension = max(maxSlidingTension, s.ropes().tension()[0]);
        }
    }
    const double dp = s.ropes().plasticElongation()[0];
    const flexibleStructure::energyBudget& e = s.energies();
    std::cout
        << "    slid " << slidingSteps << " steps, dissipated "
        << e.brakeDissipation << " J, largest tension while sliding "
        << maxSlidingTension << " N" << std::endl;

    EXPECT_GT(slidingSteps, 10);
    EXPECT_LE(maxSlidingTension, Fb*(1 + 1e-12));
    EXPECT_EQ(dp, maxElongation);
    EXPECT_NEAR(e.brakeDissipation, Fb*dp, 1e-12*Fb*dp);

    // Hardened back to elastic: the static stretch under Fmax
    const double stretch = s.nodes().x[mid] - L;
    EXPECT_NEAR(stretch, maxElongation + Fmax*L/EA, 1e-9);
    EXPECT_NEAR(s.ropes().tension()[0], Fmax, 1e-6*Fmax);
    EXPECT_EQ(s.ropes().tension()[1], 0);

    // The budget closes: work = strain + dissipated (at rest)
    constexpr double tol = 1e-3;    // O(dt^2) book-keeping of the leapfrog
    EXPECT_NEAR(e.total(), e.externalWork, tol*e.externalWork);
}
