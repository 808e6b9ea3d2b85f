/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "gridDecomposition.H"
#include "mpmGrid.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include <chrono>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Domain cell of coordinate x along axis d, clamped to the domain
static inline label domainCell
(
    const gridGeometry& g,
    const int d,
    const double x
)
{
    const label i = label(std::floor((x - g.origin[d])*g.invDx[d]));
    return i < 0 ? 0 : (i >= g.nCellsDomain[d] ? g.nCellsDomain[d] - 1 : i);
}


//- Seconds since start
static inline double since(const std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
}


//- Number of nodes in a box
static inline label nNodesIn(const nodeBox& b)
{
    return b.empty()
      ? 0
      : label(b.hi[0] - b.lo[0])*(b.hi[1] - b.lo[1])*(b.hi[2] - b.lo[2]);
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Fn>
void Foam::gridDecomposition::forEachNode(const nodeBox& b, Fn&& fn) const
{
    for (label k = b.lo[2]; k < b.hi[2]; ++k)
    {
        for (label j = b.lo[1]; j < b.hi[1]; ++j)
        {
            const label row = geom_.nodeStride[1]*j + geom_.nodeStride[2]*k;
            for (label i = b.lo[0]; i < b.hi[0]; ++i)
            {
                fn(row + i);
            }
        }
    }
}


void Foam::gridDecomposition::reachOf
(
    const label p,
    label lo[3],
    label hi[3]
) const
{
    for (int d = 0; d < 3; ++d)
    {
        const bool along = d < geom_.dim;
        lo[d] = along ? boxes_[p][d] - 1 : 0;
        hi[d] = along ? boxes_[p][3 + d] + 2 : 1;
    }
}


void Foam::gridDecomposition::findNeighbours()
{
    const label me = Pstream::myProcNo();
    label myLo[3], myHi[3];
    reachOf(me, myLo, myHi);

    // Domain nodes to this part's node lattice (ghosts included)
    const auto toLocal = [&](const label lo[3], const label hi[3])
    {
        nodeBox b;
        for (int d = 0; d < 3; ++d)
        {
            const label shift =
                d < geom_.dim ? gridGeometry::nGhost - geom_.offset[d] : 0;
            b.lo[d] = lo[d] + shift;
            b.hi[d] = hi[d] + shift;
        }
        return b;
    };

    forAll(boxes_, p)
    {
        if (p == me)
        {
            continue;
        }
        label lo[3], hi[3];
        reachOf(p, lo, hi);
        bool overlaps = true;
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = max(lo[d], myLo[d]);
            hi[d] = min(hi[d], myHi[d]);
            overlaps = overlaps && lo[d] < hi[d];
        }
        if (overlaps)
        {
            const nodeBox overlap = toLocal(lo, hi);
            neighbours_.append({p, overlap, overlap});
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gridDecomposition::gridDecomposition(const mpmGrid& grid)
:
    geom_(grid.geometry()),
    boxes_(Pstream::nProcs()),
    call_(0),
    commTime_(0)
{
    FixedList<label, 6>& mine = boxes_[Pstream::myProcNo()];
    for (int d = 0; d < 3; ++d)
    {
        mine[d] = grid.ownLo(d);
        mine[3 + d] = grid.ownHi(d);
    }
    if (!active())
    {
        return;
    }
    Pstream::gatherList(boxes_);
    Pstream::scatterList(boxes_);
    findNeighbours();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::gridDecomposition::holds
(
    const double x,
    const double y,
    const double z
) const
{
    if (!active())
    {
        return true;
    }
    const FixedList<label, 6>& b = boxes_[Pstream::myProcNo()];
    const double pos[3] = {x, y, z};
    for (int d = 0; d < geom_.dim; ++d)
    {
        const label c = domainCell(geom_, d, pos[d]);
        if (c < b[d] || c >= b[3 + d])
        {
            return false;
        }
    }
    return true;
}


void Foam::gridDecomposition::swap
(
    const List<scalarList>& send,
    List<scalarList>& recv
) const
{
    // Receives first, then sends, all non-blocking; sizes known both sides
    const label requests = UPstream::nRequests();
    forAll(neighbours_, k)
    {
        if (recv[k].size())
        {
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking, neighbours_[k].proc,
                reinterpret_cast<char*>(recv[k].data()),
                recv[k].byteSize()
            );
        }
    }
    forAll(neighbours_, k)
    {
        if (send[k].size())
        {
            UOPstream::write
            (
                UPstream::commsTypes::nonBlocking, neighbours_[k].proc,
                reinterpret_cast<const char*>(send[k].cdata()),
                send[k].byteSize()
            );
        }
    }
    UPstream::waitRequests(requests);
}


Foam::nodeBox Foam::gridDecomposition::shareNodes
(
    const nodeBox& stencils
) const
{
    nodeBox shared;
    if (!active())
    {
        return shared;
    }
    const auto start = std::chrono::steady_clock::now();

    // Boxes in domain node indices: (local - ghost + offset)
    const auto shift = [&](const int d)
    {
        return d < geom_.dim ? geom_.offset[d] - gridGeometry::nGhost : 0;
    };
    scalarList box(6);
    for (int d = 0; d < 3; ++d)
    {
        box[d] = stencils.lo[d] + shift(d);
        box[3 + d] = stencils.hi[d] + shift(d);
    }
    const List<scalarList> send(neighbours_.size(), box);
    List<scalarList> recv(neighbours_.size(), scalarList(6));
    swap(send, recv);

    // A neighbour's sum: the shared nodes either side's stencils reach
    const auto clip = [](const nodeBox& a, const nodeBox& b)
    {
        nodeBox c;
        for (int d = 0; d < 3; ++d)
        {
            c.lo[d] = a.lo[d] > b.lo[d] ? a.lo[d] : b.lo[d];
            c.hi[d] = a.hi[d] < b.hi[d] ? a.hi[d] : b.hi[d];
        }
        return c;
    };
    forAll(neighbours_, k)
    {
        const neighbour& nb = neighbours_[k];
        nodeBox theirs;
        for (int d = 0; d < 3; ++d)
        {
            theirs.lo[d] = label(recv[k][d]) - shift(d);
            theirs.hi[d] = label(recv[k][3 + d]) - shift(d);
        }
        nodeBox reached = clip(nb.overlap, stencils);
        reached.unite(clip(nb.overlap, theirs));
        nb.sum = reached.empty() ? nodeBox() : reached;
        shared.unite(nb.sum);
    }
    commTime_ += since(start);
    return shared;
}


void Foam::gridDecomposition::sumNodes(double* values, const int nComp) const
{
    if (!active())
    {
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    acc_.resize(size_t(nComp)*geom_.nNodes());
    stamp_.resize(geom_.nNodes(), 0);
    ++call_;

    // This processor's partial sums on the nodes each neighbour shares
    List<scalarList> send(neighbours_.size()), recv(neighbours_.size());
    forAll(neighbours_, q)
    {
        const neighbour& nb = neighbours_[q];
        send[q].setSize(nComp*nNodesIn(nb.sum));
        recv[q].setSize(send[q].size());
        label k = 0;
        forEachNode
        (
            nb.sum,
            [&](const label n)
            {
                for (int c = 0; c < nComp; ++c)
                {
                    send[q][k++] = values[nComp*n + c];
                }
            }
        );
    }
    swap(send, recv);

    // Every processor's share in rank order: the same rounding everywhere
    for (const neighbour& nb : neighbours_)
    {
        forEachNode
        (
            nb.sum,
            [&](const label n)
            {
                std::fill_n(&acc_[nComp*n], nComp, 0.0);
            }
        );
    }
    const auto addOwn = [&]()
    {
        for (const neighbour& nb : neighbours_)
        {
            forEachNode
            (
                nb.sum,
                [&](const label n)
                {
                    if (stamp_[n] != call_)
                    {
                        stamp_[n] = call_;
                        for (int c = 0; c < nComp; ++c)
                        {
                            acc_[nComp*n + c] += values[nComp*n + c];
                        }
                    }
                }
            );
        }
    };
    bool ownAdded = false;
    forAll(neighbours_, q)
    {
        const neighbour& nb = neighbours_[q];
        if (!ownAdded && nb.proc > Pstream::myProcNo())
        {
            addOwn();
            ownAdded = true;
        }
        label k = 0;
        forEachNode
        (
            nb.sum,
            [&](const label n)
            {
                for (int c = 0; c < nComp; ++c)
                {
                    acc_[nComp*n + c] += recv[q][k++];
                }
            }
        );
    }
    if (!ownAdded)
    {
        addOwn();
    }
    for (const neighbour& nb : neighbours_)
    {
        forEachNode
        (
            nb.sum,
            [&](const label n)
            {
                std::copy_n(&acc_[nComp*n], nComp, &values[nComp*n]);
            }
        );
    }
    commTime_ += since(start);
}


Foam::label Foam::gridDecomposition::neighbourHolding
(
    const double x,
    const double y,
    const double z
) const
{
    const double pos[3] = {x, y, z};
    label cell[3] = {0, 0, 0};
    for (int d = 0; d < geom_.dim; ++d)
    {
        cell[d] = domainCell(geom_, d, pos[d]);
    }
    forAll(neighbours_, k)
    {
        const FixedList<label, 6>& b = boxes_[neighbours_[k].proc];
        bool in = true;
        for (int d = 0; d < geom_.dim; ++d)
        {
            in = in && cell[d] >= b[d] && cell[d] < b[3 + d];
        }
        if (in)
        {
            return k;
        }
    }
    FatalErrorInFunction
        << "the point (" << x << ' ' << y << ' ' << z << ") left processor"
        << Pstream::myProcNo() << " for no neighbour's cells (a particle"
        << " moved more than a cell in a step?)" << abort(FatalError);
    return -1;
}


void Foam::gridDecomposition::exchange
(
    const List<scalarList>& send,
    List<scalarList>& received
) const
{
    const auto start = std::chrono::steady_clock::now();

    // The sizes first, then the values
    List<scalarList> sizes(neighbours_.size(), scalarList(1));
    List<scalarList> theirSizes(neighbours_.size(), scalarList(1));
    forAll(neighbours_, k)
    {
        sizes[k][0] = send[k].size();
    }
    swap(sizes, theirSizes);
    received.setSize(neighbours_.size());
    forAll(neighbours_, k)
    {
        received[k].setSize(label(theirSizes[k][0]));
    }
    swap(send, received);
    commTime_ += since(start);
}


void Foam::gridDecomposition::gatherLattice
(
    const double* values,
    scalarList& lattice
) const
{
    const label nx = geom_.nCellsDomain[0] + 1;
    const label ny = geom_.nCellsDomain[1] + 1;
    if (!active())
    {
        // One part: the lattice is this grid's (on every processor that
        // holds it whole)
        lattice.setSize(nx*ny);
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                lattice[i + nx*j] = values[geom_.nodeIndex(i, j, 0)];
            }
        }
        return;
    }

    // Each processor's own lattice nodes (its cells' corners), rows in order
    List<scalarList> parts(Pstream::nProcs());
    const FixedList<label, 6>& mine = boxes_[Pstream::myProcNo()];
    scalarList& own = parts[Pstream::myProcNo()];
    own.setSize((mine[3] - mine[0] + 1)*(mine[4] - mine[1] + 1));
    label k = 0;
    for (label j = mine[1]; j <= mine[4]; ++j)
    {
        for (label i = mine[0]; i <= mine[3]; ++i)
        {
            own[k++] = values
            [
                geom_.nodeIndex(i - geom_.offset[0], j - geom_.offset[1], 0)
            ];
        }
    }
    Pstream::gatherList(parts);

    lattice.clear();
    if (!Pstream::master())
    {
        return;
    }
    lattice.setSize(nx*ny);
    forAll(parts, p)
    {
        const FixedList<label, 6>& b = boxes_[p];
        label k = 0;
        for (label j = b[1]; j <= b[4]; ++j)
        {
            for (label i = b[0]; i <= b[3]; ++i)
            {
                lattice[i + nx*j] = parts[p][k++];
            }
        }
    }
}


// ************************************************************************* //
