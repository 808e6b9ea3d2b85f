/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "bareTransport.H"
#include "transfers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bareTransport::bareTransport
(
    const gridGeometry& g,
    const double massTol
)
:
    g_(g),
    schedule_(g),
    massTol_(massTol)
{
    nodes_.resize(g.nNodes());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bareTransport::step
(
    particleArrays& p,
    const label gradU,
    const double dt
)
{
    const quadraticBSplineKernel kernel;
    p.sortByCell(g_, schedule_.maxStale());

    // The nodes the columns touch, and those of last step to clear them
    activeNodes_ = stencilNodes_;
    stencilNodes_ = p.stencilNodes(g_);
    activeNodes_.unite(stencilNodes_);
    zeroNodes(g_, activeNodes_, nodes_);

    shallowColumns cols;
    cols.n = p.size();
    cols.x = p.column(particleArrays::X);
    cols.y = p.column(particleArrays::Y);
    cols.ux = p.column(particleArrays::UX);
    cols.uy = p.column(particleArrays::UY);
    cols.m = p.column(particleArrays::M);
    for (int k = 0; k < 4; ++k)
    {
        cols.C[k] = p.column(gradU + k);
    }
    const columnScatter scatter
    {
        g_, stencilNodes_, schedule_, p.cellStart().data()
    };
    scatterMomentum(scatter, kernel, nodes_, cols);

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

    const double* vel[2] = {nodes_.vx.data(), nodes_.vy.data()};
    gridToParticlesVelocity<2>(g_, kernel, p, gradU, vel);

    const label n = p.size();
    double* x = p.column(particleArrays::X);
    double* y = p.column(particleArrays::Y);
    const double* ux = p.column(particleArrays::UX);
    const double* uy = p.column(particleArrays::UY);
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        x[i] += dt*ux[i];
        y[i] += dt*uy[i];
    }
}


// ************************************************************************* //
