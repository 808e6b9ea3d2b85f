/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "anchorGroups.H"
#include "structureInput.H"
#include "boundBox.H"
#include "Enum.H"
#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<Foam::label> Foam::anchorGroups::select
(
    const dictionary& dict,
    const structureNodes& nodes,
    const std::vector<label>& boundary
) const
{
    enum class selectionType { boundary, box };
    static const Enum<selectionType> selectionTypes
    ({
        {selectionType::boundary, "boundary"},
        {selectionType::box, "box"}
    });
    structureInput::onlyKeywords(dict, {"type", "min", "max"});
    const selectionType type = selectionTypes.get("type", dict);

    boundBox box(point::uniform(-GREAT), point::uniform(GREAT));
    if (type == selectionType::box || dict.found("min") || dict.found("max"))
    {
        box = boundBox(dict.get<point>("min"), dict.get<point>("max"));
    }

    std::vector<label> candidates(boundary);
    if (type == selectionType::box)
    {
        candidates.resize(nodes.size());
        for (label nodei = 0; nodei < nodes.size(); ++nodei)
        {
            candidates[nodei] = nodei;
        }
    }

    std::vector<label> selected;
    for (const label nodei : candidates)
    {
        if (box.contains(nodes.referencePosition(nodei)) && !grouped(nodei))
        {
            selected.push_back(nodei);
        }
    }
    if (selected.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Anchor group " << dict.dictName() << " selects no node "
            << "(not in another group)" << exit(FatalIOError);
    }
    return selected;
}


bool Foam::anchorGroups::grouped(const label nodei) const
{
    for (const std::vector<label>& group : nodes_)
    {
        if (std::find(group.begin(), group.end(), nodei) != group.end())
        {
            return true;
        }
    }
    return false;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::anchorGroups::anchorGroups
(
    const dictionary& dict,
    structureNodes& nodes,
    const std::vector<label>& boundary
)
{
    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << e.keyword() << " of anchors is not a group; "
                << "allowed: named sub-dictionaries" << exit(FatalIOError);
        }
        add(e.keyword(), select(e.dict(), nodes, boundary), nodes);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::anchorGroups::add
(
    const word& name,
    const std::vector<label>& groupNodes,
    structureNodes& nodes
)
{
    if (names_.found(name))
    {
        FatalErrorInFunction
            << "Anchor group " << name << " defined twice (a rope's fixed "
            << "ends form a group named after the rope)" << exit(FatalError);
    }
    std::vector<label> ungrouped;
    for (const label nodei : groupNodes)
    {
        if (!grouped(nodei))
        {
            ungrouped.push_back(nodei);
            nodes.fixed[nodei] = 1;
        }
    }
    if (!ungrouped.empty())
    {
        names_.append(name);
        nodes_.push_back(ungrouped);
    }
}


Foam::vector Foam::anchorGroups::reaction
(
    const label groupi,
    const structureNodes& nodes
) const
{
    vector sum(Zero);
    for (const label nodei : nodes_[groupi])
    {
        sum -= vector
        (
            nodes.fx[nodei] + nodes.fExtX[nodei],
            nodes.fy[nodei] + nodes.fExtY[nodei],
            nodes.fz[nodei] + nodes.fExtZ[nodei]
        );
    }
    return sum;
}


// ************************************************************************* //
