/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "triSurfaceBarrier.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include "OSspecific.H"
#include <fstream>
#include <cstring>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace barrierModels
{
    defineTypeNameAndDebug(triSurfaceBarrier, 0);
    addToRunTimeSelectionTable(barrierModel, triSurfaceBarrier, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::barrierModels::triSurfaceBarrier::readSurface()
{
    const fileName path = caseDir_/"constant"/"triSurface"/file_;
    if (!isFile(path))
    {
        FatalIOErrorInFunction(dict_)
            << "file " << file_ << ": no such file " << path
            << exit(FatalIOError);
    }

    // A binary STL whose size disagrees with its triangle count is taken
    // for ASCII by OpenFOAM's reader, whose scanner then exits the process:
    // check it here
    if (path.hasExt("stl") || path.hasExt("STL"))
    {
        std::ifstream is(path, std::ios::binary);
        char head[84] = {};
        is.read(head, 84);
        const bool ascii = std::string(head, 5) == "solid";
        if (!ascii)
        {
            uint32_t n = 0;
            std::memcpy(&n, head + 80, 4);
            const off_t expected = 84 + 50*off_t(n);
            if (!is || fileSize(path) != expected)
            {
                FatalIOErrorInFunction(dict_)
                    << "file " << file_ << ": " << path << " is not a valid"
                    << " binary STL (" << fileSize(path) << " bytes, "
                    << expected << " expected for the " << n
                    << " triangles it declares)" << exit(FatalIOError);
            }
        }
    }

    // The readers stop with their own message on a broken file: catch it
    // and say which barrier and keyword it came from
    string why;
    const bool throwing = FatalError.throwExceptions();
    try
    {
        surface_.reset(new triSurface(path));
    }
    catch (const Foam::error& err)
    {
        why = err.message();
    }
    FatalError.throwExceptions(throwing);

    if (!why.empty() || !surface_ || surface_->empty())
    {
        FatalIOErrorInFunction(dict_)
            << "file " << file_ << ": cannot read a triangulated surface"
            << " from " << path << (why.empty() ? " (no triangles)" : ": ")
            << why.c_str() << exit(FatalIOError);
    }

    const triSurface& surf = *surface_;
    label nOpen = 0;
    for (const labelList& ef : surf.edgeFaces())
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

    // Orientation from the sign of the enclosed volume
    const pointField& pts = surf.points();
    scalar volume6 = 0;
    for (const labelledTri& t : surf)
    {
        volume6 += pts[t[0]] & (pts[t[1]] ^ pts[t[2]]);
    }
    outwardNormal_ = surf.faceNormals();
    if (volume6 < 0)
    {
        outwardNormal_ = -outwardNormal_;
    }
    search_.reset(new triSurfaceSearch(surf));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierModels::triSurfaceBarrier::triSurfaceBarrier
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    barrierModel(name, dict, caseDir),
    file_(dict.get<fileName>("file"))
{
    knownKeywords::add(dict, {"file"});

    readSurface();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::boundBox Foam::barrierModels::triSurfaceBarrier::bounds() const
{
    return boundBox(surface_->points());
}


void Foam::barrierModels::triSurfaceBarrier::distance
(
    const pointField& points,
    scalarField& phi,
    vectorField& normal
) const
{
    List<pointIndexHit> hits;
    search_->findNearest(points, scalarField(points.size(), GREAT), hits);
    const boolList inside(search_->calcInside(points));

    phi.setSize(points.size());
    normal.setSize(points.size());
    forAll(points, i)
    {
        const scalar d = mag(points[i] - hits[i].hitPoint());
        phi[i] = inside[i] ? -d : d;
        normal[i] = outwardNormal_[hits[i].index()];
    }
}


void Foam::barrierModels::triSurfaceBarrier::inside
(
    const pointField& points,
    boolList& in
) const
{
    in = search_->calcInside(points);
}


void Foam::barrierModels::triSurfaceBarrier::describeGeometry
(
    Ostream& os
) const
{
    os  << "triSurface " << file_ << " (" << surface_->size()
        << " triangles, bounds " << bounds() << ")";
}


// ************************************************************************* //
