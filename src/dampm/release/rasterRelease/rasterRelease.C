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
            terrainRaster::noDataPolicy::fill
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
    const boundBox bb(raster_->bounds());
    if
    (
        x < bb.min().x() - 0.5*raster_->dx()
     || x > bb.max().x() + 0.5*raster_->dx()
     || y < bb.min().y() - 0.5*raster_->dy()
     || y > bb.max().y() + 0.5*raster_->dy()
    )
    {
        return 0;
    }
    return max(raster_->Z(x, y), scalar(0));
}


void Foam::releaseModels::rasterRelease::describe(Ostream& os) const
{
    os  << "raster (" << raster_->nx() << " x " << raster_->ny()
        << " samples of " << raster_->dx() << " m, U = " << U_ << ')';
}


// ************************************************************************* //
