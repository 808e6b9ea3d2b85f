/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneSurface.H"
#include <algorithm>
#include <cmath>
#include <utility>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

inline double dot3(const double a[3], const double b[3])
{
    return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

// Barycentric weights of the point of triangle (a, b, c) nearest to p, by
// its Voronoi regions: vertex, edge or face
void nearestWeights
(
    const double a[3],
    const double b[3],
    const double c[3],
    const double p[3],
    double w[3]
)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    for (int d = 0; d < 3; ++d)
    {
        ab[d] = b[d] - a[d];
        ac[d] = c[d] - a[d];
        ap[d] = p[d] - a[d];
        bp[d] = p[d] - b[d];
        cp[d] = p[d] - c[d];
    }
    auto set = [&](const double wa, const double wb, const double wc)
    {
        w[0] = wa;
        w[1] = wb;
        w[2] = wc;
    };
    const double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
    if (d1 <= 0 && d2 <= 0)
    {
        return set(1, 0, 0);
    }
    const double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    if (d3 >= 0 && d4 <= d3)
    {
        return set(0, 1, 0);
    }
    const double vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        const double t = d1/(d1 - d3);
        return set(1 - t, t, 0);
    }
    const double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    if (d6 >= 0 && d5 <= d6)
    {
        return set(0, 0, 1);
    }
    const double vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        const double t = d2/(d2 - d6);
        return set(1 - t, 0, t);
    }
    const double va = d3*d6 - d5*d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    {
        const double t = (d4 - d3)/((d4 - d3) + (d5 - d6));
        return set(0, 1 - t, t);
    }
    const double s = 1/(va + vb + vc);
    set(va*s, vb*s, vc*s);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::membraneSurface::build(const gridGeometry& g)
{
    const structureNodes& n = nodes_;
    const double r = reach_ + slack_;
    const label nTri = label(triangles_.size()/3);

    // (cell, triangle) of the cells each triangle's box, grown by r, spans
    std::vector<std::pair<gridGeometry::index, label>> pairs;
    for (int d = 0; d < 3; ++d)
    {
        bucketLo_[d] = 1e300;
        bucketHi_[d] = -1e300;
    }
    for (label t = 0; t < nTri; ++t)
    {
        gridGeometry::index lo[3], hi[3];
        for (int d = 0; d < 3; ++d)
        {
            const std::vector<double>& x = d == 0 ? n.x : (d == 1 ? n.y : n.z);
            double a = x[node(t, 0)], b = a;
            for (int k = 1; k < 3; ++k)
            {
                a = std::min(a, x[node(t, k)]);
                b = std::max(b, x[node(t, k)]);
            }
            lo[d] = g.cellDir(d, a - r);
            hi[d] = g.cellDir(d, b + r);
            bucketLo_[d] = std::min(bucketLo_[d], g.nodeCoord(d, lo[d]));
            bucketHi_[d] = std::max(bucketHi_[d], g.nodeCoord(d, hi[d] + 1));
        }
        for (gridGeometry::index k = lo[2]; k <= hi[2]; ++k)
        {
            for (gridGeometry::index j = lo[1]; j <= hi[1]; ++j)
            {
                for (gridGeometry::index i = lo[0]; i <= hi[0]; ++i)
                {
                    pairs.emplace_back(g.cellIndex(i, j, k), t);
                }
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());

    for (const gridGeometry::index c : cells_)
    {
        inBucket_[c] = 0;
    }
    inBucket_.resize(g.nCellsTotal(), 0);
    cells_.clear();
    start_.clear();
    tri_.resize(pairs.size());
    for (size_t k = 0; k < pairs.size(); ++k)
    {
        if (cells_.empty() || cells_.back() != pairs[k].first)
        {
            cells_.push_back(pairs[k].first);
            start_.push_back(label(k));
            inBucket_[pairs[k].first] = 1;
        }
        tri_[k] = pairs[k].second;
    }
    start_.push_back(label(pairs.size()));

    builtAt_[0] = n.x;
    builtAt_[1] = n.y;
    builtAt_[2] = n.z;
}


void Foam::membraneSurface::setSpheres()
{
    const structureNodes& n = nodes_;
    const label nTri = label(triangles_.size()/3);
    radius_.resize(nTri);
    for (int d = 0; d < 3; ++d)
    {
        centre_[d].resize(nTri);
        normal_[d].resize(nTri);
    }
    for (label t = 0; t < nTri; ++t)
    {
        double v[3][3];
        for (int k = 0; k < 3; ++k)
        {
            const label i = node(t, k);
            v[k][0] = n.x[i];
            v[k][1] = n.y[i];
            v[k][2] = n.z[i];
        }
        double c[3], r2 = 0;
        for (int d = 0; d < 3; ++d)
        {
            c[d] = (v[0][d] + v[1][d] + v[2][d])/3;
            centre_[d][t] = c[d];
        }
        for (int k = 0; k < 3; ++k)
        {
            const double e[3] =
                {v[k][0] - c[0], v[k][1] - c[1], v[k][2] - c[2]};
            r2 = std::max(r2, dot3(e, e));
        }
        radius_[t] = std::sqrt(r2);
        const double ab[3] =
            {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
        const double ac[3] =
            {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
        const double nrm[3] =
        {
            ab[1]*ac[2] - ab[2]*ac[1],
            ab[2]*ac[0] - ab[0]*ac[2],
            ab[0]*ac[1] - ab[1]*ac[0]
        };
        const double s = 1/std::sqrt(dot3(nrm, nrm));
        for (int d = 0; d < 3; ++d)
        {
            normal_[d][t] = s*nrm[d];
        }
    }
}


bool Foam::membraneSurface::moved() const
{
    const structureNodes& n = nodes_;
    const double limit2 = 0.25*slack_*slack_;
    for (label i = 0; i < n.size(); ++i)
    {
        const double d[3] =
        {
            n.x[i] - builtAt_[0][i],
            n.y[i] - builtAt_[1][i],
            n.z[i] - builtAt_[2][i]
        };
        if (dot3(d, d) > limit2)
        {
            return true;
        }
    }
    return false;
}


void Foam::membraneSurface::nearestOn
(
    const label t,
    const double p[3],
    nearPoint& q
) const
{
    const structureNodes& n = nodes_;
    double v[3][3];
    for (int k = 0; k < 3; ++k)
    {
        const label i = node(t, k);
        v[k][0] = n.x[i];
        v[k][1] = n.y[i];
        v[k][2] = n.z[i];
    }
    nearestWeights(v[0], v[1], v[2], p, q.w);

    double ab[3], ac[3], gap[3];
    for (int d = 0; d < 3; ++d)
    {
        ab[d] = v[1][d] - v[0][d];
        ac[d] = v[2][d] - v[0][d];
        gap[d] = p[d] - (q.w[0]*v[0][d] + q.w[1]*v[1][d] + q.w[2]*v[2][d]);
    }
    double nrm[3] =
    {
        ab[1]*ac[2] - ab[2]*ac[1],
        ab[2]*ac[0] - ab[0]*ac[2],
        ab[0]*ac[1] - ab[1]*ac[0]
    };
    const double s = 1/std::sqrt(dot3(nrm, nrm));
    for (int d = 0; d < 3; ++d)
    {
        q.n[d] = s*nrm[d];
    }
    q.tri = t;
    q.phi = dot3(gap, q.n);
    q.lateral2 = std::max(dot3(gap, gap) - q.phi*q.phi, 0.0);
}


int Foam::membraneSurface::shares
(
    const nearPoint& q,
    label nodei[6],
    double w[6]
) const
{
    if (nodes_.twin.empty())
    {
        for (int k = 0; k < 3; ++k)
        {
            nodei[k] = node(q.tri, k);
            w[k] = q.w[k];
        }
        return 3;
    }
    // Twins move together: a pair takes the weights of both
    int n = 0;
    auto add = [&](const label i, const double wi)
    {
        for (int k = 0; k < n; ++k)
        {
            if (nodei[k] == i)
            {
                w[k] += wi;
                return;
            }
        }
        nodei[n] = i;
        w[n++] = wi;
    };
    for (int k = 0; k < 3; ++k)
    {
        const label i = node(q.tri, k);
        add(i, 0.5*q.w[k]);
        add(nodes_.twin[i], 0.5*q.w[k]);
    }
    return n;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneSurface::membraneSurface
(
    structureNodes& nodes,
    const std::vector<label>& triangles
)
:
    nodes_(nodes),
    triangles_(triangles),
    reach_(-1),
    slack_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::membraneSurface::update
(
    const gridGeometry& g,
    const double reach,
    const double slack
)
{
    if (reach != reach_ || slack != slack_ || moved())
    {
        reach_ = reach;
        slack_ = slack;
        build(g);
    }
    setSpheres();
}


bool Foam::membraneSurface::nearest
(
    const gridGeometry& g,
    const double x[3],
    nearPoint& q
) const
{
    // A plane slice's point on its face y0, as its nodes (the bucket's
    // cells are one across)
    const double p[3] = {x[0], g.plane ? g.origin[1] : x[1], x[2]};
    const gridGeometry::index c = g.cellOf(p[0], p[1], p[2]);
    const auto it = std::lower_bound(cells_.begin(), cells_.end(), c);
    q.tri = -1;
    if (it == cells_.end() || *it != c)
    {
        return false;
    }
    const size_t b = it - cells_.begin();
    // No point of a triangle is nearer than its sphere or its plane: the
    // candidate with the nearest centroid first, then only those whose
    // spheres and planes come nearer than the best so far (squared
    // distances: no root per candidate)
    auto centreDist2 = [&](const label t)
    {
        const double e[3] =
        {
            p[0] - centre_[0][t], p[1] - centre_[1][t], p[2] - centre_[2][t]
        };
        return dot3(e, e);
    };
    label first = start_[b];
    double firstDist2 = centreDist2(tri_[first]);
    for (label k = start_[b] + 1; k < start_[b + 1]; ++k)
    {
        const double d2 = centreDist2(tri_[k]);
        if (d2 < firstDist2)
        {
            first = k;
            firstDist2 = d2;
        }
    }
    nearestOn(tri_[first], p, q);
    double best = std::sqrt(q.phi*q.phi + q.lateral2);
    nearPoint trial;
    for (label k = start_[b]; k < start_[b + 1]; ++k)
    {
        const label t = tri_[k];
        const double reach = best + radius_[t];
        if (k == first || centreDist2(t) >= reach*reach)
        {
            continue;
        }
        // Nor nearer than its plane
        const double e[3] =
        {
            p[0] - centre_[0][t], p[1] - centre_[1][t], p[2] - centre_[2][t]
        };
        const double toPlane =
            e[0]*normal_[0][t] + e[1]*normal_[1][t] + e[2]*normal_[2][t];
        if (std::abs(toPlane) >= best)
        {
            continue;
        }
        nearestOn(t, p, trial);
        const double d = std::sqrt(trial.phi*trial.phi + trial.lateral2);
        if (d < best)
        {
            best = d;
            q = trial;
        }
    }
    return true;
}


double Foam::membraneSurface::inverseMass(const nearPoint& q) const
{
    label nodei[6];
    double w[6];
    const int n = shares(q, nodei, w);
    double inv = 0;
    for (int k = 0; k < n; ++k)
    {
        const label i = nodei[k];
        if (!nodes_.fixed[i])
        {
            inv += w[k]*w[k]/nodes_.mass[i];
        }
    }
    return inv;
}


void Foam::membraneSurface::kick
(
    const nearPoint& q,
    const double J[3],
    std::vector<double> anchored[3]
)
{
    structureNodes& n = nodes_;
    isKicked_.resize(n.size(), 0);
    label nodei[6];
    double w[6];
    const int nShares = shares(q, nodei, w);
    for (int k = 0; k < nShares; ++k)
    {
        const label i = nodei[k];
        const double Jk[3] = {w[k]*J[0], w[k]*J[1], w[k]*J[2]};
        if (n.fixed[i])
        {
            for (int d = 0; d < 3; ++d)
            {
                anchored[d][i] += Jk[d];
            }
            continue;
        }
        double* v[3] = {&n.vx[i], &n.vy[i], &n.vz[i]};
        if (!isKicked_[i])
        {
            isKicked_[i] = 1;
            kicked_.push_back(i);
            for (int d = 0; d < 3; ++d)
            {
                vBefore_[d].resize(n.size());
                impulse_[d].resize(n.size());
                vBefore_[d][i] = *v[d];
                impulse_[d][i] = 0;
            }
        }
        const double m = n.mass[i];
        for (int d = 0; d < 3; ++d)
        {
            impulse_[d][i] += Jk[d];
            *v[d] += Jk[d]/m;
        }
    }
}


double Foam::membraneSurface::settleKicks()
{
    const structureNodes& n = nodes_;
    double work = 0;
    for (const label i : kicked_)
    {
        const double v[3] = {n.vx[i], n.vy[i], n.vz[i]};
        for (int d = 0; d < 3; ++d)
        {
            work += impulse_[d][i]*0.5*(vBefore_[d][i] + v[d]);
        }
        isKicked_[i] = 0;
    }
    kicked_.clear();
    return work;
}


void Foam::membraneSurface::velocity(const nearPoint& q, double v[3]) const
{
    label nodei[6];
    double w[6];
    const int n = shares(q, nodei, w);
    v[0] = v[1] = v[2] = 0;
    for (int k = 0; k < n; ++k)
    {
        const label i = nodei[k];
        v[0] += w[k]*nodes_.vx[i];
        v[1] += w[k]*nodes_.vy[i];
        v[2] += w[k]*nodes_.vz[i];
    }
}


// ************************************************************************* //
