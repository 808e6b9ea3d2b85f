/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneBarrier.H"
#include "boundBox.H"
#include "boundedScalar.H"
#include "knownKeywords.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::membraneBarrier::structureDict(const dictionary& dict)
{
    dictionary s(dict);
    for (const word& key : contactCondition::keywords)
    {
        s.remove(key);
    }
    s.remove("contactStiffness");
    return s;
}


Foam::scalar Foam::membraneBarrier::contactStiffness(const dictionary& dict)
{
    const scalar kappa = boundedScalar
    (
        dict, "contactStiffness",
        dict.getOrDefault<scalar>("contactStiffness", 0.8),
        scalarBound::positive
    );
    // omega dt = kappa: the explicit pair is unstable from 2 and gains
    // energy well before
    if (kappa >= 2)
    {
        FatalIOErrorInFunction(dict)
            << "contactStiffness = " << kappa << " is invalid; allowed: "
            << "0 < contactStiffness < 2 (the push's omega dt; unstable "
            << "from 2, default 0.8)" << exit(FatalIOError);
    }
    if (kappa > 1)
    {
        WarningInFunction
            << "contactStiffness = " << kappa << " in " << dict.name()
            << ": above 1 the explicit push gains energy; 0.8 is the default"
            << endl;
    }
    return kappa;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneBarrier::membraneBarrier
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir,
    const vector& g
)
:
    name_(name),
    condition_(dict),
    structure_(structureDict(dict), caseDir),
    surface_(structure_.nodes(), structure_.membrane().triangles()),
    contact_
    (
        condition_,
        structure_.nodes().size(),
        structure_.membrane().arealMass(),
        contactStiffness(dict)
    ),
    monitor_(name, structure_.anchors().names().size()),
    g_(g),
    dt_(1),
    move_(0),
    minSubSteps_(labelMax),
    maxSubSteps_(0),
    nPutBack_(0)
{
    knownKeywords::add(dict, {"contactStiffness"});

    // The external force: the weight (the flow's impulses change the
    // velocities at once)
    structureNodes& n = structure_.nodes();
    for (label i = 0; i < n.size(); ++i)
    {
        n.fExtX[i] = n.mass[i]*g_.x();
        n.fExtY[i] = n.mass[i]*g_.y();
        n.fExtZ[i] = n.mass[i]*g_.z();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::membraneBarrier::checkInMesh
(
    const gridGeometry& g,
    const dictionary& dict
) const
{
    const structureNodes& n = structure_.nodes();
    boundBox nodes;
    for (label i = 0; i < n.size(); ++i)
    {
        nodes.add(n.position(i));
    }
    const boundBox mesh
    (
        point(g.origin[0], g.origin[1], g.origin[2]),
        point(g.domainUpper(0), g.domainUpper(1), g.domainUpper(2))
    );
    if (!nodes.overlaps(mesh))
    {
        FatalIOErrorInFunction(dict)
            << "flexible barrier " << name_ << " lies wholly outside the mesh:"
            << " its nodes span " << nodes.min() << " to " << nodes.max()
            << ", the mesh " << mesh.min() << " to " << mesh.max()
            << "; allowed: a membrane that meets the mesh (see its geometry)"
            << exit(FatalIOError);
    }
}


void Foam::membraneBarrier::onPlaneSlice
(
    const gridGeometry& g,
    const dictionary& dict
)
{
    structure_.acrossSlice(g.origin[1], g.domainUpper(1), dict);
    monitor_.perUnitWidth(g.domainUpper(1) - g.origin[1]);
}


const std::vector<Foam::membraneContact::push>&
Foam::membraneBarrier::pushParticles
(
    const gridGeometry& g,
    const mpm3dParticles& p,
    const nodeBox& particleNodes,
    const membraneContact::penalty& stiffness,
    const double dt
)
{
    // The bucket reaches the particles whose stencils reach the membrane;
    // rebuilt after a move of half a cell
    const double h = g.hMax();
    surface_.update(g, 2*h, 0.5*h);
    return contact_.pushParticles
    (
        g, surface_, p, particleNodes, stiffness, dt
    );
}


void Foam::membraneBarrier::advance(const double dt)
{
    contact_.kickMembrane(surface_, dt);
    const structureNodes& n = structure_.nodes();
    xStart_[0] = n.x;
    xStart_[1] = n.y;
    xStart_[2] = n.z;
    const flexibleStructure::subCycleReport r = structure_.subCycle(dt);
    double move2 = 0;
    for (label i = 0; i < n.size(); ++i)
    {
        const double d[3] =
        {
            n.x[i] - xStart_[0][i], n.y[i] - xStart_[1][i],
            n.z[i] - xStart_[2][i]
        };
        move2 = max(move2, d[0]*d[0] + d[1]*d[1] + d[2]*d[2]);
    }
    move_ = std::sqrt(move2);
    dt_ = dt;
    if (!maxSubSteps_)
    {
        Info<< "Flexible barrier " << name_ << ": " << r.nSteps
            << " sub-step" << (r.nSteps > 1 ? "s" : "") << " of " << r.dt
            << " s per flow step of " << dt << " s: its stable step is "
            << structure_.stableTimeStep() << " s, limited by "
            << r.limiter.c_str() << endl;
    }
    minSubSteps_ = min(minSubSteps_, r.nSteps);
    maxSubSteps_ = max(maxSubSteps_, r.nSteps);
}


void Foam::membraneBarrier::openFiles(const Time& runTime)
{
    monitor_.openFiles(runTime, structure_.anchors().names());
    // Written once, by the master (every processor holds the structure)
    if (Pstream::master())
    {
        vtk_.reset
        (
            new structureVTKWriter
            (
                runTime.globalPath(), name_, runTime.startTimeIndex()
            )
        );
    }
}


Foam::List<Foam::vector> Foam::membraneBarrier::anchorForces() const
{
    const anchorGroups& anchors = structure_.anchors();
    List<vector> F(anchors.names().size());
    forAll(F, gi)
    {
        // The structure's force on the anchor: minus the support's
        F[gi] = -structure_.reaction(anchors.names()[gi]);
        for (const label i : anchors.nodes(gi))
        {
            F[gi] += contact_.anchored(i)/dt_;
        }
    }
    return F;
}


void Foam::membraneBarrier::writeState(dictionary& state) const
{
    dictionary s;
    contact_.writeState(s);
    structure_.writeState(s);
    state.set(word(name_ + "Membrane"), s);
}


void Foam::membraneBarrier::readState(const dictionary& state)
{
    const word key(name_ + "Membrane");
    if (!state.isDict(key))
    {
        FatalIOErrorInFunction(state)
            << "no entry " << key << ": the state of flexible barrier "
            << name_ << " is missing (a membrane added for the restart"
            << " cannot start from the flow's state)" << exit(FatalIOError);
    }
    const dictionary& s = state.subDict(key);
    contact_.readState(s);
    structure_.readState(s);
}


void Foam::membraneBarrier::report(Ostream& os) const
{
    monitor_.report(os, structure_.anchors().names());
    if (maxSubSteps_)
    {
        os  << "    sub-steps per flow step: " << minSubSteps_ << " to "
            << maxSubSteps_ << " (stable step " << structure_.stableTimeStep()
            << " s, " << structure_.limiter().c_str() << ")" << nl;
    }
    os  << "    particles the guard put back: "
        << returnReduce(nPutBack_, sumOp<label>())
        << " (the push held the rest)" << nl;
}


void Foam::membraneBarrier::describe(Ostream& os) const
{
    const flexibleStructure& s = structure_;
    os  << "    " << name_ << ": flexible membrane, " << s.nodes().size()
        << " nodes, " << s.membrane().size() << " triangles, "
        << s.ropes().names().size() << " rope(s), anchors "
        << flatOutput(s.anchors().names()) << ", contact ";
    condition_.describe(os);
    os  << ", stable step " << s.stableTimeStep() << " s ("
        << s.limiter().c_str() << ")" << nl;
}


// ************************************************************************* //
