/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "polygonRelease.H"
#include "knownKeywords.H"
#include "addToRunTimeSelectionTable.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace releaseModels
{
    defineTypeNameAndDebug(polygonRelease, 0);
    addToRunTimeSelectionTable(releaseModel, polygonRelease, dictionary);
}
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::releaseModels::polygonRelease::setPolygon
(
    const List<vector2D>& vertices
)
{
    vertices_ = vertices;
    if (vertices_.size() < 3)
    {
        FatalIOErrorInFunction(dict_)
            << "the release polygon has " << vertices_.size()
            << " vertices; allowed: at least 3" << exit(FatalIOError);
    }

    knownKeywords::add(dict_, {"surfaceLevel", "thickness"});
    const bool hasLevel = dict_.found("surfaceLevel");
    const bool hasThickness = dict_.found("thickness");
    if (hasLevel == hasThickness)
    {
        FatalIOErrorInFunction(dict_)
            << "give exactly one of surfaceLevel (fill to a free-surface"
            << " elevation [m]) or thickness (uniform [m])"
            << exit(FatalIOError);
    }
    toLevel_ = hasLevel;
    value_ = dict_.get<scalar>(hasLevel ? "surfaceLevel" : "thickness");
    if (!toLevel_ && !(value_ > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "thickness = " << value_ << " is invalid; allowed: > 0 [m]"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::releaseModels::polygonRelease::polygonRelease
(
    const dictionary& dict,
    const topographyModel& topography,
    const fileName& caseDir,
    const bool readVertices
)
:
    releaseModel(dict, topography, caseDir),
    toLevel_(false),
    value_(0)
{
    if (readVertices)
    {
        knownKeywords::add(dict, {"vertices"});
        setPolygon(dict.get<List<vector2D>>("vertices"));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::releaseModels::polygonRelease::inside
(
    const scalar x,
    const scalar y
) const
{
    bool in = false;
    const label n = vertices_.size();
    for (label i = 0, j = n - 1; i < n; j = i++)
    {
        const vector2D& a = vertices_[i];
        const vector2D& b = vertices_[j];
        if
        (
            (a.y() > y) != (b.y() > y)
         && x < (b.x() - a.x())*(y - a.y())/(b.y() - a.y()) + a.x()
        )
        {
            in = !in;
        }
    }
    return in;
}


Foam::scalar Foam::releaseModels::polygonRelease::height
(
    const scalar x,
    const scalar y
) const
{
    if (!inside(x, y))
    {
        return 0;
    }
    if (!toLevel_)
    {
        return value_;
    }
    // A terrain that is not finite here is passed on to be refused
    const scalar h = value_ - topography_.Z(x, y);
    return std::isfinite(h) ? max(h, scalar(0)) : h;
}


Foam::boundBox Foam::releaseModels::polygonRelease::bounds() const
{
    boundBox bb;
    for (const vector2D& v : vertices_)
    {
        bb.add(point(v.x(), v.y(), 0));
    }
    return bb;
}


void Foam::releaseModels::polygonRelease::describe(Ostream& os) const
{
    os  << type() << " (" << vertices_.size() << " vertices, "
        << (toLevel_ ? "surfaceLevel " : "thickness ") << value_
        << " m, U = " << U_ << ')';
}


// ************************************************************************* //
