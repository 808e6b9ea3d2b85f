/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "runOutMaps.H"
#include "threadTeam.H"
#include "exactPrecision.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "vectorLanes.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::runOutMaps::dictName("runOutMaps");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runOutMaps::runOutMaps
(
    const fileName& sourceCase,
    const word& sourceTime
)
:
    sourceTime_(sourceTime),
    case_(sourceCase)
{
    case_.setTime(instant(readScalar(sourceTime_), sourceTime_), 0);
    // (whole on every processor of a decomposed 3D run)
    grid_.reset(new mpmGrid(case_.mesh(), true));
    topography_ = topographyModel::New(case_.properties(), case_.path());

    const gridGeometry& g = grid_->geometry();
    nodes_.resize(g.nNodes());
    topography_->sampleNodes(g, nodes_.Z.data());
    sums_.assign(nSums*g.nNodes(), 0.0);

    // The run-out's maps of the hand-off time (point fields there)
    maps_.reset(new hazardMaps(*grid_, *topography_, nodes_.Z.data()));
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::runOutMaps::scatterBand
(
    const gridGeometry& g,
    const particleArrays& particles,
    const int32_t rows[2],
    double* sums,
    int32_t lo[2],
    int32_t hi[2]
)
{
    // The grid and the arrays in locals: stores into the sums cannot then
    // be taken to change them (benchmarks/outputShare/results.md)
    const gridGeometry lattice(g);
    const int32_t* const nCells = lattice.nCells;
    const int32_t r0 = rows[0], r1 = rows[1];
    const gridGeometry::index sy = lattice.nodeStride[1];
    const gridGeometry::index first = lattice.nodeIndex(0, 0, 0);
    const label n = particles.size();
    const double* x = particles.component(particleArrays::X);
    const double* y = particles.component(particleArrays::Y);
    const double* ux = particles.component(particleArrays::UX);
    const double* uy = particles.component(particleArrays::UY);
    const double* m = particles.component(particleArrays::M);
    const double* V = particles.component(particleArrays::VOL);
    static_assert(nSums == 4, "a node's sums are four lanes");

    int32_t boxLo[2] = {lo[0], lo[1]}, boxHi[2] = {hi[0], hi[1]};
    for (label p = 0; p < n; ++p)
    {
        const double eta = lattice.local(1, y[p]);
        if (!(eta >= 0 && eta <= nCells[1]))
        {
            continue;
        }
        const int32_t j = std::min(int32_t(eta), nCells[1] - 1);
        if (j + 1 < r0 || j >= r1)
        {
            continue;
        }
        const double xi = lattice.local(0, x[p]);
        if (!(xi >= 0 && xi <= nCells[0]))
        {
            continue;
        }
        const int32_t i = std::min(int32_t(xi), nCells[0] - 1);
        const double fx = xi - i, fy = eta - j;
        const double w[4] =
            {(1 - fx)*(1 - fy), fx*(1 - fy), (1 - fx)*fy, fx*fy};
        // A corner adds (w m, w m ux, w m uy, w V) = (w M) P: w m times
        // (1, ux, uy) is exact, and w times 1 is w
        const lanes4 M{m[p], m[p], m[p], 1};
        const lanes4 P{1, ux[p], uy[p], V[p]};
        const gridGeometry::index k = first + i + sy*j;
        for (int c = 0; c < 4; ++c)
        {
            const int32_t row = j + (c >> 1);
            if (row >= r0 && row < r1)
            {
                asLanes<lanes4>(sums + nSums*(k + (c & 1) + (c >> 1)*sy)) +=
                    (w[c]*M)*P;
            }
        }
        boxLo[0] = std::min(boxLo[0], i);
        boxLo[1] = std::min(boxLo[1], j);
        boxHi[0] = std::max(boxHi[0], i + 2);
        boxHi[1] = std::max(boxHi[1], j + 2);
    }
    for (int d = 0; d < 2; ++d)
    {
        lo[d] = boxLo[d];
        hi[d] = boxHi[d];
    }
}


void Foam::runOutMaps::sumProcessors(int32_t lo[2], int32_t hi[2])
{
    // The box of cells every processor's particles touched, and the node
    // sums over it completed (in the gather's fixed order)
    for (int d = 0; d < 2; ++d)
    {
        lo[d] = returnReduce(lo[d], minOp<int32_t>());
        hi[d] = returnReduce(hi[d], maxOp<int32_t>());
    }
    if (hi[0] <= lo[0])
    {
        return;
    }
    const gridGeometry& g = grid_->geometry();
    List<scalar> box(nSums*(hi[0] - lo[0])*(hi[1] - lo[1]));
    const auto forEachNode = [&](const auto& fn)
    {
        label k = 0;
        for (int32_t j = lo[1]; j < hi[1]; ++j)
        {
            for (int32_t i = lo[0]; i < hi[0]; ++i)
            {
                double* s = sums_.data() + nSums*g.nodeIndex(i, j, 0);
                for (int c = 0; c < nSums; ++c)
                {
                    fn(s[c], box[k++]);
                }
            }
        }
    };
    forEachNode([](const double v, scalar& b) { b = v; });
    Pstream::listCombineGather(box, plusEqOp<scalar>());
    Pstream::listCombineScatter(box);
    forEachNode([](double& v, const scalar b) { v = b; });
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::runOutMaps> Foam::runOutMaps::New(const Time& runTime3D)
{
    const IOobject io
    (
        dictName,
        runTime3D.timeName(),
        "uniform",
        runTime3D,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!isFile(io.objectPath()))
    {
        return nullptr;
    }
    const IOdictionary dict(io);
    const fileName sourceCase(dict.get<fileName>("sourceCase"));
    const word sourceTime(dict.get<string>("sourceTime"));
    autoPtr<runOutMaps> maps(new runOutMaps(sourceCase, sourceTime));
    if (dict.found("maxHeight"))
    {
        maps->maps_->loadMaxima(dict);
    }
    maps->dict_ = source(runTime3D, sourceCase, sourceTime);
    Info<< "Hazard maps: continuing those of the run-out "
        << maps->case_.path() << " (time " << maps->sourceTime_
        << ") on its grid" << nl << endl;
    return maps;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::autoPtr<Foam::IOdictionary> Foam::runOutMaps::source
(
    const Time& runTime3D,
    const fileName& sourceCase,
    const word& sourceTime
)
{
    // ASCII whatever writeFormat: OpenFOAM's token streams cannot read the
    // maxima's lists back from binary (exactAsciiIO)
    autoPtr<IOdictionary> dict
    (
        new exactAsciiIO<IOdictionary>
        (
            IOobject
            (
                dictName,
                runTime3D.timeName(),
                "uniform",
                runTime3D,
                IOobject::NO_READ,
                IOobject::AUTO_WRITE
            )
        )
    );
    dict->set("sourceCase", sourceCase);
    // A string: a time name such as 1.5 would read back as a number
    dict->set("sourceTime", string(sourceTime));
    return dict;
}


void Foam::runOutMaps::update(const particleArrays& particles)
{
    const gridGeometry& g = grid_->geometry();

    // Clear the nodes of the last projection
    g.forEachNodeRow(active_, [&](const label first, const label last)
    {
        for (label i = first; i < last; ++i)
        {
            std::fill_n(sums_.data() + nSums*i, nSums, 0.0);
            nodes_.h[i] = nodes_.vx[i] = nodes_.vy[i] = 0;
        }
    });

    // Bilinear scatter in bands of node rows, a thread each (the bands
    // split last step's rows of the flow): every thread reads the
    // particles' y, and adds those with a node in its band, in particle
    // order, so that every node's sums are those of one thread whatever
    // the number of threads
    const int32_t nRows = g.nCells[1] + 1;
    const bool flowed = !active_.empty();
    const int32_t split0 = flowed ? active_.lo[1] - gridGeometry::nGhost : 0;
    const int32_t split1 =
        flowed ? active_.hi[1] - gridGeometry::nGhost : nRows;
    int32_t lo[2] = {g.nCells[0], g.nCells[1]}, hi[2] = {0, 0};
    #pragma omp parallel
    {
        const threadTeam team = thisThread();
        const int tid = team.index, nThreads = team.size;
        const int32_t rows[2] =
        {
            tid ? split0 + (split1 - split0)*tid/nThreads : 0,
            tid + 1 < nThreads
          ? split0 + (split1 - split0)*(tid + 1)/nThreads
          : nRows
        };
        int32_t bandLo[2] = {g.nCells[0], g.nCells[1]}, bandHi[2] = {0, 0};
        scatterBand(g, particles, rows, sums_.data(), bandLo, bandHi);
        #pragma omp critical(runOutMapsBounds)
        for (int d = 0; d < 2; ++d)
        {
            lo[d] = std::min(lo[d], bandLo[d]);
            hi[d] = std::max(hi[d], bandHi[d]);
        }
    }

    if (Pstream::parRun())
    {
        sumProcessors(lo, hi);
    }
    active_ = nodeBox();
    if (hi[0] <= lo[0])
    {
        return;
    }
    for (int d = 0; d < 2; ++d)
    {
        active_.lo[d] = lo[d] + gridGeometry::nGhost;
        active_.hi[d] = hi[d] + gridGeometry::nGhost;
    }
    active_.lo[2] = 0;
    active_.hi[2] = 1;

    // Depth and velocity; boundary nodes own half a cell per side
    const double cellArea = g.dx[0]*g.dx[1];
    g.forEachNodeRow(active_, [&](const label first, const label last)
    {
        for (label k = first; k < last; ++k)
        {
            const double* s = sums_.data() + nSums*k;
            if (!(s[0] > 0))
            {
                continue;
            }
            gridGeometry::index ijk[3];
            g.nodeIJK(k, ijk);
            double area = cellArea;
            for (int d = 0; d < 2; ++d)
            {
                if (ijk[d] == 0 || ijk[d] == g.nCells[d])
                {
                    area *= 0.5;
                }
            }
            nodes_.h[k] = s[3]/area;
            nodes_.vx[k] = s[1]/s[0];
            nodes_.vy[k] = s[2]/s[0];
        }
    });
    maps_->update(nodes_, active_);
}


void Foam::runOutMaps::writeRasters(const Time& runTime3D) const
{
    maps_->writeRasters(runTime3D);
}


void Foam::runOutMaps::write()
{
    // (The dictionary is written in ASCII at exact precision: exactAsciiIO)
    maps_->saveMaxima(dict_());
}


// ************************************************************************* //
