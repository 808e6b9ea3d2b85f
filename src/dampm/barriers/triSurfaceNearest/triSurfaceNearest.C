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
    //- Boxes per axis of a leaf at most, and in all at most
    constexpr Foam::label maxPerAxis = 16;
    constexpr Foam::label maxBoxes = 1 << 17;

    //- Relative widening of a box's candidate radius (rounding: the lists
    //  hold more triangles, never fewer)
    constexpr Foam::scalar widen = 1e-6;

    //- How far beyond its leaf's box (in boxes) a point is taken as in it
    //  (rounding at the box's faces; far within the widened radius)
    constexpr Foam::scalar beyond = 1e-9;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::triSurfaceNearest::leafOf(const point& p) const
{
    const List<octree::node>& nodes = tree_.nodes();
    label nodeI = 0;
    while (!nodes.empty())
    {
        const octree::node& nod = nodes[nodeI];
        const labelBits index = nod.subNodes_[nod.bb_.subOctant(p)];
        if (!octree::isNode(index))
        {
            return octree::isContent(index) ? octree::getContent(index) : -1;
        }
        nodeI = octree::getNode(index);
    }
    return -1;
}


Foam::label Foam::triSurfaceNearest::nearestCandidate
(
    const label leaf,
    const point& p,
    pointHit& hit,
    label& nearType
) const
{
    // The box of the leaf holding p (a point beyond the leaf's box, which
    // the octree's descent gives for a point outside its own: none)
    const leafBoxes& l = leaves_[leaf];
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

    // The smallest distance, as the octree computes it (findNearestOp)
    const pointField& points = surf_.points();
    scalar best = VGREAT;
    label facei = -1;
    bool tie = false;
    for (label j = start_[box]; j < start_[box + 1]; ++j)
    {
        const label f = faces_[j];
        label type = -1, edge = -1;
        const pointHit h = surf_[f].nearestPointClassify(p, points, type, edge);
        const scalar d2 = sqr(h.distance());
        if (d2 < best)
        {
            best = d2;
            facei = f;
            hit = h;
            nearType = type;
            tie = false;
        }
        else if (d2 == best)
        {
            tie = true;
        }
    }
    return tie ? -1 : facei;
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
    const octree& tree
)
:
    surf_(surf),
    tree_(tree),
    leaves_(tree.contents().size(), leafBoxes{point::zero, vector::zero, 0, 0}),
    start_(1, 0)
{
    const List<octree::node>& nodes = tree.nodes();
    if (nodes.empty())
    {
        return;
    }

    // Boxes of about 1/256 of the surface's extent, fewer where there would
    // be more than maxBoxes in all
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
    scalar target = cmptMax(tree.bb().span())/256;
    while (nBoxes(target) > maxBoxes)
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
    const label leaf = leafOf(p);
    if (leaf >= 0)
    {
        pointHit hit;
        label nearType = -1;
        const label facei = nearestCandidate(leaf, p, hit, nearType);
        if (facei >= 0)
        {
            return pointIndexHit(true, hit.rawPoint(), facei);
        }
    }
    return tree_.findNearest(p, GREAT);
}


bool Foam::triSurfaceNearest::inside(const point& p) const
{
    // triSurfaceSearch::calcInside: outside the octree's box, outside;
    // else indexedOctree::getVolumeType, its octants' types down to a leaf
    const List<octree::node>& nodes = tree_.nodes();
    if (!tree_.bb().contains(p) || nodes.empty())
    {
        return false;
    }
    label nodeI = 0;
    for (;;)
    {
        const octree::node& nod = nodes[nodeI];
        const direction octant = nod.bb_.subOctant(p);
        const volumeType type =
            volumeType::type(tree_.nodeTypes().get((nodeI << 3) + octant));
        if (type != volumeType::MIXED)
        {
            return type == volumeType::INSIDE;
        }
        const labelBits index = nod.subNodes_[octant];
        if (octree::isNode(index))
        {
            nodeI = octree::getNode(index);
            continue;
        }
        pointHit hit;
        label nearType = -1;
        const label facei =
            octree::isContent(index)
          ? nearestCandidate(octree::getContent(index), p, hit, nearType)
          : -1;
        if (facei < 0)
        {
            return tree_.getVolumeType(p) == volumeType::INSIDE;
        }
        // treeDataPrimitivePatch<triSurface>::getVolumeType: the side of
        // the nearest triangle (triSurfaceTools::surfaceSide; by the face's
        // normal where the nearest point is inside the triangle)
        if (nearType == triPointRef::NONE)
        {
            return !(((p - hit.rawPoint()) & surf_.faceNormals()[facei]) > 0);
        }
        return
            triSurfaceTools::surfaceSide(surf_, p, facei)
         == triSurfaceTools::INSIDE;
    }
}


Foam::scalar Foam::triSurfaceNearest::meanCandidates() const
{
    return scalar(faces_.size())/max(label(start_.size()) - 1, label(1));
}


// ************************************************************************* //
