/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "handOff.H"
#include "barrier.H"
#include "knownKeywords.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "strictIOdictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::handOff::frontDepthFraction = 1e-3;


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
        // The shape alone; a barrier's other keywords (contact, ...) may
        // come with it and do not matter here, but a contact the 3D stage
        // refuses is refused now, not after the whole run-out
        knownKeywords::add(e.dict(), barrier::keywords());
        if (e.dict().found("contact"))
        {
            const contactCondition checked(e.dict());
        }
        region_.append(barrierGeometry::New(e.keyword(), e.dict(), caseDir));
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
    const scalar releaseThickness
)
:
    trigger_(triggerType::none),
    time_(GREAT),
    distance_(0),
    frontDepth_(frontDepthFraction*releaseThickness),
    frontDepthGiven_(false),
    trigger3D_(point::zero),
    triggerDepth_(0),
    searchBox_(boundBox::invertedBox),
    nearest_(GREAT)
{
    knownKeywords::add(dampmProperties, {"handOff"});
    if (!dampmProperties.found("handOff"))
    {
        return;
    }
    const dictionary& dict = dampmProperties.subDict("handOff");
    if (dict.found("frontHeight"))
    {
        FatalIOErrorInFunction(dict)
            << "frontHeight is no longer read: use frontDepth (the depth [m]"
            << " from which a column counts as the front; default "
            << frontDepthFraction*100 << " % of the thickest released"
            << " column)" << exit(FatalIOError);
    }
    knownKeywords::add
    (
        dict, {"time", "region", "regionCase", "distance", "frontDepth"}
    );
    frontDepthGiven_ = dict.found("frontDepth");
    if (frontDepthGiven_)
    {
        frontDepth_ = dict.get<scalar>("frontDepth");
        if (!(frontDepth_ > 0 && frontDepth_ < 1e6))
        {
            FatalIOErrorInFunction(dict)
                << "frontDepth = " << frontDepth_ << " is invalid; allowed:"
                << " 0 < frontDepth < 1e6 [m]" << exit(FatalIOError);
        }
    }
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
    if (!(distance_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "distance = " << distance_ << " is invalid; allowed: >= 0 [m]"
            << exit(FatalIOError);
    }

    for (const barrierGeometry& b : region_)
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

    // Front columns in the search box: their bed points and depths
    const double* x = columns.component(particleArrays::X);
    const double* y = columns.component(particleArrays::Y);
    const double* h = columns.component(hField);
    const boundBox& sb = searchBox_;
    DynamicList<point> bed;
    DynamicList<scalar> depth;
    for (label i = 0; i < columns.size(); ++i)
    {
        if
        (
            h[i] >= frontDepth_
         && x[i] >= sb.min().x() && x[i] <= sb.max().x()
         && y[i] >= sb.min().y() && y[i] <= sb.max().y()
        )
        {
            bed.append(point(x[i], y[i], Z.Z(x[i], y[i])));
            depth.append(h[i]);
        }
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

    // The nearest of every processor's front (the lowest rank of equals):
    // its column, depth and body go to all
    List<scalar> found({nearest, 0, 0, 0, 0, scalar(nearestBody)});
    if (nearestPoint >= 0)
    {
        found[1] = pts[nearestPoint].x();
        found[2] = pts[nearestPoint].y();
        found[3] = pts[nearestPoint].z();
        found[4] = depth[nearestPoint];
    }
    if (Pstream::parRun())
    {
        const scalar least = returnReduce(nearest, minOp<scalar>());
        const label from = returnReduce
        (
            nearest == least ? Pstream::myProcNo() : Pstream::nProcs(),
            minOp<label>()
        );
        if (Pstream::myProcNo() != from)
        {
            found = 0;
        }
        Pstream::listCombineGather(found, plusEqOp<scalar>());
        Pstream::listCombineScatter(found);
    }
    nearest = found[0];
    nearest_ = min(nearest_, nearest);
    if (nearest > distance_)
    {
        return false;
    }

    trigger3D_ = point(found[1], found[2], found[3]);
    triggerDepth_ = found[4];
    nearestBody = label(found[5]);
    OStringStream os;
    os  << max(nearest, 0.0) << " m from " << region_[nearestBody].name()
        << " of the 3D region (hand-off distance " << distance_ << " m)";
    reason_ = os.str();
    return true;
}


Foam::string Foam::handOff::reason(const particleArrays& columns) const
{
    if (trigger_ != triggerType::region || reason_.empty())
    {
        return reason_;
    }
    // The column is found by its position: the write may have re-sorted
    // the columns since due() (positions do not change)
    const double* x = columns.component(particleArrays::X);
    const double* y = columns.component(particleArrays::Y);
    label index = -1;
    for (label i = 0; i < columns.size() && index < 0; ++i)
    {
        if (x[i] == trigger3D_.x() && y[i] == trigger3D_.y())
        {
            index = i;
        }
    }
    OStringStream os;
    os  << "the front, column ";
    if (Pstream::parRun())
    {
        // The processor whose cloud holds it
        const label proc = returnReduce
        (
            index >= 0 ? Pstream::myProcNo() : Pstream::nProcs(),
            minOp<label>()
        );
        reduce(index, maxOp<label>());
        os  << index << " of processor" << proc << "'s cloud";
    }
    else
    {
        os  << index << " of the cloud";
    }
    os  << " at (x y) = ("
        << trigger3D_.x() << ' ' << trigger3D_.y() << "), " << triggerDepth_
        << " m deep (frontDepth " << frontDepth_ << " m), is "
        << reason_.c_str();
    return os.str();
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
    os  << "when the front (columns at least frontDepth = " << frontDepth_
        << " m deep";
    if (!frontDepthGiven_)
    {
        os  << ", the default: " << 100*frontDepthFraction
            << " % of the thickest released column";
    }
    os  << ") comes within " << distance_ << " m of the 3D region ("
        << regionSource_ << ":";
    for (const barrierGeometry& b : region_)
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
