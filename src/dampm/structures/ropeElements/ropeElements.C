/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "ropeElements.H"
#include "structureInput.H"
#include "exactPrecision.H"
#include "scalarList.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::ropeElements::endNode
(
    const point& p,
    structureNodes& nodes,
    const scalar snap,
    const label ropei
)
{
    scalar distance;
    const label nearest = nodes.nearest(p, distance);
    if (nearest >= 0 && distance <= snap)
    {
        return nearest;
    }
    const label nodei = nodes.append(p);
    nodes.fixed[nodei] = 1;
    fixedEnds_[ropei].push_back(nodei);
    return nodei;
}


void Foam::ropeElements::readRope
(
    const dictionary& dict,
    structureNodes& nodes,
    const scalar snap
)
{
    structureInput::onlyKeywords
    (
        dict,
        {"from", "to", "EA", "linearDensity", "pretension", "segments",
         "brake"}
    );
    const point from = dict.get<point>("from");
    const point to = dict.get<point>("to");
    const scalar EA = structureInput::positive(dict, "EA", "[N]");
    const scalar mu =
        structureInput::positive(dict, "linearDensity", "[kg/m]");
    const scalar T0 = structureInput::nonNegative(dict, "pretension", 0, "[N]");
    const label nSeg = dict.getOrDefault<label>("segments", 1);
    if (nSeg < 1)
    {
        FatalIOErrorInFunction(dict)
            << "segments = " << nSeg << " is invalid; allowed: segments >= 1"
            << exit(FatalIOError);
    }
    if (!(mag(to - from) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "from and to are the same point " << from
            << "; a rope needs a length" << exit(FatalIOError);
    }

    scalar threshold = GREAT;
    scalar maxPlastic = 0;
    if (dict.found("brake"))
    {
        const dictionary& brake = dict.subDict("brake");
        structureInput::onlyKeywords(brake, {"threshold", "maxElongation"});
        threshold = structureInput::positive(brake, "threshold", "[N]");
        maxPlastic =
            structureInput::positive(brake, "maxElongation", "[m]");
        if (!(threshold > T0))
        {
            FatalIOErrorInFunction(brake)
                << "threshold = " << threshold << " is invalid; allowed: "
                << "threshold > pretension = " << T0 << " [N]"
                << exit(FatalIOError);
        }
    }

    const label ropei = names_.size();
    names_.append(dict.dictName());
    fixedEnds_.emplace_back();

    // End nodes first: intermediate nodes never capture a rope end
    const label first = endNode(from, nodes, snap, ropei);
    const label last = endNode(to, nodes, snap, ropei);
    label prev = first;
    for (label segi = 0; segi < nSeg; ++segi)
    {
        const label next = segi + 1 == nSeg
            ? last
            : nodes.append(from + (to - from)*scalar(segi + 1)/nSeg);
        const scalar L =
            mag(nodes.referencePosition(next) - nodes.referencePosition(prev));
        node_.push_back(prev);
        node_.push_back(next);
        L_.push_back(L);
        EA_.push_back(EA);
        T0_.push_back(T0);
        mu_.push_back(mu);
        threshold_.push_back(segi == 0 ? threshold : GREAT);
        maxPlastic_.push_back(segi == 0 ? maxPlastic : 0);
        nodes.mass[prev] += 0.5*mu*L;
        nodes.mass[next] += 0.5*mu*L;
        prev = next;
    }
    ropeStart_.push_back(size());
}


void Foam::ropeElements::readSegmentValues
(
    const dictionary& state,
    const word& keyword,
    std::vector<double>& values
) const
{
    const scalarList read(state.get<scalarList>(keyword));
    structureInput::checkSize
    (
        state, keyword, read.size(), size(), "one per rope segment"
    );
    std::copy(read.begin(), read.end(), values.begin());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ropeElements::ropeElements()
:
    ropeStart_(1, 0),
    brakeDissipation_(0)
{}


Foam::ropeElements::ropeElements
(
    const dictionary& dict,
    structureNodes& nodes,
    const scalar snap
)
:
    ropeElements()
{
    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << e.keyword() << " of ropes is not a rope; "
                << "allowed: named sub-dictionaries" << exit(FatalIOError);
        }
        readRope(e.dict(), nodes, snap);
    }
    plastic_.assign(size(), 0.0);
    tension_.assign(size(), 0.0);
    slotForce_.assign(6*size(), 0.0);
    incidence_ = nodeIncidence(node_, nodes.size());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

double Foam::ropeElements::addInternalForces
(
    structureNodes& nodes,
    const double beta,
    double& dampingPower
)
{
    const label nSeg = size();
    double energy = 0;
    double power = 0;
    double brakeWork = 0;

    #pragma omp parallel for schedule(static) \
        reduction(+:energy, power, brakeWork)
    for (label segi = 0; segi < nSeg; ++segi)
    {
        const label i = node_[2*segi];
        const label j = node_[2*segi + 1];
        const double d[3] =
        {
            nodes.x[j] - nodes.x[i],
            nodes.y[j] - nodes.y[i],
            nodes.z[j] - nodes.z[i]
        };
        const double l = std::sqrt(d[0]*d[0] + d[1]*d[1] + d[2]*d[2]);
        const double L = L_[segi];
        const double k = EA_[segi]/L;

        double Ne = T0_[segi] + k*(l - L - plastic_[segi]);
        if (Ne > threshold_[segi] && plastic_[segi] < maxPlastic_[segi])
        {
            // Return mapping: slide until the elastic force is Fb
            const double dp = std::min
            (
                maxPlastic_[segi],
                l - L - (threshold_[segi] - T0_[segi])/k
            );
            brakeWork += threshold_[segi]*(dp - plastic_[segi]);
            plastic_[segi] = dp;
            Ne = T0_[segi] + k*(l - L - dp);
        }
        Ne = std::max(Ne, 0.0);
        energy += 0.5*Ne*Ne/k;

        // Coincident ends (a rope folded onto itself) pull nowhere
        const double il = l > 0 ? 1/l : 0;
        const double t[3] = {d[0]*il, d[1]*il, d[2]*il};
        double N = Ne;
        if (Ne > 0 && beta > 0)
        {
            const double rate =
                (nodes.vx[j] - nodes.vx[i])*t[0]
              + (nodes.vy[j] - nodes.vy[i])*t[1]
              + (nodes.vz[j] - nodes.vz[i])*t[2];
            N += beta*k*rate;
            power += beta*k*rate*rate;
        }
        tension_[segi] = N;

        double* f = &slotForce_[6*segi];
        for (label c = 0; c < 3; ++c)
        {
            f[c] = N*t[c];
            f[3 + c] = -N*t[c];
        }
    }

    incidence_.gatherAdd(slotForce_, nodes.fx, nodes.fy, nodes.fz);
    brakeDissipation_ += brakeWork;
    dampingPower = power;
    return energy;
}


double Foam::ropeElements::stableTimeStep(label& segi) const
{
    segi = -1;
    double dt = GREAT;
    for (label elemi = 0; elemi < size(); ++elemi)
    {
        const double dtSeg = L_[elemi]*std::sqrt(mu_[elemi]/EA_[elemi]);
        if (dtSeg < dt)
        {
            dt = dtSeg;
            segi = elemi;
        }
    }
    return dt;
}


Foam::label Foam::ropeElements::ropeOf(const label segi) const
{
    return label
    (
        std::upper_bound(ropeStart_.begin(), ropeStart_.end(), segi)
      - ropeStart_.begin()
    ) - 1;
}


void Foam::ropeElements::writeState(dictionary& state) const
{
    // An entry keeps its value as printed when it is set
    const exactPrecision exact;
    state.set
    (
        "plasticElongation",
        scalarList(plastic_.begin(), plastic_.end())
    );
    state.set("tension", scalarList(tension_.begin(), tension_.end()));
    state.set("brakeDissipation", brakeDissipation_);
}


void Foam::ropeElements::readState(const dictionary& state)
{
    readSegmentValues(state, "plasticElongation", plastic_);
    readSegmentValues(state, "tension", tension_);
    brakeDissipation_ = state.get<scalar>("brakeDissipation");
}


// ************************************************************************* //
