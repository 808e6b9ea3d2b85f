/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "triSurfaceGeometry.H"
#include "errorsThrown.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "OSspecific.H"
#include "STLcheck.H"
#include <cstdint>
#include <cstring>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace barrierGeometries
{
    defineTypeNameAndDebug(triSurfaceGeometry, 0);
    addToRunTimeSelectionTable(barrierGeometry, triSurfaceGeometry, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::barrierGeometries::triSurfaceGeometry::readSurface()
{
    const fileName path = caseDir_/"constant"/"triSurface"/file_;
    if (!isFile(path))
    {
        FatalIOErrorInFunction(dict_)
            << "file " << file_ << ": no such file " << path
            << exit(FatalIOError);
    }

    // An STL file is checked before OpenFOAM's reader sees it (STLcheck):
    // its scanner exits the process on a binary file whose header starts
    // with "solid", and a NaN vertex raises a signal when points are merged
    const word ext = path.ext();
    const bool stl = (ext == "stl" || ext == "STL");
    bool binary = false;
    if (stl)
    {
        const STLcheck check(path);
        if (!check.valid())
        {
            FatalIOErrorInFunction(dict_)
                << "file " << file_ << ": cannot read a triangulated surface"
                << " from " << path << ": " << check.error().c_str()
                << exit(FatalIOError);
        }
        binary = check.binary();
    }

    // The readers stop with their own message on a broken file: catch it
    // and say which barrier and keyword it came from
    string why;
    try
    {
        const errorsThrown throwing;
        surface_.reset
        (
            stl
          ? new triSurface(path, word(binary ? "stlb" : "stl"))
          : new triSurface(path)
        );
    }
    catch (const Foam::error& err)
    {
        why = err.message();
    }

    if (!why.empty() || !surface_ || surface_->empty())
    {
        FatalIOErrorInFunction(dict_)
            << "file " << file_ << ": cannot read a triangulated surface"
            << " from " << path << (why.empty() ? " (no triangles)" : ": ")
            << why.c_str() << exit(FatalIOError);
    }

    // Other formats (STLcheck checked STL files): the points as read
    // (their bits: a signalling NaN is not loaded)
    const pointField& pts = surface_->points();
    for (label pointi = 0; !stl && pointi < pts.size(); ++pointi)
    {
        for (direction d = 0; d < 3; ++d)
        {
            std::uint64_t bits;
            std::memcpy(&bits, &pts[pointi][d], 8);
            if
            (
                ((bits >> 52) & 0x7ff) == 0x7ff
             || !STLcheck::allowedCoordinate(pts[pointi][d])
            )
            {
                FatalIOErrorInFunction(dict_)
                    << "file " << file_ << ": point " << pointi << " of "
                    << path << " has a coordinate that is not finite or"
                    << " beyond " << STLcheck::maxCoordinate << " m; allowed:"
                    << " finite coordinates within " << STLcheck::maxCoordinate
                    << " m of the origin" << exit(FatalIOError);
            }
        }
    }

    label nOpen = 0;
    for (const labelList& ef : surface_->edgeFaces())
    {
        nOpen += (ef.size() != 2);
    }
    if (nOpen)
    {
        FatalIOErrorInFunction(dict_)
            << "file " << file_ << ": the surface in " << path << " is not"
            << " closed (" << nOpen << " edges not shared by exactly two"
            << " triangles); a barrier needs a closed surface"
            << exit(FatalIOError);
    }

    orient(path);
    outwardNormal_ = surface_->faceNormals();
    search_.reset(new triSurfaceSearch(*surface_));
    buildSearch();
    nearest_.reset(new triSurfaceNearest(*surface_, search_->tree()));
}


void Foam::barrierGeometries::triSurfaceGeometry::buildSearch() const
{
    // OpenFOAM builds the octree, its octants' inside/outside types and
    // the surface's addressing on first use: built here, once, queries only
    // read them and may run on several threads at once. (The addressing is
    // what a triSurface's inside test reads, by face, edge or vertex:
    // triSurfaceTools::surfaceSide)
    const triSurface& surf = *surface_;
    surf.localFaces();
    surf.localPoints();
    surf.edges();
    surf.faceEdges();
    surf.edgeFaces();
    surf.pointEdges();
    surf.faceNormals();
    // The octants' types, by a point in the octree's own box (calcInside
    // answers a point outside it without them)
    const indexedOctree<treeDataTriSurface>& tree = search_->tree();
    tree.getVolumeType(tree.bb().centre());
}


void Foam::barrierGeometries::triSurfaceGeometry::orient(const fileName& path)
{
    const triSurface& surf = *surface_;
    const string fix
    (
        "reorient it, e.g. with OpenFOAM's surfaceOrient (surfaceOrient "
      + file_ + " \"(x y z)\" " + file_.lessExt() + "Oriented."
      + file_.ext() + ", with (x y z) a point outside it), and check it"
        " with surfaceCheck"
    );

    // Consistent: the two triangles of each edge run along it in opposite
    // directions. Else OpenFOAM's inside test, which takes the side of the
    // nearest triangle, is wrong near the flipped ones
    const edgeList& edges = surf.edges();
    const labelListList& edgeFaces = surf.edgeFaces();
    const List<labelledTri>& faces = surf.localFaces();
    label nSame = 0;
    forAll(edges, edgei)
    {
        const labelList& ef = edgeFaces[edgei];
        nSame +=
            faces[ef[0]].edgeDirection(edges[edgei])
         == faces[ef[1]].edgeDirection(edges[edgei]);
    }
    if (nSame)
    {
        FatalIOErrorInFunction(dict_)
            << "file " << file_ << ": the triangles of " << path << " do not"
            << " all face the same way: at " << nSame << " of its "
            << edges.size() << " edges both triangles run the same way (some"
            << " are flipped), so its inside is undefined; allowed: a closed"
            << " surface whose triangles all face outwards (or all inwards);"
            << " " << fix.c_str() << exit(FatalIOError);
    }

    // Each connected part: its volume, positive when its triangles face
    // outwards (the divergence theorem), and its box
    labelList part;
    const label nParts = surf.markZones(boolList(edges.size(), false), part);
    scalarField volume6(nParts, Zero);
    List<boundBox> box(nParts, boundBox::invertedBox);
    const pointField& pts = surf.localPoints();
    forAll(faces, facei)
    {
        const labelledTri& f = faces[facei];
        volume6[part[facei]] += pts[f[0]] & (pts[f[1]] ^ pts[f[2]]);
        box[part[facei]].add(pts, f);
    }

    // A part facing inwards is inside out, unless it is a cavity: inside
    // the box of a part that faces outwards. Inside out, it is flipped:
    // a closed surface bounds one solid, the barrier the user meant (the
    // outside of a surface would hold the whole domain)
    boolList flip(nParts, false);
    label nFlipped = 0, nCavities = 0;
    for (label parti = 0; parti < nParts; ++parti)
    {
        const scalar span = cmptMax(box[parti].span());
        if (!(mag(volume6[parti]) > 1e-9*6*span*span*span))
        {
            FatalIOErrorInFunction(dict_)
                << "file " << file_ << ": a part of the surface in " << path
                << " (within " << box[parti] << ") encloses no volume"
                << " (" << volume6[parti]/6 << " m^3); allowed: closed"
                << " surfaces around a solid" << exit(FatalIOError);
        }
        if (volume6[parti] > 0)
        {
            continue;
        }
        bool cavity = false;
        for (label outer = 0; outer < nParts && !cavity; ++outer)
        {
            cavity = volume6[outer] > 0 && box[outer].contains(box[parti]);
        }
        flip[parti] = !cavity;
        nFlipped += !cavity;
        nCavities += cavity;
    }
    if (nCavities)
    {
        Info<< "Barrier " << name_ << ": " << nCavities << " part(s) of "
            << file_ << " face inwards inside another part: cavities of the"
            << " barrier" << endl;
    }
    if (!nFlipped)
    {
        return;
    }

    List<labelledTri> oriented(surf);
    label nTriangles = 0;
    forAll(oriented, facei)
    {
        if (flip[part[facei]])
        {
            oriented[facei].flip();
            ++nTriangles;
        }
    }
    WarningInFunction
        << "barrier " << name_ << ": the surface in " << path << " is inside"
        << " out (its triangles face inwards: negative volume) in "
        << nFlipped << " of its " << nParts << " parts; their " << nTriangles
        << " triangles are flipped to face outwards, so the barrier is the"
        << " solid the surface bounds. To fix the file, " << fix.c_str()
        << endl;
    surface_.reset(new triSurface(oriented, surf.patches(), surf.points()));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierGeometries::triSurfaceGeometry::triSurfaceGeometry
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    barrierGeometry(name, dict, caseDir),
    file_(dict.get<fileName>("file"))
{
    knownKeywords::add(dict, {"file"});

    readSurface();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::boundBox Foam::barrierGeometries::triSurfaceGeometry::bounds() const
{
    return boundBox(surface_->points());
}


void Foam::barrierGeometries::triSurfaceGeometry::distance
(
    const pointField& points,
    scalarField& phi,
    vectorField& normal
) const
{
    // The octree's answers (triSurfaceNearest), not triSurfaceSearch::
    // findNearest's, which sets (and resets) a static tolerance, a race
    // between threads; the same nearest triangle
    phi.setSize(points.size());
    normal.setSize(points.size());
    forAll(points, i)
    {
        bool in;
        const pointIndexHit hit = nearest_->nearest(points[i], in);
        const scalar d = mag(points[i] - hit.hitPoint());
        phi[i] = in ? -d : d;
        normal[i] = outwardNormal_[hit.index()];
    }
}


void Foam::barrierGeometries::triSurfaceGeometry::firstCrossings
(
    const pointField& start,
    const pointField& end,
    scalarField& fraction
) const
{
    // The octree's own line query: its nearest triangle crossed, in the
    // octree's tree built with the surface, read only (as distance(), it
    // leaves the static perturbation tolerance alone; its rare "stuck"
    // diagnosis writes to the log unsynchronised, and answers a miss). The
    // triangle test takes any crossing of the line within a tolerance of
    // the segment, and either way: a hit counts only where the path enters
    // the solid (an exit next to the start of a path along a concave
    // corner, say, is no entry: the guard then bisects), at its fraction
    // of the segment by projection, clamped to it
    const indexedOctree<treeDataTriSurface>& tree = search_->tree();
    const label n = start.size();
    fraction.setSize(n);
    #pragma omp parallel for schedule(dynamic, 64)
    for (label i = 0; i < n; ++i)
    {
        const vector d(end[i] - start[i]);
        const scalar d2 = magSqr(d);
        const pointIndexHit hit = tree.findLine(start[i], end[i]);
        const bool enters =
            hit.hit() && d2 > 0 && (outwardNormal_[hit.index()] & d) < 0;
        fraction[i] = -1;
        if (enters)
        {
            const scalar f = ((hit.hitPoint() - start[i]) & d)/d2;
            fraction[i] = min(max(f, scalar(0)), scalar(1));
        }
    }
}


void Foam::barrierGeometries::triSurfaceGeometry::inside
(
    const pointField& points,
    boolList& in
) const
{
    // (triSurfaceSearch::calcInside's answers)
    in.setSize(points.size());
    forAll(points, i)
    {
        in[i] = nearest_->inside(points[i]);
    }
}


void Foam::barrierGeometries::triSurfaceGeometry::describe
(
    Ostream& os
) const
{
    os  << "triSurface " << file_ << " (" << surface_->size()
        << " triangles, bounds " << bounds() << ")";
}


// ************************************************************************* //
