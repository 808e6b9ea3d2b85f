/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "nodeContact.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "knownKeywords.H"
#include "orderedSums.H"
#include <algorithm>
#include <numeric>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::nodeContact::keywords({"writePressure"});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nodeContact::nodeContact
(
    const word& name,
    const dictionary& dict,
    const contactCondition& condition
)
:
    name_(name),
    condition_(condition),
    writePressure_(dict.getOrDefault<bool>("writePressure", false)),
    band_(0),
    onSurface_(0),
    nOwned_(0),
    force_(Zero)
{
    knownKeywords::add(dict, keywords);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::nodeContact::startSearch(const gridGeometry& g)
{
    // Nodes to a depth of three cells: the stencils of particles that touch
    // the surface, and of those that have entered it by up to a cell
    // (Sizes along the axes the flow varies along: a plane slice's width
    // across y is no resolution)
    band_ = 3*g.hMax();
    onSurface_ = surfaceTolerance(g);
    nodes_.clear();
    depth_.clear();
    for (int d = 0; d < 3; ++d)
    {
        normal_[d].clear();
    }
    return band_;
}


void Foam::nodeContact::addNode
(
    const gridGeometry::index n,
    const scalar phi,
    const vector& normal
)
{
    if (phi <= onSurface_ && phi >= -band_)
    {
        nodes_.push_back(n);
        depth_.push_back(-phi);
        for (int d = 0; d < 3; ++d)
        {
            normal_[d].push_back(normal[d]);
        }
    }
}


void Foam::nodeContact::finishSearch
(
    const gridGeometry& g,
    const bool wall[3][2]
)
{
    normalForce_.assign(nodes_.size(), 0.0);
    share_.assign(nodes_.size(), 1.0);
    blocks_.build(g, nodes_);
    blockForced_.assign(blocks_.size(), false);
    // A decomposed grid's part counts the force of the nodes it owns only:
    // the processors' sums add up to the whole barrier's
    nOwned_ = 0;
    for (label c = 0; c < label(nodes_.size()); ++c)
    {
        const bool own = g.ownsNode(nodes_[c]);
        share_[c] = own ? domainShare(g, wall, nodes_[c]) : 0;
        nOwned_ += own;
    }

    if (returnReduce(nodes_.size(), sumOp<label>()) == 0)
    {
        WarningInFunction
            << "barrier " << name_ << " has no grid node inside it or on its"
            << " surface: it lies outside the mesh or is thinner than the"
            << " node spacing; only the particles' guard stops the flow at"
            << " it, and its force acts on the particles alone (no node"
            << " pressure, writePressure)" << endl;
    }
    warnIfThin(g);
    depth_.clear();
}


double Foam::nodeContact::domainShare
(
    const gridGeometry& g,
    const bool wall[3][2],
    const gridGeometry::index node
)
{
    gridGeometry::index ijk[3];
    g.nodeIJK(node, ijk);
    double share = 1;
    for (int d = 0; d < g.dim; ++d)
    {
        const gridGeometry::index side[2] = {0, g.nCells[d]};
        for (int s = 0; s < 2; ++s)
        {
            if (!wall[d][s])
            {
                continue;
            }
            const gridGeometry::index beyond =
                s ? ijk[d] - side[s] : side[s] - ijk[d];
            share *= beyond > 0 ? 0 : (beyond == 0 ? 0.5 : 1);
        }
    }
    return share;
}


void Foam::nodeContact::warnIfThin(const gridGeometry& g) const
{
    // Neighbouring contact nodes less than a cell deep whose nearest faces
    // look opposite ways lie in a part thinner than about two cells: a node
    // there may take the far face's normal, and flow arriving at it is not
    // stopped at the nodes (contact acts only on approach); the particles'
    // guard stops it, so the force there acts on the particles and is
    // missing from the node pressure
    const double h = g.hMax();
    const std::vector<double>& depth = depth_;
    std::vector<gridGeometry::index> sorted(nodes_);
    std::vector<label> order(nodes_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b) { return nodes_[a] < nodes_[b]; }
    );
    for (label k = 0; k < label(order.size()); ++k)
    {
        sorted[k] = nodes_[order[k]];
    }
    // The contact node at a flat index (-1: none)
    auto contactNode = [&](const gridGeometry::index n) -> label
    {
        const auto it = std::lower_bound(sorted.begin(), sorted.end(), n);
        return it != sorted.end() && *it == n ? order[it - sorted.begin()] : -1;
    };
    label nThin = 0;
    for (label c = 0; c < label(nodes_.size()); ++c)
    {
        if (!(depth[c] < h))
        {
            continue;
        }
        // One node layer: nothing behind the node, against its normal
        int a = 0;
        for (int d = 1; d < 3; ++d)
        {
            a = mag(normal_[d][c]) > mag(normal_[a][c]) ? d : a;
        }
        const gridGeometry::index behind = nodes_[c]
          - (normal_[a][c] > 0 ? 1 : -1)*g.nodeStride[a];
        if (g.dim == 3 && contactNode(behind) < 0)
        {
            ++nThin;
            continue;
        }
        for (int d = 0; d < 3; ++d)
        {
            const label o = contactNode(nodes_[c] + g.nodeStride[d]);
            if (o < 0)
            {
                continue;
            }
            if (!(depth[o] < h))
            {
                continue;
            }
            const double dot =
                normal_[0][c]*normal_[0][o] + normal_[1][c]*normal_[1][o]
              + normal_[2][c]*normal_[2][o];
            if (dot < -0.5)
            {
                ++nThin;
                break;
            }
        }
    }
    if (nThin)
    {
        WarningInFunction
            << "barrier " << name_ << " is thinner than about two cells at "
            << nThin << " grid nodes: the particles' guard stops the flow"
            << " there, but part of the contact force acts on particles and"
            << " is missing from the node pressure (writePressure); refine"
            << " the mesh for a resolved pressure" << endl;
    }
}


