/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "depthAveragedFlow.H"
#include "boundedScalar.H"
#include "depthAveragedSeeding.H"
#include "knownKeywords.H"
#include "staticSwitches.H"
#include "visitShape.H"
#include "particleTransfers.H"
#include "particleCloudIO.H"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::depthAveragedFlow::pressureFormType>
Foam::depthAveragedFlow::pressureFormNames
({
    { pressureFormType::gradient, "gradient" },
    { pressureFormType::divergence, "divergence" },
});

const Foam::word Foam::depthAveragedFlow::cloudName("dampmCloud");



// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::depthAveragedFlow::readPositive
(
    const dictionary& dict,
    const word& key
)
{
    knownKeywords::add(dict, {key});
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << key << " = " << value << " is invalid; allowed: " << key
            << " > 0" << exit(FatalIOError);
    }
    return value;
}


template<class View>
void Foam::depthAveragedFlow::bindCommon(View& v)
{
    particleArrays& p = particles_;
    v.n = p.size();
    v.m = p.component(particleArrays::M);
    v.h = p.component(fields_.h());
    v.a = p.component(fields_.A());
    v.kappa = p.component(fields_.kappa());
    for (int k = 0; k < 4; ++k)
    {
        v.C[k] = p.component(fields_.gradU() + k);
    }
    // In-plane components xx, xy, yy of the symmTensor field
    v.sigma[0] = p.component(fields_.sigma());
    v.sigma[1] = p.component(fields_.sigma() + 1);
    v.sigma[2] = p.component(fields_.sigma() + 3);
    const unsigned terms = basalTerms();
    const auto basal = [&](const unsigned term, const int k)
    {
        return (terms & term) ? p.component(fields_.basal() + k) : nullptr;
    };
    v.s = basal(basalTerm::s, 0);
    v.k1 = basal(basalTerm::k1, 1);
    v.k2 = basal(basalTerm::k2, 2);
}


Foam::shallowColumns Foam::depthAveragedFlow::columns()
{
    particleArrays& p = particles_;
    shallowColumns c;
    bindCommon(c);
    c.x = p.component(particleArrays::X);
    c.y = p.component(particleArrays::Y);
    c.ux = p.component(particleArrays::UX);
    c.uy = p.component(particleArrays::UY);
    c.V = p.component(particleArrays::VOL);
    c.Zb = p.component(fields_.Zb());
    c.gradZetaX = p.component(fields_.gradZeta());
    c.gradZetaY = p.component(fields_.gradZeta() + 1);
    c.gradZx = p.component(fields_.gradZ());
    c.gradZy = p.component(fields_.gradZ() + 1);
    return c;
}


Foam::shallowParticles Foam::depthAveragedFlow::modelView()
{
    shallowParticles v;
    bindCommon(v);
    v.rho = rho_;
    v.g = g_;
    v.hMin = hMin_;
    return v;
}


unsigned Foam::depthAveragedFlow::basalTerms() const
{
    return friction_->basalTerms() | rheology_->basalTerms();
}


bool Foam::depthAveragedFlow::basalActive() const
{
    return basalTerms() != 0;
}


bool Foam::depthAveragedFlow::fusedGather() const
{
    return
        pressureForm_ == pressureFormType::gradient
     && !basalActive()
     && !rheology_->active();
}


Foam::scalar Foam::depthAveragedFlow::maxColumnThickness() const
{
    const label n = particles_.size();
    const label Fc = fields_.F();
    const double* F[4] =
    {
        particles_.component(Fc), particles_.component(Fc + 1),
        particles_.component(Fc + 2), particles_.component(Fc + 3)
    };
    const double* V = particles_.component(particleArrays::VOL);
    double hMax = 0;
    for (label i = 0; i < n; ++i)
    {
        const double area = std::abs(F[0][i]*F[3][i] - F[1][i]*F[2][i]);
        hMax = area > 0 && V[i]/area > hMax ? V[i]/area : hMax;
    }
    return returnReduce(hMax, maxOp<scalar>());
}


