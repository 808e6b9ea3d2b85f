/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    membraneContact, the flow's penalty push on a membrane and the
    particles' guard, on a square membrane in x = 0 (four free nodes of
    2 kg, 10 kg/m^2) and particles of 1 kg at 1000 kg/m^3 (width 0.1 m,
    reach delta = 0.05 m, ms = 0.1 kg behind a particle's face), c = 10 m/s,
    h = 0.1 m, maxCo 0.4, kappa 0.8 (omega = 200 1/s), dt = 1 ms:
    - a particle 0.02 m from the membrane is pushed away along the normal
      by mu omega^2 (delta - 0.02), mu = m ms/(m + ms), and holds
      1/2 f (delta - 0.02); the membrane takes -f dt, the impulse the flow
      takes, to round-off;
    - its sliding along the membrane: kept (slip), removed (noSlip: f_t =
      -mu vt/dt, dissipating 1/2 mu vt^2) or, with Coulomb, a tangential
      force of the friction coefficient times the push;
    - no push beyond delta or beside the rim farther than delta; two
      particles mirrored across the membrane are pushed apart, the
      membrane's net force zero;
    - a particle that crossed the membrane in its move is put back on its
      side at delta, at the membrane's velocity along the normal there,
      with momentum conserved and its loss reported as dissipation, to
      round-off.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "membraneContact.H"
#include "IStringStream.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

const double rho = 1000, arealMass = 10, kappa = 0.8, dt = 1e-3;
const double delta = 0.05, ms = 0.1, mu = ms/(1 + ms), omega = 200;

//- The membrane x = 0, |y|, |z| <= 0.4, on a grid of 0.1 m cells, and the
//  particles (1 kg each) beside it
struct membraneScene
{
    gridGeometry g;
    structureNodes nodes;
    std::vector<label> triangles;
    membraneSurface surface;
    contactCondition condition;
    membraneContact contact;
    std::vector<double> x[3], u[3], m, V;

    static contactCondition readCondition(const std::string& text)
    {
        IStringStream is(text);
        return contactCondition(dictionary(is));
    }

    static structureNodes square()
    {
        structureNodes n;
        for
        (
            const point& p
          : {
                point(0, -0.4, -0.4), point(0, 0.4, -0.4),
                point(0, 0.4, 0.4), point(0, -0.4, 0.4)
            }
        )
        {
            n.mass[n.append(p)] = 2;
        }
        return n;
    }

    explicit membraneScene(const std::string& conditionText)
    :
        g(uniformGrid(3, {-1, -1, -1}, {0.1, 0.1, 0.1}, {20, 20, 20})),
        nodes(square()),
        triangles({0, 1, 2, 0, 2, 3}),
        surface(nodes, triangles),
        condition(readCondition(conditionText)),
        contact(condition, nodes.size(), arealMass, kappa)
    {
        surface.update(g, 0.2, 0.05);
    }

    void add(const point& p, const vector& v)
    {
        for (int d = 0; d < 3; ++d)
        {
            x[d].push_back(p[d]);
            u[d].push_back(v[d]);
        }
        m.push_back(1);
        V.push_back(1/rho);
    }

    mpm3dParticles view()
    {
        mpm3dParticles p;
        p.n = m.size();
        for (int d = 0; d < 3; ++d)
        {
            p.x[d] = x[d].data();
            p.u[d] = u[d].data();
        }
        p.m = m.data();
        p.V = V.data();
        return p;
    }

    const std::vector<membraneContact::push>& push()
    {
        nodeBox all;
        for (int d = 0; d < 3; ++d)
        {
            all.hi[d] = g.nNodesDir[d];
        }
        const membraneContact::penalty stiffness{rho, 10, 0.1, 0.4, 0};
        return contact.pushParticles(g, surface, view(), all, stiffness, dt);
    }

    vector momentum() const
    {
        vector P(Zero);
        for (label i = 0; i < nodes.size(); ++i)
        {
            P += nodes.mass[i]*vector(nodes.vx[i], nodes.vy[i], nodes.vz[i]);
        }
        return P;
    }

    double kinetic() const
    {
        double e = 0;
        for (label i = 0; i < nodes.size(); ++i)
        {
            e += 0.5*nodes.mass[i]
               *(sqr(nodes.vx[i]) + sqr(nodes.vy[i]) + sqr(nodes.vz[i]));
        }
        return e;
    }
};

vector force(const membraneContact::push& p)
{
    return vector(p.f[0], p.f[1], p.f[2]);
}

} // End anonymous namespace


TEST(membraneContact, PushAlongTheNormalWithItsEnergyAndItsReaction)
{
    membraneScene s("contact slip;");
    s.add(point(-0.02, 0.05, 0.1), vector(1, 0, 0));
    const std::vector<membraneContact::push>& pushes = s.push();
    ASSERT_EQ(pushes.size(), 1u);
    const double fn = mu*sqr(omega)*(delta - 0.02);
    EXPECT_LT(mag(force(pushes[0]) - vector(-fn, 0, 0)), 1e-12*fn);
    EXPECT_NEAR(s.contact.energy(), 0.5*fn*(delta - 0.02), 1e-12);
    EXPECT_LT(mag(s.contact.force() - vector(fn, 0, 0)), 1e-12*fn);

    const vector P0 = s.momentum();
    s.contact.kickMembrane(s.surface, dt);
    EXPECT_LT(mag(s.momentum() - P0 - vector(fn*dt, 0, 0)), 1e-15);
    EXPECT_EQ(s.contact.dissipation(), 0);
}


