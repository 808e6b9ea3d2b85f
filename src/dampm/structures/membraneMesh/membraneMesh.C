/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneMesh.H"
#include "structureInput.H"
#include "triSurface.H"
#include "STLcheck.H"
#include "Enum.H"
#include "FlatOutput.H"
#include "OSspecific.H"
#include <map>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::membraneMesh::makePanel(const dictionary& dict)
{
    structureInput::onlyKeywords(dict, {"type", "corners", "resolution"});
    const List<point> corners = dict.get<List<point>>("corners");
    if (corners.size() != 4)
    {
        FatalIOErrorInFunction(dict)
            << "corners has " << corners.size() << " points; allowed: 4, "
            << "in order around the panel" << exit(FatalIOError);
    }
    const labelList resolution = dict.get<labelList>("resolution");
    if (resolution.size() != 2 || min(resolution) < 1)
    {
        FatalIOErrorInFunction(dict)
            << "resolution = " << flatOutput(resolution) << " is invalid; "
            << "allowed: (n1 n2), n1, n2 >= 1" << exit(FatalIOError);
    }
    const label n1 = resolution[0];
    const label n2 = resolution[1];

    points_.setSize((n1 + 1)*(n2 + 1));
    for (label j = 0; j <= n2; ++j)
    {
        const scalar t = scalar(j)/n2;
        for (label i = 0; i <= n1; ++i)
        {
            const scalar s = scalar(i)/n1;
            points_[j*(n1 + 1) + i] =
                (1 - s)*(1 - t)*corners[0] + s*(1 - t)*corners[1]
              + s*t*corners[2] + (1 - s)*t*corners[3];
        }
    }
    for (label j = 0; j < n2; ++j)
    {
        for (label i = 0; i < n1; ++i)
        {
            const label p00 = j*(n1 + 1) + i;
            const label p10 = p00 + 1;
            const label p01 = p00 + n1 + 1;
            const label p11 = p01 + 1;
            const bool rising = (i + j) % 2 == 0;
            const label tris[6] =
            {
                p00, p10, rising ? p11 : p01,
                rising ? p00 : p10, p11, p01
            };
            triangles_.insert(triangles_.end(), tris, tris + 6);
        }
    }
}


void Foam::membraneMesh::readSTL(const fileName& file, const dictionary& dict)
{
    if (!isFile(file))
    {
        FatalIOErrorInFunction(dict)
            << "file " << file << " not found" << exit(FatalIOError);
    }
    // Checked first: OpenFOAM's STL scanner exits the process on some
    // broken files (STLcheck)
    const STLcheck check(file);
    if (!check.valid())
    {
        FatalIOErrorInFunction(dict)
            << "file " << file << " is not a valid STL file: "
            << check.error().c_str() << exit(FatalIOError);
    }
    const triSurface surf(file, word(check.binary() ? "stlb" : "stl"));
    points_ = surf.points();
    for (const labelledTri& tri : surf)
    {
        triangles_.insert(triangles_.end(), {tri[0], tri[1], tri[2]});
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneMesh::membraneMesh
(
    const pointField& points,
    const std::vector<label>& triangles
)
:
    points_(points),
    triangles_(triangles)
{}


Foam::membraneMesh::membraneMesh
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    enum class geometryType { panel, STL };
    static const Enum<geometryType> geometryTypes
    ({
        {geometryType::panel, "panel"},
        {geometryType::STL, "STL"}
    });

    if (geometryTypes.get("type", dict) == geometryType::panel)
    {
        makePanel(dict);
    }
    else
    {
        structureInput::onlyKeywords(dict, {"type", "file"});
        fileName file = dict.get<fileName>("file");
        file.expand();
        readSTL(file.isAbsolute() ? file : caseDir/file, dict);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<Foam::label> Foam::membraneMesh::boundaryPoints() const
{
    // Edges counted by their sorted point pair
    std::map<std::pair<label, label>, label> edgeCount;
    for (size_t k = 0; k < triangles_.size(); k += 3)
    {
        for (label i = 0; i < 3; ++i)
        {
            const label a = triangles_[k + i];
            const label b = triangles_[k + (i + 1) % 3];
            ++edgeCount[{min(a, b), max(a, b)}];
        }
    }
    std::vector<char> onBoundary(points_.size(), 0);
    for (const auto& edge : edgeCount)
    {
        if (edge.second == 1)
        {
            onBoundary[edge.first.first] = 1;
            onBoundary[edge.first.second] = 1;
        }
    }
    std::vector<label> result;
    for (label pointi = 0; pointi < points_.size(); ++pointi)
    {
        if (onBoundary[pointi])
        {
            result.push_back(pointi);
        }
    }
    return result;
}


// ************************************************************************* //
