/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrierModel.H"
#include "orderedSums.H"
#include <algorithm>
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
    runUp_(-GREAT),
    maxRunUp_(-GREAT),
    passLevel_(GREAT),
    force_(Zero),
    peakForce_(0),
    peakTime_(0),
    passedOutflow_(0)
{
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
        overtopDir_ = dict.get<vector>("overtoppingDirection");
        if (!(mag(overtopDir_) > 0))
        {
            FatalIOErrorInFunction(dict)
                << "overtoppingDirection = " << overtopDir_ << " is invalid;"
                << " allowed: a non-zero vector" << exit(FatalIOError);
        }
        overtopDir_ /= mag(overtopDir_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierModel::findContactNodes(const gridGeometry& g)
{
    // Nodes to a depth of three cells: the stencils of particles that touch
    // the surface, and of those that have entered it by up to a cell
    const scalar h = max(max(g.dx[0], g.dx[1]), g.dx[2]);
    const scalar band = 3*h;
    const scalar onSurface = 1e-9*h;

    const boundBox bb = bounds();
    const point lo = bb.min() - vector::uniform(band);
    const point hi = bb.max() + vector::uniform(band);

    gridGeometry::index first[3], last[3];
    for (int d = 0; d < 3; ++d)
    {
        const scalar l = max((lo[d] - g.origin[d])*g.invDx[d], -2.0);
        const scalar u = min((hi[d] - g.origin[d])*g.invDx[d], g.nCells[d] + 2.0);
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
        forAll(pts, pi)
        {
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
    }
    if (nodes_.empty())
    {
        WarningInFunction
            << "barrier " << name_ << " has no grid node inside it or on its"
            << " surface: it lies outside the mesh or is thinner than the"
            << " node spacing, and takes no part in the flow" << endl;
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
    // there may take the far face's normal, and flow arriving at it then
    // passes (contact acts only on approach)
    const double h = max(max(g.dx[0], g.dx[1]), g.dx[2]);
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
            << nThin << " grid nodes: flow may pass through it there; refine"
            << " the mesh or thicken the barrier" << endl;
    }
}


void Foam::barrierModel::applyContact
(
    mpm3DGrid& grid,
    const double massTol,
    const double dt,
    const scalar t
)
{
    const label nc = label(nodes_.size());
    const gridGeometry::index* nodes = nodes_.data();
    const double* nx = normal_[0].data();
    const double* ny = normal_[1].data();
    const double* nz = normal_[2].data();
    double* fn = normalForce_.data();
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
        // Tangential velocity kept, removed or reduced by friction
        double vt[3] =
        {
            v[0] - vn*nx[c], v[1] - vn*ny[c], v[2] - vn*nz[c]
        };
        double keep = 1;
        if (contact == contactType::noSlip)
        {
            keep = 0;
        }
        else if (contact == contactType::Coulomb)
        {
            const double magVt =
                std::sqrt(vt[0]*vt[0] + vt[1]*vt[1] + vt[2]*vt[2]);
            keep = magVt > -mu*vn ? 1 + mu*vn/magVt : 0;
        }
        for (int d = 0; d < 3; ++d)
        {
            vt[d] *= keep;
        }
        const double k = mi/dt;
        S[0] += k*(v[0] - vt[0]);
        S[1] += k*(v[1] - vt[1]);
        S[2] += k*(v[2] - vt[2]);
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
    if (mag(force_) > peakForce_)
    {
        peakForce_ = mag(force_);
        peakTime_ = t;
    }
}


void Foam::barrierModel::nodePressure
(
    const gridGeometry& g,
    std::vector<double>& p
) const
{
    p.assign(g.nNodes(), 0.0);
    const scalar area = g.dx[0]*g.dx[1];
    forAll(nodes_, c)
    {
        p[nodes_[c]] = normalForce_[c]/area;
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
