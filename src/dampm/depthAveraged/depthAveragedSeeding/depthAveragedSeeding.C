/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "depthAveragedSeeding.H"
#include "depthAveragedKernels.H"
#include "visitShape.H"
#include "particleMemory.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::depthAveragedSeeding::project
(
    const shapeFunction& shape,
    const double* nodalArea,
    std::vector<double>& x,
    std::vector<double>& y,
    std::vector<double>& h
) const
{
    const scalar a = seedArea(geometry_, nPerCell_);
    const auto volume = [&]()
    {
        double v = 0;
        for (const double hk : h)
        {
            v += hk*a;
        }
        return v;
    };
    const double before = volume();
    const size_t nSampled = x.size();
    double moved = 0;
    visitShape
    (
        shape,
        [&](const auto& kernel)
        {
            moved = projectRelease
            (
                geometry_, kernel, nPerCell_, nodalArea, hMin_, x, y, h
            );
        }
    );
    const double after = volume();
    Info<< "Release projected onto the grid (releaseProjection): "
        << x.size() << " columns (" << nSampled << " sampled), " << after
        << " m^3, relative change " << (after - before)/before;
    if (moved > 0)
    {
        Info<< "; " << moved << " m^3 of the smeared edge, thinner than hMin "
            << hMin_ << " m, moved to the nearest column";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depthAveragedSeeding::depthAveragedSeeding
(
    const gridGeometry& geometry,
    const label nPerCell,
    const scalar rho,
    const scalar hMin,
    const bool projection
)
:
    geometry_(geometry),
    nPerCell_(nPerCell),
    rho_(rho),
    hMin_(hMin),
    projection_(projection)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::depthAveragedSeeding::seedArea
(
    const gridGeometry& g,
    const label nPerCell
)
{
    return g.dx[0]*g.dx[1]/(nPerCell*nPerCell);
}


void Foam::depthAveragedSeeding::seed
(
    const releaseModel& release,
    const shapeFunction& shape,
    const double* nodalArea,
    particleArrays& particles,
    const depthAveragedFields& fields
) const
{
    const gridGeometry& g = geometry_;
    const label n = nPerCell_;
    const scalar cellArea = seedArea(geometry_, nPerCell_);

    // Checked by the release, which logs what it puts in and leaves out;
    // the count refused before anything else is made for it
    std::vector<double> x, y, h;
    release.sampleColumns(g, n, rho_, x, y, h);
    const std::string what("the release (constant/dampmProperties)");
    particleMemory::reserve(particles, x.size(), what, g, n);
    if (projection_)
    {
        project(shape, nodalArea, x, y, h);
        particleMemory::reserve(particles, x.size(), what, g, n);
    }

    const label first = particles.append(label(x.size()));
    double* px = particles.component(particleArrays::X);
    double* py = particles.component(particleArrays::Y);
    double* ux = particles.component(particleArrays::UX);
    double* uy = particles.component(particleArrays::UY);
    double* V = particles.component(particleArrays::VOL);
    double* m = particles.component(particleArrays::M);
    double* ph = particles.component(fields.h());
    double* A = particles.component(fields.A());
    double* Fxx = particles.component(fields.F());
    double* Fyy = particles.component(fields.F() + 3);
    for (size_t k = 0; k < x.size(); ++k)
    {
        const label i = first + label(k);
        px[i] = x[k];
        py[i] = y[k];
        ux[i] = release.U().x();
        uy[i] = release.U().y();
        V[i] = h[k]*cellArea;
        m[i] = rho_*h[k]*cellArea;
        ph[i] = h[k];
        A[i] = cellArea;
        Fxx[i] = g.dx[0]/n;
        Fyy[i] = g.dx[1]/n;
    }
}


// ************************************************************************* //
