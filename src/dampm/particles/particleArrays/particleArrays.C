/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "particleArrays.H"
#include "threadTeam.H"
#include <cmath>
#include "error.H"
#include <algorithm>
#include <limits>
#include <cstring>
#include <cstdint>
#if defined(__SSE2__) && defined(__x86_64__)
#define DAMPM_STREAM_STORES
#include <immintrin.h>
#endif

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Store a value past the caches (where the machine can)
inline void streamStore(double* to, const double value)
{
#ifdef DAMPM_STREAM_STORES
    long long bits;
    std::memcpy(&bits, &value, sizeof(bits));
    _mm_stream_si64(reinterpret_cast<long long*>(to), bits);
#else
    *to = value;
#endif
}

//- Order the streaming stores before what follows
inline void streamFence()
{
#ifdef DAMPM_STREAM_STORES
    _mm_sfence();
#endif
}

//- Move len values of a from a + from to a + to, in place (the ranges may
//  overlap: each value is read before its place is written); with
//  streaming stores, or memmove's
inline void moveValues
(
    double* a,
    const Foam::label to,
    const Foam::label from,
    const Foam::label len,
    const bool stream
)
{
    // Within a shift of 8 a value is read from a cache line that a
    // streaming store has just taken out of the cache (the four-at-a-time
    // stores below rely on a shift of 4 or more)
    if (!stream || std::abs(to - from) < 8)
    {
        std::memmove(a + to, a + from, len*sizeof(double));
        return;
    }
    // Four at a time once the place written is aligned, from the end when
    // moving up
    const auto aligned = [](const double* p)
    {
        return reinterpret_cast<std::uintptr_t>(p) % 32 == 0;
    };
    const auto move4 = [a, to, from](const Foam::label k)
    {
#if defined(DAMPM_STREAM_STORES) && defined(__AVX__)
        _mm256_stream_pd(a + to + k, _mm256_loadu_pd(a + from + k));
#else
        for (int l = 0; l < 4; ++l)
        {
            streamStore(a + to + k + l, a[from + k + l]);
        }
#endif
    };
    if (to < from)
    {
        Foam::label k = 0;
        for (; k < len && !aligned(a + to + k); ++k)
        {
            streamStore(a + to + k, a[from + k]);
        }
        for (; k + 4 <= len; k += 4)
        {
            move4(k);
        }
        for (; k < len; ++k)
        {
            streamStore(a + to + k, a[from + k]);
        }
    }
    else
    {
        Foam::label k = len;
        for (; k > 0 && !aligned(a + to + k); --k)
        {
            streamStore(a + to + k - 1, a[from + k - 1]);
        }
        for (; k >= 4; k -= 4)
        {
            move4(k - 4);
        }
        for (; k > 0; --k)
        {
            streamStore(a + to + k - 1, a[from + k - 1]);
        }
    }
}

