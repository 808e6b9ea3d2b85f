/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "depthAveragedFlow.H"
#include "knownKeywords.H"
#include "orderedSums.H"
#include "visitShape.H"
#include "particleTransfers.H"
#include "particleCloudIO.H"
#include "particleMemory.H"

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

const Foam::scalar Foam::depthAveragedFlow::splitHMinFraction = 0.01;



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
    v.m = p.column(particleArrays::M);
    v.h = p.column(h_);
    v.a = p.column(A_);
    v.kappa = p.column(kappa_);
    for (int k = 0; k < 4; ++k)
    {
        v.C[k] = p.column(gradU_ + k);
    }
    // In-plane components xx, xy, yy of the symmTensor field
    v.sigma[0] = p.column(sigma_);
    v.sigma[1] = p.column(sigma_ + 1);
    v.sigma[2] = p.column(sigma_ + 3);
    v.s = p.column(basal_);
    v.k1 = p.column(basal_ + 1);
    v.k2 = p.column(basal_ + 2);
}


Foam::shallowColumns Foam::depthAveragedFlow::columns()
{
    particleArrays& p = particles_;
    shallowColumns c;
    bindCommon(c);
    c.x = p.column(particleArrays::X);
    c.y = p.column(particleArrays::Y);
    c.ux = p.column(particleArrays::UX);
    c.uy = p.column(particleArrays::UY);
    c.V = p.column(particleArrays::VOL);
    c.Zb = p.column(Zb_);
    c.gradZetaX = p.column(gradZeta_);
    c.gradZetaY = p.column(gradZeta_ + 1);
    c.gradZx = p.column(gradZ_);
    c.gradZy = p.column(gradZ_ + 1);
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


bool Foam::depthAveragedFlow::basalActive() const
{
    return friction_->active() || rheology_->basalShear();
}


bool Foam::depthAveragedFlow::fusedGather() const
{
    return
        pressureForm_ == pressureFormType::gradient
     && !basalActive()
     && !rheology_->active();
}


void Foam::depthAveragedFlow::seed(const releaseModel& release)
{
    const gridGeometry& g = grid_.geometry();
    const label n = nPerCell_;
    const scalar cellArea = g.dx[0]*g.dx[1]/(n*n);

    // Checked by the release, which logs what it puts in and leaves out;
    // the count refused before anything else is made for it
    std::vector<double> x, y, h;
    release.sampleColumns(g, n, rho_, x, y, h);
    const std::string what("the release (constant/dampmProperties)");
    particleMemory::reserve(particles_, x.size(), what, g, n);
    if (releaseProjection_)
    {
        projectRelease(x, y, h);
        particleMemory::reserve(particles_, x.size(), what, g, n);
    }

    const label first = particles_.append(label(x.size()));
    for (size_t k = 0; k < x.size(); ++k)
    {
        const label i = first + label(k);
        particles_.column(particleArrays::X)[i] = x[k];
        particles_.column(particleArrays::Y)[i] = y[k];
        particles_.column(particleArrays::UX)[i] = release.U().x();
        particles_.column(particleArrays::UY)[i] = release.U().y();
        particles_.column(particleArrays::VOL)[i] = h[k]*cellArea;
        particles_.column(particleArrays::M)[i] = rho_*h[k]*cellArea;
        particles_.column(h_)[i] = h[k];
        particles_.column(A_)[i] = cellArea;
        particles_.column(F_)[i] = g.dx[0]/n;
        particles_.column(F_ + 3)[i] = g.dx[1]/n;
    }
}


void Foam::depthAveragedFlow::projectRelease
(
    std::vector<double>& x,
    std::vector<double>& y,
    std::vector<double>& h
) const
{
    const gridGeometry& g = grid_.geometry();
    const scalar a = seedArea();
    const auto volume = [&]()
    {
        double v = 0;
        for (const double hk : h)
        {
            v += hk*a;
        }
        return v;
    };
    const double before = volume();
    const size_t nSampled = x.size();
    double moved = 0;
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            moved = Foam::projectRelease
            (
                g, kernel, nPerCell_, nodes_.area.data(), hMin_, x, y, h
            );
        }
    );
    const double after = volume();
    Info<< "Release projected onto the grid (releaseProjection): "
        << x.size() << " columns (" << nSampled << " sampled), " << after
        << " m^3, relative change " << (after - before)/before;
    if (moved > 0)
    {
        Info<< "; " << moved << " m^3 of the smeared edge, thinner than hMin "
            << hMin_ << " m, moved to the nearest column";
    }
    Info<< endl;
}


