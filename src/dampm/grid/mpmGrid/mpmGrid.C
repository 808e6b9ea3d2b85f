/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "mpmGrid.H"
#include "emptyPolyPatch.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"
#include "boundBox.H"

#include <cstdio>
#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(mpmGrid, 0);

    //- Relative tolerance (of the cell size) for lattice checks
    static const scalar latticeTol = 1e-6;

    //- The significant digits of an ASCII mesh at writePrecision 12
    static const int meshDigits = 12;

    //- A box corner as an ASCII mesh of meshDigits holds it, when that
    //  moves it by round-off only (less than a billionth of the cell size
    //  h, far inside the lattice checks): a binary mesh carries blockMesh's
    //  round-off (274.00000000000006 for 274), which a 3D impact amplifies,
    //  so both formats give one lattice. Rounding is monotonic: the box of
    //  the rounded points is the rounded box, and a corner of meshDigits or
    //  fewer is kept as it is. A corner of more digits that rounding would
    //  move further (5123456.789012345 m) is kept as it is too
    static scalar asWritten(const scalar x, const scalar h)
    {
        char text[32];
        std::snprintf(text, sizeof(text), "%.*g", meshDigits, x);
        const scalar rounded = std::strtod(text, nullptr);
        return mag(rounded - x) < 1e-3*latticeTol*h ? rounded : x;
    }

    //- The whole domain's origin as a point
    static point originOf(const gridGeometry& g)
    {
        return point(g.origin[0], g.origin[1], g.origin[2]);
    }

    //- The box of cell 0's points, from the faces beside it: the mesh's
    //  cell-to-point addressing for every cell is not built for one cell
    static boundBox firstCellBox(const polyMesh& mesh)
    {
        const pointField& pts = mesh.points();
        const faceList& faces = mesh.faces();
        const labelList& own = mesh.faceOwner();
        const labelList& nbr = mesh.faceNeighbour();
        boundBox bb(boundBox::invertedBox);
        forAll(faces, facei)
        {
            if (own[facei] == 0 || (facei < nbr.size() && nbr[facei] == 0))
            {
                for (const label pointi : faces[facei])
                {
                    bb.add(pts[pointi]);
                }
            }
        }
        return bb;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::mpmGrid::notStructured(const string& why) const
{
    FatalErrorInFunction
        << "The mesh " << mesh_.time().path()/mesh_.dbDir()
        << " is not a uniform, axis-aligned structured block: " << why
        << nl << "    dampm needs one blockMesh block of hexahedra with"
        << " axis-aligned edges and simpleGrading (1 1 1)"
        << " (see system/blockMeshDict)." << exit(FatalError);
    ::abort();
}


void Foam::mpmGrid::detectEmpty(const label n[3])
{
    // Axes with empty patches normal to them
    bool empty[3] = {false, false, false};
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(pp) || pp.empty())
        {
            continue;
        }
        const vector n = pp.faceAreas()[0]/mag(pp.faceAreas()[0]);
        const direction d = n.x()*n.x() > 0.5 ? 0 : (n.y()*n.y() > 0.5 ? 1 : 2);
        if (mag(n[d]) < 1 - latticeTol || d == 0)
        {
            notStructured
            (
                "empty patch " + pp.name() + " is not normal to z (a 2D"
                " grid, bed in the x-y plane) or to y (a plane slice in x-z)"
            );
        }
        empty[d] = true;
    }
    if (empty[1] && empty[2])
    {
        notStructured("empty patches normal to y and to z; allowed: one axis");
    }
    for (const direction d : {1, 2})
    {
        if (empty[d] && n[d] != 1)
        {
            notStructured
            (
                word(d == 2 ? "a 2D mesh (empty patches normal to z) must be"
                " one cell thick in z" : "a plane slice (empty patches normal"
                " to y) must be one cell across y")
            );
        }
    }
    geom_.dim = empty[2] ? 2 : 3;
    geom_.plane = empty[1];
}


