/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "depthAveragedSplitting.H"
#include "depthAveragedSeeding.H"
#include "speedLimit.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::depthAveragedSplitting::splitHMinFraction = 0.01;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::depthAveragedSplitting::seedArea() const
{
    return depthAveragedSeeding::seedArea(geometry_, nPerCell_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depthAveragedSplitting::depthAveragedSplitting
(
    const dictionary& dict,
    const gridGeometry& geometry,
    const label nPerCell,
    const scalar hMin
)
:
    geometry_(geometry),
    nPerCell_(nPerCell),
    hMin_(hMin),
    splitRatio_(dict.getOrDefault<scalar>("splitRatio", 1.25)),
    splitHMin_(dict.getOrDefault<scalar>("splitHMin", 0)),
    splitHMinGiven_(dict.found("splitHMin"))
{
    if (!(splitRatio_ == 0 || splitRatio_ >= 1))
    {
        FatalIOErrorInFunction(dict)
            << "splitRatio = " << splitRatio_ << " is invalid; allowed: 0"
            << " (no splitting) or >= 1 (seed areas)" << exit(FatalIOError);
    }
    if (!(splitHMin_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "splitHMin = " << splitHMin_ << " is invalid; allowed:"
            << " splitHMin >= 0 [m]" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::splitRule Foam::depthAveragedSplitting::rule() const
{
    splitRule r;
    r.maxArea = splitRatio_*seedArea();
    r.hSplit = max(hMin_, splitHMin_);
    for (int d = 0; d < 2; ++d)
    {
        r.cell[d] = geometry_.dx[d];
        r.lo[d] = geometry_.origin[d];
        r.hi[d] = geometry_.domainUpper(d);
    }
    return r;
}


void Foam::depthAveragedSplitting::setDefaultHMin(const scalar thickest)
{
    if (!splitHMinGiven_)
    {
        splitHMin_ = speedLimit::threeDigits(splitHMinFraction*thickest);
    }
}


void Foam::depthAveragedSplitting::reserve(const label n)
{
    flags_.reserve(n);
    list_.reserve(n);
}


Foam::label Foam::depthAveragedSplitting::split
(
    particleArrays& particles,
    const depthAveragedFields& fields,
    const bool marked
)
{
    if (!active())
    {
        return 0;
    }
    const double cell[2] = {geometry_.dx[0], geometry_.dx[1]};
    const label n = particles.size();
    const label Fc0 = fields.F();
    const label Cc0 = fields.gradU();
    const splitRule r = rule();

    // The candidates (marked here, or by the caller in flags()), and of
    // them those whose halves fit the domain, in storage order
    {
        const double* F[4] =
        {
            particles.component(Fc0), particles.component(Fc0 + 1),
            particles.component(Fc0 + 2), particles.component(Fc0 + 3)
        };
        const double* x = particles.component(particleArrays::X);
        const double* y = particles.component(particleArrays::Y);
        const double* V = particles.component(particleArrays::VOL);
        if (marked)
        {
            if (label(flags_.size()) != n)
            {
                FatalErrorInFunction
                    << flags_.size() << " split marks for " << n
                    << " columns" << abort(FatalError);
            }
        }
        else
        {
            flags_.resize(n);

            #pragma omp parallel for simd schedule(static)
            for (label i = 0; i < n; ++i)
            {
                flags_[i] =
                    r.candidate(F[0][i], F[1][i], F[2][i], F[3][i], V[i]);
            }
        }
        list_.clear();
        particleArrays::forEachFlagged
        (
            flags_,
            [&](const label i)
            {
                const double Fi[4] = {F[0][i], F[1][i], F[2][i], F[3][i]};
                if (r.fits(Fi, x[i], y[i]))
                {
                    list_.push_back(i);
                }
            }
        );
    }
    const label nSplit = label(list_.size());
    if (!nSplit)
    {
        return 0;
    }

    // A child starts as a copy of its parent, every field included (the
    // append may move the arrays: pointers are taken after it)
    const label first = particles.append(nSplit);
    const label* parent = list_.data();
    for (label c = 0; c < particles.nComponentArrays(); ++c)
    {
        double* col = particles.component(c);
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nSplit; ++k)
        {
            col[first + k] = col[parent[k]];
        }
    }

    double* F[4] =
    {
        particles.component(Fc0), particles.component(Fc0 + 1),
        particles.component(Fc0 + 2), particles.component(Fc0 + 3)
    };
    const double* C[4] =
    {
        particles.component(Cc0), particles.component(Cc0 + 1),
        particles.component(Cc0 + 2), particles.component(Cc0 + 3)
    };
    double* x = particles.component(particleArrays::X);
    double* y = particles.component(particleArrays::Y);
    double* ux = particles.component(particleArrays::UX);
    double* uy = particles.component(particleArrays::UY);
    double* m = particles.component(particleArrays::M);
    double* V = particles.component(particleArrays::VOL);
    double* A = particles.component(fields.A());

    // The halves: mass, volume and basal area halved (exactly), positions
    // at the centroids of the two halves of the footprint and velocities
    // from the column's affine field there (centre of mass and momentum
    // kept)
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nSplit; ++k)
    {
        const label i = parent[k];
        const label j = first + k;
        const double Fi[4] = {F[0][i], F[1][i], F[2][i], F[3][i]};
        double d[2], Fh[4];
        splitFootprint(Fi, cell, d, Fh);
        const double du[2] =
        {
            C[0][i]*d[0] + C[1][i]*d[1],
            C[2][i]*d[0] + C[3][i]*d[1]
        };
        x[j] = x[i] + d[0];
        y[j] = y[i] + d[1];
        x[i] -= d[0];
        y[i] -= d[1];
        ux[j] = ux[i] + du[0];
        uy[j] = uy[i] + du[1];
        ux[i] -= du[0];
        uy[i] -= du[1];
        m[i] *= 0.5;
        m[j] = m[i];
        V[i] *= 0.5;
        V[j] = V[i];
        A[i] *= 0.5;
        A[j] = A[i];
        for (int c = 0; c < 4; ++c)
        {
            F[c][i] = F[c][j] = Fh[c];
        }
    }
    return nSplit;
}


void Foam::depthAveragedSplitting::writeState(dictionary& state) const
{
    state.set("splitHMin", splitHMin_);
}


void Foam::depthAveragedSplitting::readState(const dictionary& state)
{
    // The default of the run's start, not this one's
    if (!splitHMinGiven_)
    {
        splitHMin_ = state.get<scalar>("splitHMin");
    }
}


void Foam::depthAveragedSplitting::describe(Ostream& os) const
{
    if (active())
    {
        os  << "above " << splitRatio_ << " seed areas ("
            << splitRatio_*seedArea() << " m^2), if not thinner than "
            << max(hMin_, splitHMin_) << " m";
    }
    else
    {
        os  << "off";
    }
}


// ************************************************************************* //