Foam::scalar Foam::depthAveragedFlow::speedScale() const
{
    const label n = particles_.size();
    const double* ux = particles_.component(particleArrays::UX);
    const double* uy = particles_.component(particleArrays::UY);
    const double* h = particles_.component(fields_.h());
    double wave = 0, hMax = 0;
    for (label i = 0; i < n; ++i)
    {
        const double hi = max(h[i], 0.0);
        wave = max(wave, std::hypot(ux[i], uy[i]) + std::sqrt(g_*hi));
        hMax = max(hMax, hi);
    }
    const auto range = std::minmax_element(nodes_.Z.begin(), nodes_.Z.end());
    const double relief =
        returnReduce(*range.second, maxOp<scalar>())
      - returnReduce(*range.first, minOp<scalar>());
    reduce(wave, maxOp<scalar>());
    reduce(hMax, maxOp<scalar>());
    return wave + std::sqrt(2*g_*(relief + hMax));
}


void Foam::depthAveragedFlow::checkInput(const dictionary& dict) const
{
    if (!grid_.is2D())
    {
        FatalErrorInFunction
            << "dampmFoam needs a 2D mesh (one cell thick in z, empty front"
            << " and back: the bed plane x-y); see system/blockMeshDict"
            << exit(FatalError);
    }
    if (nPerCell_ < 1 || nPerCell_ > 8)
    {
        FatalIOErrorInFunction(dict)
            << "particlesPerCell = " << nPerCell_ << " is invalid; allowed:"
            << " 1 to 8 (per cell and axis)" << exit(FatalIOError);
    }
    boundedScalar(dict, "hMin", hMin_, scalarBound::nonNegative, "[m]");
}


void Foam::depthAveragedFlow::selectModels
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    dictionary shapeDict(dict);
    if (!shapeDict.found("shapeFunction"))
    {
        shapeDict.add("shapeFunction", word("quadraticBSpline"));
    }
    shape_ = shapeFunction::New(shapeDict, 0.5/nPerCell_);
    topography_ = topographyModel::New(dict, caseDir);
    friction_ = bedFrictionModel::New(dict);
    rheology_ = rheologyModel::New(dict);
}


void Foam::depthAveragedFlow::nodalAreas
(
    const gridGeometry& g,
    double* area
) const
{
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            Foam::nodalAreas(g, kernel, nPerCell_, area);
        }
    );
}


void Foam::depthAveragedFlow::initialiseNodes()
{
    const gridGeometry& geom = grid_.geometry();
    nodes_.resize(geom.nNodes());
    topography_->sampleNodes(geom, nodes_.Z.data());
    nodalAreas(geom, nodes_.area.data());
    kappaNode_.assign(geom.nNodes(), 1.0);
    if (slopeCorrection_ && !topography_->isFlat())
    {
        std::vector<double> gx(geom.nNodes()), gy(geom.nNodes());
        nodeTerrainGradient(geom, nodes_.Z.data(), gx.data(), gy.data());
        for (label n = 0; n < geom.nNodes(); ++n)
        {
            kappaNode_[n] = 1/(1 + gx[n]*gx[n] + gy[n]*gy[n]);
        }
    }
}


void Foam::depthAveragedFlow::startColumns
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    if (particleCloudIO::readStartTime(particles_, grid_, cloudName))
    {
        fields_.checkRead
        (
            particles_, particleCloudIO::cloudDir(grid_.mesh(), cloudName)
        );
    }
    else
    {
        seedRelease(dict, caseDir);
    }
}


