/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    planeBarrier, an inclined half-space (normal (1 -2 2), of any length):
    - signed distance (x - o).n and normal n, n the unit normal;
    - the particles' guard: a particle that enters in a step is put back on
      the plane, at its end point projected along n (to 2^-30 of its move:
      the bisection), and loses its velocity into the plane by the contact
      condition (slip, Coulomb); the force is the momentum taken,
      m (u - u_new)/dt. Particles that start inside, or end outside, are
      left alone.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const point o(0.43, 0.61, 0.55);
const vector n = vector(1, -2, 2)/3;

//- A unit vector along the plane
const vector t = vector(2, 2, 1)/3;

std::string inclinedPlane(const std::string& contact)
{
    return "type plane; point (0.43 0.61 0.55); normal (1 -2 2); contact "
      + contact + ";";
}

} // End anonymous namespace


TEST(planeBarrier, SignedDistanceAlongTheUnitNormal)
{
    barrierProbe probe(inclinedPlane("slip"));
    constexpr double tol = 1e-15; // round-off of a dot product
    for (const point& x :
        {point(0, 0, 0), point(0.9, 0.1, 1.1), point(0.43, 0.61, 0.55)})
    {
        vector normal;
        EXPECT_NEAR(probe.distance(x, normal), (x - o) & n, tol) << x;
        EXPECT_LT(mag(normal - n), tol) << x;
    }
}


TEST(planeBarrier, EnteringParticleStopsOnThePlane)
{
    const scalar m = 0.01, dt = 1e-3;
    const point x0 = o + 0.02*n - 0.03*t;
    const point x1 = o - 0.03*n + 0.01*t;
    const vector u = -2*n + t;
    // Bisection to 2^-30 of the move
    const scalar tol = 1e-9*mag(x1 - x0);

    for (const auto& c : {std::make_pair(word("slip"), 0.0),
         std::make_pair(word("Coulomb"), 0.2)})
    {
        barrierProbe probe
        (
            inclinedPlane(c.first + "; frictionCoefficient 0.2")
        );
        point x = x1;
        vector v = u, F;
        EXPECT_TRUE(probe.entry(x0, x, v, m, dt, F)) << c.first;
        EXPECT_LT(mag(x - (x1 + 0.03*n)), tol) << c.first;
        EXPECT_GE(probe.distance(x), 0) << c.first;
        const vector expected = contactVelocity(u, n, c.first, c.second);
        EXPECT_LT(mag(v - expected), 1e-15) << c.first;
        EXPECT_LT(mag(F - m*(u - expected)/dt), 1e-12) << c.first;
    }
    // Coulomb's worked value: 1 m/s along, 2 m/s into it, mu 0.2
    EXPECT_LT(mag(contactVelocity(u, n, "Coulomb", 0.2) - 0.6*t), 1e-15);
}


TEST(planeBarrier, ParticlesThatDoNotEnterAreLeftAlone)
{
    barrierProbe probe(inclinedPlane("noSlip"));
    const vector u = -2*n + t;
    // Inside at the start; outside at the end
    const std::pair<point, point> moves[] =
    {
        {o - 0.01*n, o - 0.04*n + 0.01*t},
        {o + 0.05*n, o + 0.01*n + 0.01*t}
    };
    for (const auto& move : moves)
    {
        point x = move.second;
        vector v = u, F;
        EXPECT_FALSE(probe.entry(move.first, x, v, 0.01, 1e-3, F));
        EXPECT_EQ(x, move.second);
        EXPECT_EQ(v, u);
        EXPECT_EQ(F, vector(Zero));
    }
}


// ************************************************************************* //
