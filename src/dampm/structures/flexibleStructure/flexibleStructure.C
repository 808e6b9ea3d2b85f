/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "flexibleStructure.H"
#include "structureInput.H"
#include "exactPrecision.H"
#include "Enum.H"
#include "FlatOutput.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The energies in the restart state, by keyword
const std::pair<const char*, double Foam::flexibleStructure::energyBudget::*>
    energyKeywords[] =
{
    {"kinetic", &Foam::flexibleStructure::energyBudget::kinetic},
    {"membraneStrain", &Foam::flexibleStructure::energyBudget::membraneStrain},
    {"ropeStrain", &Foam::flexibleStructure::energyBudget::ropeStrain},
    {
        "dampingDissipation",
        &Foam::flexibleStructure::energyBudget::dampingDissipation
    },
    {
        "brakeDissipation",
        &Foam::flexibleStructure::energyBudget::brakeDissipation
    },
    {"externalWork", &Foam::flexibleStructure::energyBudget::externalWork}
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::flexibleStructure::read
(
    const dictionary& dict,
    const membraneMesh* mesh
)
{
    enum class structureType { membrane, ropes };
    static const Enum<structureType> structureTypes
    ({
        {structureType::membrane, "membrane"},
        {structureType::ropes, "ropes"}
    });
    const bool withMembrane =
        structureTypes.get("type", dict) == structureType::membrane;

    wordList allowed
    ({
        "type", "ropes", "anchors", "damping", "safetyFactor",
        "snapTolerance"
    });
    if (withMembrane)
    {
        allowed.append
        (
            wordList({"geometry", "thickness", "E", "nu", "rho", "prestress"})
        );
    }
    structureInput::onlyKeywords(dict, allowed);

    std::vector<label> boundary;
    if (withMembrane)
    {
        for (const point& p : mesh->points())
        {
            nodes_.append(p);
        }
        membrane_ = membraneElements(dict, mesh->triangles(), nodes_);
        boundary = mesh->boundaryPoints();
    }

    const scalar snap =
        structureInput::nonNegative(dict, "snapTolerance", 1e-3, "[m]");
    if (dict.found("ropes") || !withMembrane)
    {
        ropes_ = ropeElements(dict.subDict("ropes"), nodes_, snap);
    }

    anchors_ = anchorGroups(dict.subOrEmptyDict("anchors"), nodes_, boundary);
    for (label ropei = 0; ropei < ropes_.names().size(); ++ropei)
    {
        anchors_.add(ropes_.names()[ropei], ropes_.fixedEnds(ropei), nodes_);
    }

    const dictionary& damping = dict.subOrEmptyDict("damping");
    structureInput::onlyKeywords
    (
        damping,
        {"massProportional", "stiffnessProportional"}
    );
    alpha_ = structureInput::nonNegative
    (
        damping, "massProportional", 0, "[1/s]"
    );
    beta_ = structureInput::nonNegative
    (
        damping, "stiffnessProportional", 0, "[s]"
    );

    const scalar safety = dict.getOrDefault<scalar>("safetyFactor", 0.5);
    if (!(safety > 0 && safety <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "safetyFactor = " << safety << " is invalid; allowed: "
            << "0 < safetyFactor <= 1" << exit(FatalIOError);
    }

    for (label nodei = 0; nodei < nodes_.size(); ++nodei)
    {
        if (!nodes_.fixed[nodei] && !(nodes_.mass[nodei] > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Node " << nodei << " at " << nodes_.position(nodei)
                << " belongs to no triangle or rope (it has no mass)"
                << exit(FatalIOError);
        }
    }

    setStableTimeStep(safety);
}


void Foam::flexibleStructure::setStableTimeStep(const scalar safety)
{
    label trii = -1;
    label segi = -1;
    const scalar dtMembrane = membrane_.stableTimeStep(trii);
    const scalar dtRopes = ropes_.stableTimeStep(segi);
    scalar dt = min(dtMembrane, dtRopes);

    if (dtMembrane <= dtRopes)
    {
        limiter_ = "membrane triangle " + std::to_string(trii);
    }
    else
    {
        const label ropei = ropes_.ropeOf(segi);
        limiter_ =
            "rope " + ropes_.names()[ropei] + " segment "
          + std::to_string(segi - ropes_.segments(ropei).first);
    }

    // The highest frequency 2/dt with damping ratio xi = beta*omega/2
    const scalar xi = beta_/dt;
    dtStable_ = safety*dt*(std::sqrt(1 + xi*xi) - xi);
}


void Foam::flexibleStructure::advance(const scalar dt)
{
    structureNodes& n = nodes_;
    const label nNodes = n.size();
    const double a = alpha_;
    const double c1 = (1 - 0.5*a*dt)/(1 + 0.5*a*dt);

    double kinetic = 0;
    double work = 0;
    double dissipation = 0;

    #pragma omp parallel for schedule(static) \
        reduction(+:kinetic, work, dissipation)
    for (label nodei = 0; nodei < nNodes; ++nodei)
    {
        if (n.fixed[nodei])
        {
            n.vx[nodei] = n.vy[nodei] = n.vz[nodei] = 0;
            continue;
        }
        const double m = n.mass[nodei];
        const double c2 = dt/(m*(1 + 0.5*a*dt));
        const double fe[3] = {n.fExtX[nodei], n.fExtY[nodei], n.fExtZ[nodei]};
        const double v0[3] = {n.vx[nodei], n.vy[nodei], n.vz[nodei]};
        const double v1[3] =
        {
            c1*v0[0] + c2*(n.fx[nodei] + fe[0]),
            c1*v0[1] + c2*(n.fy[nodei] + fe[1]),
            c1*v0[2] + c2*(n.fz[nodei] + fe[2])
        };
        double vm2 = 0;
        for (label c = 0; c < 3; ++c)
        {
            const double vm = 0.5*(v0[c] + v1[c]);
            vm2 += vm*vm;
            work += dt*fe[c]*vm;
        }
        kinetic += 0.5*m*vm2;
        dissipation += dt*a*m*vm2;

        n.vx[nodei] = v1[0];
        n.vy[nodei] = v1[1];
        n.vz[nodei] = v1[2];
        n.x[nodei] += dt*v1[0];
        n.y[nodei] += dt*v1[1];
        n.z[nodei] += dt*v1[2];
    }

    energy_.kinetic = kinetic;
    energy_.externalWork += work;
    energy_.dampingDissipation += dissipation;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flexibleStructure::flexibleStructure
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    if (dict.get<word>("type") == "membrane")
    {
        const membraneMesh mesh(dict.subDict("geometry"), caseDir);
        read(dict, &mesh);
    }
    else
    {
        read(dict, nullptr);
    }
}


Foam::flexibleStructure::flexibleStructure
(
    const dictionary& dict,
    const membraneMesh& mesh
)
{
    read(dict, &mesh);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::flexibleStructure::acrossSlice
(
    const scalar yLo,
    const scalar yHi,
    const dictionary& dict
)
{
    // Faces and twins to round-off of the slice's thickness
    nodes_.pairAcross(yLo, yHi, 1e-6*(yHi - yLo), dict);

    // A triangle within one element of the strip (its nodes in two pairs
    // of twins) stays a flat piece of the strip's plane section: its
    // normal in the x-z plane
    const std::vector<label>& tri = membrane_.triangles();
    for (size_t t = 0; 3*t < tri.size(); ++t)
    {
        label pair[3];
        for (int k = 0; k < 3; ++k)
        {
            const label i = tri[3*t + k];
            pair[k] = min(i, nodes_.twin[i]);
        }
        if (pair[0] != pair[1] && pair[1] != pair[2] && pair[0] != pair[2])
        {
            FatalIOErrorInFunction(dict)
                << "membrane triangle " << label(t) << " (nodes at "
                << nodes_.position(tri[3*t]) << ' '
                << nodes_.position(tri[3*t + 1]) << ' '
                << nodes_.position(tri[3*t + 2]) << ") spans more than one"
                << " element of the strip across the plane slice; allowed:"
                << " triangles within one element (geometry: a panel one"
                << " element across the slice)" << exit(FatalIOError);
        }
    }
}


void Foam::flexibleStructure::step(const scalar dt)
{
    std::fill(nodes_.fx.begin(), nodes_.fx.end(), 0.0);
    std::fill(nodes_.fy.begin(), nodes_.fy.end(), 0.0);
    std::fill(nodes_.fz.begin(), nodes_.fz.end(), 0.0);

    double membranePower = 0;
    double ropePower = 0;
    energy_.membraneStrain =
        membrane_.addInternalForces(nodes_, beta_, membranePower);
    energy_.ropeStrain = ropes_.addInternalForces(nodes_, beta_, ropePower);
    energy_.brakeDissipation = ropes_.brakeDissipation();
    energy_.dampingDissipation += dt*(membranePower + ropePower);
    nodes_.tieTwins();

    advance(dt);
    time_ += dt;
}


Foam::flexibleStructure::subCycleReport
Foam::flexibleStructure::subCycle(const scalar dtFlow)
{
    // Equal sub-steps: no sliver step at the end of the flow step
    const label nSteps = max(label(1), label(std::ceil(dtFlow/dtStable_)));
    const scalar dt = dtFlow/nSteps;
    for (label stepi = 0; stepi < nSteps; ++stepi)
    {
        step(dt);
    }
    return {nSteps, dt, limiter_};
}


Foam::scalar Foam::flexibleStructure::maxDeflection() const
{
    scalar maxMag2 = 0;
    for (label nodei = 0; nodei < nodes_.size(); ++nodei)
    {
        maxMag2 = max
        (
            maxMag2,
            magSqr(nodes_.position(nodei) - nodes_.referencePosition(nodei))
        );
    }
    return std::sqrt(maxMag2);
}


Foam::vector Foam::flexibleStructure::reaction(const word& name) const
{
    const label groupi = anchors_.names().find(name);
    if (groupi < 0)
    {
        FatalErrorInFunction
            << "No anchor group " << name << "; the groups: "
            << flatOutput(anchors_.names()) << exit(FatalError);
    }
    return anchors_.reaction(groupi, nodes_);
}


Foam::vector Foam::flexibleStructure::momentum() const
{
    vector sum(Zero);
    for (label nodei = 0; nodei < nodes_.size(); ++nodei)
    {
        if (!nodes_.fixed[nodei])
        {
            sum += nodes_.mass[nodei]
               *vector(nodes_.vx[nodei], nodes_.vy[nodei], nodes_.vz[nodei]);
        }
    }
    return sum;
}


void Foam::flexibleStructure::writeState(dictionary& state) const
{
    // An entry keeps its value as printed when it is set
    const exactPrecision exact;
    state.set("time", time_);
    nodes_.writeState(state);
    ropes_.writeState(state);

    dictionary energies;
    for (const auto& keyed : energyKeywords)
    {
        energies.set(keyed.first, energy_.*keyed.second);
    }
    state.set("energies", energies);
}


void Foam::flexibleStructure::readState(const dictionary& state)
{
    time_ = state.get<scalar>("time");
    nodes_.readState(state);
    ropes_.readState(state);

    const dictionary& energies = state.subDict("energies");
    for (const auto& keyed : energyKeywords)
    {
        energy_.*keyed.second = energies.get<scalar>(keyed.first);
    }
}


// ************************************************************************* //
