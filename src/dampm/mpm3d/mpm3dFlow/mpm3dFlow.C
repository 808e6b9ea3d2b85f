/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "mpm3dFlow.H"
#include "knownKeywords.H"
#include "orderedSums.H"
#include "processorTotals.H"
#include "visitShape.H"
#include "stencil.H"
#include "particleCloudIO.H"
#include "particleMemory.H"
#include "Time.H"
#include "fpTrapsHeld.H"
#include <type_traits>
#include "HashSet.H"
#include "HashOps.H"
#include "OStringStream.H"
#include <cmath>
#include <numeric>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::mpm3dFlow::cloudName("mpm3dCloud");

const Foam::Enum<Foam::mpm3dFlow::overlapType>
Foam::mpm3dFlow::overlapTypeNames
({
    { overlapType::error, "error" },
    { overlapType::add, "add" },
    { overlapType::skip, "skip" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Fn>
void Foam::mpm3dFlow::visitKernel(Fn&& fn) const
{
    const bool plane = grid_.isPlane();
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            if (plane)
            {
                fn(planeKernel<std::decay_t<decltype(kernel)>>(kernel));
            }
            else
            {
                fn(kernel);
            }
        }
    );
}


void Foam::mpm3dFlow::planeFlow()
{
    if (!grid_.isPlane())
    {
        return;
    }
    // gradU row-major: the y row (3, 4, 5) and the y column (1, 7); the
    // shear stresses across (xy, yz)
    double* const zeroed[] =
    {
        particles_.component(particleArrays::UY),
        particles_.component(gradU_ + 1), particles_.component(gradU_ + 3),
        particles_.component(gradU_ + 4), particles_.component(gradU_ + 5),
        particles_.component(gradU_ + 7),
        particles_.component(sigma_ + 1), particles_.component(sigma_ + 4)
    };
    for (double* c : zeroed)
    {
        std::fill(c, c + particles_.size(), 0.0);
    }
}


Foam::mpm3dParticles Foam::mpm3dFlow::kernelView()
{
    particleArrays& p = particles_;
    mpm3dParticles v;
    v.n = p.size();
    for (int d = 0; d < 3; ++d)
    {
        v.x[d] = p.component(particleArrays::X + d);
        v.u[d] = p.component(particleArrays::UX + d);
    }
    v.m = p.component(particleArrays::M);
    v.V = p.component(particleArrays::VOL);
    for (int c = 0; c < 9; ++c)
    {
        v.C[c] = p.component(gradU_ + c);
    }
    for (int c = 0; c < 6; ++c)
    {
        v.sigma[c] = p.component(sigma_ + c);
    }
    v.J = p.component(J_);
    v.div = p.component(div_);
    if (settings_.smoothJ)
    {
        for (int d = 0; d < 3; ++d)
        {
            vGrid_[d].resize(v.n);
            v.vGrid[d] = vGrid_[d].data();
        }
    }
    return v;
}


Foam::materialParticles Foam::mpm3dFlow::materialView()
{
    const mpm3dParticles k = kernelView();
    materialParticles v;
    v.n = k.n;
    for (int c = 0; c < 9; ++c)
    {
        v.L[c] = k.C[c];
    }
    v.J = k.J;
    v.div = k.div;
    for (int c = 0; c < 6; ++c)
    {
        v.sigma[c] = particles_.component(sigma_ + c);
    }
    v.p = particles_.component(p_);
    return v;
}


void Foam::mpm3dFlow::seed(const dictionary& regions)
{
    // The domain's lattice of particle positions; a decomposed grid's part
    // keeps those in its own cells
    const gridGeometry& part = grid_.geometry();
    const gridGeometry g = part.domain();
    const gridDecomposition& parts = grid_.decomposition();
    const label n = nPerCell_;
    const label nAcross = perCell(1);
    const scalar subVolume = g.dx[0]*g.dx[1]*g.dx[2]/(n*nAcross*n);
    const scalar rho0 = material_->rho();
    const scalar gMag =
        mag(vector(settings_.g[0], settings_.g[1], settings_.g[2]));
    const boundBox mesh
    (
        point(g.origin[0], g.origin[1], g.origin[2]),
        point(g.upper(0), g.upper(1), g.upper(2))
    );

    // The regions seeded so far: a lattice position inside one of their
    // boxes holds their particles already
    DynamicList<boundBox> earlier;
    DynamicList<word> earlierNames;

    for (const entry& e : regions)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(regions)
                << "initialRegions entry " << e.keyword() << " is not a"
                << " dictionary; allowed: name { type box; min (..); max (..);"
                << " }" << exit(FatalIOError);
        }
        const dictionary& dict = e.dict();
        knownKeywords::add
        (
            dict,
            {
                "type", "min", "max", "U", "hydrostatic", "freeSurface",
                "overlap"
            }
        );
        const word type = dict.get<word>("type");
        if (type != "box")
        {
            FatalIOErrorInFunction(dict)
                << "type " << type << " is invalid; allowed: box"
                << exit(FatalIOError);
        }
        const boundBox box
        (
            barrierGeometry::readPoint(dict, "min"),
            barrierGeometry::readPoint(dict, "max")
        );
        const vector U = speedLimit::readVelocity(dict, vector::zero);
        const bool hydrostatic = dict.getOrDefault<bool>("hydrostatic", false);
        const scalar zs =
            dict.getOrDefault<scalar>("freeSurface", box.max().z());
        particleMemory::reserve
        (
            particles_, particleMemory::seedsInBox(part, n, box),
            "the initial region " + e.keyword() + " (constant/mpm3dProperties)",
            part, n
        );
        const overlapType overlap = overlapTypeNames.getOrDefault
        (
            "overlap", dict, overlapType::error
        );

        // The lattice positions in the box; those of earlier regions
        std::vector<point> pts;
        label nShared = 0;
        wordHashSet shared;
        for (label k = 0; k < g.nCells[2]*n; ++k)
        {
            const scalar z = g.origin[2] + (k + 0.5)*g.dx[2]/n;
            for (label j = 0; j < g.nCells[1]*nAcross; ++j)
            {
                const scalar y = g.origin[1] + (j + 0.5)*g.dx[1]/nAcross;
                for (label i = 0; i < g.nCells[0]*n; ++i)
                {
                    const point x
                    (
                        g.origin[0] + (i + 0.5)*g.dx[0]/n, y, z
                    );
                    if (!box.contains(x) || !parts.holds(x.x(), x.y(), x.z()))
                    {
                        continue;
                    }
                    bool inEarlier = false;
                    forAll(earlier, r)
                    {
                        if (earlier[r].contains(x))
                        {
                            inEarlier = true;
                            shared.insert(earlierNames[r]);
                        }
                    }
                    nShared += inEarlier;
                    if (!(inEarlier && overlap == overlapType::skip))
                    {
                        pts.push_back(x);
                    }
                }
            }
        }
        // Over every processor: the counts, the earlier regions it overlaps
        reduce(nShared, sumOp<label>());
        const label nPts = returnReduce(label(pts.size()), sumOp<label>());
        Pstream::combineGather(shared, HashSetOps::plusEqOp<word>());
        Pstream::combineScatter(shared);
        string sharedWith;
        for (const word& r : shared.sortedToc())
        {
            sharedWith += (sharedWith.empty() ? "" : ", ") + r;
        }
        if (nShared && overlap == overlapType::error)
        {
            FatalIOErrorInFunction(dict)
                << "initial region " << e.keyword() << " (" << box.min()
                << " to " << box.max() << ") overlaps the earlier region(s) "
                << sharedWith.c_str() << " at " << nShared
                << " particle positions: " << nShared*subVolume << " m^3, "
                << rho0*nShared*subVolume << " kg would be seeded twice;"
                << " allowed: regions that do not overlap, or the keyword"
                << " overlap in this region: add (both regions' particles,"
                << " twice the mass there) or skip (the overlap stays the"
                << " earlier region's)" << exit(FatalIOError);
        }
        if (nPts == 0)
        {
            FatalIOErrorInFunction(dict)
                << "initial region " << e.keyword() << " (" << box.min()
                << " to " << box.max() << ") holds no particle position of"
                << " the grid (the mesh spans " << mesh.min() << " to "
                << mesh.max() << ")"
                << (nShared ? ": all of them are in earlier regions" : "")
                << exit(FatalIOError);
        }

        // No particle may start inside a barrier
        label nInside = 0;
        const label holding = barrierHolding
        (
            pointField(UList<point>(pts.data(), label(pts.size()))),
            nInside
        );
        if (holding >= 0)
        {
            OStringStream shape;
            barriers_[holding].geometry().describe(shape);
            FatalIOErrorInFunction(dict)
                << nInside << " of the " << nPts << " particles of"
                << " initial region " << e.keyword() << " (" << box.min()
                << " to " << box.max() << ") would start inside barrier "
                << barriers_[holding].name() << " (" << shape.str().c_str()
                << "); allowed: regions outside the barriers (move or shrink"
                << " the region)" << exit(FatalIOError);
        }

        // The deepest particle's state at rest, before any is made: J too
        // small would give huge masses
        if (hydrostatic)
        {
            scalar zMin = GREAT;
            for (const point& x : pts)
            {
                zMin = min(zMin, x.z());
            }
            reduce(zMin, minOp<scalar>());
            scalar pMax = 0, JMin = 0;
            {
                const fpTrapsHeld hold;
                pMax = rho0*gMag*max(zs - zMin, 0.0);
                JMin = material_->restJ(pMax);
            }
            if (!(std::isfinite(pMax) && JMin >= 0.5 && JMin <= 1))
            {
                FatalIOErrorInFunction(dict)
                    << "freeSurface = " << zs << " of the hydrostatic initial"
                    << " region " << e.keyword() << " gives a pressure of "
                    << pMax << " Pa at its deepest particle (z = " << zMin
                    << " m), which compresses the material to J = " << JMin
                    << "; allowed: a free surface for which J >= 0.5 (the"
                    << " material keeps at least half its volume)"
                    << exit(FatalIOError);
            }
        }

        const label first = particles_.append(label(pts.size()));
        scalar mass = 0;
        for (size_t q = 0; q < pts.size(); ++q)
        {
            const label i = first + label(q);
            const scalar p =
                hydrostatic ? rho0*gMag*max(zs - pts[q].z(), 0.0) : 0;
            const scalar J = material_->restJ(p);
            for (int d = 0; d < 3; ++d)
            {
                particles_.component(particleArrays::X + d)[i] = pts[q][d];
                particles_.component(particleArrays::UX + d)[i] = U[d];
            }
            particles_.component(particleArrays::VOL)[i] = subVolume;
            particles_.component(particleArrays::M)[i] = rho0*subVolume/J;
            particles_.component(J_)[i] = J;
            particles_.component(p_)[i] = p;
            // xx, yy, zz of the symmetric tensor
            particles_.component(sigma_)[i] = -p;
            particles_.component(sigma_ + 3)[i] = -p;
            particles_.component(sigma_ + 5)[i] = -p;
            mass += rho0*subVolume/J;
        }
        reduce(mass, sumOp<scalar>());

        // What was kept, and what of the box lies outside the mesh
        boundBox kept(box);
        const scalar inside = kept.intersect(mesh) ? kept.volume() : 0;
        const scalar outside =
            mesh.contains(box) ? 0 : box.volume() - inside;
        Info<< "Initial region " << e.keyword() << ": " << nPts
            << " particles" << (hydrostatic ? ", hydrostatic" : "")
            << ", kept " << mass << " kg";
        if (outside > 0)
        {
            Info<< "; lost " << rho0*outside << " kg: " << outside << " m^3"
                << " of its box lies outside the mesh (" << mesh.min()
                << " to " << mesh.max() << "; at the reference density, not"
                << " seeded)";
        }
        if (nShared)
        {
            Info<< "; overlaps " << sharedWith.c_str() << " at " << nShared
                << " particle positions, "
                << (overlap == overlapType::add
                    ? "seeded twice (overlap add: twice the mass there)"
                    : "left to them (overlap skip)");
        }
        Info<< endl;
        earlier.append(box);
        earlierNames.append(e.keyword());
    }
    if (returnReduce(particles_.size(), sumOp<label>()) == 0)
    {
        FatalIOErrorInFunction(regions)
            << "initialRegions holds no region: nothing to simulate"
            << exit(FatalIOError);
    }
}


