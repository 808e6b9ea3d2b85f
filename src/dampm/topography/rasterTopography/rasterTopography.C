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
            )
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


void Foam::topographyModels::rasterTopography::describe(Ostream& os) const
{
    os  << "raster (" << raster_->nx() << " x " << raster_->ny()
        << " samples of " << raster_->dx() << " m, offset "
        << raster_->offset() << ')';
}


// ************************************************************************* //
