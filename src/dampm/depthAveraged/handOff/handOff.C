/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "handOff.H"
#include "knownKeywords.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "strictIOdictionary.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::handOff::readRegion
(
    const dictionary& barriers,
    const fileName& caseDir
)
{
    for (const entry& e : barriers)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(barriers)
                << "region entry " << e.keyword() << " is not a dictionary;"
                << " allowed: name { type box|plane|triSurface; ... }"
                << exit(FatalIOError);
        }
        const word type = e.dict().get<word>("type");
        if (type == "terrain")
        {
            // The ground is everywhere: it does not mark the 3D region
            continue;
        }
        dictionary dict(e.dict());
        if (!dict.found("contact"))
        {
            dict.add("contact", word("slip"));
        }
        region_.append(barrierModel::New(e.keyword(), dict, caseDir));
    }
    if (region_.empty())
    {
        FatalIOErrorInFunction(barriers)
            << "the hand-off region (" << regionSource_ << ") holds no body"
            << " other than terrain; allowed: box, plane or triSurface"
            << " entries" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::handOff::handOff
(
    const dictionary& dampmProperties,
    const fileName& caseDir,
    const scalar hMin
)
:
    trigger_(triggerType::none),
    time_(GREAT),
    distance_(0),
    frontHeight_(hMin),
    searchBox_(boundBox::invertedBox),
    nearest_(GREAT)
{
    knownKeywords::add(dampmProperties, {"handOff"});
    if (!dampmProperties.found("handOff"))
    {
        return;
    }
    const dictionary& dict = dampmProperties.subDict("handOff");
    knownKeywords::add
    (
        dict, {"time", "region", "regionCase", "distance", "frontHeight"}
    );
    const label nWays =
        label(dict.found("time")) + label(dict.found("region"))
      + label(dict.found("regionCase"));
    if (nWays != 1)
    {
        FatalIOErrorInFunction(dict)
            << "handOff needs exactly one of the keywords time, region and"
            << " regionCase (it has " << nWays << ")" << exit(FatalIOError);
    }

    if (dict.found("time"))
    {
        trigger_ = triggerType::time;
        time_ = dict.get<scalar>("time");
        if (!(time_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "time = " << time_ << " is invalid; allowed: > 0 [s]"
                << exit(FatalIOError);
        }
        return;
    }

    trigger_ = triggerType::region;
    if (dict.found("region"))
    {
        regionSource_ = "region";
        readRegion(dict.subDict("region"), caseDir);
    }
    else
    {
        fileName other = dict.get<fileName>("regionCase");
        other.expand();
        if (!other.isAbsolute())
        {
            other = caseDir/other;
        }
        const fileName file = other/"constant"/"mpm3dProperties";
        if (!isFile(file))
        {
            FatalIOErrorInFunction(dict)
                << "regionCase " << other << ": no file " << file
                << exit(FatalIOError);
        }
        // As mpm3dFoam reads it: a barrier named twice is refused
        IFstream is(file);
        dictionary props;
        strictIOdictionary::read(is, props);
        if (!props.isDict("barriers"))
        {
            FatalIOErrorInFunction(dict)
                << "regionCase " << other << ": " << file << " has no"
                << " barriers sub-dictionary to mark the 3D region"
                << exit(FatalIOError);
        }
        regionSource_ = "barriers of " + other;
        readRegion(props.subDict("barriers"), other);
    }

    distance_ = dict.get<scalar>("distance");
    frontHeight_ = dict.getOrDefault<scalar>("frontHeight", hMin);
    if (!(distance_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "distance = " << distance_ << " is invalid; allowed: >= 0 [m]"
            << exit(FatalIOError);
    }
    if (!(frontHeight_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "frontHeight = " << frontHeight_ << " is invalid; allowed:"
            << " > 0 [m]" << exit(FatalIOError);
    }

    for (const barrierModel& b : region_)
    {
        searchBox_.add(b.bounds());
    }
    searchBox_.min() -= vector::uniform(distance_);
    searchBox_.max() += vector::uniform(distance_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::handOff::limitDeltaT(const scalar t, const scalar dt) const
{
    if (trigger_ != triggerType::time || t >= time_)
    {
        return dt;
    }
    // Land on the hand-off time, in two equal steps rather than a full
    // one and a sliver
    const scalar left = time_ - t;
    if (left <= (1 + 1e-9)*dt)
    {
        return left;
    }
    return left < 2*dt ? 0.5*left : dt;
}


bool Foam::handOff::due
(
    const scalar t,
    const particleArrays& columns,
    const label hField,
    const topographyModel& Z
)
{
    if (trigger_ == triggerType::time)
    {
        if (t >= time_*(1 - 1e-12))
        {
            reason_ = "the set hand-off time " + Foam::name(time_) + " s";
            return true;
        }
        return false;
    }
    if (trigger_ != triggerType::region)
    {
        return false;
    }

    // Front columns in the search box: their bed points
    const double* x = columns.column(particleArrays::X);
    const double* y = columns.column(particleArrays::Y);
    const double* h = columns.column(hField);
    const boundBox& sb = searchBox_;
    DynamicList<point> bed;
    for (label i = 0; i < columns.size(); ++i)
    {
        if
        (
            h[i] >= frontHeight_
         && x[i] >= sb.min().x() && x[i] <= sb.max().x()
         && y[i] >= sb.min().y() && y[i] <= sb.max().y()
        )
        {
            bed.append(point(x[i], y[i], Z.Z(x[i], y[i])));
        }
    }
    if (bed.empty())
    {
        return false;
    }

    const pointField pts(std::move(bed));
    scalar nearest = GREAT;
    label nearestPoint = -1, nearestBody = -1;
    forAll(region_, b)
    {
        scalarField phi;
        vectorField normal;
        region_[b].distance(pts, phi, normal);
        forAll(phi, i)
        {
            if (phi[i] < nearest)
            {
                nearest = phi[i];
                nearestPoint = i;
                nearestBody = b;
            }
        }
    }
    nearest_ = min(nearest_, nearest);
    if (nearest > distance_)
    {
        return false;
    }

    OStringStream os;
    os  << "the front (a column at least " << frontHeight_ << " m deep, at ("
        << pts[nearestPoint].x() << ' ' << pts[nearestPoint].y()
        << ")) is " << max(nearest, 0.0) << " m from "
        << region_[nearestBody].name() << " of the 3D region (hand-off"
        << " distance " << distance_ << " m)";
    reason_ = os.str();
    return true;
}


void Foam::handOff::describe(Ostream& os) const
{
    os  << "    hand-off to the 3D stage: ";
    if (trigger_ == triggerType::none)
    {
        os  << "none (the run ends at endTime)" << nl;
        return;
    }
    if (trigger_ == triggerType::time)
    {
        os  << "at t = " << time_ << " s" << nl;
        return;
    }
    os  << "when the front (columns at least " << frontHeight_
        << " m deep) comes within " << distance_ << " m of the 3D region ("
        << regionSource_ << ":";
    for (const barrierModel& b : region_)
    {
        os  << ' ' << b.name();
    }
    os  << ")" << nl;
}


void Foam::handOff::reportNotDue(Ostream& os) const
{
    if (trigger_ == triggerType::region)
    {
        os  << "No hand-off: the front ";
        if (nearest_ < GREAT)
        {
            os  << "came no closer than " << nearest_ << " m to";
        }
        else
        {
            os  << "never came within " << distance_ << " m of the box of";
        }
        os  << " the 3D region" << nl;
    }
    else if (trigger_ == triggerType::time)
    {
        os  << "No hand-off: endTime came before the hand-off time "
            << time_ << " s" << nl;
    }
}


// ************************************************************************* //