void Foam::mpmGrid::setGeometry()
{
    const pointField& pts = mesh_.points();
    if (mesh_.nCells() == 0)
    {
        notStructured("it has no cells");
    }
    const boundBox localBb(pts, false);

    // The spacing from the first cell's bounding box; the lattice checks
    // below catch any other cell size
    const boundBox cellBb(firstCellBox(mesh_));
    vector h(cellBb.span());
    if (decomposed())
    {
        // Every processor rounds the box alike
        reduce(h, minOp<vector>());
    }

    // The whole domain's box: on a decomposed case the same numbers as the
    // undecomposed mesh's, so the lattice is that of a serial run
    boundBox& bb = bounds_;
    bb = boundBox(pts, decomposed());
    for (direction d = 0; d < 3; ++d)
    {
        bb.min()[d] = asWritten(bb.min()[d], h[d]);
        bb.max()[d] = asWritten(bb.max()[d], h[d]);
    }

    label n[3], nOwn[3];
    for (direction d = 0; d < 3; ++d)
    {
        geom_.origin[d] = bb.min()[d];
        geom_.dx[d] = cellBb.span()[d];
        if (!(geom_.dx[d] > 0))
        {
            notStructured("cell 0 has zero extent along axis " + Foam::name(d));
        }
        const scalar ratio = bb.span()[d]/geom_.dx[d];
        n[d] = label(std::round(ratio));
        if (mag(ratio - n[d]) > 1e3*latticeTol*ratio)
        {
            notStructured
            (
                "the domain length along axis " + Foam::name(d) + " ("
              + Foam::name(bb.span()[d]) + ") is not a whole number of cell"
                " sizes (" + Foam::name(geom_.dx[d]) + "): graded cells?"
            );
        }
        // Spacing from the whole span: less round-off than one cell
        geom_.dx[d] = bb.span()[d]/n[d];
        geom_.nCells[d] = n[d];
        nOwn[d] = label(std::round(localBb.span()[d]/geom_.dx[d]));
        ownLo_[d] =
            label(std::round((localBb.min()[d] - bb.min()[d])/geom_.dx[d]));
    }

    if (label(nOwn[0])*nOwn[1]*nOwn[2] != mesh_.nCells())
    {
        if (decomposed())
        {
            FatalErrorInFunction
                << "processor " << Pstream::myProcNo() << " of the decomposed"
                << " case " << mesh_.time().globalPath() << " holds "
                << mesh_.nCells() << " cells that are not one box of the"
                << " structured grid (its bounding box spans " << nOwn[0]
                << " x " << nOwn[1] << " x " << nOwn[2] << " cells): dampm"
                << " runs on boxes only. In system/decomposeParDict use"
                << " method simple or hierarchical with subdomain counts n"
                << " that divide the cell counts (" << n[0] << ' ' << n[1]
                << ' ' << n[2] << "), or the method manual that"
                << " tools/python/decomposition.py writes for any count;"
                << " allowed methods: simple, hierarchical, manual (boxes)"
                << exit(FatalError);
        }
        notStructured
        (
            "it has " + Foam::name(mesh_.nCells()) + " cells, but its bounding"
            " box and first cell give " + Foam::name(n[0]) + " x "
          + Foam::name(n[1]) + " x " + Foam::name(n[2])
          + ": graded, skewed or not a single box"
        );
    }

    detectEmpty(nOwn);
    setPart(nOwn);
    geom_.finalise();
}


void Foam::mpmGrid::setPart(const label nOwn[3])
{
    // Serial: the part is the domain
    for (int d = 0; d < 3; ++d)
    {
        ownHi_[d] = ownLo_[d] + nOwn[d];
    }
    if (!decomposed())
    {
        return;
    }

    // A part: its own cells and one cell more on each side that another
    // processor holds, so that every node its particles reach (one beyond
    // its cells' nodes) has its full-width neighbours (terrain gradients)
    geom_.decomposed = true;
    for (int d = 0; d < geom_.dim; ++d)
    {
        // A particle's stencil reaches two nodes beyond its cell: a part
        // thinner than three cells along a cut would not see its
        // neighbour's neighbour
        const label nMin = 3;
        if (nOwn[d] < nMin && nOwn[d] < geom_.nCells[d])
        {
            FatalErrorInFunction
                << "processor " << Pstream::myProcNo() << " of the decomposed"
                << " case " << mesh_.time().globalPath() << " holds "
                << nOwn[d] << " cell" << (nOwn[d] > 1 ? "s" : "")
                << " along axis " << "xyz"[d] << " of the " << geom_.nCells[d]
                << " there; allowed: at least " << nMin << " along every"
                << " axis the decomposition cuts (a particle's stencil"
                << " reaches two nodes beyond its cell). Use fewer"
                << " subdomains along that axis in system/decomposeParDict,"
                << " or tools/python/decomposition.py, which keeps them"
                << " that thick" << exit(FatalError);
        }
    }
    for (int d = 0; d < 3; ++d)
    {
        geom_.nCellsDomain[d] = geom_.nCells[d];
        const label lo = (d < geom_.dim && ownLo_[d] > 0) ? 1 : 0;
        const label hi = (d < geom_.dim && ownHi_[d] < geom_.nCells[d]) ? 1 : 0;
        geom_.offset[d] = ownLo_[d] - lo;
        geom_.nCells[d] = nOwn[d] + lo + hi;
    }
}


