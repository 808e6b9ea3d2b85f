/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "terrainGeometry.H"
#include "addToRunTimeSelectionTable.H"
#include "IOmanip.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "terrainRaster.H"
#include <cmath>
#include <limits>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace barrierGeometries
{
    defineTypeNameAndDebug(terrainGeometry, 0);
    addToRunTimeSelectionTable(barrierGeometry, terrainGeometry, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{

//- The barrier's dictionary, once it names its terrain (required here:
//  the flat default of dampmFoam would hide a forgotten keyword)
const Foam::dictionary& namingTerrain(const Foam::dictionary& dict)
{
    dict.get<Foam::word>("topography");
    return dict;
}

} // End anonymous namespace


Foam::barrierGeometries::terrainGeometry::terrainGeometry
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    barrierGeometry(name, dict, caseDir),
    topography_(topographyModel::New(namingTerrain(dict), caseDir))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

inline void Foam::barrierGeometries::terrainGeometry::gradient
(
    const scalar x,
    const scalar y,
    scalar& Zx,
    scalar& Zy
) const
{
    const vector2D gradZ = topography_->gradient(x, y);
    Zx = gradZ.x();
    Zy = gradZ.y();
}


inline void Foam::barrierGeometries::terrainGeometry::slope
(
    const terrainRaster* raster,
    const scalar x,
    const scalar y,
    scalar& Z,
    scalar& Zx,
    scalar& Zy
) const
{
    if (raster)
    {
        raster->evaluate(x, y, Z, Zx, Zy);
        return;
    }
    gradient(x, y, Zx, Zy);
    Z = topography_->Z(x, y);
}


void Foam::barrierGeometries::terrainGeometry::distance
(
    const pointField& points,
    scalarField& phi,
    vectorField& normal
) const
{
    phi.setSize(points.size());
    normal.setSize(points.size());

    // Each point its own (Z is pure): on several threads when not called
    // from a parallel region already
    const terrainRaster* const raster = topography_->raster();
    const label n = points.size();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        scalar Z0, Zx, Zy;
        slope(raster, points[i].x(), points[i].y(), Z0, Zx, Zy);
        const scalar norm = std::sqrt(1 + Zx*Zx + Zy*Zy);
        phi[i] = (points[i].z() - Z0)/norm;
        normal[i] = vector(-Zx, -Zy, 1)/norm;
    }
}


void Foam::barrierGeometries::terrainGeometry::deeperThan
(
    const pointField& points,
    const scalar depth,
    boolList& in
) const
{
    in.setSize(points.size());

    // Z first, and the gradient only below the depth (a point less deep
    // vertically is less deep along the normal); a raster gives both from
    // one evaluation (the guard's bisection tests each entered particle 30
    // times)
    const terrainRaster* const raster = topography_->raster();
    const label n = points.size();
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        const scalar x = points[i].x(), y = points[i].y();
        scalar Z0, Zx = 0, Zy = 0;
        if (raster)
        {
            raster->evaluate(x, y, Z0, Zx, Zy);
        }
        else
        {
            Z0 = topography_->Z(x, y);
        }
        const scalar dz = points[i].z() - Z0;
        const bool deep = dz < -depth;
        if (deep && !raster)
        {
            gradient(x, y, Zx, Zy);
        }
        in[i] = deep && dz/std::sqrt(1 + Zx*Zx + Zy*Zy) < -depth;
    }
}


void Foam::barrierGeometries::terrainGeometry::columnTops
(
    const gridGeometry& g,
    std::vector<double>& top
) const
{
    // deeperThan's first test, z - Z < -depth, fails wherever z is at
    // least the highest Z of the column. The column widened by far more
    // than the rounding that puts a point in it (gridGeometry::local)
    const auto edge = [&](const int d, const gridGeometry::index i)
    {
        const double x = g.nodeCoord(d, i);
        return 1e-9*(std::abs(x) + std::abs(g.origin[d]) + g.dx[d]);
    };
    top.assign(size_t(g.nCells[0])*g.nCells[1], 0.0);
    bool bounded = false;
    for (gridGeometry::index j = 0; j < g.nCells[1]; ++j)
    {
        for (gridGeometry::index i = 0; i < g.nCells[0]; ++i)
        {
            const double highest = topography_->highestOver
            (
                g.nodeCoord(0, i) - edge(0, i),
                g.nodeCoord(0, i + 1) + edge(0, i + 1),
                g.nodeCoord(1, j) - edge(1, j),
                g.nodeCoord(1, j + 1) + edge(1, j + 1)
            );
            // (Where the bound is infinite or NaN, every particle tested)
            const bool finite = std::isfinite(highest);
            top[i + g.nCells[0]*j] =
                finite ? highest : std::numeric_limits<double>::infinity();
            bounded = bounded || finite;
        }
    }
    if (!bounded)
    {
        top.clear();
    }
}


void Foam::barrierGeometries::terrainGeometry::checkGrid
(
    const gridGeometry& g
) const
{
    std::vector<double> Znodes(size_t(g.nodeStride[1])*g.nNodesDir[1]);
    topography_->sampleNodes(g, Znodes.data());

    label lowest, highest;
    topographyModel::meshRange(g, Znodes.data(), lowest, highest);
    // Over the whole domain (every processor's part)
    const scalar zMin = returnReduce(Znodes[lowest], minOp<scalar>());
    const scalar zMax = returnReduce(Znodes[highest], maxOp<scalar>());
    const scalar zLo = g.origin[2];
    const scalar zHi = g.domainUpper(2);
    const bool below = zMax < zLo;
    if (below || zMin > zHi)
    {
        FatalIOErrorInFunction(dict_)
            << setprecision(12)
            << "the terrain of barrier " << name_ << " (topography "
            << topography_->description().c_str() << ") lies wholly "
            << (below ? "below" : "above") << " the mesh: Z from "
            << zMin << " to " << zMax << " m over the"
            << " mesh's nodes, the mesh's z-range " << zLo << " to " << zHi
            << " m (the vertices of system/blockMeshDict). "
            << (
                   below
                 ? "The material would rest on the mesh's bottom and never"
                   " touch the terrain."
                 : "The whole mesh would be underground."
               )
            << " Allowed: a terrain that enters the mesh's z-range, Z >= "
            << zLo << " m at some node of the mesh and Z <= " << zHi
            << " m at some node"
            << exit(FatalIOError);
    }
}


void Foam::barrierGeometries::terrainGeometry::describe(Ostream& os) const
{
    os  << "terrain ";
    topography_->describe(os);
}


// ************************************************************************* //
