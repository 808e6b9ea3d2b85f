/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "samplingDesign.H"
#include <algorithm>
#include <cmath>
#include <numeric>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

double Foam::samplingDesign::unitUniform(std::mt19937_64& rng)
{
    return (double(rng() >> 11) + 0.5)*0x1.0p-53;
}


std::uint64_t Foam::samplingDesign::uniformIndex
(
    std::mt19937_64& rng,
    const std::uint64_t n
)
{
    // The largest multiple of n that fits: draws at or above it are redrawn
    const std::uint64_t limit = (UINT64_MAX/n)*n;
    std::uint64_t x;
    do
    {
        x = rng();
    } while (x >= limit);
    return x % n;
}


std::vector<Foam::label> Foam::samplingDesign::permutation
(
    std::mt19937_64& rng,
    const label n
)
{
    std::vector<label> p(n);
    std::iota(p.begin(), p.end(), 0);
    for (label i = n - 1; i > 0; --i)
    {
        std::swap(p[i], p[uniformIndex(rng, i + 1)]);
    }
    return p;
}


Foam::samplingDesign::probabilities Foam::samplingDesign::monteCarlo
(
    std::mt19937_64& rng,
    const label nParameters,
    const label nMembers
)
{
    probabilities u(nParameters, std::vector<double>(nMembers));
    for (std::vector<double>& parameter : u)
    {
        for (double& member : parameter)
        {
            member = unitUniform(rng);
        }
    }
    return u;
}


Foam::samplingDesign::probabilities Foam::samplingDesign::latinHypercube
(
    std::mt19937_64& rng,
    const label nParameters,
    const label nMembers
)
{
    // (k + r)/N can round up to the next stratum's edge only for r within
    // round-off of 1; the largest double below 1 keeps the inverse CDFs
    // finite there
    const double below1 = std::nextafter(1.0, 0.0);

    probabilities u(nParameters, std::vector<double>(nMembers));
    for (std::vector<double>& parameter : u)
    {
        const std::vector<label> stratum(permutation(rng, nMembers));
        for (label memberi = 0; memberi < nMembers; ++memberi)
        {
            parameter[memberi] = std::min
            (
                (stratum[memberi] + unitUniform(rng))/nMembers,
                below1
            );
        }
    }
    return u;
}


std::vector<Foam::labelList> Foam::samplingDesign::fullFactorial
(
    const labelList& levels
)
{
    label nMembers = 1;
    for (const label n : levels)
    {
        nMembers *= n;
    }

    std::vector<labelList> index(levels.size(), labelList(nMembers));
    for (label memberi = 0; memberi < nMembers; ++memberi)
    {
        label rest = memberi;
        for (label parami = levels.size() - 1; parami >= 0; --parami)
        {
            index[parami][memberi] = rest % levels[parami];
            rest /= levels[parami];
        }
    }
    return index;
}


// ************************************************************************* //
