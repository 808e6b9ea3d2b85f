/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrierModel.H"
#include "knownKeywords.H"
#include "DynamicField.H"
#include "orderedSums.H"
#include "STLcheck.H"
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(barrierModel, 0);
    defineRunTimeSelectionTable(barrierModel, dictionary);
}

const Foam::Enum<Foam::barrierModel::contactType>
Foam::barrierModel::contactTypeNames
({
    { contactType::slip, "slip" },
    { contactType::noSlip, "noSlip" },
    { contactType::Coulomb, "Coulomb" },
});


namespace
{

//- The velocity v after contact with a surface of outward unit normal n,
//  when it moves into it (vn = v.n < 0): the normal part removed and the
//  tangential one kept (slip), removed (noSlip) or reduced by mu |vn|
//  (Coulomb)
inline void contactVelocity
(
    const Foam::barrierModel::contactType contact,
    const double mu,
    const double n[3],
    const double vn,
    double v[3]
)
{
    typedef Foam::barrierModel::contactType type;
    double vt[3] = {v[0] - vn*n[0], v[1] - vn*n[1], v[2] - vn*n[2]};
    double keep = 1;
    if (contact == type::noSlip)
    {
        keep = 0;
    }
    else if (contact == type::Coulomb)
    {
        const double magVt =
            std::sqrt(vt[0]*vt[0] + vt[1]*vt[1] + vt[2]*vt[2]);
        keep = magVt > -mu*vn ? 1 + mu*vn/magVt : 0;
    }
    for (int d = 0; d < 3; ++d)
    {
        v[d] = keep*vt[d];
    }
}

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

Foam::barrierModel::barrierModel
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    name_(name),
    dict_(dict),
    caseDir_(caseDir),
    contact_(contactTypeNames.get("contact", dict)),
    friction_(0),
    writePressure_(dict.getOrDefault<bool>("writePressure", false)),
    overtopDir_(Zero),
    guardDepth_(0),
    nearLo_{0, 0, 0},
    nearHi_{-1, -1, -1},
    reached_(true),
    runUp_(-GREAT),
    maxRunUp_(-GREAT),
    passLevel_(GREAT),
    force_(Zero),
    peakForce_(0),
    peakTime_(0),
    passedOutflow_(0)
{
    knownKeywords::add
    (
        dict,
        {
            "contact", "frictionCoefficient", "writePressure",
            "overtoppingDirection"
        }
    );

    if (contact_ == contactType::Coulomb)
    {
        friction_ = dict.get<scalar>("frictionCoefficient");
        if (!(friction_ >= 0))
        {
            FatalIOErrorInFunction(dict)
                << "frictionCoefficient = " << friction_ << " is invalid;"
                << " allowed: >= 0" << exit(FatalIOError);
        }
    }
    if (dict.found("overtoppingDirection"))
    {
        overtopDir_ = readDirection("overtoppingDirection");
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::point Foam::barrierModel::readPoint
(
    const dictionary& dict,
    const word& key
)
{
    const point p = dict.get<point>(key);
    for (direction d = 0; d < 3; ++d)
    {
        if (!STLcheck::allowedCoordinate(p[d]))
        {
            FatalIOErrorInFunction(dict)
                << key << " = " << p << " is invalid; allowed: coordinates"
                << " within " << STLcheck::maxCoordinate << " m of the origin"
                << exit(FatalIOError);
        }
    }
    return p;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::vector Foam::barrierModel::readDirection(const word& key) const
{
    const vector v = dict_.get<vector>(key);
    const scalar scale = cmptMax(cmptMag(v));
    if (!(std::isfinite(scale) && scale > 0))
    {
        FatalIOErrorInFunction(dict_)
            << key << " = " << v << " is invalid; allowed: a non-zero vector"
            << " with finite components" << exit(FatalIOError);
    }
    // Scaled first only where the square of the length would overflow or
    // underflow: otherwise v/|v| as it always was, bit for bit
    const vector u = (scale > 1e-150 && scale < 1e150) ? v : v/scale;
    return u/mag(u);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierModel::planeNormals(vectorField& normals)
{
    for (vector& n : normals)
    {
        n.y() = 0;
        const scalar len = mag(n);
        n = len > SMALL ? n/len : Zero;
    }
}


void Foam::barrierModel::findContactNodes
(
    const gridGeometry& g,
    const bool wall[3][2]
)
{
    checkGrid(g);

    // Nodes to a depth of three cells: the stencils of particles that touch
    // the surface, and of those that have entered it by up to a cell
    // (Sizes along the axes the flow varies along: a plane slice's width
    // across y is no resolution)
    const scalar h = g.hMax();
    const scalar band = 3*h;
    const scalar onSurface = 1e-9*h;
    // A cell that holds a point of the barrier has every corner node within
    // a cell diagonal of it (margin: terrain's distance is approximate)
    scalar diagonal2 = 0;
    for (int d = 0; d < 3; ++d)
    {
        diagonal2 += g.varies(d) ? sqr(g.dx[d]) : 0;
    }
    const scalar nearCellDistance = 1.25*std::sqrt(diagonal2);
    nearCell_.assign(g.nCellsTotal(), 0);
    for (int d = 0; d < 3; ++d)
    {
        nearLo_[d] = g.nCells[d];
        nearHi_[d] = -1;
    }
    guardDepth_ = guardDepthCells()*g.hMin();
    // The screen's clearance phi + guardDepth - margin; the margin covers
    // the rounding of the distances, which grows with the coordinates
    // (1e-10 m at 1e6 m). Nodes outside the searched box are farther than
    // the band from the barrier: the band bounds their distance from below
    const scalar clearance =
        guardDepth_ - 1e-6*g.hMin();
    nodeClearance_.clear();
    if (exactDistance())
    {
        nodeClearance_.assign(g.nNodes(), floatBelow(band + clearance));
    }

    const boundBox bb = bounds();
    const point lo = bb.min() - vector::uniform(band);
    const point hi = bb.max() + vector::uniform(band);

    gridGeometry::index first[3], last[3];
    for (int d = 0; d < 3; ++d)
    {
        const scalar l = max((lo[d] - g.origin[d])*g.invDx[d], -2.0);
        const scalar u =
            min((hi[d] - g.origin[d])*g.invDx[d], g.nCells[d] + 2.0);
        first[d] = gridGeometry::index(std::ceil(l)) + gridGeometry::nGhost;
        last[d] = gridGeometry::index(std::floor(u)) + gridGeometry::nGhost + 1;
        first[d] = max(first[d], 0);
        last[d] = min(last[d], g.nNodesDir[d]);
    }

    // One plane of nodes at a time: bounded memory for big grids
    nodes_.clear();
    std::vector<double> depth;
    nearNodes_.clear();
    nearZ_.clear();
    for (int d = 0; d < 3; ++d)
    {
        normal_[d].clear();
    }
    const gridGeometry::index nG = gridGeometry::nGhost;
    for (gridGeometry::index k = first[2]; k < last[2]; ++k)
    {
        DynamicList<point> pts;
        DynamicList<gridGeometry::index> ids;
        for (gridGeometry::index j = first[1]; j < last[1]; ++j)
        {
            for (gridGeometry::index i = first[0]; i < last[0]; ++i)
            {
                pts.append
                (
                    point
                    (
                        g.nodeCoord(0, i - nG),
                        g.nodeCoord(1, j - nG),
                        g.nodeCoord(2, k - nG)
                    )
                );
                ids.append(i + g.nodeStride[1]*j + g.nodeStride[2]*k);
            }
        }
        if (pts.empty())
        {
            continue;
        }
        scalarField phi;
        vectorField nrm;
        distance(pointField(pts), phi, nrm);
        if (g.plane)
        {
            planeNormals(nrm);
        }
        forAll(pts, pi)
        {
            if (!nodeClearance_.empty())
            {
                nodeClearance_[ids[pi]] = floatBelow(phi[pi] + clearance);
            }
            if (phi[pi] <= nearCellDistance)
            {
                // The (up to) eight cells around the node
                gridGeometry::index ijk[3];
                g.nodeIJK(ids[pi], ijk);
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
                        const gridGeometry::index c[3] = {ci, cj, ck};
                        for (int d = 0; d < 3; ++d)
                        {
                            nearLo_[d] = min(nearLo_[d], c[d]);
                            nearHi_[d] = max(nearHi_[d], c[d]);
                        }
                    }
                }
            }
            if (phi[pi] <= onSurface && phi[pi] >= -band)
            {
                nodes_.push_back(ids[pi]);
                depth.push_back(-phi[pi]);
                for (int d = 0; d < 3; ++d)
                {
                    normal_[d].push_back(nrm[pi][d]);
                }
            }
            else if (phi[pi] > onSurface && phi[pi] <= 1.5*h)
            {
                nearNodes_.push_back(ids[pi]);
                nearZ_.push_back(pts[pi].z());
            }
        }
    }
    normalForce_.assign(nodes_.size(), 0.0);
    share_.assign(nodes_.size(), 1.0);
    forAll(nodes_, c)
    {
        gridGeometry::index ijk[3];
        g.nodeIJK(nodes_[c], ijk);
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
                share_[c] *= beyond > 0 ? 0 : (beyond == 0 ? 0.5 : 1);
            }
        }
    }

    if (measuresOvertopping())
    {
        passLevel_ = -GREAT;
        for (const gridGeometry::index n : nodes_)
        {
            gridGeometry::index ijk[3];
            g.nodeIJK(n, ijk);
            const point x
            (
                g.nodeCoord(0, ijk[0]),
                g.nodeCoord(1, ijk[1]),
                g.nodeCoord(2, ijk[2])
            );
            passLevel_ = max(passLevel_, x & overtopDir_);
        }
        // No node inside a barrier thinner than the node spacing: its far
        // side, from its bounding box
        const boundBox bb = bounds();
        if (nodes_.empty() && bb != boundBox::greatBox)
        {
            const pointField corners(bb.points());
            for (const point& c : corners)
            {
                passLevel_ = max(passLevel_, c & overtopDir_);
            }
        }
    }
    if (nodes_.empty())
    {
        WarningInFunction
            << "barrier " << name_ << " has no grid node inside it or on its"
            << " surface: it lies outside the mesh or is thinner than the"
            << " node spacing; only the particles' guard stops the flow at"
            << " it, and its force acts on the particles alone (no node"
            << " pressure, writePressure)" << endl;
    }
    warnIfThin(g, depth);
}


void Foam::barrierModel::warnIfThin
(
    const gridGeometry& g,
    const std::vector<double>& depth
) const
{
    // Neighbouring contact nodes less than a cell deep whose nearest faces
    // look opposite ways lie in a part thinner than about two cells: a node
    // there may take the far face's normal, and flow arriving at it is not
    // stopped at the nodes (contact acts only on approach); the particles'
    // guard stops it, so the force there acts on the particles and is
    // missing from the node pressure
    const double h = g.hMax();
    std::vector<gridGeometry::index> sorted(nodes_);
    std::vector<label> order(nodes_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b) { return nodes_[a] < nodes_[b]; }
    );
    for (size_t k = 0; k < order.size(); ++k)
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
    forAll(nodes_, c)
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


void Foam::barrierModel::applyContact
(
    mpm3DGrid& grid,
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
    const contactType contact = contact_;
    const double mu = friction_;
    // Force summed in a fixed order: the same on any number of threads
    double F[3], none[1];
    orderedSums<3, 0>(nc, F, none, [&](label c, double* S, double*)
    {
        const gridGeometry::index n = nodes[c];
        const double mi = grid.mass[n];
        const double v[3] = {grid.vx[n], grid.vy[n], grid.vz[n]};
        const double vn = v[0]*nx[c] + v[1]*ny[c] + v[2]*nz[c];
        if (!(mi > massTol) || vn >= 0)
        {
            fn[c] = 0;
            return;
        }
        const double nrm[3] = {nx[c], ny[c], nz[c]};
        double vt[3] = {v[0], v[1], v[2]};
        contactVelocity(contact, mu, nrm, vn, vt);
        const double k = mi/dt;
        const double kDomain = share[c]*k;
        S[0] += kDomain*(v[0] - vt[0]);
        S[1] += kDomain*(v[1] - vt[1]);
        S[2] += kDomain*(v[2] - vt[2]);
        fn[c] = -k*vn;
        grid.vx[n] = vt[0];
        grid.vy[n] = vt[1];
        grid.vz[n] = vt[2];
    });

    force_ = vector(F[0], F[1], F[2]);

    // Run-up: the highest node beside the barrier holding flow
    const label nn = label(nearNodes_.size());
    const gridGeometry::index* near = nearNodes_.data();
    const double* z = nearZ_.data();
    double top = -GREAT;
    #pragma omp parallel for schedule(static) reduction(max:top)
    for (label c = 0; c < nn; ++c)
    {
        if (grid.mass[near[c]] > massTol && z[c] > top)
        {
            top = z[c];
        }
    }
    runUp_ = top;
    maxRunUp_ = max(maxRunUp_, top);
}


void Foam::barrierModel::inside
(
    const pointField& points,
    boolList& in
) const
{
    deeperThan(points, 0, in);
}


void Foam::barrierModel::deeperThan
(
    const pointField& points,
    const scalar depth,
    boolList& in
) const
{
    scalarField phi;
    vectorField normal;
    distance(points, phi, normal);
    in.setSize(points.size());
    forAll(points, i)
    {
        in[i] = phi[i] < -depth;
    }
}


void Foam::barrierModel::guardInside
(
    const pointField& points,
    boolList& in
) const
{
    if (guardDepth_ > 0)
    {
        deeperThan(points, guardDepth_, in);
    }
    else
    {
        inside(points, in);
    }
}


bool Foam::barrierModel::mayBeDeep
(
    const gridGeometry& g,
    const double x,
    const double y,
    const double z
) const
{
    // A non-finite position has no nearest node: the exact test answers
    if (nodeClearance_.empty() || !std::isfinite(x + y + z))
    {
        return true;
    }
    const double xyz[3] = {x, y, z};
    gridGeometry::index ijk[3];
    double r2 = 0;
    for (int d = 0; d < 3; ++d)
    {
        const double l = std::min
        (
            std::max(std::round(g.local(d, xyz[d])), 0.0),
            double(g.nCells[d])
        );
        ijk[d] = gridGeometry::index(l);
        r2 += sqr(xyz[d] - g.nodeCoord(d, ijk[d]));
    }
    // phi >= phi_n - r: not deeper than the guard's depth while the node's
    // clearance phi_n + guardDepth (less the margin) is at least r
    return
        nodeClearance_[g.nodeIndex(ijk[0], ijk[1], ijk[2])]
      < std::sqrt(r2);
}


void Foam::barrierModel::markEntered
(
    const gridGeometry& g,
    const mpm3DParticles& p
)
{
    // In chunks: bounded scratch, and a virtual call per chunk, not per
    // particle. Only particles in a cell the barrier may occupy are tested;
    // each chunk keeps those inside, joined in storage order
    constexpr label chunk = 4096;
    const label n = p.n;
    const label nChunks = (n + chunk - 1)/chunk;
    List<DynamicList<label>> inside(nChunks);
    #pragma omp parallel for schedule(dynamic) if (threadSafeDistance())
    for (label c = 0; c < nChunks; ++c)
    {
        const label first = c*chunk;
        const label last = std::min(n, first + chunk);
        DynamicList<label>& ids = inside[c];
        DynamicField<point> pts;
        for (label i = first; i < last; ++i)
        {
            const double x = p.x[0][i], y = p.x[1][i], z = p.x[2][i];
            if (nearCell_[g.cellOf(x, y, z)] && mayBeDeep(g, x, y, z))
            {
                ids.append(i);
                pts.append(point(x, y, z));
            }
        }
        if (ids.empty())
        {
            continue;
        }
        boolList in;
        guardInside(pts, in);
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
}


bool Foam::barrierModel::guardReach(const nodeBox& particleNodes)
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


Foam::label Foam::barrierModel::stopEntries
(
    const gridGeometry& g,
    const double* const x0[3],
    const mpm3DParticles& p,
    const double dt,
    const scalar t
)
{
    // Candidates: the particles that end the step inside the barrier
    // (beyond the guard's depth), then those of them that were outside at
    // the start
    candidates_.clear();
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
        // Where each path entered: bisection between the start (outside,
        // a) and the end (inside, b), to 2^-30 of the step's move
        const pointField end(b);
        pointField mid(nc);
        boolList in;
        for (int iter = 0; iter < 30; ++iter)
        {
            forAll(mid, c)
            {
                mid[c] = 0.5*(a[c] + b[c]);
            }
            guardInside(mid, in);
            forAll(mid, c)
            {
                (in[c] ? b[c] : a[c]) = mid[c];
            }
        }

        // The entered face's normal, at the point just outside it; the end
        // point projected on that face's tangent plane keeps the motion
        // along the face (exact on plane faces)
        scalarField phi;
        vectorField normal;
        distance(a, phi, normal);
        if (g.plane)
        {
            planeNormals(normal);
        }
        pointField onFace(nc);
        forAll(onFace, c)
        {
            onFace[c] = end[c] + ((a[c] - end[c]) & normal[c])*normal[c];
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
                contactVelocity(contact_, friction_, nrm, vn, v);
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

    force_ += vector(F[0], F[1], F[2]);
    if (mag(force_) > peakForce_)
    {
        peakForce_ = mag(force_);
        peakTime_ = t;
    }
    return nc;
}


void Foam::barrierModel::nodePressure
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
    forAll(nodes_, c)
    {
        double area = 0;
        for (int d = 0; d < 3; ++d)
        {
            area += std::abs(normal_[d][c])*faceArea[d];
        }
        p[nodes_[c]] = area > 0 ? normalForce_[c]/area : 0;
    }
}


void Foam::barrierModel::describe(Ostream& os) const
{
    os  << "    " << name_ << ": ";
    describeGeometry(os);
    os  << ", " << contactTypeNames[contact_];
    if (contact_ == contactType::Coulomb)
    {
        os  << " (friction coefficient " << friction_ << ")";
    }
    os  << ", " << nodes_.size() << " contact nodes";
    if (measuresOvertopping())
    {
        os  << ", overtopping beyond " << passLevel_ << " m along "
            << overtopDir_;
    }
    os  << nl;
}


// ************************************************************************* //
