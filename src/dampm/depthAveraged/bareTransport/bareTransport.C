/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "bareTransport.H"
#include "particleTransfers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bareTransport::bareTransport
(
    const gridGeometry& g,
    const double massTol
)
:
    g_(g),
    schedule_(g),
    massTol_(massTol),
    rho_(0),
    gravity_(0),
    gradU_(-1),
    F_(-1),
    h_(-1),
    a_(-1),
    kappa_(-1),
    gradZeta_(-1)
{
    nodes_.resize(g.nNodes());
}


Foam::bareTransport::bareTransport
(
    const gridGeometry& g,
    const double massTol,
    particleArrays& p,
    const int nPerCell,
    const double rho,
    const double gravity
)
:
    bareTransport(g, massTol)
{
    rho_ = rho;
    gravity_ = gravity;
    typedef particleArrays::fieldKind kind;
    gradU_ = p.addField("gradU", kind::tensor2D);
    F_ = p.addField("F", kind::internal, 0, 4);
    h_ = p.addField("h", kind::internal);
    a_ = p.addField("a", kind::internal);
    kappa_ = p.addField("kappa", kind::internal, 1);
    gradZeta_ = p.addField("gradZeta", kind::internal, 0, 2);

    // Footprints of the seed lattice
    for (int d = 0; d < 2; ++d)
    {
        std::fill_n(p.component(F_ + 3*d), p.size(), g.dx[d]/nPerCell);
    }
    nodalAreas(g, quadraticBSplineKernel(), nPerCell, nodes_.area.data());
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::shallowColumns Foam::bareTransport::columns
(
    particleArrays& p,
    const label gradU
) const
{
    shallowColumns cols;
    cols.n = p.size();
    cols.x = p.component(particleArrays::X);
    cols.y = p.component(particleArrays::Y);
    cols.ux = p.component(particleArrays::UX);
    cols.uy = p.component(particleArrays::UY);
    cols.m = p.component(particleArrays::M);
    cols.V = p.component(particleArrays::VOL);
    for (int k = 0; k < 4; ++k)
    {
        cols.C[k] = p.component(gradU + k);
    }
    if (h_ >= 0)
    {
        cols.h = p.component(h_);
        cols.a = p.component(a_);
        cols.kappa = p.component(kappa_);
        cols.gradZetaX = p.component(gradZeta_);
        cols.gradZetaY = p.component(gradZeta_ + 1);
    }
    return cols;
}


void Foam::bareTransport::scatter(particleArrays& p, const label gradU)
{
    p.sortByCell(g_, schedule_);

    // The nodes the columns touch, and those of last step to clear them
    activeNodes_ = stencilNodes_;
    stencilNodes_ = p.stencilNodes(g_);
    activeNodes_.unite(stencilNodes_);
    zeroNodes(g_, activeNodes_, nodes_);

    const columnScatter sc{g_, stencilNodes_, schedule_, p.binStart().data()};
    scatterMomentum(sc, quadraticBSplineKernel(), nodes_, columns(p, gradU));
}


void Foam::bareTransport::gather(particleArrays& p, const label gradU)
{
    const double* vel[2] = {nodes_.vx.data(), nodes_.vy.data()};
    gridToParticlesVelocity<2>
    (
        g_, quadraticBSplineKernel(), p, gradU, vel
    );
}


void Foam::bareTransport::move
(
    particleArrays& p,
    const label gradU,
    const double dt
)
{
    const label n = p.size();
    double* x = p.component(particleArrays::X);
    double* y = p.component(particleArrays::Y);
    const double* ux = p.component(particleArrays::UX);
    const double* uy = p.component(particleArrays::UY);
    double* C[4] = {};
    double* F[4] = {};
    for (int k = 0; F_ >= 0 && k < 4; ++k)
    {
        C[k] = p.component(gradU + k);
        F[k] = p.component(F_ + k);
    }
    auto loop = [&](auto footprints)
    {
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            x[i] += dt*ux[i];
            y[i] += dt*uy[i];
            if (footprints())
            {
                advanceColumn
                (
                    dt, C[0][i], C[1][i], C[2][i], C[3][i],
                    F[0][i], F[1][i], F[2][i], F[3][i]
                );
            }
        }
    };
    F_ >= 0 ? loop(std::true_type()) : loop(std::false_type());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bareTransport::advect
(
    particleArrays& p,
    const label gradU,
    const double dt
)
{
    scatter(p, gradU);

    // Node velocities (zero on empty nodes)
    const double massTol = massTol_;
    shallowGrid& grid = nodes_;
    g_.forEachNodeRow
    (
        activeNodes_,
        [&](const gridGeometry::index first, const gridGeometry::index last)
        {
            for (gridGeometry::index i = first; i < last; ++i)
            {
                const double* mp =
                    grid.momentum.data() + shallowGrid::nMomentum*i;
                const double mi = mp[shallowGrid::M];
                const bool active = mi > massTol;
                grid.vx[i] = active ? mp[shallowGrid::PX]/mi : 0;
                grid.vy[i] = active ? mp[shallowGrid::PY]/mi : 0;
            }
        }
    );

    gather(p, gradU);
    move(p, gradU, dt);
}


void Foam::bareTransport::shallowWater(particleArrays& p, const double dt)
{
    // hMin of the basal area V/max(h, hMin): dampmFoam's default
    const double hMin = 1e-4;

    scatter(p, gradU_);
    nodeHeights(g_, activeNodes_, nodes_, rho_, massTol_, false, nullptr);
    const columnScatter sc{g_, stencilNodes_, schedule_, p.binStart().data()};
    scatterForces<quadraticBSplineKernel, true, false, false, true, false>
    (
        sc, quadraticBSplineKernel(), nodes_, columns(p, gradU_), rho_,
        gravity_, hMin
    );
    resistanceUpdate
    (
        g_, activeNodes_, nodes_, domainSides(), dt, massTol_, false
    );
    gather(p, gradU_);
    move(p, gradU_, dt);
}


// ************************************************************************* //
