/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "ensembleMaps.H"
#include "knownKeywords.H"
#include "OSspecific.H"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <utility>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::ensembleMaps::fieldNames
({
    "maxHeight", "maxSpeed", "maxIntensity", "maxDischarge"
});


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A node by its indices (i east, j north)
typedef std::pair<long, long> nodeIndex;


//- The fields' names for the messages: (maxHeight maxSpeed ...)
std::string fieldList()
{
    std::string text;
    for (const word& field : ensembleMaps::fieldNames)
    {
        text += (text.empty() ? "(" : " ") + field;
    }
    return text + ")";
}


//- A number of a message as written (shortest exact form), whatever the
//  stream's precision
word text(const scalar x)
{
    return ensembleMaps::numberName(x);
}


//- The maps sub-dictionary of ensembleDict, empty (and named so) when absent
dictionary mapsDict(const dictionary& ensembleDict)
{
    if (ensembleDict.found("maps") && !ensembleDict.isDict("maps"))
    {
        FatalIOErrorInFunction(ensembleDict)
            << "maps is not a dictionary; allowed: maps { reachHeight ...;"
            << " percentiles (...); <field> (<thresholds>); ... }"
            << exit(FatalIOError);
    }
    return ensembleDict.subOrEmptyDict("maps");
}


//- FatalIOError on dict naming keyword unless its values are finite,
//  inRange and strictly increasing; allowed: the rule, for the message
template<class InRange>
void checkIncreasing
(
    const dictionary& dict,
    const word& keyword,
    const scalarList& values,
    const InRange& inRange,
    const char* allowed
)
{
    forAll(values, i)
    {
        if (!std::isfinite(values[i]) || !inRange(values[i]))
        {
            FatalIOErrorInFunction(dict)
                << keyword << " holds " << text(values[i]) << "; allowed: "
                << allowed << exit(FatalIOError);
        }
        if (i && !(values[i] > values[i - 1]))
        {
            FatalIOErrorInFunction(dict)
                << keyword << " holds " << text(values[i]) << " after "
                << text(values[i - 1]) << "; allowed: " << allowed
                << exit(FatalIOError);
        }
    }
}


//- z of the cross product (a - o) x (b - o): > 0 for a left turn, exact on
//  node indices
long cross(const nodeIndex& o, const nodeIndex& a, const nodeIndex& b)
{
    return (a.first - o.first)*(b.second - o.second)
         - (a.second - o.second)*(b.first - o.first);
}