void Foam::depthAveragedFlow::seedRelease
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    if (!dict.isDict("release"))
    {
        FatalIOErrorInFunction(dict)
            << "no cloud " << cloudName << " at time "
            << grid_.mesh().time().timeName() << " and no release"
            << " sub-dictionary: nothing to simulate" << exit(FatalIOError);
    }
    autoPtr<releaseModel> release = releaseModel::New
    (
        dict.subDict("release"), *topography_, caseDir
    );
    Info<< "Release: ";
    release->describe(Info);
    Info<< endl;
    const gridDecomposition& parts = grid_.decomposition();
    if (!parts.active())
    {
        depthAveragedSeeding
        (
            grid_.geometry(), nPerCell_, rho_, hMin_, releaseProjection_
        ).seed(*release, *shape_, nodes_.area.data(), particles_, fields_);
        return;
    }

    // Decomposed: every processor seeds the whole release, as a serial run
    // does (the projection and its volume balance reach across parts), and
    // keeps the columns in its own cells
    const gridGeometry domain = grid_.geometry().domain();
    std::vector<double> area(domain.nNodes());
    nodalAreas(domain, area.data());
    depthAveragedSeeding
    (
        domain, nPerCell_, rho_, hMin_, releaseProjection_
    ).seed(*release, *shape_, area.data(), particles_, fields_);

    const label n = particles_.size();
    const double* x = particles_.component(particleArrays::X);
    const double* y = particles_.component(particleArrays::Y);
    std::vector<char> elsewhere(n);
    for (label i = 0; i < n; ++i)
    {
        elsewhere[i] = !parts.holds(x[i], y[i], 0);
    }
    particles_.removeFlagged(elsewhere);
    particles_.shrink();
}


void Foam::depthAveragedFlow::setStartDefaults()
{
    scalar mMax = 0;
    for (label i = 0; i < particles_.size(); ++i)
    {
        mMax = max(mMax, particles_.component(particleArrays::M)[i]);
    }
    massTol_ = 1e-12*returnReduce(mMax, maxOp<scalar>());
    releaseThickness_ = speedLimit::threeDigits(maxColumnThickness());
    splitting_.setDefaultHMin(maxColumnThickness());
    speedLimit_.setDefault(speedScale());
    if (rheology_->defaultShearModulus())
    {
        // G = rho g H0/2: elastic wave speed sqrt(2 G/rho) = sqrt(g H0), the
        // gravity-wave speed of the thickest column (doc section 9)
        rheology_->setDefaultShearModulus
        (
            speedLimit::threeDigits(0.5*rho_*g_*maxColumnThickness())
        );
    }
}


void Foam::depthAveragedFlow::detectFlatBed()
{
    // The terrain terms of S5 are then exactly 0, 0 and 1; set once, kept
    // by splits
    const gridGeometry& geom = grid_.geometry();
    terrainFree_ = topography_->isFlat();
    for (label n = 0; terrainFree_ && n < geom.nNodes(); ++n)
    {
        terrainFree_ = nodes_.Z[n] == 0;
    }
    reduce(terrainFree_, andOp<bool>());
    if (terrainFree_)
    {
        const label n = particles_.size();
        std::fill_n(particles_.component(fields_.Zb()), n, 0.0);
        std::fill_n(particles_.component(fields_.gradZ()), n, 0.0);
        std::fill_n(particles_.component(fields_.gradZ() + 1), n, 0.0);
        std::fill_n(particles_.component(fields_.kappa()), n, 1.0);
    }
}


