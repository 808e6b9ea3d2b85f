/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneContact.H"
#include "dictionary.H"
#include "Pstream.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// How far beside the membrane's rim a particle or a path's crossing still
// counts as on it [cells]
constexpr double rimTolerance = 0.5;

// A particle put back sits this far on its side [cells]
constexpr double guardGap = 1e-3;

inline double dot3(const double a[3], const double b[3])
{
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::membraneContact::findNear
(
    const gridGeometry& g,
    const membraneSurface& surface,
    const mpm3dParticles& p,
    const nodeBox& particleNodes
)
{
    near_.clear();
    side_.clear();
    nearQ_.clear();
    phi0_.clear();
    for (int d = 0; d < 3; ++d)
    {
        x0_[d].clear();
    }
    const double rim = rimTolerance*g.hMax();

    // The particles within reach of the membrane (none while their box
    // is clear of the membrane's), their nearest points searched in
    // parallel
    candidates_.clear();
    double lo[3], hi[3];
    for (int d = 0; d < 3; ++d)
    {
        lo[d] = g.nodeCoord(d, particleNodes.lo[d] - gridGeometry::nGhost);
        hi[d] = g.nodeCoord(d, particleNodes.hi[d] - gridGeometry::nGhost);
    }
    if (particleNodes.empty() || !surface.meets(lo, hi))
    {
        return;
    }
    inReach_.resize(p.n);
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < p.n; ++i)
    {
        const double x[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
        inReach_[i] = surface.inReach(g, x);
    }
    for (label i = 0; i < p.n; ++i)
    {
        if (inReach_[i])
        {
            candidates_.push_back(i);
        }
    }
    const label nc = label(candidates_.size());
    nearPoints_.resize(nc);
    #pragma omp parallel for schedule(static)
    for (label c = 0; c < nc; ++c)
    {
        const label i = candidates_[c];
        const double x[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
        surface.nearest(g, x, nearPoints_[c]);
    }

    // In storage order: the same on any number of threads
    for (label c = 0; c < nc; ++c)
    {
        const membraneSurface::nearPoint& q = nearPoints_[c];
        if (!onMembrane(q, rim))
        {
            continue;
        }
        const label i = candidates_[c];
        const signed char s = q.phi < 0 ? -1 : 1;
        near_.push_back(i);
        side_.push_back(s);
        nearQ_.push_back(q);
        phi0_.push_back(s*q.phi);
        for (int d = 0; d < 3; ++d)
        {
            x0_[d].push_back(p.x[d][i]);
        }
    }
}


void Foam::membraneContact::collide
(
    membraneSurface& surface,
    const membraneSurface::nearPoint& q,
    const double n[3],
    const double m,
    double v[3],
    double J[3]
)
{
    double vm[3];
    surface.velocity(q, vm);
    // The membrane's share of the common velocity: 1 at an anchor
    const double a = 1/(1 + m*surface.inverseMass(q));
    const double vcm[3] =
    {
        v[0] + a*(vm[0] - v[0]), v[1] + a*(vm[1] - v[1]),
        v[2] + a*(vm[2] - v[2])
    };
    double rel[3] = {v[0] - vcm[0], v[1] - vcm[1], v[2] - vcm[2]};
    const double vn = dot3(rel, n);
    if (vn >= 0)
    {
        return;
    }
    condition_.apply(n, vn, rel);
    double Jq[3];
    for (int d = 0; d < 3; ++d)
    {
        const double vNew = vcm[d] + rel[d];
        Jq[d] = m*(v[d] - vNew);
        J[d] += Jq[d];
        v[d] = vNew;
    }
    surface.kick(q, Jq, anchored_);
}


double Foam::membraneContact::reach
(
    const double m,
    const penalty& stiffness,
    double& ms
) const
{
    // The particle's width along the membrane's normal and its face
    const double V = m/stiffness.rho;
    const double w = stiffness.width;
    const double a = w > 0 ? std::sqrt(V/w) : std::cbrt(V);
    ms = arealMass_*(w > 0 ? a*w : a*a);
    return 0.5*a;
}


void Foam::membraneContact::contactForce
(
    const size_t k,
    const membraneSurface& surface,
    const mpm3dParticles& p,
    const double mu,
    const double fn,
    const double dt,
    double f[3]
)
{
    const label i = near_[k];
    const membraneSurface::nearPoint& q = nearQ_[k];
    const double n[3] =
        {side_[k]*q.n[0], side_[k]*q.n[1], side_[k]*q.n[2]};
    double vm[3];
    surface.velocity(q, vm);
    double rel[3] =
        {p.u[0][i] - vm[0], p.u[1][i] - vm[1], p.u[2][i] - vm[2]};

    // The relative velocity's tangential part, changed by the contact
    // condition as the normal force's velocity change would
    const double vn = dot3(rel, n);
    const double dvn = -fn*dt/mu;
    double vt[3];
    for (int d = 0; d < 3; ++d)
    {
        vt[d] = rel[d] - vn*n[d];
        rel[d] = vt[d] + dvn*n[d];
    }
    condition_.apply(n, dvn, rel);
    for (int d = 0; d < 3; ++d)
    {
        f[d] = fn*n[d] + mu*(rel[d] - vt[d])/dt;
    }
    dissipation_ += 0.5*mu*(dot3(vt, vt) - dot3(rel, rel));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneContact::membraneContact
(
    const contactCondition& condition,
    const label nNodes,
    const double arealMass,
    const double kappa
)
:
    condition_(condition),
    arealMass_(arealMass),
    kappa_(kappa),
    dissipation_(0),
    energy_(0),
    force_(Zero)
{
    for (int d = 0; d < 3; ++d)
    {
        anchored_[d].assign(nNodes, 0.0);
    }
}


void Foam::membraneContact::saveKicks(const structureNodes& n)
{
    if (!Pstream::parRun())
    {
        return;
    }
    const double* v[3] = {n.vx.data(), n.vy.data(), n.vz.data()};
    for (int d = 0; d < 3; ++d)
    {
        before_.v[d].assign(v[d], v[d] + n.size());
        before_.anchored[d] = anchored_[d];
    }
    before_.dissipation = dissipation_;
    before_.energy = energy_;
    before_.force = force_;
}


void Foam::membraneContact::sumKicks(structureNodes& n)
{
    if (!Pstream::parRun())
    {
        return;
    }
    // Every processor's changes, summed in the gather's fixed order: the
    // same on every processor's copy
    const label nn = n.size();
    double* v[3] = {n.vx.data(), n.vy.data(), n.vz.data()};
    List<scalar>& change = before_.change;
    change.setSize(6*nn + 5);
    for (int d = 0; d < 3; ++d)
    {
        for (label i = 0; i < nn; ++i)
        {
            change[d*nn + i] = v[d][i] - before_.v[d][i];
            change[(3 + d)*nn + i] = anchored_[d][i] - before_.anchored[d][i];
        }
    }
    label k = 6*nn;
    change[k++] = dissipation_ - before_.dissipation;
    change[k++] = energy_ - before_.energy;
    for (int d = 0; d < 3; ++d)
    {
        change[k++] = force_[d] - before_.force[d];
    }
    Pstream::listCombineGather(change, plusEqOp<scalar>());
    Pstream::listCombineScatter(change);

    for (int d = 0; d < 3; ++d)
    {
        for (label i = 0; i < nn; ++i)
        {
            v[d][i] = before_.v[d][i] + change[d*nn + i];
            anchored_[d][i] = before_.anchored[d][i] + change[(3 + d)*nn + i];
        }
    }
    k = 6*nn;
    dissipation_ = before_.dissipation + change[k++];
    energy_ = before_.energy + change[k++];
    for (int d = 0; d < 3; ++d)
    {
        force_[d] = before_.force[d] + change[k++];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const std::vector<Foam::membraneContact::push>&
Foam::membraneContact::pushParticles
(
    const gridGeometry& g,
    const membraneSurface& surface,
    const mpm3dParticles& p,
    const nodeBox& particleNodes,
    const penalty& stiffness,
    const double dt
)
{
    for (int d = 0; d < 3; ++d)
    {
        std::fill(anchored_[d].begin(), anchored_[d].end(), 0.0);
    }
    pushes_.clear();
    energy_ = 0;
    force_ = Zero;
    saveKicks(surface.nodes());
    findNear(g, surface, p, particleNodes);
    reach_.resize(near_.size());

    const double omega = kappa_*stiffness.c/(stiffness.maxCo*stiffness.h);
    for (size_t k = 0; k < near_.size(); ++k)
    {
        const label i = near_[k];
        double ms;
        reach_[k] = reach(p.m[i], stiffness, ms);
        const double overlap = reach_[k] - phi0_[k];
        if (overlap <= 0 || nearQ_[k].lateral2 > sqr(reach_[k]))
        {
            continue;
        }
        const double mu = p.m[i]*ms/(p.m[i] + ms);
        const double fn = mu*omega*omega*overlap;
        energy_ += 0.5*fn*overlap;
        push pi;
        pi.particle = i;
        pi.q = nearQ_[k];
        contactForce(k, surface, p, mu, fn, dt, pi.f);
        force_ -= vector(pi.f[0], pi.f[1], pi.f[2]);
        pushes_.push_back(pi);
    }
    return pushes_;
}


void Foam::membraneContact::kickMembrane
(
    membraneSurface& surface,
    const double dt
)
{
    for (const push& pi : pushes_)
    {
        const double J[3] = {-pi.f[0]*dt, -pi.f[1]*dt, -pi.f[2]*dt};
        surface.kick(pi.q, J, anchored_);
    }
    // (The push's work is its energy's change: only the guard's kicks
    // are settled)
    surface.settleKicks();
    sumKicks(surface.nodes());
}


Foam::label Foam::membraneContact::stopCrossings
(
    const gridGeometry& g,
    membraneSurface& surface,
    const mpm3dParticles& p,
    const double membraneMove,
    const double dt
)
{
    saveKicks(surface.nodes());
    const double h = g.hMax();
    const double rim = rimTolerance*h;
    const double gap = guardGap*h;
    double J[3] = {0, 0, 0};
    label nStopped = 0;
    membraneSurface::nearPoint q, q0, cross;
    for (size_t k = 0; k < near_.size(); ++k)
    {
        const label i = near_[k];
        const double s = side_[k];
        const double x[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
        const double x0[3] = {x0_[0][k], x0_[1][k], x0_[2][k]};
        // Only a particle that moved, with the membrane's move, as far as
        // its start distance can have reached the membrane
        const double dx[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
        const double reach = phi0_[k] - gap - membraneMove;
        if
        (
            (reach > 0 && dot3(dx, dx) < reach*reach)
         || !surface.nearest(g, x, q) || s*q.phi >= gap
         || !surface.nearest(g, x0, q0)
        )
        {
            continue;
        }
        // Where the path meets the membrane: a crossing, or a pass beside
        // its rim
        const double phi0 = s*q0.phi, phi1 = s*q.phi;
        const double f = phi0 > phi1 ? std::max(phi0, 0.0)/(phi0 - phi1) : 0;
        const double xc[3] =
        {
            x0[0] + f*(x[0] - x0[0]), x0[1] + f*(x[1] - x0[1]),
            x0[2] + f*(x[2] - x0[2])
        };
        if (!surface.nearest(g, xc, cross) || !onMembrane(cross, rim))
        {
            continue;
        }
        // Back on its side: along the normal where it ends beyond the
        // membrane, else (beyond its rim) to where it crossed
        const bool beyond = onMembrane(q, rim);
        if (!beyond)
        {
            q = cross;
        }
        const double nrm[3] = {s*q.n[0], s*q.n[1], s*q.n[2]};
        const double back = std::max(gap, reach_[k]) - s*q.phi;
        const double* const from = beyond ? x : xc;
        const double u0[3] = {p.u[0][i], p.u[1][i], p.u[2][i]};
        double u[3] = {u0[0], u0[1], u0[2]};
        collide(surface, q, nrm, p.m[i], u, J);
        // The meeting's loss: the particle's kinetic energy less the
        // membrane's gain
        dissipation_ +=
            0.5*p.m[i]*(dot3(u0, u0) - dot3(u, u)) - surface.settleKicks();
        for (int d = 0; d < 3; ++d)
        {
            p.x[d][i] = from[d] + back*nrm[d];
            p.u[d][i] = u[d];
        }
        ++nStopped;
    }
    force_ += vector(J[0], J[1], J[2])/dt;
    sumKicks(surface.nodes());
    return nStopped;
}


void Foam::membraneContact::writeState(dictionary& state) const
{
    state.set("contactDissipation", dissipation_);
}


void Foam::membraneContact::readState(const dictionary& state)
{
    dissipation_ = state.get<scalar>("contactDissipation");
}


// ************************************************************************* //
