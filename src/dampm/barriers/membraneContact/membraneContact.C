/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneContact.H"
#include "nodeContact.H"
#include "dictionary.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Reach of a particle's stencil [cells per axis]: the quadratic B-spline's
// and GIMP's support
constexpr double stencilReach = 1.5;

// How far beside the membrane's rim a node or a path's crossing still
// counts as on it [cells]
constexpr double rimTolerance = 0.5;

// Nodes on the flow's side nearer than this take the contact [cells]
constexpr double contactDepth = 0.5;

// The sides of the particles that touched a node
constexpr char plusSide = 1, minusSide = 2;

// A particle put back sits this far on its side [cells]
constexpr double guardGap = 1e-3;

inline double dot3(const double a[3], const double b[3])
{
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::membraneContact::addSide
(
    const gridGeometry& g,
    const double x[3],
    const double m,
    const int side,
    const double phi
)
{
    gridGeometry::index lo[3], hi[3];
    double xi[3];
    for (int d = 0; d < 3; ++d)
    {
        xi[d] = g.local(d, x[d]);
        lo[d] = std::max
        (
            gridGeometry::index(std::ceil(xi[d] - stencilReach)),
            -gridGeometry::nGhost
        );
        hi[d] = std::min
        (
            gridGeometry::index(std::floor(xi[d] + stencilReach)),
            g.nCells[d] + gridGeometry::nGhost
        );
        if (!g.varies(d))
        {
            // A plane slice's one row of nodes, level with the particle
            xi[d] = lo[d] = hi[d] = 0;
        }
    }
    const char sideBit = side > 0 ? plusSide : minusSide;
    for (gridGeometry::index k = lo[2]; k <= hi[2]; ++k)
    {
        const double dz = (xi[2] - k)*g.dx[2];
        const double wz = 1 - std::abs(xi[2] - k)/stencilReach;
        for (gridGeometry::index j = lo[1]; j <= hi[1]; ++j)
        {
            const double dy = (xi[1] - j)*g.dx[1];
            const double wyz = wz*(1 - std::abs(xi[1] - j)/stencilReach);
            for (gridGeometry::index i = lo[0]; i <= hi[0]; ++i)
            {
                const double dx = (xi[0] - i)*g.dx[0];
                const double w = wyz*(1 - std::abs(xi[0] - i)/stencilReach);
                const gridGeometry::index n = g.nodeIndex(i, j, k);
                // The node lies at least phi - r from the membrane on the
                // particle's side (a distance changes no faster than the
                // point moves)
                const double far = phi - std::sqrt(dx*dx + dy*dy + dz*dz);
                if (!touchedSides_[n])
                {
                    touched_.push_back(n);
                    farOnSide_[n] = far;
                }
                touchedSides_[n] |= sideBit;
                farOnSide_[n] = std::max(farOnSide_[n], far);
                sideSum_[n] += w*side*m;
            }
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneContact::membraneContact
(
    const contactCondition& condition,
    const label nNodes
)
:
    condition_(condition),
    flowLoss_(0),
    membraneGain_(0),
    force_(Zero),
    J_(Zero)
{
    for (int d = 0; d < 3; ++d)
    {
        anchored_[d].assign(nNodes, 0.0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::membraneContact::findSides
(
    const gridGeometry& g,
    const membraneSurface& surface,
    const mpm3dParticles& p,
    const nodeBox& particleNodes
)
{
    sideSum_.resize(g.nNodes(), 0.0);
    touchedSides_.resize(g.nNodes(), 0);
    farOnSide_.resize(g.nNodes(), 0.0);
    touched_.clear();
    near_.clear();
    side_.clear();
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

    // Their sides, summed in storage order: the same on any number of
    // threads
    for (label c = 0; c < nc; ++c)
    {
        const membraneSurface::nearPoint& q = nearPoints_[c];
        if (!onMembrane(q, rim))
        {
            continue;
        }
        const label i = candidates_[c];
        const double x[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
        const signed char s = q.phi < 0 ? -1 : 1;
        near_.push_back(i);
        side_.push_back(s);
        phi0_.push_back(s*q.phi);
        for (int d = 0; d < 3; ++d)
        {
            x0_[d].push_back(x[d]);
        }
        addSide(g, x, p.m[i], s, s*q.phi);
    }
}


void Foam::membraneContact::findContacts
(
    const gridGeometry& g,
    const membraneSurface& surface,
    const bool wall[3][2],
    const double massTol,
    const mpm3dGrid& grid
)
{
    for (int d = 0; d < 3; ++d)
    {
        std::fill(anchored_[d].begin(), anchored_[d].end(), 0.0);
    }
    J_ = vector::zero;
    const double h = g.hMax();
    const double rim = rimTolerance*h;
    const label nt = label(touched_.size());
    nearPoints_.resize(nt);
    // The nodes with flow that may be in contact: not those the particles
    // of one side place a cell beyond the contact's depth on their side
    const double farEnough = (contactDepth + 1)*h;
    #pragma omp parallel for schedule(static)
    for (label c = 0; c < nt; ++c)
    {
        const gridGeometry::index n = touched_[c];
        nearPoints_[c].tri = -1;
        const bool oneSide = touchedSides_[n] != (plusSide | minusSide);
        if
        (
            grid.mass[n] > massTol
         && !(oneSide && farOnSide_[n] >= farEnough)
        )
        {
            double x[3];
            g.nodePosition(n, x);
            surface.nearest(g, x, nearPoints_[c]);
        }
    }

    // In the order the particles found the nodes
    contacts_.clear();
    for (label c = 0; c < nt; ++c)
    {
        const gridGeometry::index n = touched_[c];
        const double s = sideSum_[n] < 0 ? -1 : 1;
        sideSum_[n] = 0;
        touchedSides_[n] = 0;
        const membraneSurface::nearPoint& q = nearPoints_[c];
        if (!onMembrane(q, rim) || s*q.phi >= contactDepth*h)
        {
            continue;
        }
        contactNode cn;
        cn.node = n;
        cn.q = q;
        for (int d = 0; d < 3; ++d)
        {
            cn.q.n[d] *= s;
        }
        cn.mass = nodeContact::domainShare(g, wall, n)*grid.mass[n];
        cn.v[0] = grid.vx[n];
        cn.v[1] = grid.vy[n];
        cn.v[2] = grid.vz[n];
        std::copy(cn.v, cn.v + 3, cn.v0);
        contacts_.push_back(cn);
    }
    touched_.clear();
}


void Foam::membraneContact::collideAtNodes(membraneSurface& surface)
{
    double J[3] = {0, 0, 0};
    for (contactNode& c : contacts_)
    {
        collide(surface, c.q, c.q.n, c.mass, c.v, J);
    }
    J_ += vector(J[0], J[1], J[2]);
}


void Foam::membraneContact::settleAtNodes(membraneSurface& surface)
{
    membraneGain_ += surface.settleKicks();
}


void Foam::membraneContact::finishAtNodes(const double dt, mpm3dGrid& grid)
{
    // The work of the step's impulses on the flow: its particles move with
    // the nodes' velocity after the contact (x + dt v)
    double work = 0;
    for (const contactNode& c : contacts_)
    {
        grid.vx[c.node] = c.v[0];
        grid.vy[c.node] = c.v[1];
        grid.vz[c.node] = c.v[2];
        for (int d = 0; d < 3; ++d)
        {
            work += c.mass*(c.v[d] - c.v0[d])*c.v[d];
        }
    }
    flowLoss_ -= work;
    force_ = J_/dt;
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
        const double back = gap - s*q.phi;
        const double* const from = beyond ? x : xc;
        double u[3] = {p.u[0][i], p.u[1][i], p.u[2][i]};
        const double Jp[3] = {J[0], J[1], J[2]};
        collide(surface, q, nrm, p.m[i], u, J);
        membraneGain_ += surface.settleKicks();
        // The impulse at the particle's velocity after it
        flowLoss_ +=
            (J[0] - Jp[0])*u[0] + (J[1] - Jp[1])*u[1] + (J[2] - Jp[2])*u[2];
        for (int d = 0; d < 3; ++d)
        {
            p.x[d][i] = from[d] + back*nrm[d];
            p.u[d][i] = u[d];
        }
        ++nStopped;
    }
    force_ += vector(J[0], J[1], J[2])/dt;
    return nStopped;
}


void Foam::membraneContact::writeState(dictionary& state) const
{
    state.set("contactFlowLoss", flowLoss_);
    state.set("contactMembraneGain", membraneGain_);
}


void Foam::membraneContact::readState(const dictionary& state)
{
    flowLoss_ = state.get<scalar>("contactFlowLoss");
    membraneGain_ = state.get<scalar>("contactMembraneGain");
}


// ************************************************************************* //