Foam::scalar Foam::depthAveragedFlow::seedArea() const
{
    const gridGeometry& g = grid_.geometry();
    return g.dx[0]*g.dx[1]/(nPerCell_*nPerCell_);
}


Foam::scalar Foam::depthAveragedFlow::maxColumnThickness() const
{
    const label n = particles_.size();
    const double* F[4] =
    {
        particles_.column(F_), particles_.column(F_ + 1),
        particles_.column(F_ + 2), particles_.column(F_ + 3)
    };
    const double* V = particles_.column(particleArrays::VOL);
    double hMax = 0;
    for (label i = 0; i < n; ++i)
    {
        const double area = std::abs(F[0][i]*F[3][i] - F[1][i]*F[2][i]);
        hMax = area > 0 && V[i]/area > hMax ? V[i]/area : hMax;
    }
    return hMax;
}


Foam::scalar Foam::depthAveragedFlow::speedScale() const
{
    const label n = particles_.size();
    const double* ux = particles_.column(particleArrays::UX);
    const double* uy = particles_.column(particleArrays::UY);
    const double* h = particles_.column(h_);
    double wave = 0, hMax = 0;
    for (label i = 0; i < n; ++i)
    {
        const double hi = max(h[i], 0.0);
        wave = max(wave, std::hypot(ux[i], uy[i]) + std::sqrt(g_*hi));
        hMax = max(hMax, hi);
    }
    const auto range = std::minmax_element(nodes_.Z.begin(), nodes_.Z.end());
    const double relief = *range.second - *range.first;
    return wave + std::sqrt(2*g_*(relief + hMax));
}


bool Foam::depthAveragedFlow::splitting() const
{
    return splitRatio_ > 0;
}


Foam::splitRule Foam::depthAveragedFlow::splitRules() const
{
    const gridGeometry& g = grid_.geometry();
    splitRule rule;
    rule.maxArea = splitRatio_*seedArea();
    rule.hSplit = max(hMin_, splitHMin_);
    for (int d = 0; d < 2; ++d)
    {
        rule.cell[d] = g.dx[d];
        rule.lo[d] = g.origin[d];
        rule.hi[d] = g.upper(d);
    }
    return rule;
}