void Foam::mpmGrid::mapPoints()
{
    const pointField& pts = mesh_.points();
    const label nLattice =
        (ownHi_[0] - ownLo_[0] + 1)*(ownHi_[1] - ownLo_[1] + 1)
       *(is2D() ? 2 : ownHi_[2] - ownLo_[2] + 1);
    if (pts.size() != nLattice)
    {
        notStructured
        (
            "it has " + Foam::name(pts.size()) + " points instead of "
          + Foam::name(nLattice)
        );
    }

    pointNode_.setSize(pts.size());
    forAll(pts, pointi)
    {
        label ijk[3];
        for (direction d = 0; d < 3; ++d)
        {
            const scalar xi = (pts[pointi][d] - geom_.origin[d])/geom_.dx[d];
            ijk[d] = label(std::round(xi));
            if (mag(xi - ijk[d]) > latticeTol*max(scalar(1), mag(xi)))
            {
                notStructured
                (
                    "point " + Foam::name(pointi) + " at "
                  + Foam::name(pts[pointi]) + " is off the uniform lattice"
                    " (graded or skewed cells)"
                );
            }
        }
        pointNode_[pointi] = geom_.nodeIndex
        (
            ijk[0] - geom_.offset[0], ijk[1] - geom_.offset[1],
            ijk[2] - geom_.offset[2]
        );
    }
}


void Foam::mpmGrid::cellCentresAndVolumes
(
    vectorField& C,
    scalarField& V
) const
{
    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nbr = mesh_.faceNeighbour();
    const point o(originOf(geom_));
    C.setSize(mesh_.nCells());
    V.setSize(mesh_.nCells());
    C = Zero;
    V = Zero;
    labelList nFaces(mesh_.nCells(), Zero);
    forAll(faces, facei)
    {
        const face& f = faces[facei];
        vector c(Zero);
        for (const label pointi : f)
        {
            c += pts[pointi] - o;
        }
        c /= f.size();
        vector S(Zero);
        forAll(f, i)
        {
            S += 0.5*((pts[f[i]] - o - c) ^ (pts[f.nextLabel(i)] - o - c));
        }
        const scalar v = (c & S)/3;
        C[own[facei]] += c;
        V[own[facei]] += v;
        ++nFaces[own[facei]];
        if (facei < nbr.size())
        {
            C[nbr[facei]] += c;
            V[nbr[facei]] -= v;
            ++nFaces[nbr[facei]];
        }
    }
    forAll(C, celli)
    {
        C[celli] /= max(nFaces[celli], 1);
    }
}


