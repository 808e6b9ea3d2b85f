/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "rasterTopography.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "IOmanip.H"
#include <cstdio>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace topographyModels
{
    defineTypeNameAndDebug(rasterTopography, 0);
    addToRunTimeSelectionTable(topographyModel, rasterTopography, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::topographyModels::rasterTopography::rasterTopography
(
    const dictionary& coeffs,
    const fileName& caseDir
)
:
    topographyModel(coeffs, caseDir),
    raster_
    (
        new terrainRaster
        (
            caseFile("file"),
            terrainRaster::noDataPolicyNames.getOrDefault
            (
                "noData",
                coeffs,
                terrainRaster::noDataPolicy::fail
            ),
            maxAbsZ
        )
    )
{
    knownKeywords::add(coeffs, {"noData", "offset"});
    raster_->setOffset
    (
        coeffs.getOrDefault<vector2D>("offset", raster_->mapLowerLeft())
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::topographyModels::rasterTopography::Z
(
    const scalar x,
    const scalar y
) const
{
    return raster_->Z(x, y);
}


Foam::vector2D Foam::topographyModels::rasterTopography::gradient
(
    const scalar x,
    const scalar y
) const
{
    scalar Z, dZdx, dZdy;
    raster_->evaluate(x, y, Z, dZdx, dZdy);
    return vector2D(dZdx, dZdy);
}


void Foam::topographyModels::rasterTopography::checkCovers
(
    const gridGeometry& g
) const
{
    // The raster's cells, local coordinates, and how far the mesh reaches
    // beyond them on each side (west, east, south, north)
    const terrainRaster& r = *raster_;
    const boundBox cells(r.cellBounds());
    const scalar lo[2] = {cells.min().x(), cells.min().y()};
    const scalar hi[2] = {cells.max().x(), cells.max().y()};
    const scalar beyond[4] =
    {
        lo[0] - g.origin[0], g.domainUpper(0) - hi[0],
        lo[1] - g.origin[1], g.domainUpper(1) - hi[1]
    };
    const scalar cell[4] = {r.dx(), r.dx(), r.dy(), r.dy()};
    const char* const sides[4] = {"west", "east", "south", "north"};

    // Half a raster cell past its cells: the edge samples' own reach (the
    // rounding of map coordinates in an export often leaves a sliver)
    scalar worst = 0;
    string where;
    for (int s = 0; s < 4; ++s)
    {
        if (beyond[s] > 1e-9*cell[s])
        {
            worst = max(worst, beyond[s]/cell[s]);
            where += (where.empty() ? "" : ", ") + string(sides[s]) + ' '
                + Foam::name(beyond[s]) + " m";
        }
    }
    if (worst > 0.5)
    {
        FatalIOErrorInFunction(coeffs_)
            << setprecision(12)
            << "the raster " << r.file() << " does not cover the mesh: its"
            << " cells span x " << lo[0] << " to " << hi[0] << ", y " << lo[1]
            << " to " << hi[1] << " m (local coordinates: map coordinates"
            << " minus the offset " << r.offset() << "), the mesh"
            << " (system/blockMeshDict) x " << g.origin[0] << " to "
            << g.domainUpper(0) << ", y " << g.origin[1] << " to " << g.domainUpper(1)
            << " m, beyond the raster by " << where.c_str() << "; allowed: a"
            << " mesh within the raster's cells, give or take half a raster"
            << " cell (" << r.dx()/2 << " x " << r.dy()/2 << " m). Check the"
            << " keyword offset and the vertices of system/blockMeshDict"
            << exit(FatalIOError);
    }
    if (worst > 0)
    {
        char cells[16];
        std::snprintf(cells, sizeof(cells), "%.2g", worst);
        Info<< "rasterTopography: the mesh reaches beyond the cells of the"
            << " raster " << r.file() << " by " << where.c_str() << " (at"
            << " most " << cells << " raster cells); Z there continues the"
            << " edge samples" << endl;
    }
}


void Foam::topographyModels::rasterTopography::describe(Ostream& os) const
{
    os  << "raster (" << raster_->nx() << " x " << raster_->ny()
        << " samples of " << raster_->dx() << " m, offset "
        << raster_->offset() << ')';
}


// ************************************************************************* //
