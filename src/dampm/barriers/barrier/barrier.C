/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "barrier.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::wordList Foam::barrier::keywords()
{
    wordList all(contactCondition::keywords);
    all.append(nodeContact::keywords);
    all.append(barrierMonitor::keywords);
    return all;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::barrier::barrier
(
    const word& name,
    const dictionary& dict,
    const fileName& caseDir
)
:
    condition_(dict),
    contact_(name, dict, condition_),
    monitor_(name, dict),
    geometry_(barrierGeometry::New(name, dict, caseDir)),
    guard_(*geometry_, condition_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::barrier::findNodes
(
    const gridGeometry& g,
    const bool wall[3][2]
)
{
    geometry_->checkGrid(g);

    const scalar band = contact_.startSearch(g);
    guard_.startSearch(g, band);
    monitor_.startSearch(g);
    geometry_->nodeDistances
    (
        g,
        band,
        [&]
        (
            const gridGeometry::index n,
            const point& x,
            const scalar phi,
            const vector& normal
        )
        {
            guard_.addNode(g, n, phi);
            contact_.addNode(n, phi, normal);
            monitor_.addNode(n, x, phi);
        }
    );
    contact_.finishSearch(g, wall);
    monitor_.finishSearch(g, contact_.nodes(), geometry_->bounds());
}


void Foam::barrier::describe(Ostream& os) const
{
    os  << "    " << name() << ": ";
    geometry_->describe(os);
    os  << ", ";
    condition_.describe(os);
    os  << ", " << contact_.nNodesTotal() << " contact nodes";
    monitor_.describe(os);
    os  << nl;
}


// ************************************************************************* //
