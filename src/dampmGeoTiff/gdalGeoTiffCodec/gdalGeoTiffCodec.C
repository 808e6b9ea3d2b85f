/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "gdalGeoTiffCodec.H"
#include "addToRunTimeSelectionTable.H"
#include "error.H"
#include <gdal.h>
#include <cpl_error.h>
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gdalGeoTiffCodec, 0);
    addToRunTimeSelectionTable(geoTiffCodec, gdalGeoTiffCodec, null);
}


namespace
{

//- A GDAL dataset closed when it goes out of scope
struct gdalDataset
{
    GDALDatasetH h;

    explicit gdalDataset(GDALDatasetH handle)
    :
        h(handle)
    {}

    gdalDataset(const gdalDataset&) = delete;
    void operator=(const gdalDataset&) = delete;

    ~gdalDataset()
    {
        if (h)
        {
            GDALClose(h);
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gdalGeoTiffCodec::gdalGeoTiffCodec()
{
    static const bool registered = (GDALAllRegister(), true);
    (void)registered;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gdalGeoTiffCodec::read(const fileName& file, image& img) const
{
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    gdalDataset ds(GDALOpen(file.c_str(), GA_ReadOnly));
    CPLPopErrorHandler();
    if (!ds.h)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << "GDAL cannot open the GeoTIFF " << file << ": "
            << CPLGetLastErrorMsg()
            << exit(FatalIOError);
    }

    img.hasTransform = GDALGetGeoTransform(ds.h, img.transform) == CE_None;
    img.nBands = GDALGetRasterCount(ds.h);
    img.nx = GDALGetRasterXSize(ds.h);
    img.ny = GDALGetRasterYSize(ds.h);
    const char* wkt = GDALGetProjectionRef(ds.h);
    img.projection = (wkt ? wkt : "");
    img.values.clear();
    if (!img.hasTransform || img.nBands < 1)
    {
        return;
    }

    GDALRasterBandH band = GDALGetRasterBand(ds.h, 1);
    int hasNoData = 0;
    img.noData = GDALGetRasterNoDataValue(band, &hasNoData);
    img.hasNoData = hasNoData;

    img.values.resize(size_t(img.nx)*img.ny);
    for (label r = 0; r < img.ny; ++r)
    {
        if
        (
            GDALRasterIO
            (
                band, GF_Read, 0, r, img.nx, 1,
                img.values.data() + size_t(img.nx)*r, img.nx, 1,
                GDT_Float64, 0, 0
            ) != CE_None
        )
        {
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
                << "GDAL cannot read row " << r + 1 << " of band 1 of the"
                << " GeoTIFF " << file << ": " << CPLGetLastErrorMsg()
                << exit(FatalIOError);
        }
    }
}


void Foam::gdalGeoTiffCodec::write
(
    const fileName& file,
    const image& img,
    const bool float64,
    const double noData
) const
{
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    bool created = false;
    {
        gdalDataset ds
        (
            driver
          ? GDALCreate
            (
                driver, file.c_str(), img.nx, img.ny, 1,
                float64 ? GDT_Float64 : GDT_Float32, nullptr
            )
          : nullptr
        );
        created = (ds.h != nullptr);
        if (created)
        {
            double gt[6];
            std::copy(img.transform, img.transform + 6, gt);
            GDALSetGeoTransform(ds.h, gt);
            if (!img.projection.empty())
            {
                GDALSetProjection(ds.h, img.projection.c_str());
            }
            GDALRasterBandH band = GDALGetRasterBand(ds.h, 1);
            GDALSetRasterNoDataValue(band, noData);
            for (label r = 0; r < img.ny; ++r)
            {
                // GDAL's one signature for reads and writes takes void*
                double* v =
                    const_cast<double*>(img.values.data()) + size_t(img.nx)*r;
                if
                (
                    GDALRasterIO
                    (
                        band, GF_Write, 0, r, img.nx, 1, v, img.nx, 1,
                        GDT_Float64, 0, 0
                    ) != CE_None
                )
                {
                    break;
                }
            }
        }
    }
    CPLPopErrorHandler();
    if (!created || CPLGetLastErrorType() >= CE_Failure)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << "GDAL cannot write the GeoTIFF " << file << ": "
            << CPLGetLastErrorMsg()
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
