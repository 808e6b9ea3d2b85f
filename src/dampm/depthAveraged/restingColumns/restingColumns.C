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
    nLeft_(0)
{}


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

    // Each node's window a - 2 .. a + 3 along x, then along y to the
    // cells (cell c's first node is c + nGhost); a window leaving the box
    // is not at rest
    #pragma omp parallel for schedule(static)
    for (index b = 0; b < h; ++b)
    {
        const uint8_t* s = both_.data() + size_t(w)*b;
        uint8_t* r = rows_.data() + size_t(w)*b;
        std::fill(r, r + w, 0);
        for (index a = 2; a < w - 3; ++a)
        {
            r[a] = s[a - 2] & s[a - 1] & s[a] & s[a + 1] & s[a + 2] & s[a + 3];
        }
    }

    // Written for the cells whose first node lies in the box: those of
    // every column (its stencil lies in the box)
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
        uint8_t* q = quiet_.data() + size_t(nCx)*cj;
        const index b = cj + nG - lo1;
        if (b < 2 || b + 3 >= h)
        {
            std::fill(q + ci0, q + ci1, 0);
            continue;
        }
        const uint8_t* r = rows_.data() + size_t(w)*(b - 2);
        for (index ci = ci0; ci < ci1; ++ci)
        {
            const index a = ci + nG - lo0;
            uint8_t all = 1;
            for (int d = 0; d < 6; ++d)
            {
                all &= r[a + size_t(w)*d];
            }
            q[ci] = all;
        }
    }
    return quiet_.data();
}


void Foam::restingColumns::wake
(
    const gridGeometry& g,
    const double x,
    const double y
)
{
    const gridGeometry::index n =
        g.nodeIndex(g.cellDir(0, x), g.cellDir(1, y), 0);
    if (box_.overlaps(g.nodeBoxOf(n)))
    {
        now_[n] = 0;
    }
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
}


// ************************************************************************* //
