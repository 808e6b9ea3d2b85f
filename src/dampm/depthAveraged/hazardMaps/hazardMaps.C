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
#include "primitiveEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::word Foam::hazardMaps::names[hazardMaps::nMaps] =
    {"maxHeight", "maxSpeed", "maxIntensity", "maxDischarge"};


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
    // The whole domain's nodes, on the master (which alone writes)
    const gridGeometry& g = grid_.geometry();
    const label nx = g.nCellsDomain[0] + 1;
    const label ny = g.nCellsDomain[1] + 1;
    scalarList samples;
    grid_.decomposition().gatherLattice(values.data(), samples);
    if (!Pstream::master())
    {
        return;
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
    const fvMesh& mesh = grid.mesh();
    const dimensionSet dims[nMaps] =
    {
        dimLength,
        dimVelocity,
        dimLength*dimVelocity*dimVelocity,
        dimLength*dimVelocity
    };
    for (int k = 0; k < nMaps; ++k)
    {
        maxima_[k].assign(n, 0.0);
        readMaximum(names[k], maxima_[k]);
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
    double* maxHeight = maxima_[0].data();
    double* maxSpeed = maxima_[1].data();
    double* maxIntensity = maxima_[2].data();
    double* maxDischarge = maxima_[3].data();
    grid_.geometry().forEachNodeRow
    (
        active,
        [&](const label first, const label last)
        {
            // The maps and the node arrays are distinct arrays: simd, so
            // that the row vectorises (the alias checks of nine arrays kept
            // the vectoriser out)
            #pragma omp simd
            for (label i = first; i < last; ++i)
            {
                const double h = nodes.h[i];
                const double w = Gx_[i]*nodes.vx[i] + Gy_[i]*nodes.vy[i];
                const double v2 = nodes.vx[i]*nodes.vx[i]
                  + nodes.vy[i]*nodes.vy[i] + w*w;
                const double v = std::sqrt(v2);
                maxHeight[i] = max(maxHeight[i], h);
                maxSpeed[i] = max(maxSpeed[i], v);
                maxIntensity[i] = max(maxIntensity[i], h*v2);
                maxDischarge[i] = max(maxDischarge[i], h*v);
            }
        }
    );
}


void Foam::hazardMaps::write()
{
    for (int k = 0; k < nMaps; ++k)
    {
        grid_.nodeToPoint(maxima_[k].data(), fields_[k]->primitiveFieldRef());
    }
}


void Foam::hazardMaps::writeRasters(const Time& runTime) const
{
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"hazardMaps"/runTime.timeName()
    );
    if (Pstream::master())
    {
        mkDir(dir);
    }
    for (int k = 0; k < nMaps; ++k)
    {
        writeRaster(dir, names[k], maxima_[k]);
    }
}


void Foam::hazardMaps::saveMaxima(dictionary& dict) const
{
    // The tokens the list's text parses into, N ( v ... ), made directly:
    // a list given as a value is printed and parsed back, number by number
    // (2 s a write for the 6.8e6 nodes of hillsideBarrier -full's maps).
    // The dictionary prints the same text (a zero as the label 0, as
    // parsed; the others as doubles, at the precision it is written with)
    for (int k = 0; k < nMaps; ++k)
    {
        const std::vector<double>& m = maxima_[k];
        List<token> tokens(m.size() + 3);
        tokens[0] = label(m.size());
        tokens[1] = token::BEGIN_LIST;
        for (size_t i = 0; i < m.size(); ++i)
        {
            tokens[i + 2] = m[i] == 0 ? token(label(0)) : token(m[i]);
        }
        tokens.last() = token::END_LIST;
        dict.set(new primitiveEntry(names[k], std::move(tokens)));
    }
}


void Foam::hazardMaps::loadMaxima(const dictionary& dict)
{
    for (int k = 0; k < nMaps; ++k)
    {
        const scalarList values(dict.get<scalarList>(names[k]));
        if (values.size() != label(maxima_[k].size()))
        {
            FatalIOErrorInFunction(dict)
                << names[k] << " has " << values.size() << " values; the"
                << " run-out grid has " << maxima_[k].size() << " nodes"
                << exit(FatalIOError);
        }
        std::copy(values.begin(), values.end(), maxima_[k].begin());
    }
}


// ************************************************************************* //
