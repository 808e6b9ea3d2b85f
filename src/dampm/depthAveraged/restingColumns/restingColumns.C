/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "restingColumns.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "registerSwitch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

int Foam::restingColumns::skip
(
    Foam::debug::optimisationSwitch("restingColumns", 1)
);
registerOptSwitch("restingColumns", int, Foam::restingColumns::skip);

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::restingColumns::restingColumns()
:
    lastBounded_(false),
    nUpdates_(0),
    nLeft_(0),
    quietValid_(false),
    ci0_(0),
    ci1_(0),
    cj0_(0),
    cj1_(0),
    nPassed_{0, 0, 0},
    nPassLeft_{0, 0, 0}
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<bool All>
void Foam::restingColumns::window
(
    const std::vector<uint8_t>& in,
    std::vector<uint8_t>& out,
    const gridGeometry::index w,
    const gridGeometry::index h,
    const int lo,
    const int hi
)
{
    typedef gridGeometry::index index;
    pass_.resize(size_t(w)*h);
    out.resize(size_t(w)*h);

    // Along x, then along y; each inner loop over a row (vectorised)
    #pragma omp parallel for schedule(static)
    for (index b = 0; b < h; ++b)
    {
        const uint8_t* s = in.data() + size_t(w)*b;
        uint8_t* r = pass_.data() + size_t(w)*b;
        std::fill(r, r + w, 0);
        const index a0 = -lo, a1 = w - hi;
        for (index a = a0; a < a1; ++a)
        {
            r[a] = s[a + lo];
        }
        for (int d = lo + 1; d <= hi; ++d)
        {
            for (index a = a0; a < a1; ++a)
            {
                r[a] = All ? r[a] & s[a + d] : r[a] | s[a + d];
            }
        }
    }
    #pragma omp parallel for schedule(static)
    for (index b = 0; b < h; ++b)
    {
        uint8_t* o = out.data() + size_t(w)*b;
        if (b + lo < 0 || b + hi >= h)
        {
            std::fill(o, o + w, 0);
            continue;
        }
        const uint8_t* r0 = pass_.data() + size_t(w)*(b + lo);
        std::copy(r0, r0 + w, o);
        for (int d = lo + 1; d <= hi; ++d)
        {
            const uint8_t* r = pass_.data() + size_t(w)*(b + d);
            for (index a = 0; a < w; ++a)
            {
                o[a] = All ? uint8_t(o[a] & r[a]) : uint8_t(o[a] | r[a]);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::nodeRest* Foam::restingColumns::nodes
(
    const gridGeometry& g,
    const nodeBox& box
)
{
    if (!skip)
    {
        return nullptr;
    }
    now_.resize(g.nNodes());
    box_ = box;
    rest_ = nodeRest();
    rest_.still = now_.data();
    return &rest_;
}


const uint8_t* Foam::restingColumns::quietCells(const gridGeometry& g)
{
    typedef gridGeometry::index index;
    quietValid_ = false;
    woken_.clear();
    if
    (
        !skip || !lastBounded_ || box_.empty() || lastBox_.empty()
     || !rest_.nResting
     || rest_.nResting < minRestingFraction*rest_.nMassive
    )
    {
        return nullptr;
    }

    const index nx = g.nNodesDir[0];
    const index lo0 = box_.lo[0], lo1 = box_.lo[1];
    const index w = box_.hi[0] - lo0, h = box_.hi[1] - lo1;
    both_.resize(size_t(w)*h);
    rows_.resize(size_t(w)*h);

    // The nodes at rest after both steps' S8 (the last step's flags only
    // where it had them)
    const nodeBox& last = lastBox_;
    #pragma omp parallel for schedule(static)
    for (index b = 0; b < h; ++b)
    {
        const index jj = lo1 + b;
        const bool lastRow = jj >= last.lo[1] && jj < last.hi[1];
        const uint8_t* nowRow = now_.data() + nx*jj;
        const uint8_t* lastRowFlags = last_.data() + nx*jj;
        uint8_t* s = both_.data() + size_t(w)*b;
        for (index a = 0; a < w; ++a)
        {
            const index ii = lo0 + a;
            const bool inLast = lastRow && ii >= last.lo[0] && ii < last.hi[0];
            s[a] = inLast ? uint8_t(nowRow[ii] & lastRowFlags[ii]) : 0;
        }
    }

    // Each node's window a - 2 .. a + 3 per axis; a window leaving the box
    // is not at rest
    window<true>(both_, rows_, w, h, -2, 3);

    // Written for the cells whose first node (c + nGhost) lies in the box:
    // those of every column (its stencil lies in the box)
    const index nG = gridGeometry::nGhost;
    const index nCx = g.nCells[0];
    quiet_.resize(size_t(nCx)*g.nCells[1]);
    const index ci0 = std::max(lo0 - nG, index(0));
    const index ci1 = std::min(lo0 + w - nG, nCx);
    const index cj0 = std::max(lo1 - nG, index(0));
    const index cj1 = std::min(lo1 + h - nG, g.nCells[1]);

    #pragma omp parallel for schedule(static)
    for (index cj = cj0; cj < cj1; ++cj)
    {
        const uint8_t* r =
            rows_.data() + size_t(w)*(cj + nG - lo1) + (ci0 + nG - lo0);
        std::copy(r, r + (ci1 - ci0), quiet_.data() + size_t(nCx)*cj + ci0);
    }
    quietValid_ = true;
    ci0_ = ci0;
    ci1_ = ci1;
    cj0_ = cj0;
    cj1_ = cj1;
    return quiet_.data();
}


void Foam::restingColumns::wake
(
    const gridGeometry& g,
    const double x,
    const double y
)
{
    const gridGeometry::index ci = g.cellDir(0, x), cj = g.cellDir(1, y);
    const gridGeometry::index n = g.nodeIndex(ci, cj, 0);
    if (box_.overlaps(g.nodeBoxOf(n)))
    {
        now_[n] = 0;
    }
    woken_.push_back(g.cellIndex(ci, cj, 0));
}


void Foam::restingColumns::endStep(const gridGeometry& g, const double dt)
{
    std::swap(now_, last_);
    lastBox_ = box_;
    const double reach = maxMove*std::min(g.dx[0], g.dx[1]);
    lastBounded_ = !box_.empty() && dt*dt*rest_.maxSpeed2 < reach*reach;
    box_ = nodeBox();
    rest_ = nodeRest();
}


Foam::keptSums Foam::restingColumns::keptNodes
(
    const gridGeometry& g,
    const bool loads,
    const uint8_t* binChanged
)
{
    typedef gridGeometry::index index;
    if (!skip || !quietValid_ || !lastBounded_ || ci1_ <= ci0_ || cj1_ <= cj0_)
    {
        return keptSums();
    }

    // Cells and nodes in one local array: a cell at its first node. The
    // quiet map's cells and a margin of m, where nothing is stable
    const index m = 3, nG = gridGeometry::nGhost, nCx = g.nCells[0];
    const index w = ci1_ - ci0_ + 2*m, h = cj1_ - cj0_ + 2*m;
    const index x0 = ci0_ + nG - m, y0 = cj0_ + nG - m;
    stable_.assign(size_t(w)*h, 0);
    #pragma omp parallel for schedule(static)
    for (index cj = cj0_; cj < cj1_; ++cj)
    {
        const uint8_t* q = quiet_.data() + size_t(nCx)*cj;
        const uint8_t* b = binChanged ? binChanged + size_t(nCx)*cj : nullptr;
        uint8_t* s = stable_.data() + size_t(w)*(cj - cj0_ + m) + m;
        for (index ci = ci0_; ci < ci1_; ++ci)
        {
            s[ci - ci0_] = q[ci] != 0 && !(b && b[ci]);
        }
    }
    for (const index c : woken_)
    {
        const index ci = c % nCx, cj = c/nCx;
        if (ci >= ci0_ && ci < ci1_ && cj >= cj0_ && cj < cj1_)
        {
            stable_[size_t(w)*(cj - cj0_ + m) + ci - ci0_ + m] = 0;
        }
    }

    // S3 kept where the cells c - 2 .. c + 1 are stable; S7 where the nodes
    // within 3 keep S3
    window<true>(stable_, kept3_, w, h, -2, 1);
    if (loads)
    {
        window<true>(kept3_, kept7_, w, h, -3, 3);
    }
    else
    {
        kept7_.assign(size_t(w)*h, 0);
    }

    const index nx = g.nNodesDir[0], ny = g.nNodesDir[1];
    keptNodes_.assign(g.nNodes(), 0);
    uint8_t somewhere = 0;
    #pragma omp parallel for schedule(static) reduction(|:somewhere)
    for (index b = 0; b < h; ++b)
    {
        const index jj = y0 + b;
        if (jj < 0 || jj >= ny)
        {
            continue;
        }
        const uint8_t* k3 = kept3_.data() + size_t(w)*b;
        const uint8_t* k7 = kept7_.data() + size_t(w)*b;
        uint8_t rowBits = 0;
        for (index a = std::max(-x0, index(0)); a < w && x0 + a < nx; ++a)
        {
            const uint8_t bits = uint8_t
            (
                k3[a]*keptSums::momentumKept | k7[a]*keptSums::loadsKept
            );
            rowBits |= bits;
            keptNodes_[x0 + a + size_t(nx)*jj] = bits;
        }
        somewhere |= rowBits;
    }
    if (!somewhere)
    {
        // The scatters then take every column without looking
        return keptSums();
    }

    // Per cell: do its columns' nodes c - 1 .. c + 2 keep, any or all?
    cellCodes_.assign(size_t(nCx)*g.nCells[1], 0);
    const std::pair<const std::vector<uint8_t>*, uint8_t> sums[2] =
    {
        {&kept3_, keptSums::momentumTouch}, {&kept7_, keptSums::loadsTouch}
    };
    for (const auto& sum : sums)
    {
        window<false>(*sum.first, any_, w, h, -1, 2);
        window<true>(*sum.first, all_, w, h, -1, 2);
        const uint8_t touch = sum.second, all = 2*sum.second;
        #pragma omp parallel for schedule(static)
        for (index cj = cj0_; cj < cj1_; ++cj)
        {
            uint8_t* c = cellCodes_.data() + size_t(nCx)*cj;
            const size_t row = size_t(w)*(cj - cj0_ + m) + m;
            for (index ci = ci0_; ci < ci1_; ++ci)
            {
                const size_t a = row + (ci - ci0_);
                c[ci] |= any_[a]*touch | all_[a]*all;
            }
        }
    }

    keptSums k;
    k.nodes = keptNodes_.data();
    k.cells = cellCodes_.data();
    k.somewhere = somewhere;
    return k;
}


void Foam::restingColumns::report(Ostream& os) const
{
    const scalar n = returnReduce(nUpdates_, sumOp<scalar>());
    const scalar nLeft = returnReduce(nLeft_, sumOp<scalar>());
    if (nLeft > 0)
    {
        os  << "Columns at rest left as they were by G2P: " << nLeft
            << " of " << n << " column-updates ("
            << 100*nLeft/n << " %)" << nl << endl;
    }
    const char* names[nPasses] =
    {
        "scatter of mass and momentum (S3)",
        "gather of the surface (S5)",
        "scatter of forces (S7)"
    };
    for (int p = 0; p < nPasses; ++p)
    {
        const scalar nP = returnReduce(nPassed_[p], sumOp<scalar>());
        const scalar nOut = returnReduce(nPassLeft_[p], sumOp<scalar>());
        if (nOut > 0)
        {
            os  << "Columns at rest left out of the " << names[p] << ": "
                << nOut << " of " << nP << " column-updates ("
                << 100*nOut/nP << " %)" << nl << endl;
        }
    }
}


// ************************************************************************* //
