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

    // The same rounding on any number of threads; a flat bed reads no
    // gradient
    double sums[2], maxima[7];
    staticSwitches
    (
        [&](auto onTerrain)
        {
            orderedSums<2, 7>
            (
                n, sums, maxima, [&](label i, double* S, double* mx)
                {
                    // Speed along the bed: the vertical component follows
                    // the terrain
                    const double w =
                        onTerrain() ? ux[i]*gx[i] + uy[i]*gy[i] : 0;
                    const double u2 = ux[i]*ux[i] + uy[i]*uy[i];
                    const double v2 = u2 + w*w;
                    S[0] += m[i];
                    S[1] += 0.5*m[i]*v2;
                    // A NaN or infinity in any of them makes the sum one
                    const double broken =
                        std::isfinite(x[i] + y[i] + ux[i] + uy[i] + h[i])
                      ? 0 : 1;
                    const double v[7] =
                        {v2, -x[i], x[i], -y[i], y[i], u2, broken};
                    for (int k = 0; k < 7; ++k)
                    {
                        mx[k] = v[k] > mx[k] ? v[k] : mx[k];
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