TEST(membraneContact, SlidingKeptRemovedOrResistedByFriction)
{
    const double fn = mu*sqr(omega)*(delta - 0.02);
    const double vt = 0.5;
    auto tangential = [&](const std::string& condition)
    {
        membraneScene s(condition);
        s.add(point(-0.02, 0.05, 0.1), vector(1, vt, 0));
        const std::vector<membraneContact::push>& pushes = s.push();
        EXPECT_EQ(pushes.size(), 1u);
        EXPECT_NEAR(pushes[0].f[0], -fn, 1e-12*fn);
        EXPECT_EQ(pushes[0].f[2], 0);
        return std::make_pair(pushes[0].f[1], s.contact.dissipation());
    };

    const auto slip = tangential("contact slip;");
    EXPECT_EQ(slip.first, 0);
    EXPECT_EQ(slip.second, 0);

    const auto noSlip = tangential("contact noSlip;");
    EXPECT_NEAR(noSlip.first, -mu*vt/dt, 1e-12*mu*vt/dt);
    EXPECT_NEAR(noSlip.second, 0.5*mu*vt*vt, 1e-15);

    // 0.3 fn dt/mu = 0.36 m/s of the 0.5 m/s: it slides on, resisted
    const auto coulomb =
        tangential("contact Coulomb; frictionCoefficient 0.3;");
    EXPECT_NEAR(coulomb.first, -0.3*fn, 1e-12*fn);
    const double vtNew = vt - 0.3*fn*dt/mu;
    EXPECT_NEAR(coulomb.second, 0.5*mu*(vt*vt - vtNew*vtNew), 1e-15);
}


TEST(membraneContact, NoPushBeyondItsReachOrBesideTheRimAndBothSidesApart)
{
    membraneScene s("contact slip;");
    s.add(point(-0.06, 0, 0), vector(1, 0, 0));     // beyond delta
    s.add(point(-0.01, 0.46, 0), vector(1, 0, 0));  // 0.06 beside the rim
    s.add(point(-0.01, 0.43, 0), vector(1, 0, 0));  // 0.03 beside it
    s.add(point(-0.02, 0.05, 0.1), vector(1, 0, 0));
    s.add(point(0.02, 0.05, 0.1), vector(-1, 0, 0));
    const std::vector<membraneContact::push>& pushes = s.push();
    ASSERT_EQ(pushes.size(), 3u);
    EXPECT_EQ(pushes[0].particle, 2);
    EXPECT_EQ(pushes[1].particle, 3);
    EXPECT_EQ(pushes[2].particle, 4);
    EXPECT_NEAR
    (
        pushes[0].f[0], -mu*sqr(omega)*(delta - 0.01), 1e-12*mu*sqr(omega)
    );
    EXPECT_LT(pushes[1].f[0], 0);
    EXPECT_EQ(pushes[1].f[0], -pushes[2].f[0]);
    EXPECT_EQ(s.contact.force().x(), -pushes[0].f[0]);
}


TEST(membraneContact, CrossingParticleIsPutBackAndMeetsTheMembrane)
{
    membraneScene s("contact slip;");
    const vector u0(3, 0.2, 0);
    s.add(point(-0.02, 0.05, 0.1), u0);
    s.push();

    // Its move took it through the still membrane
    s.x[0][0] = 0.01;
    const vector P0 = s.momentum();
    const double E0 = s.kinetic() + 0.5*magSqr(u0);
    EXPECT_EQ(s.contact.stopCrossings(s.g, s.surface, s.view(), 0, dt), 1);

    EXPECT_NEAR(s.x[0][0], -delta, 1e-15);
    EXPECT_EQ(s.x[1][0], 0.05);
    EXPECT_EQ(s.x[2][0], 0.1);
    const vector u(s.u[0][0], s.u[1][0], s.u[2][0]);
    EXPECT_LT(mag(s.momentum() + u - P0 - u0), 1e-14);
    // Along the normal at the membrane's velocity there; slip keeps the
    // rest
    membraneSurface::nearPoint q;
    const double x[3] = {s.x[0][0], s.x[1][0], s.x[2][0]};
    ASSERT_TRUE(s.surface.nearest(s.g, x, q));
    double vm[3];
    s.surface.velocity(q, vm);
    EXPECT_GT(u.x(), 0);
    EXPECT_NEAR(u.x(), vm[0], 1e-14);
    EXPECT_EQ(u.y(), u0.y());
    const double E = s.kinetic() + 0.5*magSqr(u);
    EXPECT_GT(s.contact.dissipation(), 0);
    EXPECT_NEAR(s.contact.dissipation(), E0 - E, 1e-14);
}


// ************************************************************************* //
