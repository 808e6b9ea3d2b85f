/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    contactCondition alone, a velocity v moving into a surface of unit
    normal n (v.n < 0): it loses its normal part, and its tangential part
    vt is kept (slip), removed (noSlip) or shortened by mu |v.n| (Coulomb),
    against the closed form (barrierProbe.H) and worked examples: into a
    floor at 4 m/s with 3 m/s along it and mu = 0.5, 1 m/s is left; with
    |vt| within mu |v.n| it sticks. The friction coefficient is read for
    Coulomb only.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

//- The condition of a dictionary's text
contactCondition condition(const std::string& text)
{
    IStringStream is(text);
    return contactCondition(dictionary(is));
}

//- v after the condition c at normal n
vector applied(const contactCondition& c, const vector& n, const vector& v)
{
    const double nrm[3] = {n.x(), n.y(), n.z()};
    double u[3] = {v.x(), v.y(), v.z()};
    c.apply(nrm, v & n, u);
    return vector(u[0], u[1], u[2]);
}

//- Round-off of a few products
constexpr double tol = 1e-15;

} // End anonymous namespace


TEST(contactCondition, NormalVelocityRemovedTangentialKeptRemovedOrReduced)
{
    const vector n = vector(1, 2, 2)/3;
    const vector v(-1.5, 0.4, -2);
    const scalar vn = v & n;
    ASSERT_LT(vn, 0);
    const scalar magVt = mag(v - vn*n);
    const struct { word name; std::string text; scalar magVtNew; } cases[] =
    {
        {"slip", "contact slip;", magVt},
        {"noSlip", "contact noSlip;", 0},
        {"Coulomb", "contact Coulomb; frictionCoefficient 0.3;",
            magVt + 0.3*vn}
    };
    for (const auto& c : cases)
    {
        const vector u = applied(condition(c.text), n, v);
        EXPECT_LT(mag(u - contactVelocity(v, n, c.name, 0.3)), tol)
            << c.name;
        EXPECT_NEAR(u & n, 0, tol) << c.name;
        EXPECT_NEAR(mag(u), c.magVtNew, tol) << c.name;
    }
}


TEST(contactCondition, CoulombSticksWithinMuTimesTheNormalSpeed)
{
    const contactCondition c
    (
        condition("contact Coulomb; frictionCoefficient 0.5;")
    );
    EXPECT_EQ(c.friction(), 0.5);
    const vector n(0, 0, 1);
    EXPECT_LT(mag(applied(c, n, vector(3, 0, -4)) - vector(1, 0, 0)), tol);
    // |vt| = 1.58 m/s within 0.5 x 4 m/s
    EXPECT_EQ(applied(c, n, vector(1.5, 0.5, -4)), vector(Zero));
    // Read for Coulomb only
    EXPECT_EQ(condition("contact slip; frictionCoefficient 0.5;").friction(), 0);
}


// ************************************************************************* //
