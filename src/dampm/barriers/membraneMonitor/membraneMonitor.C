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
    peakContactTime_(0)
{}


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
    anchorFile_.reset
    (
        new timeSeriesFile
        (
            runTime, name_, "anchorForces", columns,
            {"Force of flexible barrier " + name_ + " on its anchors [N], per"
             " anchor group and rope (its fixed ends): minus the supports'"
             " reaction"}
        )
    );
    membraneFile_.reset
    (
        new timeSeriesFile
        (
            runTime, name_, "membrane",
            {"time", "maxDeflection", "strainEnergy", "kineticEnergy",
             "dissipatedEnergy", "contactForceX", "contactForceY",
             "contactForceZ", "contactDissipation", "momentumX", "momentumY",
             "momentumZ", "contactEnergy"},
            {"Flexible barrier " + name_ + ": maxDeflection [m] the largest"
             " node displacement; strainEnergy (membrane and ropes),",
             "kineticEnergy, dissipatedEnergy (damping, brakes, contact) and"
             " its contactDissipation [J] since the start;",
             "contactForce [N] the flow's force on it; momentum [kg m/s] of"
             " its free nodes (at the last half step);",
             "contactEnergy [J] the energy the contact's push holds at the"
             " start of the step"}
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
    anchorFile_->write(row);

    const flexibleStructure::energyBudget& e = s.energies();
    const scalar deflection = s.maxDeflection();
    const vector P = s.momentum();
    membraneFile_->write
    (
        List<scalar>
        ({
            t, deflection, e.membraneStrain + e.ropeStrain, e.kinetic,
            e.dampingDissipation + e.brakeDissipation + contactDissipation,
            contactForce.x(), contactForce.y(), contactForce.z(),
            contactDissipation, P.x(), P.y(), P.z(), contactEnergy
        })
    );
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
    os  << "Flexible barrier " << name_ << ": peak contact force "
        << peakContact_ << " N at t = " << peakContactTime_
        << " s, largest deflection " << peakDeflection_ << " m at t = "
        << peakDeflectionTime_ << " s" << nl;
    forAll(groups, gi)
    {
        os  << "    anchor " << groups[gi] << ": peak force "
            << peakAnchor_[gi] << " N at t = " << peakAnchorTime_[gi] << " s"
            << nl;
    }
}


// ************************************************************************* //