//- The vertices of the convex hull of points, counter-clockwise, without
//  collinear points (Andrew's monotone chain)
std::vector<nodeIndex> convexHull(std::vector<nodeIndex> points)
{
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const size_t n = points.size();
    if (n < 3)
    {
        return points;
    }
    std::vector<nodeIndex> hull(2*n);
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
    {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
        {
            --k;
        }
        hull[k++] = points[i];
    }
    for (size_t i = n - 1, lower = k + 1; i > 0; --i)
    {
        while
        (
            k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0
        )
        {
            --k;
        }
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}


//- Write values as the map name (.asc and .tif) in outDir with the geometry
//  and projection of raster; float64, so that both hold the same doubles
void writeMap
(
    const terrainRaster& raster,
    const UList<scalar>& values,
    const fileName& outDir,
    const word& name
)
{
    const terrainRaster map
    (
        vector2D(raster.x(0), raster.y(0)),
        raster.dx(),
        raster.dy(),
        raster.nx(),
        raster.ny(),
        values,
        raster.offset(),
        raster.projection()
    );
    map.writeAsc(outDir/(name + ".asc"));
    map.writeGeoTiff
    (
        outDir/(name + ".tif"), terrainRaster::sampleType::float64
    );
}


//- The report's line of a probability map: where it is above 0 and 1/2
void reportProbability
(
    Ostream& os,
    const word& name,
    const UList<scalar>& P,
    const scalar cellArea
)
{
    label positive = 0;
    label likely = 0;
    for (const scalar p : P)
    {
        positive += (p > 0);
        likely += (p >= 0.5);
    }
    os  << "    " << name << ": P > 0 on " << positive*cellArea
        << " m^2, P >= 0.5 on " << likely*cellArea << " m^2" << nl;
}


//- The name of a percentile map
word percentileName(const word& field, const scalar p)
{
    return field + "_p" + ensembleMaps::numberName(p);
}


//- The name of an exceedance map
word exceedanceName(const word& field, const scalar threshold)
{
    return "P_" + field + "_gt_" + ensembleMaps::numberName(threshold);
}


//- The name of a class probability map
word classProbabilityName(const word& className)
{
    return "P_intensityClass_" + className;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::ensembleMaps::readPercentiles()
{
    percentiles_ = dict_.getOrDefault<scalarList>("percentiles", scalarList());
    checkIncreasing
    (
        dict_, "percentiles", percentiles_,
        [](const scalar p) { return p > 0 && p < 100; },
        "percentiles in (0, 100) in increasing order"
    );
    if (!percentiles_.found(50))
    {
        percentiles_.append(50);
        std::sort(percentiles_.begin(), percentiles_.end());
    }
}


Foam::scalarList Foam::ensembleMaps::readClass(const entry& e) const
{
    const dictionary& dict = e.dict();
    knownKeywords::add(dict, fieldNames);
    if (dict.empty())
    {
        FatalIOErrorInFunction(dict)
            << "class " << e.keyword() << " has no field; allowed: "
            << e.keyword() << " { <field> <threshold>; ... } with fields "
            << fieldList().c_str() << exit(FatalIOError);
    }
    scalarList t(fieldNames.size(), std::numeric_limits<scalar>::infinity());
    for (const entry& f : dict)
    {
        const label fieldi = fieldNames.find(f.keyword());
        if (fieldi < 0)
        {
            FatalIOErrorInFunction(dict)
                << "class " << e.keyword() << ": unknown field "
                << f.keyword() << "; allowed: " << fieldList().c_str()
                << exit(FatalIOError);
        }
        t[fieldi] = dict.get<scalar>(f.keyword());
        if (!std::isfinite(t[fieldi]) || t[fieldi] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "class " << e.keyword() << ": " << f.keyword() << " = "
                << text(t[fieldi]) << " is invalid; allowed: a threshold >= 0"
                << exit(FatalIOError);
        }
    }
    return t;
}


void Foam::ensembleMaps::checkClassOrder
(
    const entry& e,
    const scalarList& t
) const
{
    forAll(classNames_, classi)
    {
        forAll(fieldNames, fieldi)
        {
            const scalar before = classThresholds_[classi][fieldi];
            // inf: not given in that class (nor, if t is, in this one)
            if (std::isfinite(before) && t[fieldi] < before)
            {
                FatalIOErrorInFunction(e.dict())
                    << "class " << e.keyword() << ": " << fieldNames[fieldi]
                    << " " << text(t[fieldi]) << " is lower than class "
                    << classNames_[classi] << "'s " << text(before)
                    << "; allowed: classes in increasing order, a field's"
                    << " threshold no lower than in the classes before"
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::ensembleMaps::readClasses()
{
    if (!dict_.found("intensityClasses"))
    {
        return;
    }
    const dictionary& classes = dict_.subDict("intensityClasses");
    for (const entry& e : classes)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(classes)
                << "class " << e.keyword() << " is not a dictionary;"
                << " allowed: intensityClasses { <class> { <field>"
                << " <threshold>; ... } ... } with fields "
                << fieldList().c_str() << exit(FatalIOError);
        }
        const scalarList t(readClass(e));
        checkClassOrder(e, t);
        classNames_.append(e.keyword());
        classThresholds_.append(t);
    }
    if (classNames_.empty() || classNames_.size() > maxClasses)
    {
        FatalIOErrorInFunction(classes)
            << "intensityClasses has " << classNames_.size() << " classes;"
            << " allowed: 1 to " << maxClasses << " classes <class> {"
            << " <field> <threshold>; ... }" << exit(FatalIOError);
    }
}


Foam::terrainRaster Foam::ensembleMaps::readMember
(
    const fileName& dir,
    const word& field,
    const terrainRaster* reference
)
{
    const fileName file(dir/(field + ".asc"));
    if (!isFile(file))
    {
        FatalErrorInFunction
            << "the member raster " << file << " is missing; the ensemble's"
            << " maps need " << fieldList().c_str() << ".asc of every"
            << " member" << exit(FatalError);
    }
    terrainRaster raster(file);
    if (!reference)
    {
        return raster;
    }

    const terrainRaster& r = *reference;
    std::string differs;
    if (raster.nx() != r.nx() || raster.ny() != r.ny())
    {
        differs = "nx x ny = " + std::to_string(raster.nx()) + " x "
            + std::to_string(raster.ny()) + " against "
            + std::to_string(r.nx()) + " x " + std::to_string(r.ny());
    }
    else if (raster.dx() != r.dx() || raster.dy() != r.dy())
    {
        differs = "dx, dy = " + numberName(raster.dx()) + ", "
            + numberName(raster.dy()) + " against " + numberName(r.dx())
            + ", " + numberName(r.dy());
    }
    else if (raster.mapLowerLeft() != r.mapLowerLeft())
    {
        const vector2D a(raster.mapLowerLeft());
        const vector2D b(r.mapLowerLeft());
        differs = "lower-left corner (" + numberName(a.x()) + " "
            + numberName(a.y()) + ") against (" + numberName(b.x()) + " "
            + numberName(b.y()) + ")";
    }
    else if (raster.projection() != r.projection())
    {
        differs = "projection \"" + raster.projection() + "\" against \""
            + r.projection() + "\"";
    }
    if (!differs.empty())
    {
        FatalErrorInFunction
            << file << " and " << r.file() << " differ: " << differs.c_str()
            << "; the members' rasters must share one grid (nx, ny, dx, dy,"
            << " lower-left corner) and projection" << exit(FatalError);
    }
    return raster;
}


void Foam::ensembleMaps::raiseClasses
(
    const label fieldi,
    const std::vector<double>& values,
    std::vector<std::uint8_t>& classes
) const
{
    const label nClasses = classNames_.size();
    for (size_t k = 0; k < values.size(); ++k)
    {
        for (label classi = nClasses - 1; classi >= 0; --classi)
        {
            // A threshold not given is inf: never exceeded
            if (values[k] > classThresholds_[classi][fieldi])
            {
                classes[k] = std::max<std::uint8_t>(classes[k], classi + 1);
                break;
            }
        }
    }
}


void Foam::ensembleMaps::writeFieldMaps
(
    const label fieldi,
    const std::vector<double>& sorted,
    const label nMembers,
    const terrainRaster& geometry,
    const fileName& outDir,
    Ostream& os
) const
{
    const word& field = fieldNames[fieldi];
    const label nNodes = geometry.nx()*geometry.ny();
    scalarList map(nNodes);

    for (const scalar p : percentiles_)
    {
        const scalar pos = p/100*(nMembers - 1);
        const label lo = label(std::floor(pos));
        const scalar t = pos - lo;
        for (label nodei = 0; nodei < nNodes; ++nodei)
        {
            const double* v = sorted.data() + size_t(nodei)*nMembers;
            map[nodei] =
                lo + 1 < nMembers ? v[lo] + t*(v[lo + 1] - v[lo]) : v[lo];
        }
        const word name(percentileName(field, p));
        writeMap(geometry, map, outDir, name);
        os  << "    " << name << ": max " << max(map) << nl;
    }

    for (const scalar threshold : thresholds_[fieldi])
    {
        for (label nodei = 0; nodei < nNodes; ++nodei)
        {
            const double* v = sorted.data() + size_t(nodei)*nMembers;
            const label above =
                v + nMembers - std::upper_bound(v, v + nMembers, threshold);
            map[nodei] = scalar(above)/nMembers;
        }
        const word name(exceedanceName(field, threshold));
        writeMap(geometry, map, outDir, name);
        reportProbability(os, name, map, geometry.dx()*geometry.dy());
    }
}


void Foam::ensembleMaps::writeClassMaps
(
    const std::vector<std::uint8_t>& classes,
    const label nMembers,
    const terrainRaster& geometry,
    const fileName& outDir,
    Ostream& os
) const
{
    const label nClasses = classNames_.size();
    const label nNodes = geometry.nx()*geometry.ny();
    List<scalarList> P(nClasses, scalarList(nNodes));
    scalarList classMap(nNodes, Zero);
    labelList nInClass(nClasses + 1);
    for (label nodei = 0; nodei < nNodes; ++nodei)
    {
        nInClass = 0;
        for (label memberi = 0; memberi < nMembers; ++memberi)
        {
            ++nInClass[classes[size_t(nodei)*nMembers + memberi]];
        }
        // P(class >= k) from the top down; the highest likely class wins
        label atLeast = 0;
        for (label classi = nClasses; classi >= 1; --classi)
        {
            atLeast += nInClass[classi];
            P[classi - 1][nodei] = scalar(atLeast)/nMembers;
            if (!classMap[nodei] && P[classi - 1][nodei] >= classProbability_)
            {
                classMap[nodei] = classi;
            }
        }
    }

    const scalar cellArea = geometry.dx()*geometry.dy();
    forAll(classNames_, classi)
    {
        const word name(classProbabilityName(classNames_[classi]));
        writeMap(geometry, P[classi], outDir, name);
        reportProbability(os, name, P[classi], cellArea);
    }
    writeMap(geometry, classMap, outDir, "intensityClass");
    os  << "    intensityClass (P >= " << text(classProbability_) << "):";
    forAll(classNames_, classi)
    {
        const label n =
            std::count(classMap.begin(), classMap.end(), classi + 1);
        os  << (classi ? ", " : " ") << classNames_[classi] << ' '
            << n*cellArea << " m^2";
    }
    os  << nl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ensembleMaps::ensembleMaps(const dictionary& ensembleDict)
:
    dict_(mapsDict(ensembleDict)),
    reachHeight_(dict_.getOrDefault<scalar>("reachHeight", 0.1)),
    thresholds_(fieldNames.size()),
    classProbability_(dict_.getOrDefault<scalar>("classProbability", 0.5))
{
    knownKeywords::add(ensembleDict, {"maps"});
    knownKeywords::add
    (
        dict_,
        wordList({"reachHeight", "percentiles", "intensityClasses",
            "classProbability"})
    );
    knownKeywords::add(dict_, fieldNames);

    if (!std::isfinite(reachHeight_) || !(reachHeight_ > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "reachHeight = " << text(reachHeight_) << " is invalid; allowed:"
            << " reachHeight > 0 [m]" << exit(FatalIOError);
    }
    readPercentiles();
    forAll(fieldNames, fieldi)
    {
        const word& field = fieldNames[fieldi];
        thresholds_[fieldi] =
            dict_.getOrDefault<scalarList>(field, scalarList());
        checkIncreasing
        (
            dict_, field, thresholds_[fieldi],
            [](const scalar x) { return x >= 0; },
            "thresholds >= 0 in increasing order"
        );
    }
    readClasses();
    if (!(classProbability_ > 0 && classProbability_ <= 1))
    {
        FatalIOErrorInFunction(dict_)
            << "classProbability = " << text(classProbability_)
            << " is invalid; allowed: 0 < classProbability <= 1"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

std::string Foam::ensembleMaps::numberName(const scalar x)
{
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof(buf), x);
    return std::string(buf, res.ptr);
}


Foam::scalar Foam::ensembleMaps::runOutLength
(
    const terrainRaster& raster,
    const scalar threshold
)
{
    // The hull's vertices are among each row's outermost nodes
    std::vector<nodeIndex> outermost;
    for (label j = 0; j < raster.ny(); ++j)
    {
        label first = -1;
        label last = -1;
        for (label i = 0; i < raster.nx(); ++i)
        {
            if (raster.value(i, j) > threshold)
            {
                first = (first < 0 ? i : first);
                last = i;
            }
        }
        if (first >= 0)
        {
            outermost.emplace_back(first, j);
            outermost.emplace_back(last, j);
        }
    }

    // The farthest pair is a pair of hull vertices; the hull has few
    // vertices (O(n^(2/3)) on an n x n grid), so all pairs are cheap
    const std::vector<nodeIndex> hull(convexHull(outermost));
    scalar longest2 = 0;
    for (size_t a = 0; a < hull.size(); ++a)
    {
        for (size_t b = a + 1; b < hull.size(); ++b)
        {
            const scalar Dx = (hull[b].first - hull[a].first)*raster.dx();
            const scalar Dy = (hull[b].second - hull[a].second)*raster.dy();
            longest2 = std::max(longest2, Dx*Dx + Dy*Dy);
        }
    }
    return std::sqrt(longest2);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::ensembleMaps::mapNames() const
{
    wordList names;
    forAll(fieldNames, fieldi)
    {
        for (const scalar p : percentiles_)
        {
            names.append(percentileName(fieldNames[fieldi], p));
        }
        for (const scalar threshold : thresholds_[fieldi])
        {
            names.append(exceedanceName(fieldNames[fieldi], threshold));
        }
    }
    for (const word& className : classNames_)
    {
        names.append(classProbabilityName(className));
    }
    if (!classNames_.empty())
    {
        names.append("intensityClass");
    }
    return names;
}


Foam::List<Foam::ensembleMaps::memberFigures> Foam::ensembleMaps::write
(
    const fileNameList& dirs,
    const fileName& outDir,
    Ostream& os
) const
{
    const label nMembers = dirs.size();
    if (!nMembers)
    {
        FatalErrorInFunction
            << "no members to map into " << outDir << exit(FatalError);
    }
    const terrainRaster geometry(readMember(dirs[0], fieldNames[0], nullptr));
    const size_t nNodes = size_t(geometry.nx())*geometry.ny();
    const scalar cellArea = geometry.dx()*geometry.dy();
    mkDir(outDir);
    os  << "Maps of " << nMembers << " members in " << outDir << nl;

    List<memberFigures> figures(nMembers);
    std::vector<std::uint8_t> classes
    (
        classNames_.empty() ? 0 : nNodes*nMembers, 0
    );
    // One field at a time, by node then member: each node's values together
    std::vector<double> values(nNodes*nMembers);
    forAll(fieldNames, fieldi)
    {
        const word& field = fieldNames[fieldi];
        for (label memberi = 0; memberi < nMembers; ++memberi)
        {
            const terrainRaster raster
            (
                readMember(dirs[memberi], field, &geometry)
            );
            const scalarList& v = raster.values();
            for (size_t nodei = 0; nodei < nNodes; ++nodei)
            {
                values[nodei*nMembers + memberi] = v[nodei];
            }
            memberFigures& f = figures[memberi];
            if (field == "maxHeight")
            {
                const label reached = std::count_if
                (
                    v.begin(), v.end(),
                    [this](const scalar h) { return h > reachHeight_; }
                );
                f.affectedArea = reached*cellArea;
                f.runOutLength = runOutLength(raster, reachHeight_);
            }
            else if (field == "maxSpeed")
            {
                f.maxSpeed = raster.maxValue();
            }
        }
        if (!classes.empty())
        {
            raiseClasses(fieldi, values, classes);
        }
        for (size_t nodei = 0; nodei < nNodes; ++nodei)
        {
            std::sort
            (
                values.begin() + nodei*nMembers,
                values.begin() + (nodei + 1)*nMembers
            );
        }
        writeFieldMaps(fieldi, values, nMembers, geometry, outDir, os);
    }
    if (!classes.empty())
    {
        writeClassMaps(classes, nMembers, geometry, outDir, os);
    }
    return figures;
}


// ************************************************************************* //