Foam::label Foam::mpm3dFlow::barrierHolding
(
    const pointField& points,
    label& nInside
) const
{
    nInside = 0;
    forAll(barriers_, b)
    {
        boolList in;
        barriers_[b].geometry().inside(points, in);
        for (const bool i : in)
        {
            nInside += i;
        }
        // (the points of every processor)
        reduce(nInside, sumOp<label>());
        if (nInside)
        {
            return b;
        }
    }
    return -1;
}


Foam::scalar Foam::mpm3dFlow::removeOutflow()
{
    const gridGeometry& g = grid_.geometry();
    const label n = particles_.size();
    double* x[3];
    for (int d = 0; d < 3; ++d)
    {
        x[d] = particles_.component(particleArrays::X + d);
    }
    const double* m = particles_.component(particleArrays::M);

    // Most steps no particle has left the domain: a vector loop counts
    // those beyond it first (the same comparisons), and only when there
    // are some are they put back or flagged
    label nBeyond = 0;
    for (int d = 0; d < 3; ++d)
    {
        const double* const xd = x[d];
        const double lo = g.origin[d], hi = g.domainUpper(d);
        #pragma omp parallel for simd schedule(static) reduction(+:nBeyond)
        for (label i = 0; i < n; ++i)
        {
            nBeyond += (xd[i] < lo) | (xd[i] > hi);
        }
    }
    if (!nBeyond)
    {
        return 0;
    }

    flagged_.assign(n, 0);
    label nOut = 0;

    #pragma omp parallel for schedule(static) reduction(+:nOut)
    for (label i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            // A hair inside: the particle's cell is the last one (a part's
            // sides inside the domain: the particle moves to its neighbour)
            const double eps = 1e-9*g.dx[d];
            const double lo = g.origin[d], hi = g.domainUpper(d);
            if (x[d][i] < lo || x[d][i] > hi)
            {
                const bool wall = domainWall_[d][x[d][i] > hi];
                if (wall)
                {
                    x[d][i] = x[d][i] < lo ? lo + eps : hi - eps;
                }
                else
                {
                    flagged_[i] = 1;
                }
            }
        }
        nOut += flagged_[i];
    }
    if (!nOut)
    {
        return 0;
    }

    // Tallied in storage order: the same on any number of threads
    scalar removed = 0;
    particleArrays::forEachFlagged
    (
        flagged_,
        [&](const label i)
        {
            removed += m[i];
            forAll(barriers_, b)
            {
                barrierMonitor& monitor = barriers_[b].monitor();
                if
                (
                    monitor.measuresOvertopping()
                 && monitor.passed(x[0][i], x[1][i], x[2][i])
                )
                {
                    monitor.addPassedOutflow(m[i]);
                }
            }
        }
    );
    particles_.removeFlagged(flagged_);
    return removed;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::mpm3dFlow::mpm3dFlow
