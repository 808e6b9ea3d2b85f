/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "hazardMaps.H"
#include "terrainRaster.H"
#include "OSspecific.H"
#include "mpmTime.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::hazardMaps::readMaximum
(
    const word& name,
    std::vector<double>& values
)
{
    const fvMesh& mesh = grid_.mesh();
    const IOobject io
    (
        name,
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!isFile(io.objectPath()))
    {
        // A time directory written by a run holds its maxima
        if
        (
            mpmTime::state(mesh.time().timePath())
         == mpmTime::directoryState::complete
        )
        {
            FatalErrorInFunction
                << "hazard map " << io.objectPath() << " is missing: the"
                << " run cannot continue from time " << mesh.time().timeName()
                << " without its maxima" << exit(FatalError);
        }
        return;
    }
    const pointScalarField previous(io, pointMesh::New(mesh));
    const labelList& pointNode = grid_.pointNode();
    forAll(pointNode, pointi)
    {
        values[pointNode[pointi]] = previous[pointi];
    }
    Info<< "hazardMaps: continuing " << name << " of time "
        << mesh.time().timeName() << endl;
}


void Foam::hazardMaps::writeRaster
(
    const fileName& dir,
    const word& name,
    const std::vector<double>& values
) const
{
    const gridGeometry& g = grid_.geometry();
    const label nx = g.nCells[0] + 1;
    const label ny = g.nCells[1] + 1;
    scalarList samples(nx*ny);
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            samples[i + nx*j] = values[g.nodeIndex(i, j, 0)];
        }
    }
    const terrainRaster* terrain = topography_.raster();
    const terrainRaster raster
    (
        vector2D(g.origin[0], g.origin[1]),
        g.dx[0],
        g.dx[1],
        nx,
        ny,
        samples,
        topography_.mapOffset(),
        terrain ? terrain->projection() : string::null
    );
    raster.writeAsc(dir/(name + ".asc"));
    const word ext(terrain ? terrain->file().ext() : word());
    if (raster.hasProjection() || ext == "tif" || ext == "tiff")
    {
        raster.writeGeoTiff(dir/(name + ".tif"));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hazardMaps::hazardMaps
(
    const mpmGrid& grid,
    const topographyModel& topography,
    const double* Znodes
)
:
    grid_(grid),
    topography_(topography)
{
    const gridGeometry& g = grid.geometry();
    const label n = g.nNodes();
    Gx_.assign(n, 0.0);
    Gy_.assign(n, 0.0);
    nodeTerrainGradient(g, Znodes, Gx_.data(), Gy_.data());
    maxHeight_.assign(n, 0.0);
    maxSpeed_.assign(n, 0.0);
    maxIntensity_.assign(n, 0.0);
    readMaximum("maxHeight", maxHeight_);
    readMaximum("maxSpeed", maxSpeed_);
    readMaximum("maxIntensity", maxIntensity_);

    const fvMesh& mesh = grid.mesh();
    const word names[3] = {"maxHeight", "maxSpeed", "maxIntensity"};
    const dimensionSet dims[3] =
        {dimLength, dimVelocity, dimLength*dimVelocity*dimVelocity};
    for (int k = 0; k < 3; ++k)
    {
        fields_[k].reset
        (
            new exactPrecisionIO<pointScalarField>
            (
                IOobject
                (
                    names[k],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                pointMesh::New(mesh),
                dimensionedScalar(dims[k], Zero)
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hazardMaps::update
(
    const shallowGrid& nodes,
    const nodeBox& active
)
{
    grid_.geometry().forEachNodeRow
    (
        active,
        [&](const label first, const label last)
        {
            for (label i = first; i < last; ++i)
            {
                const double h = nodes.h[i];
                const double w = Gx_[i]*nodes.vx[i] + Gy_[i]*nodes.vy[i];
                const double v2 = nodes.vx[i]*nodes.vx[i]
                  + nodes.vy[i]*nodes.vy[i] + w*w;
                maxHeight_[i] = max(maxHeight_[i], h);
                maxSpeed_[i] = max(maxSpeed_[i], std::sqrt(v2));
                maxIntensity_[i] = max(maxIntensity_[i], h*v2);
            }
        }
    );
}


void Foam::hazardMaps::write()
{
    const std::vector<double>* maxima[3] =
        {&maxHeight_, &maxSpeed_, &maxIntensity_};
    for (int k = 0; k < 3; ++k)
    {
        grid_.nodeToPoint(maxima[k]->data(), fields_[k]->primitiveFieldRef());
    }

    const Time& runTime = grid_.mesh().time();
    writeRasters
    (
        runTime.globalPath()/"postProcessing"/"hazardMaps"/runTime.timeName()
    );
}


void Foam::hazardMaps::writeRasters(const fileName& dir) const
{
    mkDir(dir);
    writeRaster(dir, "maxHeight", maxHeight_);
    writeRaster(dir, "maxSpeed", maxSpeed_);
    writeRaster(dir, "maxIntensity", maxIntensity_);
}


void Foam::hazardMaps::saveMaxima(dictionary& dict) const
{
    dict.set("maxHeight", scalarList(maxHeight_.begin(), maxHeight_.end()));
    dict.set("maxSpeed", scalarList(maxSpeed_.begin(), maxSpeed_.end()));
    dict.set
    (
        "maxIntensity",
        scalarList(maxIntensity_.begin(), maxIntensity_.end())
    );
}


void Foam::hazardMaps::loadMaxima(const dictionary& dict)
{
    std::vector<double>* maxima[3] =
        {&maxHeight_, &maxSpeed_, &maxIntensity_};
    const word names[3] = {"maxHeight", "maxSpeed", "maxIntensity"};
    for (int k = 0; k < 3; ++k)
    {
        const scalarList values(dict.get<scalarList>(names[k]));
        if (values.size() != label(maxima[k]->size()))
        {
            FatalIOErrorInFunction(dict)
                << names[k] << " has " << values.size() << " values; the"
                << " run-out grid has " << maxima[k]->size() << " nodes"
                << exit(FatalIOError);
        }
        std::copy(values.begin(), values.end(), maxima[k]->begin());
    }
}


// ************************************************************************* //