void Foam::depthAveragedFlow::markTransientFields()
{
    // Written by S5 (or, z and its velocity, for the output) after every
    // sort before anything reads them: the sort need not move them. The
    // totals and the hand-off's test read h and grad Z after a removal (or
    // the re-sort that makes it), and S5 leaves out columns at rest (but
    // after S2's re-sort), whose h and grad Z stay from their last S5: so a
    // removal moves those
    particles_.markTransient(fields_.h());
    particles_.markTransient(fields_.gradZ(), 2);

    // Written by S5 and S6 (z and its velocity for the output only, which
    // nothing else reads in 2D: the bins, stencils and parts take x and y)
    // before anything reads them after a removal too, or one value for
    // every column (a flat bed's): neither a sort nor a removal moves them.
    // Of a column S5 leaves out, S6 and S7 read stale values (another
    // column's after a removal), whose results add to no node
    particles_.markRecomputed(fields_.A());
    particles_.markRecomputed(fields_.gradZeta(), 2);
    particles_.markRecomputed(fields_.kappa());
    particles_.markRecomputed(fields_.Zb());
    particles_.markRecomputed(fields_.basal(), 3);
    particles_.markRecomputed(particleArrays::Z);
    particles_.markRecomputed(particleArrays::UZ);

    // The stress: its out-of-plane components xz, yz, zz are zero
    // throughout, and without a stress model so are xx, xy, yy (also when a
    // restart's cloud holds another model's)
    const label nSigma =
        particleArrays::nComponents(particleArrays::fieldKind::symmTensor);
    for (label c = 0; c < nSigma; ++c)
    {
        const bool inPlane = c == 0 || c == 1 || c == 3;
        if (!(inPlane && rheology_->active()))
        {
            zeroArray
            (
                particles_.component(fields_.sigma() + c), particles_.size()
            );
            particles_.markRecomputed(fields_.sigma() + c);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depthAveragedFlow::depthAveragedFlow
(
    const mpmGrid& grid,
    const dictionary& dict,
    const scalar g
)
:
    grid_(grid),
    rho_(readPositive(dict, "rho")),
    g_(g),
    nPerCell_(dict.getOrDefault<label>("particlesPerCell", 2)),
    hMin_(dict.getOrDefault<scalar>("hMin", 1e-4)),
    releaseThickness_(0),
    releaseProjection_(dict.getOrDefault<bool>("releaseProjection", true)),
    speedLimit_(dict),
    slopeCorrection_(dict.getOrDefault<bool>("slopeCorrection", true)),
    pressureForm_
    (
        pressureFormNames.getOrDefault
        (
            "pressureForm",
            dict,
            pressureFormType::gradient
        )
    ),
    migration_(grid.decomposition()),
    fields_(particles_),
    splitting_(dict, grid.geometry(), nPerCell_, hMin_),
    schedule_(grid.geometry()),
    massTol_(0),
    outflowMass_(0),
    prepared_(false),
    binningChecked_(false),
    terrainFree_(false),
    forcesDone_(false),
    surfaceLeft_(false)
{
    knownKeywords::add
    (
        dict,
        {
            "rho", "particlesPerCell", "hMin", "splitRatio", "splitHMin",
            "releaseProjection", "slopeCorrection", "pressureForm", "release"
        }
    );
    checkInput(dict);

    const fileName caseDir = grid.mesh().time().globalPath();
    selectModels(dict, caseDir);
    {
        bool wall[3][2];
        grid_.wallSides(wall);
        for (int d = 0; d < 2; ++d)
        {
            sides_.wall[d][0] = wall[d][0];
            sides_.wall[d][1] = wall[d][1];
        }
    }
    initialiseNodes();
    startColumns(dict, caseDir);
    setStartDefaults();
    detectFlatBed();
    markTransientFields();
    if (!Pstream::parRun())
    {
        particles_.trackBinChanges(grid.geometry());
    }
    flagged_.reserve(particles_.size());
    splitting_.reserve(particles_.size());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::depthAveragedFlow::describe(Ostream& os) const
{
    const gridGeometry& g = grid_.geometry();
    const char* sideNames[2][2] = {{"x min", "x max"}, {"y min", "y max"}};
    os  << "dampmFoam physics (terms not listed as active cost nothing):" << nl
        << "    columns         "
        << returnReduce(particles_.size(), sumOp<label>()) << ", "
        << nPerCell_*nPerCell_ << " per cell, rho = " << rho_ << " kg/m^3"
        << nl << "    shape function  ";
    shape_->describe(os);
    os  << nl << "    pressure force  " << pressureFormNames[pressureForm_]
        << " form, slope correction " << (slopeCorrection_ ? "on" : "off")
        << ", hMin = " << hMin_ << " m" << nl << "    column split    ";
    splitting_.describe(os);
    os  << nl << "    speed limit     ";
    speedLimit_.describe(os);
    os  << nl << "    topography      ";
    topography_->describe(os);
    os  << nl << "    bed friction    ";
    friction_->describe(os);
    os  << (friction_->active() ? "  [active]" : "") << nl
        << "    rheology        ";
    rheology_->describe(os);
    os  << (rheology_->active() ? "  [active]" : "") << nl;
    if (rheology_->viscosityLaw().tauY() > 0 && !basalActive())
    {
        // A plug sliding on a slope has D = 0: its in-plane stress cannot
        // stop it, only a basal resistance can (doc section 7)
        os  << "    (nothing resists at the bed: on a slope a plug slides"
            << " for ever; basalShear true or a bed friction stops it)" << nl;
    }
    os  << "    sides          ";
    for (int d = 0; d < 2; ++d)
    {
        for (int s = 0; s < 2; ++s)
        {
            os  << ' ' << sideNames[d][s] << ' '
                << (sides_.wall[d][s] ? "wall" : "open") << ';';
        }
    }
    os  << nl << "    grid            " << g.nCellsDomain[0] << " x "
        << g.nCellsDomain[1]
        << " cells of " << g.dx[0] << " x " << g.dx[1] << " m" << endl;
}


void Foam::depthAveragedFlow::writeState(dictionary& state) const
{
    state.set("outflowMass", outflowMass_);
    state.set("massTolerance", massTol_);
    splitting_.writeState(state);
    state.set("releaseThickness", releaseThickness_);
    speedLimit_.writeState(state);
    if (rheology_->defaultShearModulus())
    {
        state.set("shearModulus", rheology_->shearModulus());
    }
}


void Foam::depthAveragedFlow::readState(const dictionary& state)
{
    // Every entry the run wrote: the defaults of its start, not this one's
    outflowMass_ = state.get<scalar>("outflowMass");
    massTol_ = state.get<scalar>("massTolerance");
    splitting_.readState(state);
    // A state written before it was kept: the restart's thickest column
    state.readIfPresent("releaseThickness", releaseThickness_);
    speedLimit_.readState(state);
    if (rheology_->defaultShearModulus())
    {
        rheology_->setDefaultShearModulus(state.get<scalar>("shearModulus"));
    }
}


Foam::label Foam::depthAveragedFlow::surfaceToColumns
(
    const keptSums& leftOut
)
{
    const gridGeometry& g = grid_.geometry();
    const shallowColumns cols = columns();
    label nLeft = 0;
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            typedef std::decay_t<decltype(kernel)> K;
            staticSwitches
            (
                [&](auto terrain)
                {
                    nLeft = gatherSurface<K, terrain()>
                    (
                        g, kernel, nodes_, cols, hMin_, slopeCorrection_,
                        leftOut
                    );
                },
                !terrainFree_
            );
        }
    );
    surfaceLeft_ = nLeft > 0;
    return nLeft;
}


void Foam::depthAveragedFlow::particlesToGrid(const bool output)
{
    if (prepared_)
    {
        if (output && surfaceLeft_)
        {
            // The written fields of the columns S5 left out
            surfaceToColumns(keptSums());
        }
        return;
    }
    const gridGeometry& g = grid_.geometry();
    const gridDecomposition& parts = grid_.decomposition();
    bool sorted = false;
    if (!binningChecked_)
    {
        sorted = particles_.sortByCell(g, schedule_);
    }
    binningChecked_ = false;

    // Work on the nodes the columns touch, and clear those of last step
    // (decomposed: also the shared nodes a neighbour's columns reach), but
    // the sums kept at rest. Not decomposed only: a shared node's sum is
    // its processors' together
    activeNodes_ = stencilNodes_;
    activeNodes_.unite(sharedNodes_);
    stencilNodes_ = particles_.stencilNodes(g);
    sharedNodes_ = parts.shareNodes(stencilNodes_);
    activeNodes_.unite(stencilNodes_);
    activeNodes_.unite(sharedNodes_);
    kept_ =
        Pstream::parRun()
      ? keptSums()
      : resting_.keptNodes
        (
            g, !fusedGather() && !rheology_->active(),
            particles_.binChanges()
        );
    particles_.clearBinChanges();
    zeroNodes(g, activeNodes_, nodes_, kept_);

    const shallowColumns cols = columns();
    const int32_t* binStart = particles_.binStart().data();
    const columnScatter scatter
    {
        g, stencilNodes_, schedule_, binStart, kept_.of(false)
    };
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            const label nLeft = scatterMomentum(scatter, kernel, nodes_, cols);
            resting_.countLeftOut
            (
                restingColumns::momentumScatter, cols.n, nLeft
            );
        }
    );
    parts.sumNodes(nodes_.momentum.data(), shallowGrid::nMomentum);
    nodeHeights
    (
        g, activeNodes_, nodes_, rho_, massTol_, slopeCorrection_,
        kappaNode_.data()
    );

    // S5 and S7 together when no model comes between them
    forcesDone_ = fusedGather();
    if (forcesDone_)
    {
        const columnScatter every{g, stencilNodes_, schedule_, binStart};
        visitShape
        (
            *shape_,
            [&](const auto& kernel)
            {
                typedef std::decay_t<decltype(kernel)> K;
                staticSwitches
                (
                    [&](auto terrain)
                    {
                        scatterForces<K, true, false, false, true, terrain()>
                        (
                            every, kernel, nodes_, cols, rho_, g_, hMin_,
                            slopeCorrection_
                        );
                    },
                    !terrainFree_
                );
            }
        );
        parts.sumNodes(nodes_.loads.data(), shallowGrid::nLoads);
    }
    else
    {
        // S5 leaves out the columns whose nodes all keep S7's loads (and
        // so their masses): it would write what it wrote for them last. Of
        // that, S6 and S7 read all, but add nothing of these columns; the
        // time step, the totals and the hand-off's test read h_p and grad Z,
        // which every move of S10 carries but S2's re-sort does not; the
        // output reads A and Zb too, which no move carries. So S5 takes
        // every column after a re-sort and for the output (and where no
        // node keeps loads, the view has no maps)
        const label nLeft = surfaceToColumns
        (
            !sorted && !output ? kept_.of(true) : keptSums()
        );
        resting_.countLeftOut(restingColumns::surfaceGather, cols.n, nLeft);
    }
    prepared_ = true;
}


