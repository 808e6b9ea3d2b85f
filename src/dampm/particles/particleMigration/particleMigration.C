/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "particleMigration.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleMigration::particleMigration(const gridDecomposition& parts)
:
    parts_(parts),
    nSent_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::particleMigration::migrate(particleArrays& particles)
{
    if (!parts_.active())
    {
        return 0;
    }
    const label n = particles.size();
    const label nComp = particles.nComponentArrays();
    const double* x = particles.component(particleArrays::X);
    const double* y = particles.component(particleArrays::Y);
    const double* z = particles.component(particleArrays::Z);

    // The neighbour each leaving particle goes to
    const label nNb = parts_.nNeighbours();
    dest_.assign(n, -1);
    leaving_.assign(n, 0);
    labelList count(nNb, Zero);
    label nLeaving = 0;
    for (label i = 0; i < n; ++i)
    {
        if (!parts_.holds(x[i], y[i], z[i]))
        {
            dest_[i] = parts_.neighbourHolding(x[i], y[i], z[i]);
            leaving_[i] = 1;
            ++count[dest_[i]];
            ++nLeaving;
        }
    }

    // Every field, particle by particle, for each neighbour
    List<scalarList> send(nNb);
    forAll(send, k)
    {
        send[k].setSize(count[k]*nComp);
        count[k] = 0;
    }
    for (label i = 0; i < n; ++i)
    {
        if (leaving_[i])
        {
            scalarList& s = send[dest_[i]];
            label& k = count[dest_[i]];
            for (label c = 0; c < nComp; ++c)
            {
                s[k++] = particles.component(c)[i];
            }
        }
    }
    List<scalarList> received;
    parts_.exchange(send, received);
    particles.removeFlagged(leaving_);

    // Appended in the neighbours' (ascending) rank order
    forAll(received, k)
    {
        const scalarList& r = received[k];
        const label nNew = r.size()/nComp;
        const label first = particles.append(nNew);
        label m = 0;
        for (label i = first; i < first + nNew; ++i)
        {
            for (label c = 0; c < nComp; ++c)
            {
                particles.component(c)[i] = r[m++];
            }
        }
    }
    nSent_ += nLeaving;
    return nLeaving;
}


Foam::label Foam::particleMigration::nMoved() const
{
    return returnReduce(nSent_, sumOp<label>());
}


// ************************************************************************* //
