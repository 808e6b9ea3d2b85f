/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrierMonitor.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "barrierGeometry.H"
#include "nodeContact.H"
#include "knownKeywords.H"
#include "orderedSums.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::barrierMonitor::keywords({"overtoppingDirection"});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrierMonitor::barrierMonitor
(
    const word& name,
    const dictionary& dict
)
:
    name_(name),
    overtopDir_(Zero),
    onSurface_(0),
    nearDistance_(0),
    runUp_(-GREAT),
    maxRunUp_(-GREAT),
    passLevel_(GREAT),
    force_(Zero),
    peakForce_(0),
    peakTime_(0),
    passedOutflow_(0)
{
    knownKeywords::add(dict, keywords);

    if (dict.found("overtoppingDirection"))
    {
        overtopDir_ =
            barrierGeometry::readDirection(dict, "overtoppingDirection");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrierMonitor::startSearch(const gridGeometry& g)
{
    onSurface_ = nodeContact::surfaceTolerance(g);
    nearDistance_ = 1.5*g.hMax();
    nearNodes_.clear();
    nearZ_.clear();
}


void Foam::barrierMonitor::addNode
(
    const gridGeometry::index n,
    const point& x,
    const scalar phi
)
{
    if (phi > onSurface_ && phi <= nearDistance_)
    {
        nearNodes_.push_back(n);
        nearZ_.push_back(x.z());
    }
}


void Foam::barrierMonitor::finishSearch
(
    const gridGeometry& g,
    const std::vector<gridGeometry::index>& contactNodes,
    const boundBox& bounds
)
{
    nearBlocks_.build(g, nearNodes_);
    if (!measuresOvertopping())
    {
        return;
    }
    passLevel_ = -GREAT;
    for (const gridGeometry::index n : contactNodes)
    {
        double x[3];
        g.nodePosition(n, x);
        passLevel_ = max(passLevel_, point(x[0], x[1], x[2]) & overtopDir_);
    }
    // (over every processor's part of a decomposed grid)
    reduce(passLevel_, maxOp<scalar>());
    // No node inside a barrier thinner than the node spacing: its far
    // side, from its bounding box
    if
    (
        returnReduce(label(contactNodes.size()), sumOp<label>()) == 0
     && bounds != boundBox::greatBox
    )
    {
        const pointField corners(bounds.points());
        for (const point& c : corners)
        {
            passLevel_ = max(passLevel_, c & overtopDir_);
        }
    }
}


void Foam::barrierMonitor::openFiles
(
    const Time& runTime,
    const scalar width,
    const bool planeSlice
)
{
    forceFile_.reset
    (
        new timeSeriesFile
        (
            runTime, name_, "force",
            {"time", "Fx", "Fy", "Fz", "FxPerWidth", "FyPerWidth", "FzPerWidth"},
            {
                "Contact force of the flow on barrier " + name_ + " [N],"
                " and per unit width [N/m]: over the width",
                "width " + Foam::name(width) + " m: the mesh's span"
                " across the flow (y)"
              + word(planeSlice ? ", a plane slice's thickness" : "")
            }
        )
    );
    runUpFile_.reset
    (
        new timeSeriesFile
        (
            runTime, name_, "runUp", {"time", "runUp"},
            {"Run-up on barrier " + name_ + ": the highest grid node",
             "within 1.5 cells outside it that holds flow, z [m] (to a node",
             "spacing); rows only for steps with flow beside it"}
        )
    );
    if (measuresOvertopping())
    {
        overtoppingFile_.reset
        (
            new timeSeriesFile
            (
                runTime, name_, "overtopping",
                {"time", "overtoppingMass"},
                {"Mass that has passed barrier " + name_ + " [kg],"
                 " in the domain and through open sides"}
            )
        );
    }
}


Foam::scalar Foam::barrierMonitor::overtoppingMass
(
    const particleArrays& particles
) const
{
    if (!measuresOvertopping())
    {
        return 0;
    }
    const label n = particles.size();
    const double* x = particles.component(particleArrays::X);
    const double* y = particles.component(particleArrays::Y);
    const double* z = particles.component(particleArrays::Z);
    const double* m = particles.component(particleArrays::M);
    double passedMass[1], none[1];
    orderedSums<1, 0>(n, passedMass, none, [&](label i, double* s, double*)
    {
        s[0] += passed(x[i], y[i], z[i]) ? m[i] : 0;
    });
    return returnReduce(passedMass[0] + passedOutflow_, sumOp<scalar>());
}


void Foam::barrierMonitor::execute
(
    const vector& force,
    const mpm3dGrid& grid,
    const nodeBox& active,
    const double massTol,
    const scalar t
)
{
    force_ = force;
    if (mag(force_) > peakForce_)
    {
        peakForce_ = mag(force_);
        peakTime_ = t;
    }

    // Run-up: the highest node beside the barrier holding flow (in the
    // blocks of nodes within the flow's box; a maximum in any order)
    const label nn = label(nearNodes_.size());
    const gridGeometry::index* near = nearNodes_.data();
    const double* z = nearZ_.data();
    const nodeBlockBoxes& blocks = nearBlocks_;
    double top = -GREAT;
    #pragma omp parallel for schedule(static) reduction(max:top)
    for (label b = 0; b < blocks.size(); ++b)
    {
        if (!blocks.overlaps(b, active))
        {
            continue;
        }
        const label last = std::min(nn, (b + 1)*orderedSumsBlock);
        for (label c = b*orderedSumsBlock; c < last; ++c)
        {
            if (grid.mass[near[c]] > massTol && z[c] > top)
            {
                top = z[c];
            }
        }
    }
    runUp_ = returnReduce(top, maxOp<scalar>());
    maxRunUp_ = max(maxRunUp_, runUp_);
}


void Foam::barrierMonitor::write
(
    const scalar t,
    const scalar width,
    const particleArrays& particles
)
{
    const vector f = force_/width;
    forceFile_->write
    (
        List<scalar>
        ({t, force_.x(), force_.y(), force_.z(), f.x(), f.y(), f.z()})
    );
    if (runUp_ > -GREAT)
    {
        runUpFile_->write(List<scalar>({t, runUp_}));
    }
    if (overtoppingFile_)
    {
        overtoppingFile_->write
        (
            List<scalar>({t, overtoppingMass(particles)})
        );
    }
}


void Foam::barrierMonitor::describe(Ostream& os) const
{
    if (measuresOvertopping())
    {
        os  << ", overtopping beyond " << passLevel_ << " m along "
            << overtopDir_;
    }
}


void Foam::barrierMonitor::report
(
    Ostream& os,
    const particleArrays& particles
) const
{
    os  << "Barrier " << name_ << ": peak force " << peakForce_
        << " N at t = " << peakTime_ << " s";
    if (maxRunUp_ > -GREAT)
    {
        os  << ", highest run-up z = " << maxRunUp_ << " m";
    }
    if (measuresOvertopping())
    {
        os  << ", overtopping mass " << overtoppingMass(particles) << " kg";
    }
    os  << nl;
}


// ************************************************************************* //