Foam::scalar Foam::depthAveragedFlow::stableDeltaT
(
    const scalar maxCo,
    word& limit
) const
{
    const gridGeometry& g = grid_.geometry();
    const label n = particles_.size();
    const double* ux = particles_.component(particleArrays::UX);
    const double* uy = particles_.component(particleArrays::UY);
    const double* h = particles_.component(fields_.h());
    const double gravity = g_;

    // Elastic wave speed squared of a Maxwell stress (0 if viscous)
    const bool active = rheology_->active();
    const double cE2 = active ? 2*rheology_->shearModulus()/rho_ : 0;

    // Gravity waves, and gravity and elastic waves together (without a
    // Maxwell stress only the first). simd: the maxima are exact in any
    // order, and the square roots vectorise. The elastic speed is at least
    // sqrt(2 G/rho), also when no column is left: an elasto-viscoplastic
    // stress has no viscous limit to fall back on
    double maxWave = 0, maxElastic = std::sqrt(cE2);
    if (cE2 > 0)
    {
        #pragma omp parallel for simd schedule(static) \
            reduction(max:maxWave) reduction(max:maxElastic)
        for (label i = 0; i < n; ++i)
        {
            const double u = std::sqrt(ux[i]*ux[i] + uy[i]*uy[i]);
            const double gh = gravity*(h[i] > 0 ? h[i] : 0);
            const double c = u + std::sqrt(gh);
            const double cE = u + std::sqrt(gh + cE2);
            maxWave = c > maxWave ? c : maxWave;
            maxElastic = cE > maxElastic ? cE : maxElastic;
        }
    }
    else
    {
        #pragma omp parallel for simd schedule(static) reduction(max:maxWave)
        for (label i = 0; i < n; ++i)
        {
            const double u = std::sqrt(ux[i]*ux[i] + uy[i]*uy[i]);
            const double c = u + std::sqrt(gravity*(h[i] > 0 ? h[i] : 0));
            maxWave = c > maxWave ? c : maxWave;
        }
    }

    reduce(maxWave, maxOp<scalar>());
    reduce(maxElastic, maxOp<scalar>());
    const scalar delta = min(g.dx[0], g.dx[1]);
    scalar dt = maxWave > 0 ? maxCo*delta/maxWave : GREAT;
    limit = "wave";
    const scalar muMax = active ? rheology_->maxViscosity() : 0;
    if (muMax > 0)
    {
        const scalar dtVisc = maxCo*rho_*delta*delta/(4*muMax);
        if (dtVisc < dt)
        {
            dt = dtVisc;
            limit = "viscous";

            // A Maxwell stress is stable within either the viscous or the
            // elastic limit (doc section 9): the larger one holds
            const scalar dtElastic =
                cE2 > 0 && maxElastic > 0 ? maxCo*delta/maxElastic : 0;
            if (dtElastic > dt)
            {
                dt = dtElastic;
                limit = "elastic";
            }
        }
    }
    return dt;
}