void Foam::mpmGrid::mapCells()
{
    vectorField C;
    scalarField V;
    cellCentresAndVolumes(C, V);
    const point o(originOf(geom_));
    const scalar cellVol = geom_.dx[0]*geom_.dx[1]*geom_.dx[2];

    meshCell_.setSize(nCells(), -1);
    structuredCell_.setSize(mesh_.nCells());

    forAll(C, celli)
    {
        label ijk[3];
        for (direction d = 0; d < 3; ++d)
        {
            const scalar xi = C[celli][d]/geom_.dx[d] - 0.5;
            ijk[d] = label(std::round(xi));
            if (mag(xi - ijk[d]) > 1e2*latticeTol*max(scalar(1), mag(xi)))
            {
                notStructured
                (
                    "the centre " + Foam::name(C[celli] + o) + " of cell "
                  + Foam::name(celli) + " is not a structured cell centre"
                    " (graded or skewed cells)"
                );
            }
        }
        if (mag(V[celli] - cellVol) > 1e2*latticeTol*cellVol)
        {
            notStructured
            (
                "cell " + Foam::name(celli) + " has volume "
              + Foam::name(V[celli]) + " instead of " + Foam::name(cellVol)
            );
        }
        const label sc = geom_.cellIndex
        (
            ijk[0] - geom_.offset[0], ijk[1] - geom_.offset[1],
            is2D() ? 0 : ijk[2] - geom_.offset[2]
        );
        if (meshCell_[sc] != -1)
        {
            notStructured
            (
                "cells " + Foam::name(meshCell_[sc]) + " and "
              + Foam::name(celli) + " have the same centre"
            );
        }
        meshCell_[sc] = celli;
        structuredCell_[celli] = sc;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpmGrid::mpmGrid(const fvMesh& mesh, const bool whole)
:
    mesh_(mesh),
    whole_(whole)
{
    setGeometry();
    mapPoints();
    mapCells();
    decomposition_.reset(new gridDecomposition(*this));

    const label* n = geom_.nCellsDomain;
    Info<< "mpmGrid: " << (is2D() ? "2D " : "3D ") << n[0] << " x " << n[1];
    if (!is2D())
    {
        Info<< " x " << n[2];
    }
    Info<< " cells, spacing (" << geom_.dx[0] << ' ' << geom_.dx[1];
    if (!is2D())
    {
        Info<< ' ' << geom_.dx[2];
    }
    Info<< ") m";
    if (geom_.plane)
    {
        Info<< ", a plane slice (empty patches normal to y): plane flow in"
            << " x-z, " << geom_.dx[1] << " m across";
    }
    Info<< ", origin (" << geom_.origin[0] << ' ' << geom_.origin[1] << ' '
        << geom_.origin[2] << ")";
    if (decomposed())
    {
        Info<< ", decomposed into " << Pstream::nProcs() << " boxes";
    }
    else
    {
        Info<< ", " << nNodes() << " nodes with ghosts";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::mpmGrid::findCell(const point& p) const
{
    if (!geom_.inside(p.x(), p.y(), p.z()))
    {
        return -1;
    }
    if
    (
        is2D()
     && (p.z() < geom_.origin[2] || p.z() > geom_.origin[2] + geom_.dx[2])
    )
    {
        return -1;
    }
    return meshCell_[geom_.cellOf(p.x(), p.y(), p.z())];
}


Foam::point Foam::mpmGrid::nodePosition(const label nodei) const
{
    double x[3];
    geom_.nodePosition(nodei, x);
    return point(x[0], x[1], x[2]);
}


void Foam::mpmGrid::wallSides(bool wall[3][2]) const
{
    const gridGeometry& g = geom_;
    // Sides of the domain with faces of a wall patch (+1) or another patch
    // (+2), over every processor's patches
    labelList kinds(6, Zero);
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp))
        {
            continue;
        }
        const int kind = isA<wallPolyPatch>(pp) ? 1 : 2;
        for (const face& f : pp)
        {
            const point c = f.centre(mesh_.points());
            for (int d = 0; d < g.dim; ++d)
            {
                const scalar tol = 1e-6*g.dx[d];
                if (mag(c[d] - g.origin[d]) < tol)
                {
                    kinds[2*d] |= kind;
                }
                if (mag(c[d] - g.domainUpper(d)) < tol)
                {
                    kinds[2*d + 1] |= kind;
                }
            }
        }
    }
    Pstream::listCombineGather(kinds, bitOrEqOp<label>());
    Pstream::listCombineScatter(kinds);
    const char* axes = "xyz";
    for (int d = 0; d < 3; ++d)
    {
        for (int s = 0; s < 2; ++s)
        {
            if (kinds[2*d + s] == 3)
            {
                FatalErrorInFunction
                    << "the " << axes[d] << (s ? " max" : " min")
                    << " side of the domain has faces of wall and of open"
                    << " patches; allowed: one type per side (see"
                    << " system/blockMeshDict)" << exit(FatalError);
            }
            wall[d][s] = (kinds[2*d + s] == 1);
        }
    }
}


void Foam::mpmGrid::nodeToPoint
(
    const double* nodeValues,
    scalarField& pf
) const
{
    pf.setSize(pointNode_.size());
    forAll(pointNode_, pointi)
    {
        pf[pointi] = nodeValues[pointNode_[pointi]];
    }
}


void Foam::mpmGrid::nodeToPoint
(
    const double* nodeX,
    const double* nodeY,
    const double* nodeZ,
    vectorField& pf
) const
{
    pf.setSize(pointNode_.size());
    forAll(pointNode_, pointi)
    {
        const label nodei = pointNode_[pointi];
        pf[pointi] = vector
        (
            nodeX ? nodeX[nodei] : 0,
            nodeY ? nodeY[nodei] : 0,
            nodeZ ? nodeZ[nodei] : 0
        );
    }
}


// ************************************************************************* //
