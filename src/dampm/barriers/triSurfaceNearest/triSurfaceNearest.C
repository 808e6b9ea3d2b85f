/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "triSurfaceNearest.H"
#include "triSurfaceTools.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * * Constants * * * * * * * * * * * * * * * * //

namespace
{
    //- Boxes per axis of a leaf at most
    constexpr Foam::label maxPerAxis = 16;

    //- Relative widening of a box's candidate radius (rounding: the lists
    //  hold more triangles, never fewer)
    constexpr Foam::scalar widen = 1e-6;

    //- How far beyond its leaf's box (in boxes) a point is taken as in it
    //  (rounding at the box's faces; far within the widened radius)
    constexpr Foam::scalar beyond = 1e-9;

    //- A sliver: sin^2 of its angle at a vertex below this
    constexpr Foam::scalar sliverSin2 = 1e-8;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::triSurfaceNearest::hasSliver() const
{
    const pointField& points = surf_.points();
    for (const labelledTri& f : surf_)
    {
        for (label v = 0; v < 3; ++v)
        {
            const vector a(points[f[(v + 1) % 3]] - points[f[v]]);
            const vector b(points[f[(v + 2) % 3]] - points[f[v]]);
            if (!(magSqr(a ^ b) >= sliverSin2*magSqr(a)*magSqr(b)))
            {
                return true;
            }
        }
    }
    return false;
}


Foam::label Foam::triSurfaceNearest::descend
(
    const point& p,
    volumeType& type
) const
{
    type = volumeType::MIXED;
    const List<octree::node>& nodes = tree_.nodes();
    if (nodes.empty())
    {
        type = volumeType::UNKNOWN;
        return -1;
    }
    for (label nodeI = 0;;)
    {
        const octree::node& nod = nodes[nodeI];
        const direction octant = nod.bb_.subOctant(p);
        if (type == volumeType::MIXED)
        {
            type =
                volumeType::type(tree_.nodeTypes().get((nodeI << 3) + octant));
        }
        const labelBits index = nod.subNodes_[octant];
        if (!octree::isNode(index))
        {
            return octree::isContent(index) ? octree::getContent(index) : -1;
        }
        nodeI = octree::getNode(index);
    }
}


Foam::label Foam::triSurfaceNearest::nearestCandidate
(
    const label leaf,
    const point& p,
    pointHit& hit,
    label& nearType
) const
{
    // p's box in its leaf (a point outside the octree's box can descend to
    // a leaf beyond which it lies: the octree's)
    const leafBoxes& l = leaves_[leaf];
    if (l.k == 0)
    {
        return -1;
    }
    label ijk[3];
    for (direction d = 0; d < 3; ++d)
    {
        const scalar t = (p[d] - l.lo[d])/l.size[d];
        if (!(t >= -beyond && t <= l.k + beyond))
        {
            return -1;
        }
        ijk[d] = std::min(std::max(label(t), label(0)), l.k - 1);
    }
    const label box = l.first + ijk[0] + l.k*(ijk[1] + l.k*ijk[2]);

    // The smallest distance and the next, as the octree computes them
    // (findNearestOp)
    const pointField& points = surf_.points();
    scalar best = GREAT, next = GREAT;
    label facei = -1;
    for (label j = start_[box]; j < start_[box + 1]; ++j)
    {
        const label f = faces_[j];
        label type = -1, where = -1;
        const pointHit h = surf_[f].nearestPointClassify(p, points, type, where);
        const scalar d = h.distance();
        if (d < best)
        {
            next = best;
            best = d;
            facei = f;
            hit = h;
            nearType = type;
        }
        else if (d < next)
        {
            next = d;
        }
    }
    return next - best > tieDistance_ ? facei : -1;
}


Foam::triSurfaceNearest::answer Foam::triSurfaceNearest::query
(
    const point& p
) const
{
    answer a;
    const label leaf = descend(p, a.type);
    a.facei = leaf >= 0 ? nearestCandidate(leaf, p, a.hit, a.nearType) : -1;
    return a;
}


Foam::pointIndexHit Foam::triSurfaceNearest::hitOf
(
    const point& p,
    const answer& a
) const
{
    return
        a.facei >= 0
      ? pointIndexHit(true, a.hit.rawPoint(), a.facei)
      : tree_.findNearest(p, GREAT);
}


bool Foam::triSurfaceNearest::side(const point& p, const answer& a) const
{
    // calcInside: a point outside the octree's box is outside; else
    // getVolumeType, whose first type on the way that is not MIXED holds
    if (!tree_.bb().contains(p) || a.type == volumeType::UNKNOWN)
    {
        return false;
    }
    if (a.type != volumeType::MIXED)
    {
        return a.type == volumeType::INSIDE;
    }
    if (a.facei < 0)
    {
        return tree_.getVolumeType(p) == volumeType::INSIDE;
    }
    // At a leaf, treeDataPrimitivePatch<triSurface>::getVolumeType: the
    // side of the nearest triangle (triSurfaceTools::surfaceSide, which
    // goes by the face's normal where the nearest point is inside it)
    if (a.nearType == triPointRef::NONE)
    {
        return !(((p - a.hit.rawPoint()) & surf_.faceNormals()[a.facei]) > 0);
    }
    return
        triSurfaceTools::surfaceSide(surf_, p, a.facei)
     == triSurfaceTools::INSIDE;
}


void Foam::triSurfaceNearest::addCandidates
(
    const point& centre,
    const scalar rho
)
{
    // Any point x of the box has its nearest triangle T within
    // |x - c| + d(x) <= rho + (d0 + rho) of the centre c
    const pointIndexHit near = tree_.findNearest(centre, GREAT);
    if (near.hit())
    {
        const treeBoundBox& bb = tree_.bb();
        const scalar reach =
            (mag(centre - near.hitPoint()) + 2*rho)*(1 + widen)
          + widen*(mag(bb.min()) + mag(bb.max()) + 1);
        labelList within = tree_.findSphere(centre, sqr(reach));
        std::sort(within.begin(), within.end());
        faces_.insert(faces_.end(), within.begin(), within.end());
    }
    start_.push_back(label(faces_.size()));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::triSurfaceNearest::triSurfaceNearest
(
    const triSurface& surf,
    const octree& tree,
    const label maxBoxes
)
:
    surf_(surf),
    tree_(tree),
    tieDistance_(1e-12*(mag(tree.bb().min()) + mag(tree.bb().max()) + 1)),
    leaves_(tree.contents().size(), leafBoxes{point::zero, vector::zero, 0, 0}),
    start_(1, 0)
{
    const List<octree::node>& nodes = tree.nodes();
    if (tree.nodeTypes().size() != 8*nodes.size())
    {
        FatalErrorInFunction
            << "the octree's octant types are not built (call its"
            << " getVolumeType once first)" << abort(FatalError);
    }
    if (nodes.empty() || hasSliver())
    {
        // (Every leaf without boxes: the octree answers)
        return;
    }

    // Boxes of about 1/256 of the surface's extent, fewer where there would
    // be more than maxBoxes in all (one per leaf at the least)
    const auto perAxis = [](const treeBoundBox& box, const scalar target)
    {
        const scalar n = std::ceil(cmptMax(box.span())/target);
        return label(std::min(std::max(n, scalar(1)), scalar(maxPerAxis)));
    };
    const auto nBoxes = [&](const scalar target)
    {
        label total = 0;
        for (const octree::node& nod : nodes)
        {
            for (direction octant = 0; octant < 8; ++octant)
            {
                if (octree::isContent(nod.subNodes_[octant]))
                {
                    const label k = perAxis(nod.bb_.subBbox(octant), target);
                    total += k*k*k;
                }
            }
        }
        return total;
    };
    const scalar extent = cmptMax(tree.bb().span());
    scalar target = extent/256;
    while (target < extent && nBoxes(target) > maxBoxes)
    {
        target *= 1.25;
    }

    for (const octree::node& nod : nodes)
    {
        for (direction octant = 0; octant < 8; ++octant)
        {
            const labelBits index = nod.subNodes_[octant];
            if (!octree::isContent(index))
            {
                continue;
            }
            const treeBoundBox box = nod.bb_.subBbox(octant);
            leafBoxes& l = leaves_[octree::getContent(index)];
            l.k = perAxis(box, target);
            l.lo = box.min();
            l.size = box.span()/scalar(l.k);
            l.first = label(start_.size()) - 1;
            const scalar rho = 0.5*mag(l.size)*(1 + widen);
            for (label c = 0; c < l.k; ++c)
            {
                for (label b = 0; b < l.k; ++b)
                {
                    for (label a = 0; a < l.k; ++a)
                    {
                        const vector at(a + 0.5, b + 0.5, c + 0.5);
                        addCandidates(l.lo + cmptMultiply(at, l.size), rho);
                    }
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pointIndexHit Foam::triSurfaceNearest::nearest(const point& p) const
{
    return hitOf(p, query(p));
}


bool Foam::triSurfaceNearest::inside(const point& p) const
{
    return side(p, query(p));
}


Foam::pointIndexHit Foam::triSurfaceNearest::nearest
(
    const point& p,
    bool& inside
) const
{
    const answer a = query(p);
    inside = side(p, a);
    return hitOf(p, a);
}


bool Foam::triSurfaceNearest::fromLists(const point& p) const
{
    return query(p).facei >= 0;
}


Foam::scalar Foam::triSurfaceNearest::meanCandidates() const
{
    return scalar(faces_.size())/max(label(start_.size()) - 1, label(1));
}


// ************************************************************************* //