void Foam::depthAveragedFlow::computeForces()
{
    const gridGeometry& g = grid_.geometry();
    const shallowParticles view = modelView();
    const bool basal = basalActive();
    const bool stress = rheology_->active();

    if (basal)
    {
        // Only the coefficients a model adds to (the others are null)
        for (double* coefficient : {view.s, view.k1, view.k2})
        {
            if (coefficient)
            {
                zeroArray(coefficient, view.n);
            }
        }
        if (friction_->active())
        {
            friction_->addResistance(view);
        }
        rheology_->addResistance(view);
    }
    // Scattered with S5 already (particlesToGrid)
    if (forcesDone_)
    {
        forcesDone_ = false;
        return;
    }

    const shallowColumns cols = columns();
    const columnScatter scatter
    {
        g, stencilNodes_, schedule_, particles_.binStart().data(),
        kept_.of(true)
    };

    // One instantiation per combination of terms: a term a case does not
    // select costs nothing in the scatter
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            typedef std::decay_t<decltype(kernel)> K;
            staticSwitches
            (
                [&](auto gradientForm, auto stress, auto basal)
                {
                    const label nLeft =
                        scatterForces<K, gradientForm(), stress(), basal()>
                        (
                            scatter, kernel, nodes_, cols, rho_, g_
                        );
                    resting_.countLeftOut
                    (
                        restingColumns::forceScatter, cols.n, nLeft
                    );
                },
                pressureForm_ == pressureFormType::gradient, stress, basal
            );
        }
    );
    grid_.decomposition().sumNodes(nodes_.loads.data(), shallowGrid::nLoads);
}