Foam::label Foam::depthAveragedFlow::splitColumns(const bool marked)
{
    if (!splitting())
    {
        return 0;
    }
    const gridGeometry& g = grid_.geometry();
    const double cell[2] = {g.dx[0], g.dx[1]};
    const label n = particles_.size();

    // Marked in parallel, listed in storage order: the same children on any
    // number of threads
    if (!marked)
    {
        const splitRule rule = splitRules();
        const double* F[4] =
        {
            particles_.column(F_), particles_.column(F_ + 1),
            particles_.column(F_ + 2), particles_.column(F_ + 3)
        };
        const double* x = particles_.column(particleArrays::X);
        const double* y = particles_.column(particleArrays::Y);
        const double* V = particles_.column(particleArrays::VOL);
        splitFlags_.resize(n);

        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            const double Fi[4] = {F[0][i], F[1][i], F[2][i], F[3][i]};
            splitFlags_[i] = rule(Fi, V[i], x[i], y[i]);
        }
    }
    splitList_.clear();
    for (label i = 0; i < n; ++i)
    {
        if (splitFlags_[i])
        {
            splitList_.push_back(i);
        }
    }
    const label nSplit = label(splitList_.size());
    if (!nSplit)
    {
        return 0;
    }

    // A child starts as a copy of its parent, every field included (the
    // append may move the arrays: pointers are taken after it)
    const label first = particles_.append(nSplit);
    const label* parent = splitList_.data();
    for (label c = 0; c < particles_.nColumns(); ++c)
    {
        double* col = particles_.column(c);
        #pragma omp parallel for schedule(static)
        for (label k = 0; k < nSplit; ++k)
        {
            col[first + k] = col[parent[k]];
        }
    }

    double* F[4] =
    {
        particles_.column(F_), particles_.column(F_ + 1),
        particles_.column(F_ + 2), particles_.column(F_ + 3)
    };
    const double* C[4] =
    {
        particles_.column(gradU_), particles_.column(gradU_ + 1),
        particles_.column(gradU_ + 2), particles_.column(gradU_ + 3)
    };
    double* x = particles_.column(particleArrays::X);
    double* y = particles_.column(particleArrays::Y);
    double* ux = particles_.column(particleArrays::UX);
    double* uy = particles_.column(particleArrays::UY);
    double* m = particles_.column(particleArrays::M);
    double* V = particles_.column(particleArrays::VOL);
    double* A = particles_.column(A_);

    // The halves: mass, volume and basal area halved (exactly: mass is
    // conserved to round-off), positions at the centroids of the two halves
    // of the footprint and velocities from the column's affine field there
    // (centre of mass and momentum kept)
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < nSplit; ++k)
    {
        const label i = parent[k];
        const label j = first + k;
        const double Fi[4] = {F[0][i], F[1][i], F[2][i], F[3][i]};
        double d[2], Fc[4];
        splitFootprint(Fi, cell, d, Fc);
        const double du[2] =
        {
            C[0][i]*d[0] + C[1][i]*d[1],
            C[2][i]*d[0] + C[3][i]*d[1]
        };
        x[j] = x[i] + d[0];
        y[j] = y[i] + d[1];
        x[i] -= d[0];
        y[i] -= d[1];
        ux[j] = ux[i] + du[0];
        uy[j] = uy[i] + du[1];
        ux[i] -= du[0];
        uy[i] -= du[1];
        m[i] *= 0.5;
        m[j] = m[i];
        V[i] *= 0.5;
        V[j] = V[i];
        A[i] *= 0.5;
        A[j] = A[i];
        for (int c = 0; c < 4; ++c)
        {
            F[c][i] = F[c][j] = Fc[c];
        }
    }
    return nSplit;
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
    splitRatio_(dict.getOrDefault<scalar>("splitRatio", 1.25)),
    splitHMin_(dict.getOrDefault<scalar>("splitHMin", 0)),
    splitHMinGiven_(dict.found("splitHMin")),
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
    schedule_(grid.geometry()),
    massTol_(0),
    outflowMass_(0),
    prepared_(false),
    terrainFree_(false),
    forcesDone_(false)
{
    knownKeywords::add
    (
        dict,
        {
            "rho", "particlesPerCell", "hMin", "splitRatio", "splitHMin",
            "releaseProjection", "slopeCorrection", "pressureForm", "release"
        }
    );
    if (!grid.is2D())
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
    if (!(hMin_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "hMin = " << hMin_ << " is invalid; allowed: hMin >= 0 [m]"
            << exit(FatalIOError);
    }
    if (!(splitRatio_ == 0 || splitRatio_ >= 1))
    {
        FatalIOErrorInFunction(dict)
            << "splitRatio = " << splitRatio_ << " is invalid; allowed: 0"
            << " (no splitting) or >= 1 (seed areas)" << exit(FatalIOError);
    }
    if (!(splitHMin_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "splitHMin = " << splitHMin_ << " is invalid; allowed:"
            << " splitHMin >= 0 [m]" << exit(FatalIOError);
    }

    dictionary shapeDict(dict);
    if (!shapeDict.found("shapeFunction"))
    {
        shapeDict.add("shapeFunction", word("quadraticBSpline"));
    }
    shape_ = shapeFunction::New(shapeDict, 0.5/nPerCell_);

    const fileName caseDir = grid.mesh().time().path();
    topography_ = topographyModel::New(dict, caseDir);
    friction_ = bedFrictionModel::New(dict);
    rheology_ = rheologyModel::New(dict);

    {
        bool wall[3][2];
        grid_.wallSides(wall);
        for (int d = 0; d < 2; ++d)
        {
            sides_.wall[d][0] = wall[d][0];
            sides_.wall[d][1] = wall[d][1];
        }
    }

    // Solver fields of the columns
    typedef particleArrays::fieldKind kind;
    h_ = particles_.addField("h", kind::scalar);
    A_ = particles_.addField("A", kind::scalar);
    F_ = particles_.addField("F", kind::tensor2D);
    gradU_ = particles_.addField("gradU", kind::tensor2D);
    sigma_ = particles_.addField("sigma", kind::symmTensor);
    gradZeta_ = particles_.addField("gradZeta", kind::internal, 0, 2);
    gradZ_ = particles_.addField("gradZ", kind::internal, 0, 2);
    kappa_ = particles_.addField("kappa", kind::internal, 1, 1);
    Zb_ = particles_.addField("Zb", kind::scalar);
    basal_ = particles_.addField("basal", kind::internal, 0, 3);

    // Node arrays, terrain and nodal areas
    const gridGeometry& geom = grid.geometry();
    nodes_.resize(geom.nNodes());
    topography_->sampleNodes(geom, nodes_.Z.data());
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            nodalAreas(geom, kernel, nPerCell_, nodes_.area.data());
        }
    );
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

    // The columns: the cloud of the start time, or the release
    const Time& runTime = grid.mesh().time();
    const bool restarted =
        particleCloudIO::readStartTime(particles_, grid, cloudName);
    if (restarted)
    {
        const fileName dir(particleCloudIO::cloudDir(grid.mesh(), cloudName));
        particleCloudIO::checkRange(particles_, dir, "h", 0, true, GREAT);
        particleCloudIO::checkRange(particles_, dir, "A", 0, false, GREAT);
    }
    else
    {
        if (!dict.isDict("release"))
        {
            FatalIOErrorInFunction(dict)
                << "no cloud " << cloudName << " at time "
                << runTime.timeName() << " and no release sub-dictionary:"
                << " nothing to simulate" << exit(FatalIOError);
        }
        autoPtr<releaseModel> release = releaseModel::New
        (
            dict.subDict("release"), *topography_, caseDir
        );
        Info<< "Release: ";
        release->describe(Info);
        Info<< endl;
        seed(*release);
    }

    scalar mMax = 0;
    for (label i = 0; i < particles_.size(); ++i)
    {
        mMax = max(mMax, particles_.column(particleArrays::M)[i]);
    }
    massTol_ = 1e-12*mMax;
    releaseThickness_ = speedLimit::threeDigits(maxColumnThickness());
    if (!splitHMinGiven_)
    {
        splitHMin_ =
            speedLimit::threeDigits(splitHMinFraction*maxColumnThickness());
    }
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
    // A bed flat at Z = 0: the terrain terms of S5 are exactly 0, 0 and 1
    // (a restart's cloud may hold others); set once, kept by splits
    terrainFree_ = topography_->isFlat();
    for (label n = 0; terrainFree_ && n < geom.nNodes(); ++n)
    {
        terrainFree_ = nodes_.Z[n] == 0;
    }
    if (terrainFree_)
    {
        const label n = particles_.size();
        std::fill_n(particles_.column(Zb_), n, 0.0);
        std::fill_n(particles_.column(gradZ_), n, 0.0);
        std::fill_n(particles_.column(gradZ_ + 1), n, 0.0);
        std::fill_n(particles_.column(kappa_), n, 1.0);
    }
    flagged_.reserve(particles_.size());
    splitFlags_.reserve(particles_.size());
    splitList_.reserve(particles_.size());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::depthAveragedFlow::describe(Ostream& os) const
{
    const gridGeometry& g = grid_.geometry();
    const char* sideNames[2][2] = {{"x min", "x max"}, {"y min", "y max"}};
    os  << "dampmFoam physics (terms not listed as active cost nothing):" << nl
        << "    columns         " << particles_.size() << ", "
        << nPerCell_*nPerCell_ << " per cell, rho = " << rho_ << " kg/m^3"
        << nl << "    shape function  ";
    shape_->describe(os);
    os  << nl << "    pressure force  " << pressureFormNames[pressureForm_]
        << " form, slope correction " << (slopeCorrection_ ? "on" : "off")
        << ", hMin = " << hMin_ << " m" << nl << "    column split    ";
    if (splitRatio_ > 0)
    {
        os  << "above " << splitRatio_ << " seed areas ("
            << splitRatio_*seedArea() << " m^2), if not thinner than "
            << max(hMin_, splitHMin_) << " m";
    }
    else
    {
        os  << "off";
    }
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
    os  << nl << "    grid            " << g.nCells[0] << " x " << g.nCells[1]
        << " cells of " << g.dx[0] << " x " << g.dx[1] << " m" << endl;
}


void Foam::depthAveragedFlow::writeState(dictionary& state) const
{
    state.set("outflowMass", outflowMass_);
    state.set("massTolerance", massTol_);
    state.set("splitHMin", splitHMin_);
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
    if (!splitHMinGiven_)
    {
        splitHMin_ = state.get<scalar>("splitHMin");
    }
    // A state written before it was kept: the restart's thickest column
    state.readIfPresent("releaseThickness", releaseThickness_);
    speedLimit_.readState(state);
    if (rheology_->defaultShearModulus())
    {
        rheology_->setDefaultShearModulus(state.get<scalar>("shearModulus"));
    }
}


void Foam::depthAveragedFlow::particlesToGrid()
{
    if (prepared_)
    {
        return;
    }
    const gridGeometry& g = grid_.geometry();
    particles_.sortByCell(g, schedule_.maxStale());

    // Work on the nodes the columns touch, and clear those of last step
    activeNodes_ = stencilNodes_;
    stencilNodes_ = particles_.stencilNodes(g);
    activeNodes_.unite(stencilNodes_);
    zeroNodes(g, activeNodes_, nodes_);

    const shallowColumns cols = columns();
    const columnScatter scatter
    {
        g, stencilNodes_, schedule_, particles_.cellStart().data()
    };
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            scatterMomentum(scatter, kernel, nodes_, cols);
        }
    );
    nodeHeights
    (
        g, activeNodes_, nodes_, rho_, massTol_, slopeCorrection_,
        kappaNode_.data()
    );

    // S5, or S5 and S7 together when no model comes between them
    forcesDone_ = fusedGather();
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            typedef std::decay_t<decltype(kernel)> K;
            auto run = [&](auto terrain)
            {
                if (forcesDone_)
                {
                    scatterForces<K, true, false, false, true, terrain()>
                    (
                        scatter, kernel, nodes_, cols, rho_, g_, hMin_,
                        slopeCorrection_
                    );
                }
                else
                {
                    gatherSurface<K, terrain()>
                    (
                        g, kernel, nodes_, cols, hMin_, slopeCorrection_
                    );
                }
            };
            terrainFree_ ? run(std::false_type()) : run(std::true_type());
        }
    );
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
    const double* ux = particles_.column(particleArrays::UX);
    const double* uy = particles_.column(particleArrays::UY);
    const double* h = particles_.column(h_);
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
        for (int k = 0; k < 3; ++k)
        {
            zeroArray(particles_.column(basal_ + k), particles_.size());
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
        g, stencilNodes_, schedule_, particles_.cellStart().data()
    };
    const bool gradientForm = pressureForm_ == pressureFormType::gradient;

    // One instantiation per combination of terms: a term a case does not
    // select costs nothing in the scatter
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            typedef std::decay_t<decltype(kernel)> K;
            auto run = [&](auto gf, auto st, auto ba)
            {
                scatterForces<K, gf(), st(), ba()>
                (
                    scatter, kernel, nodes_, cols, rho_, g_
                );
            };
            typedef std::true_type T;
            typedef std::false_type F;
            if (gradientForm)
            {
                if (stress)
                {
                    basal ? run(T(), T(), T()) : run(T(), T(), F());
                }
                else
                {
                    basal ? run(T(), F(), T()) : run(T(), F(), F());
                }
            }
            else
            {
                if (stress)
                {
                    basal ? run(F(), T(), T()) : run(F(), T(), F());
                }
                else
                {
                    basal ? run(F(), F(), T()) : run(F(), F(), F());
                }
            }
        }
    );
}


