/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "surfaceProbes.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "knownKeywords.H"
#include "vector2D.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::surfaceProbes::surfaceProbes
(
    const Time& runTime,
    const dictionary& dict,
    const gridGeometry& geom
)
:
    geom_(geom)
{
    knownKeywords::add(dict, {"surfaceProbes"});
    const dictionary& probes = dict.subOrEmptyDict("surfaceProbes");
    for (const entry& e : probes)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(probes)
                << "surfaceProbes entry " << e.keyword() << " is not a"
                << " dictionary; allowed: name { location (x y); }"
                << exit(FatalIOError);
        }
        knownKeywords::add(e.dict(), {"location"});
        const vector2D loc = e.dict().get<vector2D>("location");
        // Finite first: an ordered comparison with NaN raises a trap
        const bool inside =
            std::isfinite(loc.x()) && std::isfinite(loc.y())
         && loc.x() >= geom.origin[0] && loc.x() <= geom.domainUpper(0)
         && (
                geom.plane
             || (loc.y() >= geom.origin[1] && loc.y() <= geom.domainUpper(1))
            );
        if (!inside)
        {
            FatalIOErrorInFunction(e.dict())
                << "location " << loc << " of surface probe " << e.keyword()
                << " is outside the mesh; allowed: x in [" << geom.origin[0]
                << ", " << geom.domainUpper(0) << "], y in [" << geom.origin[1]
                << ", " << geom.domainUpper(1) << "]" << exit(FatalIOError);
        }
        locations_.append(loc);
        files_.append
        (
            new timeSeriesFile
            (
                runTime, e.keyword(), "surfaceHeight",
                {"time", "zTop", "nParticles"},
                {
                    "Top of the flow at (x y) = (" + Foam::name(loc.x()) + " "
                  + Foam::name(loc.y()) + ") [m]: the highest particle within"
                    " half a cell horizontally (zTop, the mesh bottom when"
                    " none is near), and how many are near"
                }
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::surfaceProbes::write
(
    const scalar t,
    const particleArrays& particles
)
{
    const label n = particles.size();
    const double* x = particles.component(particleArrays::X);
    const double* y = particles.component(particleArrays::Y);
    const double* z = particles.component(particleArrays::Z);
    const double rx = 0.5*geom_.dx[0];
    // Across a plane slice every particle is near
    const double ry = geom_.plane ? 1e300 : 0.5*geom_.dx[1];
    forAll(locations_, p)
    {
        const double px = locations_[p].x(), py = locations_[p].y();
        double top = geom_.origin[2];
        label near = 0;
        #pragma omp parallel for schedule(static) reduction(max:top) \
            reduction(+:near)
        for (label i = 0; i < n; ++i)
        {
            if (std::abs(x[i] - px) <= rx && std::abs(y[i] - py) <= ry)
            {
                ++near;
                top = z[i] > top ? z[i] : top;
            }
        }
        // (over every processor)
        reduce(top, maxOp<double>());
        reduce(near, sumOp<label>());
        files_[p].write(List<scalar>({t, top, scalar(near)}));
    }
}


// ************************************************************************* //