void Foam::depthAveragedFlow::updateGrid(const scalar dt)
{
    resistanceUpdate
    (
        grid_.geometry(), activeNodes_, nodes_, sides_, dt, massTol_,
        basalActive(), resting_.nodes(grid_.geometry(), activeNodes_)
    );
}


Foam::scalar Foam::depthAveragedFlow::gridToParticles(const scalar dt)
{
    const gridGeometry& g = grid_.geometry();
    const label n = particles_.size();
    flagged_.resize(n);
    columnMotion motion;
    motion.n = n;
    motion.x = particles_.component(particleArrays::X);
    motion.y = particles_.component(particleArrays::Y);
    motion.ux = particles_.component(particleArrays::UX);
    motion.uy = particles_.component(particleArrays::UY);
    for (int k = 0; k < 4; ++k)
    {
        motion.C[k] = particles_.component(fields_.gradU() + k);
        motion.F[k] = particles_.component(fields_.F() + k);
    }
    motion.V = particles_.component(particleArrays::VOL);
    motion.removal = flagged_.data();
    std::vector<char>& splitMarks = splitting_.flags(n);
    motion.splitCandidate = splitMarks.data();

    // Velocities from the grid, then positions, footprints, walls and open
    // sides, in one pass. The columns to split are marked here (but not
    // those leaving, below); the split checks that the marked fit the
    // domain
    const columnAdvance advance
    (
        g, sides_, dt, splitting_.active(), splitting_.rule(), motion
    );
    const uint8_t* quiet = resting_.quietCells(g);
    label nRemoved = 0;
    gridGeometry::index nLeft = 0;
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            nRemoved =
                gridToColumns
                (
                    g, kernel, nodes_.velocity.data(), advance, quiet, &nLeft
                );
        }
    );
    resting_.count(n, nLeft);
    const double* m = particles_.component(particleArrays::M);

    // The outflow tallied in storage order: the same on any number of
    // threads. The columns leaving are not split
    double removed = 0;
    if (nRemoved)
    {
        particleArrays::forEachFlagged
        (
            flagged_,
            [&](const label i)
            {
                removed += m[i];
                splitMarks[i] = false;
            }
        );
        outflowMass_ += removed;
    }

    // The stress of the end of the step, from the gradient at the new
    // positions (a split copies it to both halves; each column's own, so
    // that of the columns leaving is of no consequence)
    if (rheology_->active())
    {
        rheology_->stress(modelView(), dt);
    }
    const label nSplit = splitting_.split(particles_, fields_, true);
    wakeChanged(splitting_.parents(), n, n + nSplit);
    if (nSplit || nRemoved)
    {
        removeOutflowAndPlaceSplit(nSplit);
    }
    // The columns that arrived from other processors, appended
    const label nBefore = particles_.size();
    const label nGone = migration_.migrate(particles_);
    wakeChanged({}, nBefore - nGone, particles_.size());
    resting_.endStep(g, dt);
    prepared_ = false;
    return removed;
}


