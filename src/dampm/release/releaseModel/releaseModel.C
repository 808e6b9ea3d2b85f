/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "releaseModel.H"
#include "speedLimit.H"
#include "knownKeywords.H"
#include "fpTrapsHeld.H"
#include "boundedScalar.H"
#include "OStringStream.H"
#include "IOmanip.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(releaseModel, 0);
    defineRunTimeSelectionTable(releaseModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::releaseModel::releaseModel
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir
)
:
    dict_(dict),
    topography_(topography),
    caseDir_(caseDir),
    U_(speedLimit::readVelocity(dict, vector2D::zero)),
    thicknessScale_
    (
        boundedScalar
        (
            dict,
            "thicknessScale",
            dict.getOrDefault<scalar>("thicknessScale", 1),
            scalarBound::positive
        )
    )
{
    knownKeywords::add(dict, {"U", "thicknessScale"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::releaseModel::sampleColumns
(
    const gridGeometry& g,
    const label n,
    const scalar rho,
    std::vector<double>& x,
    std::vector<double>& y,
    std::vector<double>& h
) const
{
    const boundBox mesh
    (
        point(g.origin[0], g.origin[1], 0),
        point(g.upper(0), g.upper(1), 0)
    );
    const boundBox extent(bounds());
    const bool bounded = (extent != boundBox::greatBox);
    const auto span = [](const boundBox& bb)
    {
        return
            "x " + Foam::name(bb.min().x()) + " to " + Foam::name(bb.max().x())
          + ", y " + Foam::name(bb.min().y()) + " to "
          + Foam::name(bb.max().y()) + " m";
    };
    OStringStream what;
    describe(what);

    if
    (
        bounded
     && !(
            extent.min().x() < mesh.max().x()
         && extent.max().x() > mesh.min().x()
         && extent.min().y() < mesh.max().y()
         && extent.max().y() > mesh.min().y()
        )
    )
    {
        FatalIOErrorInFunction(dict_)
            << "the release " << what.str().c_str() << " lies wholly outside"
            << " the mesh: it spans " << span(extent).c_str() << ", the mesh"
            << " (system/blockMeshDict) " << span(mesh).c_str() << "; allowed:"
            << " a release that overlaps the mesh (local coordinates: a"
            << " raster's map coordinates less the topography's offset)"
            << exit(FatalIOError);
    }

    // Traps masked for the whole lattice, not per column: an expression may
    // give NaN or inf, which is refused below by its column
    x.clear();
    y.clear();
    h.clear();
    bool bad = false;
    scalar at[3] = {0, 0, 0};
    {
        fpTrapsHeld masked;
        for (label j = 0; j < g.nCells[1]*n && !bad; ++j)
        {
            const scalar yp = g.origin[1] + (j + 0.5)*g.dx[1]/n;
            for (label i = 0; i < g.nCells[0]*n && !bad; ++i)
            {
                const scalar xp = g.origin[0] + (i + 0.5)*g.dx[0]/n;
                const scalar hp = thicknessScale_*height(xp, yp);
                if (!(std::isfinite(hp) && hp >= 0 && hp <= maxHeight))
                {
                    bad = true;
                    at[0] = xp;
                    at[1] = yp;
                    at[2] = hp;
                }
                else if (hp > 0)
                {
                    x.push_back(xp);
                    y.push_back(yp);
                    h.push_back(hp);
                }
            }
        }
    }
    if (bad)
    {
        FatalIOErrorInFunction(dict_)
            << setprecision(12)
            << "the release " << what.str().c_str() << " gives the thickness"
            << " h = " << at[2] << " m at the column (x y) = (" << at[0] << ' '
            << at[1] << "); allowed: a finite thickness 0 <= h <= "
            << maxHeight << " m at every column in the mesh"
            << exit(FatalIOError);
    }
    if (x.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "the release " << what.str().c_str() << " puts no mass inside"
            << " the mesh: the thickness is 0 at all " << g.nCells[0]*n << " x "
            << g.nCells[1]*n << " columns of the mesh (system/blockMeshDict, "
            << span(mesh).c_str() << ')'
            << (bounded ? "; the release spans " + span(extent) : "").c_str()
            << "; allowed: a release with thickness h > 0 somewhere inside the"
            << " mesh" << exit(FatalIOError);
    }

    // The columns' volume h A, A as the solver's seed area
    const scalar area = g.dx[0]*g.dx[1]/(n*n);
    scalar volume = 0;
    for (const double hk : h)
    {
        volume += hk*area;
    }
    Info<< "Released: " << volume << " m^3 (" << rho*volume << " kg) in "
        << x.size() << " columns inside the mesh";

    const bool reachesOut =
        bounded
     && (
            extent.min().x() < mesh.min().x()
         || extent.max().x() > mesh.max().x()
         || extent.min().y() < mesh.min().y()
         || extent.max().y() > mesh.max().y()
        );
    if (reachesOut)
    {
        label stride, nNotFinite;
        const scalar lost = volumeOutside(g, n, stride, nNotFinite);
        Info<< "; the release spans " << span(extent).c_str() << ", beyond the"
            << " mesh (" << span(mesh).c_str() << "): ";
        if (lost < 0)
        {
            Info<< "the part outside the mesh is not released (too large to"
                << " sample its volume)";
        }
        else
        {
            Info<< (stride > 1 ? "about " : "") << lost << " m^3 ("
                << rho*lost << " kg, " << 100*lost/(volume + lost)
                << " % of the release) lies outside the mesh and is not"
                << " released";
        }
        if (nNotFinite)
        {
            Info<< " (" << nNotFinite << " samples outside the mesh, where the"
                << " thickness is not finite, are not counted)";
        }
    }
    Info<< endl;
}


Foam::scalar Foam::releaseModel::volumeOutside
(
    const gridGeometry& g,
    const label n,
    label& stride,
    label& nNotFinite
) const
{
    stride = 1;
    nNotFinite = 0;
    const boundBox extent(bounds());
    if (extent == boundBox::greatBox)
    {
        return -1;
    }

    // The columns' lattice, origin + (I + 1/2) s, continued over the extent
    const scalar s[2] = {g.dx[0]/n, g.dx[1]/n};
    double first[2], count[2];
    for (int d = 0; d < 2; ++d)
    {
        first[d] = std::floor((extent.min()[d] - g.origin[d])/s[d]);
        count[d] = std::ceil((extent.max()[d] - g.origin[d])/s[d]) - first[d];
    }
    // An extent beyond 1e12 columns per axis (a mistyped coordinate): not
    // sampled, and NaN or inf bounds neither
    if (!(count[0] <= 1e12 && count[1] <= 1e12))
    {
        return -1;
    }
    const double total = count[0]*count[1];
    // At most maxOutsideSamples points, and no axis beyond a label's count
    stride = label
    (
        std::max
        (
            {
                1.0,
                std::ceil(std::sqrt(total/maxOutsideSamples)),
                std::ceil(std::max(count[0], count[1])/maxOutsideSamples)
            }
        )
    );
    const label nA = label(std::ceil(count[0]/stride));
    const label nB = label(std::ceil(count[1]/stride));
    const scalar area = s[0]*s[1]*stride*stride;

    scalar volume = 0;
    fpTrapsHeld masked;
    for (label b = 0; b < nB; ++b)
    {
        const scalar yp = g.origin[1] + (first[1] + (b + 0.5)*stride)*s[1];
        const bool yInside = yp > g.origin[1] && yp < g.upper(1);
        for (label a = 0; a < nA; ++a)
        {
            const scalar xp =
                g.origin[0] + (first[0] + (a + 0.5)*stride)*s[0];
            if (yInside && xp > g.origin[0] && xp < g.upper(0))
            {
                continue;
            }
            const scalar hp = thicknessScale_*height(xp, yp);
            if (std::isfinite(hp))
            {
                volume += max(hp, scalar(0))*area;
            }
            else
            {
                ++nNotFinite;
            }
        }
    }
    return volume;
}


// ************************************************************************* //
