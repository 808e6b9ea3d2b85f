/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "particleGuard.H"
#include "DynamicField.H"
#include <algorithm>
#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The largest float not above x: a lower bound kept in single precision
inline float floatBelow(const double x)
{
    const float f = float(x);
    return double(f) > x
        ? std::nextafter(f, -std::numeric_limits<float>::max())
        : f;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleGuard::particleGuard
(
    const barrierGeometry& geometry,
    const contactCondition& condition
)
:
    geometry_(geometry),
    condition_(condition),
    nearLo_{0, 0, 0},
    nearHi_{-1, -1, -1},
    nearCellDistance_(0),
    clearance_(0),
    reached_(true),
    nTested_(0),
    guardDepth_(0),
    force_(Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleGuard::startSearch
(
    const gridGeometry& g,
    const scalar band
)
{
    // A cell that holds a point of the barrier has every corner node within
    // a cell diagonal of it (margin: terrain's distance is approximate)
    scalar diagonal2 = 0;
    for (int d = 0; d < 3; ++d)
    {
        diagonal2 += g.varies(d) ? sqr(g.dx[d]) : 0;
    }
    nearCellDistance_ = 1.25*std::sqrt(diagonal2);
    nearCell_.assign(g.nCellsTotal(), 0);
    for (int d = 0; d < 3; ++d)
    {
        nearLo_[d] = g.nCells[d];
        nearHi_[d] = -1;
    }
    guardDepth_ = geometry_.guardDepthCells()*g.hMin();
    // The screen's clearance phi + guardDepth - margin; the margin covers
    // the rounding of the distances, which grows with the coordinates
    // (1e-10 m at 1e6 m). Nodes not visited are farther than the band from
    // the barrier: the band bounds their distance from below
    clearance_ = guardDepth_ - 1e-6*g.hMin();
    nodeClearance_.clear();
    columnClearance_.clear();
    // (3D grids: the screen takes the eight corners of a cell, or a column
    // of cells)
    if (geometry_.exactDistance() && g.dim == 3)
    {
        nodeClearance_.assign(g.nNodes(), floatBelow(band + clearance_));
    }
    else if (g.dim == 3)
    {
        geometry_.columnTops(g, columnClearance_);
        for (double& h : columnClearance_)
        {
            // Less the guard's depth and clearance_'s margin; the rounding
            // of z - h (z near h) too
            h += 1e-12*std::abs(h) - clearance_;
        }
    }
}


void Foam::particleGuard::addNode
(
    const gridGeometry& g,
    const gridGeometry::index n,
    const scalar phi
)
{
    if (!nodeClearance_.empty())
    {
        nodeClearance_[n] = floatBelow(phi + clearance_);
    }
    if (phi > nearCellDistance_)
    {
        return;
    }
    // The (up to) eight cells around the node
    gridGeometry::index ijk[3];
    g.nodeIJK(n, ijk);
    for (int c = 0; c < 8; ++c)
    {
        const gridGeometry::index ci = ijk[0] - 1 + (c & 1);
        const gridGeometry::index cj = ijk[1] - 1 + ((c >> 1) & 1);
        const gridGeometry::index ck = ijk[2] - 1 + ((c >> 2) & 1);
        if
        (
            ci >= 0 && ci < g.nCells[0]
         && cj >= 0 && cj < g.nCells[1]
         && ck >= 0 && ck < g.nCells[2]
        )
        {
            nearCell_[g.cellIndex(ci, cj, ck)] = 1;
            const gridGeometry::index cell[3] = {ci, cj, ck};
            for (int d = 0; d < 3; ++d)
            {
                nearLo_[d] = min(nearLo_[d], cell[d]);
                nearHi_[d] = max(nearHi_[d], cell[d]);
            }
        }
    }
}


void Foam::particleGuard::insideBeyondDepth
(
    const pointField& points,
    boolList& in
) const
{
    if (guardDepth_ > 0)
    {
        geometry_.deeperThan(points, guardDepth_, in);
    }
    else
    {
        geometry_.inside(points, in);
    }
}


void Foam::particleGuard::guardInside
(
    const pointField& points,
    boolList& in
) const
{
    // In chunks, on all threads where the geometry allows: a bisection in
    // stopEntries queries each entered particle 30 times
    constexpr label chunk = 1024;
    const label n = points.size();
    const label nChunks = (n + chunk - 1)/chunk;
    if (nChunks <= 1 || !geometry_.threadSafeDistance())
    {
        insideBeyondDepth(points, in);
        return;
    }
    in.setSize(n);
    #pragma omp parallel for schedule(dynamic)
    for (label c = 0; c < nChunks; ++c)
    {
        const label first = c*chunk;
        const label size = min(chunk, n - first);
        boolList partIn;
        insideBeyondDepth
        (
            pointField(SubList<point>(points, size, first)), partIn
        );
        SubList<bool>(in, size, first) = partIn;
    }
}


inline bool Foam::particleGuard::mayBeDeep
(
    const gridGeometry& g,
    const double x,
    const double y,
    const double z
) const
{
    // A position off the grid's columns, or not finite, has no column or
    // cell: the exact test answers
    if (!columnClearance_.empty())
    {
        // Not deeper where at least its column's clearing height
        gridGeometry::index i, j;
        return
            !g.columnOf(x, y, i, j)
         || !(z >= columnClearance_[i + g.nCells[0]*j]);
    }
    if (nodeClearance_.empty() || !std::isfinite(x + y + z))
    {
        return true;
    }
    // Each corner n of the point's cell bounds phi >= phi_n - r_n: the
    // point is not deeper than the guard's depth where one corner's
    // clearance phi_n + guardDepth (less the margin) is at least r_n. The
    // best of the eight corners, not only the nearest: a particle lying
    // against a face is often too far from its nearest corner to be
    // cleared by it, but near enough to another corner on its side
    const double xyz[3] = {x, y, z};
    gridGeometry::index ijk[3];
    double r2[3][2];
    for (int d = 0; d < 3; ++d)
    {
        // (Clamped into the grid: any node's bound holds)
        ijk[d] = g.cellDir(d, xyz[d]);
        r2[d][0] = sqr(xyz[d] - g.nodeCoord(d, ijk[d]));
        r2[d][1] = sqr(xyz[d] - g.nodeCoord(d, ijk[d] + 1));
    }
    for (int c = 0; c < 8; ++c)
    {
        const int a = c & 1, b = (c >> 1) & 1, e = (c >> 2) & 1;
        const float clear =
            nodeClearance_[g.nodeIndex(ijk[0] + a, ijk[1] + b, ijk[2] + e)];
        // (a float squared is exact in double)
        if (clear >= 0 && double(clear)*clear >= r2[0][a] + r2[1][b] + r2[2][e])
        {
            return false;
        }
    }
    return true;
}


void Foam::particleGuard::markEntered
(
    const gridGeometry& g,
    const mpm3dParticles& p
)
{
    // In chunks: bounded scratch, and a virtual call per chunk, not per
    // particle. Only particles in a cell the barrier may occupy are tested;
    // each chunk keeps those inside, joined in storage order
    constexpr label chunk = 4096;
    const label n = p.n;
    const label nChunks = (n + chunk - 1)/chunk;
    List<DynamicList<label>> inside(nChunks);
    labelList tested(nChunks, Zero);
    #pragma omp parallel for schedule(dynamic) \
        if (geometry_.threadSafeDistance())
    for (label c = 0; c < nChunks; ++c)
    {
        const label first = c*chunk;
        const label last = std::min(n, first + chunk);
        // The cells first, in a loop of arithmetic alone (it vectorises),
        // then the lists, reserved: a terrain's chunks keep most particles
        gridGeometry::index cells[chunk];
        for (label i = first; i < last; ++i)
        {
            cells[i - first] = g.cellOf(p.x[0][i], p.x[1][i], p.x[2][i]);
        }
        DynamicList<label>& ids = inside[c];
        ids.setCapacity(last - first);
        DynamicField<point> pts(last - first);
        for (label i = first; i < last; ++i)
        {
            const double x = p.x[0][i], y = p.x[1][i], z = p.x[2][i];
            if (nearCell_[cells[i - first]] && mayBeDeep(g, x, y, z))
            {
                ids.append(i);
                pts.append(point(x, y, z));
            }
        }
        tested[c] = ids.size();
        if (ids.empty())
        {
            continue;
        }
        // (This loop is the parallel one: not guardInside's chunks)
        boolList in;
        insideBeyondDepth(pts, in);
        label m = 0;
        forAll(ids, k)
        {
            if (in[k])
            {
                ids[m++] = ids[k];
            }
        }
        ids.resize(m);
    }
    for (const DynamicList<label>& ids : inside)
    {
        candidates_.insert(candidates_.end(), ids.begin(), ids.end());
    }
    nTested_ = sum(tested);
}


void Foam::particleGuard::moveToEntries
(
    pointField& a,
    const pointField& b
) const
{
    constexpr int nHalvings = 30;
    const scalar margin = std::ldexp(1.0, -nHalvings);

    // Where the geometry finds the path entering (of the surface itself:
    // not with a guard depth), the point 2^-30 of the path before it, kept
    // when it tests outside; a itself when the entry is nearer (a tested
    // outside)
    scalarField fraction(a.size(), -1);
    if (!(guardDepth_ > 0))
    {
        geometry_.firstCrossings(a, b, fraction);
    }
    labelList atEntry(a.size());
    pointField justOutside(a.size());
    label nAt = 0;
    forAll(a, c)
    {
        if (fraction[c] > margin)
        {
            justOutside[nAt] = a[c] + (fraction[c] - margin)*(b[c] - a[c]);
            atEntry[nAt++] = c;
        }
    }
    atEntry.resize(nAt);
    justOutside.resize(nAt);
    boolList in;
    guardInside(justOutside, in);

    // The others are bisected between the start (outside) and the end, or
    // the point before the entry where rounding by an edge put it inside
    // (so the bisection stays on the part first entered)
    DynamicList<label> bisect(a.size());
    DynamicField<point> lo(a.size()), hi(a.size());
    label k = 0;
    forAll(a, c)
    {
        const bool at = k < nAt && atEntry[k] == c;
        if (at && !in[k])
        {
            a[c] = justOutside[k];
        }
        else if (at || fraction[c] < 0)
        {
            bisect.append(c);
            lo.append(a[c]);
            hi.append(at ? justOutside[k] : b[c]);
        }
        k += at;
    }

    // The bisection, to 2^-30 of the path
    const label nb = bisect.size();
    pointField mid(nb);
    for (int iter = 0; iter < nHalvings && nb; ++iter)
    {
        forAll(mid, j)
        {
            mid[j] = 0.5*(lo[j] + hi[j]);
        }
        guardInside(mid, in);
        forAll(mid, j)
        {
            (in[j] ? hi[j] : lo[j]) = mid[j];
        }
    }
    forAll(bisect, j)
    {
        a[bisect[j]] = lo[j];
    }
}


bool Foam::particleGuard::guardReach(const nodeBox& particleNodes)
{
    // The particles lie between the box's first and last nodes; the cells
    // they can reach, two cells further
    reached_ = !particleNodes.empty() && nearLo_[0] <= nearHi_[0];
    for (int d = 0; d < 3 && reached_; ++d)
    {
        const gridGeometry::index first =
            particleNodes.lo[d] - gridGeometry::nGhost - 2;
        const gridGeometry::index last =
            particleNodes.hi[d] - 1 - gridGeometry::nGhost + 2;
        reached_ = nearLo_[d] <= last && nearHi_[d] + 1 >= first;
    }
    return reached_;
}


Foam::label Foam::particleGuard::stopEntries
(
    const gridGeometry& g,
    const double* const x0[3],
    const mpm3dParticles& p,
    const double dt
)
{
    // Candidates: the particles that end the step inside the barrier
    // (beyond the guard's depth), then those of them that were outside at
    // the start
    candidates_.clear();
    nTested_ = 0;
    if (reached_)
    {
        markEntered(g, p);
    }
    label nc = label(candidates_.size());
    double F[3] = {0, 0, 0};
    pointField a, b;
    if (nc)
    {
        boolList in;
        a.setSize(nc);
        b.setSize(nc);
        forAll(a, c)
        {
            const label i = candidates_[c];
            a[c] = point(x0[0][i], x0[1][i], x0[2][i]);
            b[c] = point(p.x[0][i], p.x[1][i], p.x[2][i]);
        }
        guardInside(a, in);
        label m = 0;
        forAll(a, c)
        {
            if (!in[c])
            {
                candidates_[m] = candidates_[c];
                a[m] = a[c];
                b[m] = b[c];
                ++m;
            }
        }
        nc = m;
        candidates_.resize(nc);
        a.setSize(nc);
        b.setSize(nc);
    }
    if (nc)
    {
        // Where each path entered (a: just outside it; b: the end)
        moveToEntries(a, b);
        boolList in;

        // The entered face's normal, at the point just outside it; the end
        // point projected on that face's tangent plane keeps the motion
        // along the face (exact on plane faces)
        scalarField phi;
        vectorField normal;
        geometry_.distance(a, phi, normal);
        if (g.plane)
        {
            barrierGeometry::planeNormals(normal);
        }
        pointField onFace(nc);
        forAll(onFace, c)
        {
            onFace[c] = b[c] + ((a[c] - b[c]) & normal[c])*normal[c];
        }
        guardInside(onFace, in);

        // In storage order: the same force on any number of threads
        forAll(onFace, c)
        {
            const label i = candidates_[c];
            const point& x = in[c] ? a[c] : onFace[c];
            double v[3] = {p.u[0][i], p.u[1][i], p.u[2][i]};
            const double nrm[3] = {normal[c].x(), normal[c].y(), normal[c].z()};
            const double vn = v[0]*nrm[0] + v[1]*nrm[1] + v[2]*nrm[2];
            if (vn < 0)
            {
                condition_.apply(nrm, vn, v);
            }
            const double k = p.m[i]/dt;
            for (int d = 0; d < 3; ++d)
            {
                F[d] += k*(p.u[d][i] - v[d]);
                p.u[d][i] = v[d];
                p.x[d][i] = x[d];
            }
        }
    }

    // Until the next guardReach, check every particle (fail safe)
    reached_ = true;

    force_ = vector(F[0], F[1], F[2]);
    return nc;
}


// ************************************************************************* //