void Foam::depthAveragedFlow::wakeChanged
(
    const std::vector<label>& listed,
    const label first,
    const label last
)
{
    const gridGeometry& g = grid_.geometry();
    const double* x = particles_.component(particleArrays::X);
    const double* y = particles_.component(particleArrays::Y);
    for (const label i : listed)
    {
        resting_.wake(g, x[i], y[i]);
    }
    for (label i = first; i < last; ++i)
    {
        resting_.wake(g, x[i], y[i]);
    }
}


void Foam::depthAveragedFlow::removeOutflowAndPlaceSplit(const label nSplit)
{
    // The halves the split appended stay
    flagged_.resize(particles_.size(), false);

    // Each half beside its parent, in its parent's bin: the binning stays
    // while every column is near its bin (else the re-bin is made now),
    // and nothing moves the columns before the next S2, which has then
    // nothing to check. Decomposed, the migration's appends and removals
    // follow, and the next step sorts after them
    if (nSplit && !grid_.decomposition().active())
    {
        particles_.removeAndPlaceAppended
        (
            flagged_, splitting_.parents(), grid_.geometry(), schedule_
        );
        binningChecked_ = true;
    }
    else
    {
        particles_.removeFlagged(flagged_);
    }
}


void Foam::depthAveragedFlow::updateOutputFields()
{
    particlesToGrid(true);

    const scalar zLo = grid_.bounds().min().z();
    const scalar zHi = grid_.bounds().max().z();
    const scalar eps = 1e-6*max(zHi - zLo, scalar(1));

    const label n = particles_.size();
    double* z = particles_.component(particleArrays::Z);
    double* uz = particles_.component(particleArrays::UZ);
    const double* ux = particles_.component(particleArrays::UX);
    const double* uy = particles_.component(particleArrays::UY);
    const double* h = particles_.component(fields_.h());
    const double* Zb = particles_.component(fields_.Zb());
    const double* gx = particles_.component(fields_.gradZ());
    const double* gy = particles_.component(fields_.gradZ() + 1);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        // Free surface, kept inside the mesh so that readers find the cell
        z[i] = min(max(Zb[i] + h[i], zLo + eps), zHi - eps);
        uz[i] = ux[i]*gx[i] + uy[i]*gy[i];
    }
}


Foam::depthAveragedDiagnostics::totals
Foam::depthAveragedFlow::diagnostics() const
{
    return depthAveragedDiagnostics::sum(particles_, fields_, !terrainFree_);
}


Foam::word Foam::depthAveragedFlow::nonFiniteField() const
{
    return depthAveragedDiagnostics::nonFiniteField(particles_, fields_);
}


// ************************************************************************* //