void Foam::nodeContact::apply
(
    mpm3dGrid& grid,
    const nodeBox& active,
    const double massTol,
    const double dt
)
{
    const label nc = label(nodes_.size());
    const gridGeometry::index* nodes = nodes_.data();
    const double* nx = normal_[0].data();
    const double* ny = normal_[1].data();
    const double* nz = normal_[2].data();
    double* fn = normalForce_.data();
    const double* share = share_.data();
    const contactCondition& condition = condition_;
    const nodeBlockBoxes& blocks = blocks_;
    char* forced = blockForced_.data();
    // Force summed in a fixed order: the same on any number of threads. A
    // block of nodes outside the flow's box holds no mass and adds nothing:
    // its sum is the zero it would have been
    double F[3], none[1];
    orderedBlockSums<3, 0>
    (
        nc, F, none,
        [&](const label first, const label last, double* S, double*)
        {
            const label b = first/orderedSumsBlock;
            if (!blocks.overlaps(b, active))
            {
                if (forced[b])
                {
                    std::fill(fn + first, fn + last, 0.0);
                    forced[b] = false;
                }
                return;
            }
            forced[b] = true;
            for (label c = first; c < last; ++c)
            {
                const gridGeometry::index n = nodes[c];
                const double mi = grid.mass[n];
                const double v[3] = {grid.vx[n], grid.vy[n], grid.vz[n]};
                const double vn = v[0]*nx[c] + v[1]*ny[c] + v[2]*nz[c];
                if (!(mi > massTol) || vn >= 0)
                {
                    fn[c] = 0;
                    continue;
                }
                const double nrm[3] = {nx[c], ny[c], nz[c]};
                double vt[3] = {v[0], v[1], v[2]};
                condition.apply(nrm, vn, vt);
                const double k = mi/dt;
                const double kDomain = share[c]*k;
                S[0] += kDomain*(v[0] - vt[0]);
                S[1] += kDomain*(v[1] - vt[1]);
                S[2] += kDomain*(v[2] - vt[2]);
                fn[c] = -k*vn;
                grid.vx[n] = vt[0];
                grid.vy[n] = vt[1];
                grid.vz[n] = vt[2];
            }
        }
    );

    force_ = vector(F[0], F[1], F[2]);
}


void Foam::nodeContact::nodePressure
(
    const gridGeometry& g,
    std::vector<double>& p
) const
{
    p.assign(g.nNodes(), 0.0);
    // The node's force is the momentum of its cell (dx dy dz about it), so
    // its area on the wall is that cell seen along the normal: the faces'
    // areas projected, dy dz for a wall facing x. A normal of zero (across
    // a plane slice) takes no force
    const double faceArea[3] =
        {g.dx[1]*g.dx[2], g.dx[2]*g.dx[0], g.dx[0]*g.dx[1]};
    for (label c = 0; c < label(nodes_.size()); ++c)
    {
        double area = 0;
        for (int d = 0; d < 3; ++d)
        {
            area += std::abs(normal_[d][c])*faceArea[d];
        }
        p[nodes_[c]] = area > 0 ? normalForce_[c]/area : 0;
    }
}


// ************************************************************************* //
