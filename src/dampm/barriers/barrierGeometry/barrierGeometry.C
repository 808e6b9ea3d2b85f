/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrierGeometry.H"
#include "DynamicList.H"
#include "STLcheck.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(barrierGeometry, 0);
    defineRunTimeSelectionTable(barrierGeometry, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierGeometry::barrierGeometry
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    name_(name),
    dict_(dict),
    caseDir_(caseDir)
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::point Foam::barrierGeometry::readPoint
(
    const dictionary& dict,
    const word& key
)
{
    const point p = dict.get<point>(key);
    for (direction d = 0; d < 3; ++d)
    {
        if (!STLcheck::allowedCoordinate(p[d]))
        {
            FatalIOErrorInFunction(dict)
                << key << " = " << p << " is invalid; allowed: coordinates"
                << " within " << STLcheck::maxCoordinate << " m of the origin"
                << exit(FatalIOError);
        }
    }
    return p;
}


Foam::vector Foam::barrierGeometry::readDirection
(
    const dictionary& dict,
    const word& key
)
{
    const vector v = dict.get<vector>(key);
    const scalar scale = cmptMax(cmptMag(v));
    if (!(std::isfinite(scale) && scale > 0))
    {
        FatalIOErrorInFunction(dict)
            << key << " = " << v << " is invalid; allowed: a non-zero vector"
            << " with finite components" << exit(FatalIOError);
    }
    // Scaled first only where the square of the length would overflow or
    // underflow: otherwise v/|v| as it always was, bit for bit
    const vector u = (scale > 1e-150 && scale < 1e150) ? v : v/scale;
    return u/mag(u);
}


void Foam::barrierGeometry::planeNormals(vectorField& normals)
{
    for (vector& n : normals)
    {
        n.y() = 0;
        const scalar len = mag(n);
        n = len > SMALL ? n/len : Zero;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierGeometry::inside
(
    const pointField& points,
    boolList& in
) const
{
    deeperThan(points, 0, in);
}


void Foam::barrierGeometry::deeperThan
(
    const pointField& points,
    const scalar depth,
    boolList& in
) const
{
    scalarField phi;
    vectorField normal;
    distance(points, phi, normal);
    in.setSize(points.size());
    forAll(points, i)
    {
        in[i] = phi[i] < -depth;
    }
}


void Foam::barrierGeometry::firstCrossings
(
    const pointField& start,
    const pointField& end,
    scalarField& fraction
) const
{
    fraction.setSize(start.size());
    fraction = -1;
}


void Foam::barrierGeometry::nodeDistances
(
    const gridGeometry& g,
    const scalar band,
    const nodeVisitor& visit
) const
{
    const boundBox bb = bounds();
    const point lo = bb.min() - vector::uniform(band);
    const point hi = bb.max() + vector::uniform(band);

    gridGeometry::index first[3], last[3];
    for (int d = 0; d < 3; ++d)
    {
        // (in this part's lattice: a decomposed grid's part is shifted)
        const scalar l = max(g.local(d, lo[d]), -2.0);
        const scalar u = min(g.local(d, hi[d]), g.nCells[d] + 2.0);
        first[d] = gridGeometry::index(std::ceil(l)) + gridGeometry::nGhost;
        last[d] = gridGeometry::index(std::floor(u)) + gridGeometry::nGhost + 1;
        first[d] = max(first[d], 0);
        last[d] = min(last[d], g.nNodesDir[d]);
    }

    const gridGeometry::index nG = gridGeometry::nGhost;
    for (gridGeometry::index k = first[2]; k < last[2]; ++k)
    {
        DynamicList<point> pts;
        DynamicList<gridGeometry::index> ids;
        for (gridGeometry::index j = first[1]; j < last[1]; ++j)
        {
            for (gridGeometry::index i = first[0]; i < last[0]; ++i)
            {
                pts.append
                (
                    point
                    (
                        g.nodeCoord(0, i - nG),
                        g.nodeCoord(1, j - nG),
                        g.nodeCoord(2, k - nG)
                    )
                );
                ids.append(i + g.nodeStride[1]*j + g.nodeStride[2]*k);
            }
        }
        if (pts.empty())
        {
            continue;
        }
        scalarField phi;
        vectorField nrm;
        distance(pointField(pts), phi, nrm);
        if (g.plane)
        {
            planeNormals(nrm);
        }
        forAll(pts, pi)
        {
            visit(ids[pi], pts[pi], phi[pi], nrm[pi]);
        }
    }
}


// ************************************************************************* //
