/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "membraneMonitor.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::membraneMonitor::membraneMonitor(const word& name, const label nGroups)
:
    name_(name),
    peakAnchor_(nGroups, scalar(0)),
    peakAnchorTime_(nGroups, scalar(0)),
    peakDeflection_(0),
    peakDeflectionTime_(0),
    peakContact_(0),
    peakContactTime_(0),
    width_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::membraneMonitor::addPerWidth
(
    wordList& description,
    wordList& columns,
    const label first,
    const label last
) const
{
    if (width_ > 0)
    {
        description.append
        (
            "width " + Foam::name(width_) + " m: a plane slice's thickness;"
            " *PerWidth [N/m] the forces per unit width"
        );
        for (label c = first; c < last; ++c)
        {
            columns.append(columns[c] + "PerWidth");
        }
    }
}


void Foam::membraneMonitor::addPerWidth
(
    List<scalar>& row,
    const label first,
    const label last
) const
{
    if (width_ > 0)
    {
        for (label c = first; c < last; ++c)
        {
            row.append(row[c]/width_);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::membraneMonitor::openFiles
(
    const Time& runTime,
    const wordList& groups
)
{
    wordList columns({"time"});
    for (const word& group : groups)
    {
        for (const char* c : {"Fx", "Fy", "Fz"})
        {
            columns.append(group + c);
        }
    }
    wordList anchorHeader
    ({
        "Force of flexible barrier " + name_ + " on its anchors [N], per"
        " anchor group and rope (its fixed ends): minus the supports'"
        " reaction"
    });
    addPerWidth(anchorHeader, columns, 1, columns.size());
    anchorFile_.reset
    (
        new timeSeriesFile
        (
            runTime, name_, "anchorForces", columns, anchorHeader
        )
    );
    wordList membraneColumns
    ({
        "time", "maxDeflection", "strainEnergy", "kineticEnergy",
        "dissipatedEnergy", "contactForceX", "contactForceY",
        "contactForceZ", "contactDissipation", "momentumX", "momentumY",
        "momentumZ", "contactEnergy"
    });
    wordList membraneHeader
    ({
        "Flexible barrier " + name_ + ": maxDeflection [m] the largest"
        " node displacement; strainEnergy (membrane and ropes),",
        "kineticEnergy, dissipatedEnergy (damping, brakes, contact) and"
        " its contactDissipation [J] since the start;",
        "contactForce [N] the flow's force on it; momentum [kg m/s] of"
        " its free nodes (at the last half step);",
        "contactEnergy [J] the energy the contact's push holds at the"
        " start of the step"
    });
    addPerWidth(membraneHeader, membraneColumns, 5, 8);
    membraneFile_.reset
    (
        new timeSeriesFile
        (
            runTime, name_, "membrane", membraneColumns, membraneHeader
        )
    );
}


void Foam::membraneMonitor::write
(
    const scalar t,
    const List<vector>& anchorForces,
    const flexibleStructure& s,
    const vector& contactForce,
    const scalar contactDissipation,
    const scalar contactEnergy
)
{
    const wordList& groups = s.anchors().names();
    List<scalar> row(1 + 3*groups.size());
    row[0] = t;
    forAll(groups, gi)
    {
        const vector& R = anchorForces[gi];
        for (direction d = 0; d < 3; ++d)
        {
            row[1 + 3*gi + d] = R[d];
        }
        if (mag(R) > peakAnchor_[gi])
        {
            peakAnchor_[gi] = mag(R);
            peakAnchorTime_[gi] = t;
        }
    }
    addPerWidth(row, 1, row.size());
    anchorFile_->write(row);

    const flexibleStructure::energyBudget& e = s.energies();
    const scalar deflection = s.maxDeflection();
    const vector P = s.momentum();
    List<scalar> membraneRow
    ({
        t, deflection, e.membraneStrain + e.ropeStrain, e.kinetic,
        e.dampingDissipation + e.brakeDissipation + contactDissipation,
        contactForce.x(), contactForce.y(), contactForce.z(),
        contactDissipation, P.x(), P.y(), P.z(), contactEnergy
    });
    addPerWidth(membraneRow, 5, 8);
    membraneFile_->write(membraneRow);
    if (deflection > peakDeflection_)
    {
        peakDeflection_ = deflection;
        peakDeflectionTime_ = t;
    }
    if (mag(contactForce) > peakContact_)
    {
        peakContact_ = mag(contactForce);
        peakContactTime_ = t;
    }
}


void Foam::membraneMonitor::report
(
    Ostream& os,
    const wordList& groups
) const
{
    // On a plane slice, per unit width too
    auto perWidth = [this](const scalar F)
    {
        return width_ > 0
          ? " (" + Foam::name(F/width_) + " N/m)" : std::string();
    };
    os  << "Flexible barrier " << name_ << ": peak contact force "
        << peakContact_ << " N" << perWidth(peakContact_).c_str()
        << " at t = " << peakContactTime_
        << " s, largest deflection " << peakDeflection_ << " m at t = "
        << peakDeflectionTime_ << " s" << nl;
    forAll(groups, gi)
    {
        os  << "    anchor " << groups[gi] << ": peak force "
            << peakAnchor_[gi] << " N" << perWidth(peakAnchor_[gi]).c_str()
            << " at t = " << peakAnchorTime_[gi] << " s" << nl;
    }
}


// ************************************************************************* //