void Foam::depthAveragedFlow::updateGrid(const scalar dt)
{
    resistanceUpdate
    (
        grid_.geometry(), activeNodes_, nodes_, sides_, dt, massTol_,
        basalActive()
    );
}


Foam::scalar Foam::depthAveragedFlow::gridToParticles(const scalar dt)
{
    const gridGeometry& g = grid_.geometry();
    const double* vel[2] = {nodes_.vx.data(), nodes_.vy.data()};
    visitShape
    (
        *shape_,
        [&](const auto& kernel)
        {
            gridToParticlesVelocity<2>(g, kernel, particles_, gradU_, vel);
        }
    );

    // Positions, footprints, walls and open sides
    const label n = particles_.size();
    double* F[4] =
    {
        particles_.column(F_), particles_.column(F_ + 1),
        particles_.column(F_ + 2), particles_.column(F_ + 3)
    };
    double* C[4] =
    {
        particles_.column(gradU_), particles_.column(gradU_ + 1),
        particles_.column(gradU_ + 2), particles_.column(gradU_ + 3)
    };
    double* x = particles_.column(particleArrays::X);
    double* y = particles_.column(particleArrays::Y);
    double* ux = particles_.column(particleArrays::UX);
    double* uy = particles_.column(particleArrays::UY);
    const double* m = particles_.column(particleArrays::M);
    const double* V = particles_.column(particleArrays::VOL);
    flagged_.resize(n);
    splitFlags_.resize(n);
    const domainSides sides = sides_;
    const bool split = splitting();
    const splitRule rule = splitRules();
    label nRemoved = 0;

    // The columns to split are marked here, while their footprints are at
    // hand, and again after a removal (which moves them)
    #pragma omp parallel for schedule(static) reduction(+:nRemoved)
    for (label i = 0; i < n; ++i)
    {
        double* pos[2] = {&x[i], &y[i]};
        double* vel[2] = {&ux[i], &uy[i]};
        *pos[0] += dt*ux[i];
        *pos[1] += dt*uy[i];
        advanceColumn
        (
            dt, C[0][i], C[1][i], C[2][i], C[3][i],
            F[0][i], F[1][i], F[2][i], F[3][i]
        );
        flagged_[i] = 0;
        for (int d = 0; d < 2 && !flagged_[i]; ++d)
        {
            const double eps = 1e-6*g.dx[d];
            const double lo = g.origin[d];
            const double hi = g.upper(d);
            if (*pos[d] < lo || *pos[d] > hi)
            {
                const int s = *pos[d] > hi;
                if (sides.wall[d][s])
                {
                    *pos[d] = s ? hi - eps : lo + eps;
                    *vel[d] = 0;
                }
                else
                {
                    flagged_[i] = 1;
                    ++nRemoved;
                }
            }
        }
        if (split)
        {
            const double Fi[4] = {F[0][i], F[1][i], F[2][i], F[3][i]};
            splitFlags_[i] = rule(Fi, V[i], x[i], y[i]);
        }
    }
    // The outflow tallied in storage order: the same on any number of threads
    double removed = 0;
    if (nRemoved)
    {
        for (label i = 0; i < n; ++i)
        {
            removed += flagged_[i] ? m[i] : 0;
        }
        particles_.removeFlagged(flagged_);
        outflowMass_ += removed;
    }

    // The stress of the end of the step, from the gradient at the new
    // positions (a split copies it to both halves)
    if (rheology_->active())
    {
        rheology_->stress(modelView(), dt);
    }
    splitColumns(nRemoved == 0);
    prepared_ = false;
    return removed;
}


