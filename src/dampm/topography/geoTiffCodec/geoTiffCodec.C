/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "geoTiffCodec.H"
#include "OSspecific.H"
#include "error.H"
#include <dlfcn.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(geoTiffCodec, 0);
    defineRunTimeSelectionTable(geoTiffCodec, null);
}


namespace
{

//- The codec the library registers
const Foam::word codecType("GDAL");

//- The codec's library, beside libdampm.so (so that it is found whatever
//  LD_LIBRARY_PATH is)
Foam::fileName codecLibrary()
{
    const Foam::fileName name("libdampmGeoTiff.so");
    Dl_info info;
    if
    (
        dladdr(reinterpret_cast<void*>(&Foam::geoTiffCodec::New), &info)
     && info.dli_fname
    )
    {
        return Foam::fileName(info.dli_fname).path()/name;
    }
    return name;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::geoTiffCodec> Foam::geoTiffCodec::New()
{
    if
    (
        !nullConstructorTablePtr_
     || !nullConstructorTablePtr_->found(codecType)
    )
    {
        const fileName lib(codecLibrary());
        std::string message;
        if (!dlOpen(lib, message))
        {
            FatalErrorInFunction
                << "cannot load the GeoTIFF codec " << lib << " (GDAL), which"
                << " reads and writes .tif and .tiff rasters: "
                << message.c_str() << nl
                << "Build it with ./Allwmake; ESRI ASCII grids (.asc) need"
                << " no codec" << exit(FatalError);
        }
    }
    if
    (
        !nullConstructorTablePtr_
     || !nullConstructorTablePtr_->found(codecType)
    )
    {
        FatalErrorInFunction
            << "the library " << codecLibrary() << " provides no GeoTIFF"
            << " codec " << codecType << exit(FatalError);
    }
    return autoPtr<geoTiffCodec>((*nullConstructorTablePtr_)[codecType]());
}


// ************************************************************************* //
