/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "depthAveragedDiagnostics.H"
#include "staticSwitches.H"
#include "orderedSums.H"
#include "processorTotals.H"
#include <type_traits>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depthAveragedDiagnostics::depthAveragedDiagnostics(const Time& runTime)
:
    summary_
    (
        runTime,
        "dampmFoam",
        "summary",
        {"time", "mass", "outflowMass", "kineticEnergy", "maxSpeed", "xMin",
         "xMax", "yMin", "yMax", "nParticles", "deltaT", "clockTime"},
        {"Depth-averaged MPM run-out (SI units): mass [kg], outflowMass [kg]",
         "through open sides, kineticEnergy [J] with the speed along the bed,",
         "maxSpeed [m/s], x/y extent of all columns [m], deltaT [s],",
         "clockTime [s] wall time since start"}
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::depthAveragedDiagnostics::totals Foam::depthAveragedDiagnostics::sum
(
    const particleArrays& particles,
    const depthAveragedFields& fields,
    const bool terrain
)
{
    const label n = particles.size();
    const double* x = particles.component(particleArrays::X);
    const double* y = particles.component(particleArrays::Y);
    const double* ux = particles.component(particleArrays::UX);
    const double* uy = particles.component(particleArrays::UY);
    const double* m = particles.component(particleArrays::M);
    const double* h = particles.component(fields.h());
    const double* gx = particles.component(fields.gradZ());
    const double* gy = particles.component(fields.gradZ() + 1);

    // The same rounding on any number of threads, four columns at a time;
    // a flat bed reads no gradient
    double sums[2], maxima[7];
    staticSwitches
    (
        [&](auto onTerrain)
        {
            orderedLaneSums<2, 7>
            (
                n, sums, maxima, [&](label i, auto* S, auto* mx)
                {
                    typedef std::remove_pointer_t<decltype(S)> Real;
                    const Real xi = loadAt<Real>(x, i);
                    const Real yi = loadAt<Real>(y, i);
                    const Real uxi = loadAt<Real>(ux, i);
                    const Real uyi = loadAt<Real>(uy, i);
                    const Real mi = loadAt<Real>(m, i);

                    // Speed along the bed: the vertical component follows
                    // the terrain
                    const Real w = onTerrain()
                      ? uxi*loadAt<Real>(gx, i) + uyi*loadAt<Real>(gy, i)
                      : splat<Real>(0);
                    const Real u2 = uxi*uxi + uyi*uyi;
                    const Real v2 = u2 + w*w;
                    S[0] += mi;
                    S[1] += 0.5*mi*v2;
                    // A NaN or infinity in any of them makes the sum one
                    const Real broken = select
                    (
                        finiteOf(xi + yi + uxi + uyi + loadAt<Real>(h, i)),
                        splat<Real>(0), splat<Real>(1)
                    );
                    const Real v[7] = {v2, -xi, xi, -yi, yi, u2, broken};
                    for (int k = 0; k < 7; ++k)
                    {
                        mx[k] = select(v[k] > mx[k], v[k], mx[k]);
                    }
                }
            );
        },
        terrain
    );

    // Over every processor of a decomposed run
    const label nTotal = processorTotals<2, 7>(sums, maxima, n);

    totals t;
    t.mass = sums[0];
    t.kineticEnergy = sums[1];
    t.maxSpeed = std::sqrt(max(maxima[0], 0.0));
    t.maxHorizontalSpeed = std::sqrt(max(maxima[5], 0.0));
    t.finite = !(maxima[6] > 0);
    t.nColumns = nTotal;
    t.extent = nTotal
        ? boundBox
          (
              point(-maxima[1], -maxima[3], 0),
              point(maxima[2], maxima[4], 0)
          )
        : boundBox(point::zero, point::zero);
    return t;
}


Foam::word Foam::depthAveragedDiagnostics::nonFiniteField
(
    const particleArrays& particles,
    const depthAveragedFields& fields
)
{
    const label h = fields.h();

    // One pass in the usual case; the field is named only after a failure
    if
    (
        particles.finite
        ({
            particleArrays::X, particleArrays::Y, particleArrays::UX,
            particleArrays::UY, h
        })
    )
    {
        return word::null;
    }
    if (!particles.finite({particleArrays::X, particleArrays::Y}))
    {
        return "positions";
    }
    if (!particles.finite({particleArrays::UX, particleArrays::UY}))
    {
        return "U";
    }
    for (const particleArrays::fieldInfo& f : particles.fields())
    {
        if (f.first == h && !particles.finite({h}))
        {
            return f.name;
        }
    }
    return word::null;
}


void Foam::depthAveragedDiagnostics::write
(
    const scalar t,
    const totals& tot,
    const scalar outflowMass,
    const label nParticles,
    const scalar deltaT,
    const scalar clockTime
)
{
    summary_.write
    (
        List<scalar>
        ({
            t, tot.mass, outflowMass, tot.kineticEnergy, tot.maxSpeed,
            tot.extent.min().x(), tot.extent.max().x(),
            tot.extent.min().y(), tot.extent.max().y(),
            scalar(nParticles), deltaT, clockTime
        })
    );
}


// ************************************************************************* //