void Foam::depthAveragedFlow::updateOutputFields()
{
    particlesToGrid();

    const fvMesh& mesh = grid_.mesh();
    const scalar zLo = mesh.bounds().min().z();
    const scalar zHi = mesh.bounds().max().z();
    const scalar eps = 1e-6*max(zHi - zLo, scalar(1));

    const label n = particles_.size();
    double* z = particles_.column(particleArrays::Z);
    double* uz = particles_.column(particleArrays::UZ);
    const double* ux = particles_.column(particleArrays::UX);
    const double* uy = particles_.column(particleArrays::UY);
    const double* h = particles_.column(h_);
    const double* Zb = particles_.column(Zb_);
    const double* gx = particles_.column(gradZ_);
    const double* gy = particles_.column(gradZ_ + 1);

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        // Free surface, kept inside the mesh so that readers find the cell
        z[i] = min(max(Zb[i] + h[i], zLo + eps), zHi - eps);
        uz[i] = ux[i]*gx[i] + uy[i]*gy[i];
    }
}


Foam::depthAveragedFlow::totals Foam::depthAveragedFlow::diagnostics() const
{
    const label n = particles_.size();
    const double* x = particles_.column(particleArrays::X);
    const double* y = particles_.column(particleArrays::Y);
    const double* ux = particles_.column(particleArrays::UX);
    const double* uy = particles_.column(particleArrays::UY);
    const double* m = particles_.column(particleArrays::M);
    const double* h = particles_.column(h_);
    const double* gx = particles_.column(gradZ_);
    const double* gy = particles_.column(gradZ_ + 1);

    // The same rounding on any number of threads; a flat bed reads no
    // gradient
    double sums[2], maxima[7];
    auto pass = [&](auto terrain)
    {
        orderedSums<2, 7>(n, sums, maxima, [&](label i, double* S, double* mx)
        {
            // Speed along the bed: the vertical component follows the
            // terrain
            const double w = terrain() ? ux[i]*gx[i] + uy[i]*gy[i] : 0;
            const double u2 = ux[i]*ux[i] + uy[i]*uy[i];
            const double v2 = u2 + w*w;
            S[0] += m[i];
            S[1] += 0.5*m[i]*v2;
            // A NaN or infinity in any of them makes the sum one
            const double broken =
                std::isfinite(x[i] + y[i] + ux[i] + uy[i] + h[i]) ? 0 : 1;
            const double v[7] = {v2, -x[i], x[i], -y[i], y[i], u2, broken};
            for (int k = 0; k < 7; ++k)
            {
                mx[k] = v[k] > mx[k] ? v[k] : mx[k];
            }
        });
    };
    terrainFree_ ? pass(std::false_type()) : pass(std::true_type());

    totals t;
    t.mass = sums[0];
    t.kineticEnergy = sums[1];
    t.maxSpeed = std::sqrt(max(maxima[0], 0.0));
    t.maxHorizontalSpeed = std::sqrt(max(maxima[5], 0.0));
    t.finite = !(maxima[6] > 0);
    t.extent = n
        ? boundBox
          (
              point(-maxima[1], -maxima[3], 0),
              point(maxima[2], maxima[4], 0)
          )
        : boundBox(point::zero, point::zero);
    return t;
}


Foam::word Foam::depthAveragedFlow::nonFiniteField() const
{
    // One pass in the usual case; the field is named only after a failure
    if
    (
        particles_.finite
        ({
            particleArrays::X, particleArrays::Y, particleArrays::UX,
            particleArrays::UY, h_
        })
    )
    {
        return word::null;
    }
    if (!particles_.finite({particleArrays::X, particleArrays::Y}))
    {
        return "positions";
    }
    if (!particles_.finite({particleArrays::UX, particleArrays::UY}))
    {
        return "U";
    }
    if (!particles_.finite({h_}))
    {
        return "h";
    }
    return word::null;
}


// ************************************************************************* //