(
    const mpmGrid& grid,
    const dictionary& dict,
    const vector& g,
    const particleSource source
)
:
    grid_(grid),
    nPerCell_(dict.getOrDefault<label>("particlesPerCell", 2)),
    gradU_(-1),
    sigma_(-1),
    p_(-1),
    J_(-1),
    div_(-1),
    schedule_(grid.geometry()),
    migration_(grid.decomposition()),
    outflowMass_(0),
    speedLimit_(dict)
{
    knownKeywords::add
    (
        dict,
        {
            "particlesPerCell", "flipRatio", "damping", "barriers",
            "initialRegions"
        }
    );
    if (grid.is2D())
    {
        FatalErrorInFunction
            << "mpm3dFoam needs a 3D mesh; this one is one cell thick with"
            << " empty patches (see system/blockMeshDict)" << exit(FatalError);
    }
    if (nPerCell_ < 1 || nPerCell_ > 8)
    {
        FatalIOErrorInFunction(dict)
            << "particlesPerCell = " << nPerCell_ << " is invalid; allowed:"
            << " 1 to 8 (per cell and axis)" << exit(FatalIOError);
    }

    dictionary shapeDict(dict);
    if (!shapeDict.found("shapeFunction"))
    {
        shapeDict.add("shapeFunction", word("quadraticBSpline"));
    }
    shape_ = shapeFunction::New(shapeDict, 0.5/nPerCell_);
    material_ = materialModel::New(dict);

    if (grid.isPlane() && g.y() != 0)
    {
        FatalErrorInFunction
            << "gravity " << g << " has a component across the plane slice"
            << " (the mesh is one cell across y with empty patches);"
            << " allowed: gravity in the x-z plane (see constant/g)"
            << exit(FatalError);
    }

    // Kernel settings
    for (int d = 0; d < 3; ++d)
    {
        settings_.g[d] = g[d];
    }
    settings_.rho0 = material_->rho();
    settings_.smoothJ = material_->volumetricSmoothing();
    settings_.flipRatio = dict.getOrDefault<scalar>("flipRatio", 0);
    settings_.damping = dict.getOrDefault<scalar>("damping", 0);
    if (!(settings_.flipRatio >= 0 && settings_.flipRatio <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "flipRatio = " << settings_.flipRatio << " is invalid;"
            << " allowed: 0 (APIC) to 1 (pure FLIP)" << exit(FatalIOError);
    }
    if (!(settings_.damping >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "damping = " << settings_.damping << " is invalid; allowed:"
            << " >= 0 [1/s]" << exit(FatalIOError);
    }
    // The domain's walls; those of this processor's part: the domain's
    // sides it touches
    grid_.wallSides(domainWall_);
    const gridGeometry& geom = grid.geometry();
    for (int d = 0; d < 3; ++d)
    {
        settings_.wall[d][0] = domainWall_[d][0] && geom.ownFirst(d) == 0;
        settings_.wall[d][1] =
            domainWall_[d][1] && geom.ownEnd(d) == geom.nCells[d];
    }

    // Barriers (their files in the case, not a processor directory)
    const fileName caseDir = grid.mesh().time().globalPath();
    const dictionary& barrierDicts = dict.subOrEmptyDict("barriers");
    for (const entry& e : barrierDicts)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(barrierDicts)
                << "barriers entry " << e.keyword() << " is not a dictionary;"
                << " allowed: name { type plane|box|triSurface|terrain; ... }"
                << exit(FatalIOError);
        }
        if (membraneBarrier::isMembrane(e.dict()))
        {
            membranes_.append
            (
                new membraneBarrier(e.keyword(), e.dict(), caseDir, g)
            );
            // (every processor holds the structure whole)
            membranes_.last().checkInMesh(grid.geometry(), e.dict());
            if (grid.isPlane())
            {
                membranes_.last().onPlaneSlice(grid.geometry(), e.dict());
            }
            continue;
        }
        barriers_.append(new barrier(e.keyword(), e.dict(), caseDir));
        barriers_.last().findNodes(grid.geometry(), settings_.wall);
    }

    // Particle fields
    typedef particleArrays::fieldKind kind;
    gradU_ = particles_.addField("gradU", kind::tensor);
    sigma_ = particles_.addField("sigma", kind::symmTensor);
    p_ = particles_.addField("p", kind::scalar);
    J_ = particles_.addField("J", kind::scalar, 1);
    div_ = particles_.addField("div", kind::internal);
    material_->addFields(particles_);

    nodes_.resize(grid.geometry().nNodes());

    if (source == particleSource::none)
    {
        return;
    }

    // The particles: the cloud of the start time, or the initial regions
    const Time& runTime = grid.mesh().time();
    const bool restarted =
        particleCloudIO::readStartTime(particles_, grid, cloudName);
    if (restarted)
    {
        particleCloudIO::checkRange
        (
            particles_, particleCloudIO::cloudDir(grid.mesh(), cloudName),
            "J", 0, false, GREAT
        );
    }
    else
    {
        if (!dict.isDict("initialRegions"))
        {
            FatalIOErrorInFunction(dict)
                << "no cloud " << cloudName << " at time "
                << runTime.timeName() << " and no initialRegions"
                << " sub-dictionary: nothing to simulate"
                << exit(FatalIOError);
        }
        seed(dict.subDict("initialRegions"));
    }

    planeFlow();

    scalar mMax = 0;
    const double* m = particles_.component(particleArrays::M);
    for (label i = 0; i < particles_.size(); ++i)
    {
        mMax = max(mMax, m[i]);
    }
    settings_.massTol = 1e-12*returnReduce(mMax, maxOp<scalar>());
    flagged_.reserve(particles_.size());
    speedLimit_.setDefault(speedScale());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::mpm3dFlow::speedScale() const
{
    const gridGeometry& g = grid_.geometry();
    const scalar gMag =
        mag(vector(settings_.g[0], settings_.g[1], settings_.g[2]));
    return
        material_->waveSpeed() + diagnostics().maxSpeed
      + std::sqrt(2*gMag*(g.domainUpper(2) - g.origin[2]));
}


Foam::vector Foam::mpm3dFlow::particleSpacing() const
{
    const gridGeometry& g = grid_.geometry();
    return vector
    (
        g.dx[0]/perCell(0), g.dx[1]/perCell(1), g.dx[2]/perCell(2)
    );
}


Foam::scalar Foam::mpm3dFlow::width() const
{
    const gridGeometry& g = grid_.geometry();
    return g.domainUpper(1) - g.origin[1];
}


void Foam::mpm3dFlow::writeState(dictionary& state) const
{
    state.set("outflowMass", outflowMass_);
    speedLimit_.writeState(state);
    state.set("massTolerance", settings_.massTol);
    forAll(barriers_, b)
    {
        state.set
        (
            word(barriers_[b].name() + "PassedOutflow"),
            barriers_[b].monitor().passedOutflow()
        );
    }
    for (const membraneBarrier& m : membranes_)
    {
        m.writeState(state);
    }
}


void Foam::mpm3dFlow::readState(const dictionary& state)
{
    outflowMass_ = state.get<scalar>("outflowMass");
    settings_.massTol = state.get<scalar>("massTolerance");
    speedLimit_.readState(state);
    // A barrier added for the restart has let nothing pass yet
    forAll(barriers_, b)
    {
        barriers_[b].monitor().setPassedOutflow
        (
            state.getOrDefault<scalar>
            (
                word(barriers_[b].name() + "PassedOutflow"),
                0
            )
        );
    }
    for (membraneBarrier& m : membranes_)
    {
        m.readState(state);
    }
}


void Foam::mpm3dFlow::describe(Ostream& os) const
{
    const gridGeometry g = grid_.geometry().domain();
    const label nParticles = returnReduce(particles_.size(), sumOp<label>());
    os  << "mpm3dFoam: explicit 3D MPM, update stress last" << nl
        << "    grid: " << g.nCells[0] << " x " << g.nCells[1] << " x "
        << g.nCells[2] << " cells of " << g.dx[0] << " x " << g.dx[1]
        << " x " << g.dx[2] << " m";
    if (g.plane)
    {
        os  << ", a plane slice: plane flow in x-z, forces per unit width"
            << " over its " << width() << " m across y";
    }
    os  << nl
        << "    particles: " << nParticles << " ("
        << nPerCell_ << " per cell and axis when seeded)" << nl
        << "    shape function: " << shape_->type() << nl
        << "    transfer: "
        << (settings_.flipRatio > 0 ? "FLIP/PIC blend" : "APIC");
    if (settings_.flipRatio > 0)
    {
        os  << " (FLIP share " << settings_.flipRatio << ")";
    }
    os  << nl << "    material: ";
    material_->describe(os);
    os  << nl << "    gravity: (" << settings_.g[0] << ' ' << settings_.g[1]
        << ' ' << settings_.g[2] << ") m/s^2" << nl
        << "    damping: ";
    if (settings_.damping > 0)
    {
        os  << settings_.damping << " 1/s";
    }
    else
    {
        os  << "none (not computed)";
    }
    os  << nl << "    speed limit: ";
    speedLimit_.describe(os);
    os  << nl << "    sides:";
    const char* axes = "xyz";
    for (int d = 0; d < 3; ++d)
    {
        for (int s = 0; s < 2; ++s)
        {
            os  << ' ' << axes[d] << (s ? " max " : " min ")
                << (domainWall_[d][s] ? "wall" : "open") << ';';
        }
    }
    os  << nl << "    barriers: ";
    if (barriers_.empty() && membranes_.empty())
    {
        os  << "none (no contact computed)" << nl;
    }
    else
    {
        os  << barriers_.size() + membranes_.size() << nl;
        for (const barrier& b : barriers_)
        {
            b.describe(os);
        }
        for (const membraneBarrier& m : membranes_)
        {
            m.describe(os);
        }
    }
    os  << endl;
}


void Foam::mpm3dFlow::findNodes()
{
    const gridGeometry& g = grid_.geometry();
    const gridDecomposition& parts = grid_.decomposition();

    // Work on the nodes the particles touch, and clear those of last step
    activeNodes_ = sumNodes_;
    stencilNodes_ = particles_.stencilNodes(g);
    if (parts.active())
    {
        // Whole rows of boxes: the shared nodes a neighbour's particles
        // reach join the sums
        sumNodes_ = stencilNodes_;
        sumNodes_.unite(parts.shareNodes(stencilNodes_));
        activeNodes_.unite(sumNodes_);
        return;
    }
    activeNodes_.unite(stencilNodes_);
    std::swap(lastRows_, stencilRows_);
    particles_.stencilRows(g, stencilRows_);
    wallFoldSpans(g, settings_.wall, stencilRows_);
    activeRows_.unite(lastRows_, stencilRows_);
    stencilNodes_.rows = &stencilRows_;
    activeNodes_.rows = &activeRows_;
    sumNodes_ = stencilNodes_;
}


void Foam::mpm3dFlow::particlesToGrid()
{
    const gridGeometry& g = grid_.geometry();
    const gridDecomposition& parts = grid_.decomposition();
    particles_.sortByCell(g, schedule_);
    findNodes();
    zeroNodes3D(g, activeNodes_, nodes_);

    const mpm3dParticles view = kernelView();
    visitKernel
    (
        [&](const auto& kernel)
        {
            if (settings_.smoothJ)
            {
                pressureToGrid3D
                (
                    g, schedule_, kernel, stencilNodes_,
                    particles_.binStart().data(), view, nodes_
                );
                parts.sumNodes(nodes_.vol.data(), 1);
                parts.sumNodes(nodes_.pV.data(), 1);
                foldWalls
                (
                    g, sumNodes_, settings_.wall,
                    {nodes_.vol.data(), nodes_.pV.data()}, {}
                );
                // pV: the node pressure from here on
                nodeMeans3D
                (
                    g, sumNodes_, nodes_.vol.data(), nodes_.pV.data()
                );
            }
            scatterNodeSums3D
            (
                g, schedule_, kernel, stencilNodes_,
                particles_.binStart().data(), view, settings_, nodes_
            );
        }
    );
    parts.sumNodes(nodes_.sums.data(), mpm3dGrid::sumsWidth);
    unpackNodeSums3D(g, sumNodes_, nodes_);
}


Foam::scalar Foam::mpm3dFlow::stableDeltaT
(
    const scalar maxCo,
    word& limit
) const
{
    const gridGeometry& g = grid_.geometry();
    const label n = particles_.size();
    const double* u[3];
    for (int d = 0; d < 3; ++d)
    {
        u[d] = particles_.component(particleArrays::UX + d);
    }
    double maxU2 = 0;
    #pragma omp parallel for schedule(static) reduction(max:maxU2)
    for (label i = 0; i < n; ++i)
    {
        const double u2 = u[0][i]*u[0][i] + u[1][i]*u[1][i] + u[2][i]*u[2][i];
        maxU2 = u2 > maxU2 ? u2 : maxU2;
    }
    reduce(maxU2, maxOp<double>());
    const scalar h = g.hMin();
    scalar dt = maxCo*h/(material_->waveSpeed() + std::sqrt(maxU2));
    limit = "wave";

    const scalar mu = material_->explicitViscosity();
    if (mu > 0)
    {
        const scalar dtVisc = maxCo*material_->rho()*h*h/(6*mu);
        if (dtVisc < dt)
        {
            dt = dtVisc;
            limit = "viscous";
        }
    }
    return dt;
}


void Foam::mpm3dFlow::updateGrid(const scalar dt)
{
    gridUpdate3D(grid_.geometry(), activeNodes_, settings_, dt, nodes_);
}


void Foam::mpm3dFlow::pushFromMembranes
(
    const scalar dt,
    const scalar maxCo
)
{
    if (membranes_.empty())
    {
        return;
    }
    const gridGeometry& g = grid_.geometry();
    const gridDecomposition& parts = grid_.decomposition();
    const mpm3dParticles p = kernelView();
    const membraneContact::penalty stiffness
    {
        material_->rho(), material_->waveSpeed(), g.hMin(), maxCo,
        g.plane ? width() : 0
    };
    double* const fNode[3] =
        {nodes_.fx.data(), nodes_.fy.data(), nodes_.fz.data()};
    // A decomposed grid's node forces are complete sums already: the
    // pushes go to a node sum of their own, completed, then added
    double* f[3] = {fNode[0], fNode[1], fNode[2]};
    if (parts.active())
    {
        for (int d = 0; d < 3; ++d)
        {
            pushForce_[d].resize(g.nNodes());
            f[d] = pushForce_[d].data();
        }
        zeroNodeArrays(g, sumNodes_, {f[0], f[1], f[2]});
    }
    for (membraneBarrier& m : membranes_)
    {
        const std::vector<membraneContact::push>& pushes =
            m.pushParticles(g, p, stencilNodes_, stiffness, dt);
        // External forces, scattered to the nodes by the shape functions'
        // weights (few particles: in order, the same on any number of
        // threads)
        visitKernel
        (
            [&](const auto& kernel)
            {
                using kernelType = std::decay_t<decltype(kernel)>;
                for (const membraneContact::push& pi : pushes)
                {
                    const label i = pi.particle;
                    const stencil<3, kernelType> s
                    (
                        g, kernel, p.x[0][i], p.x[1][i], p.x[2][i]
                    );
                    s.forEachNode
                    (
                        [&](label n, double N, const double*, const double*)
                        {
                            for (int d = 0; d < 3; ++d)
                            {
                                f[d][n] += N*pi.f[d];
                            }
                        }
                    );
                }
            }
        );
    }
    if (parts.active())
    {
        for (int d = 0; d < 3; ++d)
        {
            parts.sumNodes(f[d], 1);
        }
        g.forEachNodeRow
        (
            sumNodes_,
            [&](const gridGeometry::index first, const gridGeometry::index last)
            {
                for (int d = 0; d < 3; ++d)
                {
                    for (gridGeometry::index n = first; n < last; ++n)
                    {
                        fNode[d][n] += f[d][n];
                    }
                }
            }
        );
    }
}


void Foam::mpm3dFlow::contact(const scalar dt)
{
    for (barrier& b : barriers_)
    {
        b.applyContact(nodes_, activeNodes_, settings_.massTol, dt);
    }
    for (membraneBarrier& m : membranes_)
    {
        m.advance(dt);
    }
}


void Foam::mpm3dFlow::gridToParticles(const scalar dt)
{
    const gridGeometry& g = grid_.geometry();
    const mpm3dParticles view = kernelView();
    const label n = particles_.size();
    const double* x0[3] = {nullptr, nullptr, nullptr};
    // The start positions, for the guard of the barriers the particles can
    // reach in this step
    bool guarded = false;
    for (barrier& b : barriers_)
    {
        guarded = b.guardReach(stencilNodes_) || guarded;
    }
    if (guarded)
    {
        for (int d = 0; d < 3; ++d)
        {
            const double* x = particles_.component(particleArrays::X + d);
            xOld_[d].resize(n);
            double* xo = xOld_[d].data();
            #pragma omp parallel for schedule(static)
            for (label i = 0; i < n; ++i)
            {
                xo[i] = x[i];
            }
            x0[d] = xo;
        }
    }
    visitKernel
    (
        [&](const auto& kernel)
        {
            settings_.maxJ =
                material_->maxJ(dt, g.hMin(), kernel.loneParticleStiffness());
            gridToParticles3D
            (
                g, schedule_, kernel, stencilNodes_,
                particles_.binStart().data(), settings_, dt, nodes_, view
            );
            if (settings_.smoothJ)
            {
                grid_.decomposition().sumNodes(nodes_.dVol.data(), 1);
                foldWalls
                (
                    g, sumNodes_, settings_.wall, {nodes_.dVol.data()}, {}
                );
                // dVol: the node volume ratio from here on
                nodeMeans3D
                (
                    g, sumNodes_, nodes_.vol.data(), nodes_.dVol.data()
                );
                volumeChangeToParticles3D
                (
                    g, kernel, settings_, dt, nodes_, view
                );
            }
        }
    );
    for (barrier& b : barriers_)
    {
        b.stopEntries(g, x0, view, dt);
    }
    for (membraneBarrier& m : membranes_)
    {
        m.stopCrossings(g, view, dt);
    }
    material_->updateStress(particles_, materialView(), dt);
    outflowMass_ += removeOutflow();
    migration_.migrate(particles_);
}


void Foam::mpm3dFlow::monitorBarriers(const scalar t)
{
    for (barrier& b : barriers_)
    {
        b.execute(nodes_, activeNodes_, settings_.massTol, t);
    }
}


Foam::mpm3dFlow::totals Foam::mpm3dFlow::diagnostics() const
{
    const label n = particles_.size();
    const double* x[3];
    const double* u[3];
    for (int d = 0; d < 3; ++d)
    {
        x[d] = particles_.component(particleArrays::X + d);
        u[d] = particles_.component(particleArrays::UX + d);
    }
    const double* m = particles_.component(particleArrays::M);
    const double g[3] = {settings_.g[0], settings_.g[1], settings_.g[2]};

    // The same rounding on any number of threads, four particles at a time
    double S[6], mx[7];
    orderedLaneSums<6, 7>(n, S, mx, [&](label i, auto* s, auto* M)
    {
        typedef std::remove_pointer_t<decltype(s)> Real;
        const Real mi = loadAt<Real>(m, i);
        Real xi[3], ui[3];
        for (int d = 0; d < 3; ++d)
        {
            xi[d] = loadAt<Real>(x[d], i);
            ui[d] = loadAt<Real>(u[d], i);
        }
        const Real u2 = ui[0]*ui[0] + ui[1]*ui[1] + ui[2]*ui[2];
        s[0] += mi;
        s[1] += 0.5*mi*u2;
        s[2] -= mi*(g[0]*xi[0] + g[1]*xi[1] + g[2]*xi[2]);
        s[3] += mi*ui[0];
        s[4] += mi*ui[1];
        s[5] += mi*ui[2];
        const Real v[7] = {u2, -xi[0], -xi[1], -xi[2], xi[0], xi[1], xi[2]};
        for (int k = 0; k < 7; ++k)
        {
            M[k] = select(v[k] > M[k], v[k], M[k]);
        }
    });

    // Over every processor of a decomposed run
    const label nTotal = processorTotals<6, 7>(S, mx, n);

    totals t;
    t.nParticles = nTotal;
    t.mass = S[0];
    t.kineticEnergy = S[1];
    t.potentialEnergy = S[2];
    t.maxSpeed = std::sqrt(max(mx[0], 0.0));
    t.momentum = vector(S[3], S[4], S[5]);
    t.extent = nTotal
        ? boundBox(point(-mx[1], -mx[2], -mx[3]), point(mx[4], mx[5], mx[6]))
        : boundBox(point::zero, point::zero);
    return t;
}


void Foam::mpm3dFlow::smoothPressure()
{
    if (!settings_.smoothJ)
    {
        return;
    }
    const gridGeometry& g = grid_.geometry();
    const gridDecomposition& parts = grid_.decomposition();
    const mpm3dParticles view = kernelView();
    nodeBox box = particles_.stencilNodes(g);
    box.unite(parts.shareNodes(box));
    visitKernel
    (
        [&](const auto& kernel)
        {
            nodalPressure3D
            (
                g, kernel, box, settings_.wall, view,
                particles_.component(p_), nodes_,
                [&](double* vol, double* pV)
                {
                    parts.sumNodes(vol, 1);
                    parts.sumNodes(pV, 1);
                }
            );
        }
    );
}


bool Foam::mpm3dFlow::finite() const
{
    std::vector<label> all(particles_.nComponentArrays());
    std::iota(all.begin(), all.end(), 0);
    return returnReduce(particles_.finite(all), andOp<bool>());
}


// ************************************************************************* //
