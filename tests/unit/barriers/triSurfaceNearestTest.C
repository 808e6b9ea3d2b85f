/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    triSurfaceNearest gives the octree's answers bit for bit: the nearest
    triangle and point of indexedOctree::findNearest(p, GREAT) and the
    inside test of triSurfaceSearch::calcInside. Two closed surfaces: a
    sphere of 1,280 triangles (subdivided icosahedron: every point near a
    vertex or an edge) and an L-shaped prism of 20 (concave edges, where
    two faces are equally near); most answers from the lists, not the
    octree. With fewer boxes allowed than leaves, one a leaf; on a surface
    with a sliver (a prism over a needle), the octree's answers alone. The points: uniform in and around the
    surface's box; near random points of the triangles, offset by 1e-12
    to 1e-2 along and across; on vertices, edge midpoints and centroids,
    exactly and offset by 1e-9; beyond the octree's box; NaN. Its lists
    must be short: fewer than a tenth of the sphere's triangles a box.

\*---------------------------------------------------------------------------*/

#include "triSurfaceNearest.H"
#include "triSurfaceSearch.H"
#include "sameBits.H"
#include <gtest/gtest.h>
#include <cmath>
#include <map>
#include <random>

using namespace Foam;

namespace
{

//- The sphere of radius r about c: an icosahedron, each triangle cut into
//  four n times, its points on the sphere
triSurface sphere(const point& c, const scalar r, const int n)
{
    const scalar t = 0.5*(1 + std::sqrt(5.0));
    DynamicList<point> pts
    ({
        {-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
        {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
        {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}
    });
    List<FixedList<label, 3>> tris
    ({
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
        {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
        {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}
    });
    for (int level = 0; level < n; ++level)
    {
        std::map<std::pair<label, label>, label> mid;
        const auto middle = [&](const label a, const label b)
        {
            const auto key = std::make_pair(min(a, b), max(a, b));
            const auto found = mid.find(key);
            if (found != mid.end())
            {
                return found->second;
            }
            pts.append(0.5*(pts[a] + pts[b]));
            return mid[key] = pts.size() - 1;
        };
        List<FixedList<label, 3>> finer(4*tris.size());
        forAll(tris, i)
        {
            const auto& f = tris[i];
            const label ab = middle(f[0], f[1]);
            const label bc = middle(f[1], f[2]);
            const label ca = middle(f[2], f[0]);
            finer[4*i] = {f[0], ab, ca};
            finer[4*i + 1] = {ab, f[1], bc};
            finer[4*i + 2] = {ca, bc, f[2]};
            finer[4*i + 3] = {ab, bc, ca};
        }
        tris.transfer(finer);
    }
    pointField points(pts);
    for (point& p : points)
    {
        p = c + r*p/mag(p);
    }
    List<labelledTri> faces(tris.size());
    forAll(tris, i)
    {
        faces[i] = labelledTri(tris[i][0], tris[i][1], tris[i][2], 0);
    }
    return triSurface(faces, geometricSurfacePatchList(), points);
}


//- The prism from z = 0 to 1 over the polygon xy (counter-clockwise),
//  its caps fanned from the first point (a convex part of it)
triSurface prism(const List<FixedList<scalar, 2>>& xy)
{
    const label n = xy.size();
    pointField points(2*n);
    for (label i = 0; i < n; ++i)
    {
        points[i] = point(xy[i][0], xy[i][1], 0);
        points[i + n] = point(xy[i][0], xy[i][1], 1);
    }
    DynamicList<labelledTri> faces;
    for (label i = 0; i < n; ++i)
    {
        const label j = (i + 1) % n;
        faces.append(labelledTri(i, j, j + n, 0));
        faces.append(labelledTri(i, j + n, i + n, 0));
    }
    for (label i = 1; i + 1 < n; ++i)
    {
        faces.append(labelledTri(0, i + 1, i, 0));
        faces.append(labelledTri(n, i + n, i + 1 + n, 0));
    }
    return triSurface(faces, geometricSurfacePatchList(), points);
}


//- The L of (0 0) (2 0) (2 1) (1 1) (1 2) (0 2), from z = 0 to 1 (its
//  caps fanned from (0 0): the L is convex as seen from there)
triSurface lPrism()
{
    return prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
}


//- The sample points around a surface
pointField samples(const triSurface& surf, std::mt19937& gen)
{
    const boundBox bb(surf.points());
    const vector span = bb.span();
    std::uniform_real_distribution<scalar> u(0, 1);
    DynamicList<point> pts;
    for (int i = 0; i < 20000; ++i)
    {
        const vector s(u(gen), u(gen), u(gen));
        pts.append(bb.min() - 0.2*span + cmptMultiply(s, 1.4*span));
    }
    const pointField& P = surf.points();
    std::uniform_int_distribution<label> face(0, surf.size() - 1);
    for (int i = 0; i < 40000; ++i)
    {
        const triPointRef t = surf[face(gen)].tri(P);
        scalar a = u(gen), b = u(gen);
        if (a + b > 1)
        {
            a = 1 - a;
            b = 1 - b;
        }
        const point on = t.a() + a*(t.b() - t.a()) + b*(t.c() - t.a());
        const scalar size = std::pow(10.0, -12 + 10*u(gen))*cmptMax(span);
        const vector dir(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
        pts.append(on + size*dir/mag(dir));
    }
    for (const labelledTri& f : surf)
    {
        const triPointRef t = f.tri(P);
        for (const point& x : {t.a(), 0.5*(t.a() + t.b()), t.centre()})
        {
            pts.append(x);
            pts.append(x + 1e-9*vector(1, -1, 1));
            pts.append(x - 1e-9*vector(1, 1, -1));
        }
    }
    pts.append(bb.max() + span);
    pts.append(point::uniform(std::nan("")));
    return pointField(pts);
}



//- The octree's answers and the lists' at the samples: how many differ
//  (failing the test at the first few) and how many the lists answered
void compare
(
    const triSurface& surf,
    const label maxBoxes,
    std::mt19937& gen,
    label& nFromLists,
    label& nSamples
)
{
    const triSurfaceSearch search(surf);
    const auto& tree = search.tree();
    tree.getVolumeType(tree.bb().centre());
    surf.faceNormals();
    surf.edgeFaces();
    surf.pointEdges();
    const triSurfaceNearest fast(surf, tree, maxBoxes);
    if (surf.size() > 100)
    {
        EXPECT_LT(fast.meanCandidates(), 0.1*surf.size());
    }

    const pointField pts(samples(surf, gen));
    const boolList in(search.calcInside(pts));
    label nIn = 0, differ = 0;
    nFromLists = 0;
    nSamples = pts.size();
    forAll(pts, i)
    {
        const pointIndexHit a = tree.findNearest(pts[i], GREAT);
        bool both = false;
        const pointIndexHit b = fast.nearest(pts[i], both);
        const pointIndexHit c = fast.nearest(pts[i]);
        const bool same =
            a.hit() == b.hit() && a.index() == b.index()
         && b.hit() == c.hit() && b.index() == c.index()
         && sameBits(a.rawPoint().x(), b.rawPoint().x())
         && sameBits(a.rawPoint().y(), b.rawPoint().y())
         && sameBits(a.rawPoint().z(), b.rawPoint().z())
         && in[i] == fast.inside(pts[i]) && in[i] == both;
        differ += !same;
        nIn += in[i];
        nFromLists += fast.fromLists(pts[i]);
        EXPECT_TRUE(same)
            << "(" << pts[i].x() << " " << pts[i].y() << " " << pts[i].z()
            << "): faces " << a.index() << " and " << b.index();
        if (differ > 5)
        {
            break;
        }
    }
    EXPECT_EQ(differ, 0) << surf.size() << " triangles";
    // Both sides are sampled
    EXPECT_GT(nIn, pts.size()/10);
    EXPECT_LT(nIn, pts.size() - pts.size()/10);
}

} // End anonymous namespace


TEST(triSurfaceNearest, TheOctreesNearestTriangleAndInsideTestBitForBit)
{
    std::mt19937 gen(7);
    label nFromLists = 0, n = 0;
    compare(sphere(point(1, 2, 3), 0.5, 3), 1 << 17, gen, nFromLists, n);
    // Most points answered by the lists (70 % and 73 %; the others beyond
    // the octree's box, a third of the uniform samples, or on an edge or a
    // vertex, where two triangles tie)
    EXPECT_GT(nFromLists, 0.6*n) << nFromLists << " of " << n;
    compare(lPrism(), 1 << 17, gen, nFromLists, n);
    EXPECT_GT(nFromLists, 0.6*n) << nFromLists << " of " << n;
}


TEST(triSurfaceNearest, OneBoxPerLeafAtTheLeastAndTheOctreeBySlivers)
{
    std::mt19937 gen(11);
    label nFromLists = 0, n = 0;

    // Fewer boxes allowed than the octree has leaves: one box a leaf
    compare(sphere(point(1, 2, 3), 0.5, 3), 1, gen, nFromLists, n);
    EXPECT_GT(nFromLists, 0);

    // A needle of a cross-section (angle 1e-5 at a corner, its caps
    // slivers): no lists, every answer the octree's
    compare(prism({{0, 0}, {1, 0}, {1, 1e-5}}), 1 << 17, gen, nFromLists, n);
    EXPECT_EQ(nFromLists, 0);
}


// ************************************************************************* //
