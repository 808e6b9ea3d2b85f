/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "rasterRelease.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace releaseModels
{
    defineTypeNameAndDebug(rasterRelease, 0);
    addToRunTimeSelectionTable(releaseModel, rasterRelease, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::releaseModels::rasterRelease::rasterRelease
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir
)
:
    releaseModel(dict, topography, caseDir)
{
    knownKeywords::add(dict, {"file"});

    fileName file(dict.get<fileName>("file"));
    file.expand();
    raster_.reset
    (
        new terrainRaster
        (
            file.isAbsolute() ? file : caseDir/file,
            terrainRaster::noDataPolicy::zero,
            maxHeight
        )
    );
    raster_->setOffset(topography.mapOffset());
    if (raster_->minValue() < 0)
    {
        FatalIOErrorInFunction(dict)
            << "release thickness raster " << file << " has negative values"
            << " (min " << raster_->minValue() << " m); allowed: >= 0"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::releaseModels::rasterRelease::height
(
    const scalar x,
    const scalar y
) const
{
    const boundBox bb(bounds());
    if
    (
        x < bb.min().x() || x > bb.max().x()
     || y < bb.min().y() || y > bb.max().y()
    )
    {
        return 0;
    }
    return max(raster_->Z(x, y), scalar(0));
}


Foam::boundBox Foam::releaseModels::rasterRelease::bounds() const
{
    return raster_->cellBounds();
}


void Foam::releaseModels::rasterRelease::describe(Ostream& os) const
{
    const boundBox bb(bounds());
    os  << "raster (" << raster_->nx() << " x " << raster_->ny()
        << " samples of " << raster_->dx() << " m over x " << bb.min().x()
        << " to " << bb.max().x() << ", y " << bb.min().y() << " to "
        << bb.max().y() << " m; NODATA and outside: zero thickness, U = "
        << U_ << ')';
}


// ************************************************************************* //