inline void moveValues
(
    Foam::label* a,
    const Foam::label to,
    const Foam::label from,
    const Foam::label len,
    const bool
)
{
    std::memmove(a + to, a + from, len*sizeof(Foam::label));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleArrays::particleArrays()
:
    size_(0),
    binned_(false),
    anyBinChanged_(false)
{
    addField("positions", fieldKind::vector);
    addField("U", fieldKind::vector);
    addField("m", fieldKind::scalar);
    addField("V", fieldKind::scalar);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::particleArrays::nextFlagged
(
    const char* flags,
    label i,
    const label n
)
{
    for (; i + 8 <= n; i += 8)
    {
        uint64_t eight;
        std::memcpy(&eight, flags + i, 8);
        if (eight)
        {
            break;
        }
    }
    while (i < n && !flags[i])
    {
        ++i;
    }
    return i;
}


void Foam::particleArrays::checkFlagSize
(
    const std::vector<char>& flags,
    const char* what
) const
{
    if (label(flags.size()) != size_)
    {
        FatalErrorInFunction
            << flags.size() << " " << what << " for " << size_
            << " particles" << abort(FatalError);
    }
}


Foam::label Foam::particleArrays::nComponents(const fieldKind kind)
{
    switch (kind)
    {
        case fieldKind::scalar: return 1;
        case fieldKind::vector: return 3;
        case fieldKind::symmTensor: return 6;
        case fieldKind::tensor: return 9;
        case fieldKind::tensor2D: return 4;
        default: return 0;
    }
}


Foam::label Foam::particleArrays::addField
(
    const word& name,
    const fieldKind kind,
    const double initialValue,
    const label nInternalComponents
)
{
    if (found(name))
    {
        FatalErrorInFunction
            << "particle field " << name << " exists already"
            << abort(FatalError);
    }

    const label nComp =
        kind == fieldKind::internal ? nInternalComponents : nComponents(kind);
    const label first = nComponentArrays();

    fields_.push_back(fieldInfo{name, kind, nComp, first, initialValue});
    for (label c = 0; c < nComp; ++c)
    {
        components_.emplace_back(size_, initialValue);
        components_.back().reserve(cell_.capacity());
        offset_.push_back(0);
        transient_.push_back(false);
        recomputed_.push_back(false);
    }
    return first;
}


void Foam::particleArrays::markTransient(const label first, const label n)
{
    markComponents(first, n, transient_);
}


void Foam::particleArrays::markRecomputed(const label first, const label n)
{
    markComponents(first, n, transient_);
    markComponents(first, n, recomputed_);
}


void Foam::particleArrays::markComponents
(
    const label first,
    const label n,
    std::vector<char>& marks
) const
{
    if (first < 0 || n < 0 || first + n > nComponentArrays())
    {
        FatalErrorInFunction
            << "components " << first << " to " << first + n - 1
            << " are not all among the " << nComponentArrays()
            << " component arrays" << abort(FatalError);
    }
    for (label c = first; c < first + n; ++c)
    {
        marks[c] = true;
    }
}


bool Foam::particleArrays::found(const word& name) const
{
    for (const fieldInfo& f : fields_)
    {
        if (f.name == name)
        {
            return true;
        }
    }
    return false;
}


const Foam::particleArrays::fieldInfo&
Foam::particleArrays::field(const word& name) const
{
    for (const fieldInfo& f : fields_)
    {
        if (f.name == name)
        {
            return f;
        }
    }
    FatalErrorInFunction
        << "no particle field " << name << abort(FatalError);
    return fields_.front();
}


void Foam::particleArrays::reserve(const label n)
{
    // With the room that the arrays keep before and after the particles
    const label room = roomFor(n);
    for (size_t c = 0; c < components_.size(); ++c)
    {
        components_[c].reserve(std::max(offset_[c], room) + n + room);
    }
    cell_.reserve(n);
    order_.reserve(n);
    scratch_.reserve(n + 2*room);
}


void Foam::particleArrays::shrink()
{
    // Each array in a buffer with only the room kept for the placements (a
    // removal may have left its start far into its buffer)
    for (label c = 0; c < nComponentArrays(); ++c)
    {
        componentArray old;
        old.swap(components_[c]);
        const double* from = old.data() + offset_[c];
        std::copy(from, from + size_, renew(c, size_));
    }
    cell_.shrink_to_fit();
    order_.clear();
    order_.shrink_to_fit();
    scratch_.clear();
    scratch_.shrink_to_fit();
}


Foam::label Foam::particleArrays::append(const label n)
{
    const label first = size_;
    size_ += n;
    // A set filled from empty (seeded, read) starts with room before and
    // after it for the placements
    const label room = first == 0 ? roomFor(size_) : 0;
    for (const fieldInfo& f : fields_)
    {
        for (label c = f.first; c < f.first + f.nComponents; ++c)
        {
            if (first == 0)
            {
                components_[c].clear();
                offset_[c] = room;
                components_[c].reserve(size_ + 2*room);
            }
            components_[c].resize(offset_[c] + size_, f.initialValue);
        }
    }
    cell_.resize(size_, 0);
    binned_ = false;
    return first;
}


Foam::label Foam::particleArrays::removeFlagged
(
    const std::vector<char>& flagged
)
{
    checkFlagSize(flagged, "flags");

    // The runs of particles kept: a step removes few particles, so each
    // array moves in a few long runs, and the particles of the shift most
    // of them take (before the first removal, or, by the shift of the
    // array's start, after the last) not at all
    const char* flag = flagged.data();
    const label first = nextFlagged(flag, 0, size_);
    if (first == size_)
    {
        return 0;
    }
    moves_.clear();
    if (first > 0)
    {
        moves_.push_back({0, 0, first});
    }
    label n = first;
    for (label i = first; i < size_;)
    {
        while (i < size_ && flag[i])
        {
            ++i;
        }
        const label from = i;
        i = nextFlagged(flag, i, size_);
        if (i > from)
        {
            moves_.push_back({from, n, i - from});
            n += i - from;
        }
    }
    const label nRemoved = size_ - n;
    moveInPlace(n, size_, recomputed_);

    // Compaction keeps the order: the binning stays, counted again by the
    // next sortByCell (as a restart's), since an append often comes first
    binStart_.clear();
    return nRemoved;
}


void Foam::particleArrays::clear()
{
    for (size_t c = 0; c < components_.size(); ++c)
    {
        components_[c].clear();
        offset_[c] = 0;
    }
    cell_.clear();
    binStart_.clear();
    size_ = 0;
    binned_ = false;
}


bool Foam::particleArrays::streamed
(
    const label n,
    const std::vector<char>& notMoved
) const
{
    // Arrays that together outgrow the last-level cache (taken as 32 MB)
    // are written with streaming stores: a permutation's scratch is not
    // read into the cache to be overwritten (a third less memory traffic),
    // and after a move in place no thread's cache holds the modified lines
    // that the other threads read next (with memmove's stores the next
    // step's passes took 8-10 % longer on 2 threads). Smaller ones stay in
    // the cache for the scatter that reads them next.
    label nMoved = 0;
    for (size_t c = 0; c < components_.size(); ++c)
    {
        nMoved += !notMoved[c];
    }
    return double(n)*nMoved*sizeof(double) > 32.0*(1 << 20);
}


void Foam::particleArrays::permute
(
    const label n,
    const std::vector<char>& notMoved
)
{
    const bool stream = streamed(n, notMoved);

    // Each array moved is written with room before and after it, for the
    // placements that follow
    const label room = roomFor(n);
    for (size_t c = 0; c < components_.size(); ++c)
    {
        componentArray& array = components_[c];
        if (notMoved[c])
        {
            array.resize(offset_[c] + n);
            continue;
        }
        if (label(scratch_.capacity()) < n + room + room/2)
        {
            scratch_ = componentArray();
            scratch_.reserve(n + 2*room);
        }
        scratch_.resize(room + n);
        double* s = scratch_.data() + room;
        const double* src = component(c);
        const label* ord = order_.data();

        if (stream)
        {
            #pragma omp parallel
            {
                #pragma omp for schedule(static) nowait
                for (label k = 0; k < n; ++k)
                {
                    streamStore(s + k, src[ord[k]]);
                }
                streamFence();
            }
        }
        else
        {
            #pragma omp parallel for schedule(static)
            for (label k = 0; k < n; ++k)
            {
                s[k] = src[ord[k]];
            }
        }
        array.swap(scratch_);
        offset_[c] = room;
    }

    // The bins in their new order (rank_ is free once order_ is made)
    const label* cellp = cell_.data();
    const label* ord = order_.data();
    rank_.resize(n);
    #pragma omp parallel for schedule(static)
    for (label k = 0; k < n; ++k)
    {
        rank_[k] = cellp[ord[k]];
    }
    cell_.swap(rank_);
    size_ = n;
}


void Foam::particleArrays::findMoves(const label n, const label n0)
{
    const label* ord = order_.data();
    #pragma omp parallel
    {
        const threadTeam team = thisThread();
        #pragma omp single
        threadMoves_.resize(team.size);

        std::vector<run>& mine = threadMoves_[team.index];
        mine.clear();
        const label a = label(double(n)*team.index/team.size);
        const label b = label(double(n)*(team.index + 1)/team.size);
        for (label k = a; k < b;)
        {
            const label from = ord[k];
            label len = 1;
            while
            (
                k + len < b
             && ord[k + len] == from + len
             && from + len != n0
            )
            {
                ++len;
            }
            mine.push_back({from, k, len});
            k += len;
        }
    }
    moves_.clear();
    for (const std::vector<run>& runs : threadMoves_)
    {
        moves_.insert(moves_.end(), runs.begin(), runs.end());
    }
}


Foam::label Foam::particleArrays::commonShift(const label n0)
{
    // Few distinct shifts (one more than the changes of a step at most):
    // sorted with their particles, and the longest total taken
    shifts_.clear();
    for (const run& r : moves_)
    {
        if (r.from < n0)
        {
            shifts_.push_back({r.to - r.from, r.len});
        }
    }
    std::sort(shifts_.begin(), shifts_.end());
    label best = 0, bestCount = 0;
    for (size_t i = 0; i < shifts_.size();)
    {
        const label shift = shifts_[i].first;
        label count = 0;
        for (; i < shifts_.size() && shifts_[i].first == shift; ++i)
        {
            count += shifts_[i].second;
        }
        if (count > bestCount || (count == bestCount && shift == 0))
        {
            best = shift;
            bestCount = count;
        }
    }
    return best;
}


Foam::label Foam::particleArrays::roomFor(const label n)
{
    // A sixteenth of the particles (at least 1024), a multiple of a cache
    // line of doubles
    return (std::max(label(1024), n/16) + 7)/8*8;
}


double* Foam::particleArrays::renew(const label c, const label n)
{
    const label room = roomFor(n);
    componentArray fresh;
    fresh.reserve(2*room + n);
    fresh.resize(room + n);
    components_[c].swap(fresh);
    offset_[c] = room;
    return components_[c].data() + room;
}


void Foam::particleArrays::moveInPlace
(
    const label n,
    const label n0,
    const std::vector<char>& notMoved
)
{
    const run* const mv = moves_.data();
    const label nMoves = label(moves_.size());
    label nAside = 0;
    for (const run& r : moves_)
    {
        nAside += r.from >= n0 ? r.len : 0;
    }

    // The start of each array of values moves by the shift that most of
    // the kept particles take, so that they stay where they are in memory:
    // a step's few splits are near one end or the other of the arrays
    // (those of the flow still moving), and most of the particles after
    // the last split or before the first stay
    const label shift = commonShift(n0);

    // Each run moves from a[o + from] to a[o2 + to]. The kept particles
    // keep their order, so a run moving down lands on its own source or
    // on places whose particles were removed or went down before it, and
    // one moving up, taken from the end, on its own source or on places
    // whose particles were removed, went up before it or were appended
    // (put aside first)
    const bool stream = streamed(n, notMoved);
    const auto move = [&]
    (
        auto* a,
        const label o,
        const label o2,
        auto* aside
    )
    {
        const size_t size = sizeof(*a);
        for (label r = 0, s = 0; r < nMoves; ++r)
        {
            if (mv[r].from >= n0)
            {
                std::memcpy(aside + s, a + o + mv[r].from, mv[r].len*size);
                s += mv[r].len;
            }
        }
        for (label r = 0; r < nMoves; ++r)
        {
            if (mv[r].from < n0 && o2 + mv[r].to < o + mv[r].from)
            {
                moveValues
                (
                    a, o2 + mv[r].to, o + mv[r].from, mv[r].len, stream
                );
            }
        }
        for (label r = nMoves - 1; r >= 0; --r)
        {
            if (mv[r].from < n0 && o2 + mv[r].to > o + mv[r].from)
            {
                moveValues
                (
                    a, o2 + mv[r].to, o + mv[r].from, mv[r].len, stream
                );
            }
        }
        for (label r = 0, s = 0; r < nMoves; ++r)
        {
            if (mv[r].from >= n0)
            {
                std::memcpy(a + o2 + mv[r].to, aside + s, mv[r].len*size);
                s += mv[r].len;
            }
        }
    };

    // Into an array made anew: every run copied
    const auto copy = [&](const double* from, double* to)
    {
        for (label r = 0; r < nMoves; ++r)
        {
            std::memcpy
            (
                to + mv[r].to, from + mv[r].from, mv[r].len*sizeof(double)
            );
        }
    };

    // One array per thread at a time, the bins (cell_) last; the values
    // put aside in the sort's scratch (scratch_ a slice per thread, rank_)
    const label nArrays = nComponentArrays();
    #pragma omp parallel
    {
        const threadTeam team = thisThread();
        #pragma omp single
        {
            scratch_.resize(label(team.size)*nAside);
            rank_.resize(nAside);
        }
        double* aside = scratch_.data() + label(team.index)*nAside;
        #pragma omp for schedule(dynamic, 1) nowait
        for (label c = 0; c <= nArrays; ++c)
        {
            if (c == nArrays)
            {
                move(cell_.data(), 0, 0, rank_.data());
                continue;
            }
            componentArray& array = components_[c];
            const label o = offset_[c];
            if (notMoved[c])
            {
                array.resize(o + n);
                continue;
            }
            const label capacity = label(array.capacity());
            label o2 = o - shift;
            if (o2 < 0 || o2 + n > capacity)
            {
                // No room for the shift: the start put back at the room's
                // distance where the buffer holds it (every particle
                // moves), else the array is made anew
                const label room = roomFor(n);
                o2 = n + 2*room <= capacity ? room : -1;
            }
            if (o2 >= 0)
            {
                array.resize(std::max(label(array.size()), o2 + n));
                move(array.data(), o, o2, aside);
                array.resize(o2 + n);
                offset_[c] = o2;
            }
            else
            {
                componentArray old;
                old.swap(array);
                copy(old.data() + o, renew(c, n));
            }
        }
        streamFence();
    }
    cell_.resize(n);
    size_ = n;
}


bool Foam::particleArrays::countBins()
{
    // Bins of another grid (more cells) are no binning of this one
    const label nCells =
        binOrder_.nCells[0]*binOrder_.nCells[1]*binOrder_.nCells[2];
    rank_.resize(size_);
    bool inside = true;
    #pragma omp parallel for schedule(static) reduction(&&:inside)
    for (label i = 0; i < size_; ++i)
    {
        const label c = cell_[i];
        const bool in = c >= 0 && c < nCells;
        inside = inside && in;
        rank_[i] = in ? binOrder_.rank(c) : 0;
    }
    if (!inside)
    {
        binStart_.clear();
        return false;
    }
    return countRanks(binOrder_.nRanks());
}


void Foam::particleArrays::splitRanks(const label nBins, const int nParts)
{
    // At the ranks of evenly spaced particles: even shares when the
    // particles are nearly in order, as after a step's moves
    rankSplit_.assign(nParts + 1, nBins);
    rankSplit_[0] = 0;
    for (int t = 1; t < nParts; ++t)
    {
        const label r = size_ ? rank_[label(double(size_)*t/nParts)] : 0;
        rankSplit_[t] = min(max(r, rankSplit_[t - 1]), nBins);
    }
}


bool Foam::particleArrays::countRanks(const label nBins)
{
    const label n = size_;
    const label* rank = rank_.data();
    label nDescents = 0;
    #pragma omp parallel for schedule(static) reduction(+:nDescents)
    for (label i = 1; i < n; ++i)
    {
        nDescents += rank[i] < rank[i - 1];
    }

    // Each thread counts the particles of its range of ranks and sums its
    // counts; the ranges' totals are then added on
    binStart_.assign(nBins + 1, 0);
    label* start = binStart_.data();
    #pragma omp parallel
    {
        const threadTeam team = thisThread();
        #pragma omp single
        {
            splitRanks(nBins, team.size);
            rangeTotal_.assign(team.size + 1, 0);
        }
        const label lo = rankSplit_[team.index];
        const label hi = rankSplit_[team.index + 1];
        if (lo < hi)
        {
            for (label i = 0; i < n; ++i)
            {
                const label r = rank[i];
                if (r >= lo && r < hi)
                {
                    ++start[r + 1];
                }
            }
            for (label r = lo + 1; r < hi; ++r)
            {
                start[r + 1] += start[r];
            }
            rangeTotal_[team.index + 1] = start[hi];
        }
        #pragma omp barrier
        label offset = 0;
        for (int s = 0; s < team.index; ++s)
        {
            offset += rangeTotal_[s + 1];
        }
        for (label r = lo; r < hi; ++r)
        {
            start[r + 1] += offset;
        }
    }
    return nDescents == 0;
}


void Foam::particleArrays::orderByRank()
{
    // The counting sort's placement by countRanks' ranges of ranks, each in
    // storage order: stable (a team of another size takes them in turn)
    const label n = size_;
    const label* rank = rank_.data();
    const int nParts = int(rankSplit_.size()) - 1;
    count_.resize(binStart_.size());
    order_.resize(n);
    label* next = count_.data();
    label* ord = order_.data();
    #pragma omp parallel
    {
        const threadTeam team = thisThread();
        for (int part = team.index; part < nParts; part += team.size)
        {
            const label lo = rankSplit_[part], hi = rankSplit_[part + 1];
            std::copy(binStart_.data() + lo, binStart_.data() + hi, next + lo);
            for (label i = 0; lo < hi && i < n; ++i)
            {
                const label r = rank[i];
                if (r >= lo && r < hi)
                {
                    ord[next[r]++] = i;
                }
            }
        }
    }
}


Foam::nodeBox Foam::particleArrays::stencilNodes
(
    const gridGeometry& g
) const
{
    if (!size_)
    {
        return nodeBox();
    }
    const double* pos[3] = {component(X), component(Y), component(Z)};
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    const label n = size_;
    #pragma omp parallel for schedule(static) \
        reduction(min:lo[:3]) reduction(max:hi[:3])
    for (label i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            const double xd = pos[d][i];
            lo[d] = xd < lo[d] ? xd : lo[d];
            hi[d] = xd > hi[d] ? xd : hi[d];
        }
    }
    return g.stencilBox(lo, hi);
}


void Foam::particleArrays::stencilRows
(
    const gridGeometry& g,
    nodeRowSpans& rows
) const
{
    typedef gridGeometry::index index;
    const index nG = gridGeometry::nGhost;
    const index nRows = g.nNodesDir[1]*g.nNodesDir[2];
    rows.lo.assign(nRows, g.nNodesDir[0]);
    rows.hi.assign(nRows, 0);
    const index n[3] = {g.nNodesDir[0], g.nNodesDir[1], g.nNodesDir[2]};
    const auto clip = [](const index i, const index m)
    {
        return i < 0 ? 0 : (i > m ? m : i);
    };

    // A particle in cell c (where it is now, not its bin: a bin may be
    // stale by a cell or more) has its stencil within nodes c - 1 .. c + 2
    // per axis. The particles of a bin's row of cells within a tile are
    // contiguous: their cells' bounds (a loop that vectorises) give one
    // box of node rows and spans, tight unless some particle is stale
    const double* x = component(X);
    const double* y = component(Y);
    const double* const zOr = g.dim == 3 ? component(Z) : x;
    const int dz = g.dim == 3 ? 2 : 0;
    const tileCellOrder& o = binOrder_;
    const index T = o.T;
    const index nt = o.nTiles[0]*o.nTiles[1]*o.nTiles[2];
    // Tiles on all threads: the rows of neighbouring tiles overlap, and a
    // bound taken with an atomic compare-and-swap is the same whatever the
    // order. Moves *a to v where v lies beyond it (by sign: -1 below, +1
    // above)
    const auto widen = [](int32_t* a, const int32_t v, const int sign)
    {
        int32_t now = __atomic_load_n(a, __ATOMIC_RELAXED);
        while
        (
            sign*(v - now) > 0
         && !__atomic_compare_exchange_n
            (
                a, &now, v, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED
            )
        )
        {}
    };
    int32_t* const rowLo = rows.lo.data();
    int32_t* const rowHi = rows.hi.data();
    #pragma omp parallel for schedule(dynamic, 16)
    for (index t = 0; t < nt; ++t)
    {
        // (A flow fills few of the grid's tiles)
        if (binStart_[o.firstRank(t)] == binStart_[o.firstRank(t + 1)])
        {
            continue;
        }
        for (index r0 = o.firstRank(t); r0 < o.firstRank(t + 1); r0 += T)
        {
            const label first = binStart_[r0];
            const label last = binStart_[r0 + T];
            if (first == last)
            {
                continue;
            }
            index lo[3] = {g.nCells[0], g.nCells[1], g.nCells[2]};
            index hi[3] = {0, 0, 0};
            #pragma omp simd reduction(min:lo[:3]) reduction(max:hi[:3])
            for (label p = first; p < last; ++p)
            {
                const index c[3] =
                {
                    g.cellDir(0, x[p]), g.cellDir(1, y[p]),
                    g.cellDir(dz, zOr[p])
                };
                for (int d = 0; d < 3; ++d)
                {
                    lo[d] = c[d] < lo[d] ? c[d] : lo[d];
                    hi[d] = c[d] > hi[d] ? c[d] : hi[d];
                }
            }
            // Node array indices: node c is c + nG
            const index i0 = clip(lo[0] - 1 + nG, n[0]);
            const index i1 = clip(hi[0] + 3 + nG, n[0]);
            // A plane slice's stencils take its one row of nodes along y
            const index j0 = g.plane ? nG : clip(lo[1] - 1 + nG, n[1]);
            const index j1 = g.plane ? nG + 1 : clip(hi[1] + 3 + nG, n[1]);
            const index k0 = g.dim == 3 ? clip(lo[2] - 1 + nG, n[2]) : 0;
            const index k1 = g.dim == 3 ? clip(hi[2] + 3 + nG, n[2]) : 1;
            for (index kk = k0; kk < k1; ++kk)
            {
                for (index jj = j0; jj < j1; ++jj)
                {
                    const index r = jj + n[1]*kk;
                    widen(rowLo + r, i0, -1);
                    widen(rowHi + r, i1, 1);
                }
            }
        }
    }
}


bool Foam::particleArrays::finite(const std::vector<label>& components) const
{
    // A count with no branch per value, which vectorises (every step, over
    // every component): |v| <= max is false for infinities and NaN
    const label n = size_;
    const double big = std::numeric_limits<double>::max();
    for (const label c : components)
    {
        const double* v = component(c);
        label nBad = 0;
        #pragma omp parallel for schedule(static) reduction(+:nBad)
        for (label i = 0; i < n; ++i)
        {
            nBad += !(std::abs(v[i]) <= big);
        }
        if (nBad)
        {
            return false;
        }
    }
    return true;
}


bool Foam::particleArrays::setBins
(
    const gridGeometry& g,
    const std::vector<label>& bins
)
{
    const label nCells = g.nCellsTotal();
    binned_ = label(bins.size()) == size_;
    for (label i = 0; binned_ && i < size_; ++i)
    {
        binned_ = bins[i] >= 0 && bins[i] < nCells;
    }
    // Counted in the order of the next sortByCell
    binStart_.clear();
    if (binned_)
    {
        cell_ = bins;
    }
    return binned_;
}


Foam::label Foam::particleArrays::nBeyondBins
(
    const gridGeometry& g,
    const label maxStale
) const
{
    // A count of the particles further than maxStale cells from their bin
    // per axis, in a loop without a branch or an integer division (it
    // vectorises). The bin's indices per axis from its flat index: q/n is
    // the floor of (q + 1/2) (1/n) in double, whose error (relative, about
    // 2^-52) is far below the 1/(2n) that the quotient's fraction lies from
    // an integer, for any q < 2^31
    const double* x = component(X);
    const double* y = component(Y);
    const label* cellp = cell_.data();
    const label s = maxStale;
    const label nx = g.nCells[0], ny = g.nCells[1];
    const double invNx = 1.0/nx, invNy = 1.0/ny;
    // (2D: the z-axis's one cell, so dk = 0)
    const double* const zOr = g.dim == 3 ? component(Z) : x;
    const int dz = g.dim == 3 ? 2 : 0;
    const label layers = g.dim == 3;
    label nFar = 0;
    #pragma omp parallel for simd schedule(static) reduction(+:nFar)
    for (label i = 0; i < size_; ++i)
    {
        const label c = cellp[i];
        const label row = label((c + 0.5)*invNx);
        const label layer = label((row + 0.5)*invNy);
        const label di = g.cellDir(0, x[i]) - (c - nx*row);
        const label dj = g.cellDir(1, y[i]) - (row - ny*layer);
        const label dk = layers*(g.cellDir(dz, zOr[i]) - layer);
        nFar +=
            (di > s) | (-di > s) | (dj > s) | (-dj > s)
          | (dk > s) | (-dk > s);
    }
    return nFar;
}


bool Foam::particleArrays::sortByCell
(
    const gridGeometry& g,
    const tileCellOrder& order,
    const label maxStale
)
{
    cell_.resize(size_);

    // A binning of another order (or a restart's) is kept if it is sorted
    // in this one
    if (binned_ && !binsCountedIn(order))
    {
        binOrder_ = order;
        binned_ = countBins();
    }

    // Kept while every particle is near its bin
    if (maxStale > 0 && binned_ && nBeyondBins(g, maxStale) == 0)
    {
        return false;
    }

    rebin(g, order, nullptr, transient_);
    return true;
}


void Foam::particleArrays::rebin
(
    const gridGeometry& g,
    const tileCellOrder& order,
    const char* removed,
    const std::vector<char>& notMoved
)
{
    // (2D: z is not read, and may be stale)
    const double* x = component(X);
    const double* y = component(Y);
    const double* z = g.dim == 3 ? component(Z) : x;
    cell_.resize(size_);
    label* cellp = cell_.data();

    // Counting sort by rank: binStart is the exclusive prefix sum of the
    // counts. The removed go to one bin after the last, which the sort
    // then cuts off
    binOrder_ = order;
    const label nRanks = order.nRanks();
    rank_.resize(size_);
    // The rank from the cell's indices per axis, not from its flat index
    // (two integer divisions fewer per particle). Where tracked, the cells
    // of the particles whose bin changes (cell_ holds the bins before)
    uint8_t* changed = binChanged_.empty() ? nullptr : binChanged_.data();
    bool anyChanged = false;
    #pragma omp parallel for schedule(static) reduction(||:anyChanged)
    for (label i = 0; i < size_; ++i)
    {
        gridGeometry::index ijk[3];
        g.cellIJK(x[i], y[i], z[i], ijk);
        const label c = g.cellIndex(ijk[0], ijk[1], ijk[2]);
        if (changed && cellp[i] != c)
        {
            #pragma omp atomic write
            changed[c] = 1;
            anyChanged = true;
        }
        cellp[i] = c;
        rank_[i] =
            removed && removed[i] ? nRanks : order.rank(ijk[0], ijk[1], ijk[2]);
    }
    anyBinChanged_ = anyBinChanged_ || anyChanged;
    // The removed bin's start, binStart_[nRanks], stays for the placement
    // (count_ is sized by the bins counted)
    const bool sorted = countRanks(nRanks + (removed != nullptr));
    const label n = binStart_[nRanks];
    binStart_.resize(nRanks + 1);
    binned_ = true;
    if (sorted && n == size_)
    {
        return;
    }

    orderByRank();
    permute(n, notMoved);
}


Foam::label Foam::particleArrays::removeAndSort
(
    const std::vector<char>& flagged,
    const gridGeometry& g,
    const tileCellOrder& order
)
{
    checkFlagSize(flagged, "flags");
    const label n0 = size_;
    rebin(g, order, flagged.data(), recomputed_);
    return n0 - size_;
}


Foam::label Foam::particleArrays::removeAndPlaceAppended
(
    const std::vector<char>& flagged,
    const std::vector<label>& parents,
    const gridGeometry& g,
    const tileCellOrder& order,
    const label maxStale
)
{
    checkFlagSize(flagged, "flags");
    const label nAppended = label(parents.size());
    const label n0 = size_ - nAppended;
    bool parentsValid = n0 >= 0;
    for (label k = 0; parentsValid && k < nAppended; ++k)
    {
        parentsValid =
            parents[k] >= 0 && parents[k] < n0
         && (k == 0 || parents[k] >= parents[k - 1]);
    }
    if (!parentsValid)
    {
        FatalErrorInFunction
            << "the parents of the " << nAppended << " particles appended"
            << " are not ascending indices of the " << n0 << " before them"
            << abort(FatalError);
    }
    const bool binnedBefore = binsCountedIn(order) && binStart_.back() == n0;

    // A child takes its parent's bin. When some particle (one flagged too)
    // is beyond its bin's staleness, a full re-bin instead
    label* cellp = cell_.data();
    const label* parent = parents.data();
    for (label k = 0; binnedBefore && k < nAppended; ++k)
    {
        cellp[n0 + k] = cellp[parent[k]];
    }
    if (!binnedBefore || maxStale < 1 || nBeyondBins(g, maxStale))
    {
        return removeAndSort(flagged, g, order);
    }

    // order_: each kept particle before the append, then its kept children.
    // rank_[i]: where particle i's group starts in the new order, so that a
    // bin starts where its first particle's group does
    const char* flag = flagged.data();
    order_.resize(size_);
    rank_.resize(n0 + 1);
    label* ord = order_.data();
    label* groupStart = rank_.data();
    label n = 0;
    #pragma omp parallel
    {
        const threadTeam team = thisThread();
        #pragma omp single
        rangeTotal_.assign(team.size + 1, 0);

        const auto firstChild = [=](const label i)
        {
            return label
            (
                std::lower_bound(parent, parent + nAppended, i) - parent
            );
        };
        const label a = label(double(n0)*team.index/team.size);
        const label b = label(double(n0)*(team.index + 1)/team.size);
        const label ca = firstChild(a), cb = firstChild(b);
        label kept = 0;
        for (label i = a; i < b; ++i)
        {
            kept += !flag[i];
        }
        for (label c = ca; c < cb; ++c)
        {
            kept += !flag[n0 + c];
        }
        rangeTotal_[team.index + 1] = kept;
        #pragma omp barrier

        label k = 0;
        for (int t = 0; t < team.index; ++t)
        {
            k += rangeTotal_[t + 1];
        }
        label c = ca;
        for (label i = a; i < b; ++i)
        {
            groupStart[i] = k;
            if (!flag[i])
            {
                ord[k++] = i;
            }
            for (; c < cb && parent[c] == i; ++c)
            {
                if (!flag[n0 + c])
                {
                    ord[k++] = n0 + c;
                }
            }
        }
        if (team.index == team.size - 1)
        {
            n = k;
        }
    }
    groupStart[n0] = n;

    label* start = binStart_.data();
    const label nBins = label(binStart_.size());
    #pragma omp parallel for schedule(static)
    for (label r = 0; r < nBins; ++r)
    {
        start[r] = groupStart[start[r]];
    }

    const label nRemoved = size_ - n;
    findMoves(n, n0);
    moveInPlace(n, n0, recomputed_);
    binned_ = true;
    return nRemoved;
}


// ************************************************************************* //
