/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "runOutCase.H"
#include "OSspecific.H"
#include "mpmTimeControls.H"
#include "strictIOdictionary.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runOutCase::runOutCase(const fileName& path)
:
    path_(path)
{
    if (!isFile(path_/"system"/"controlDict"))
    {
        FatalErrorInFunction
            << "the run-out case " << path_ << " is missing (no case at it:"
            << " no system/controlDict)" << exit(FatalError);
    }
    mpmTimeControls::checkControlDict(path_, false);
    runTime_.reset
    (
        new Time(Time::controlDictName, path_.path(), fileName(path_.name()))
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::instantList Foam::runOutCase::times() const
{
    instantList found;
    for (const instant& t : runTime_->times())
    {
        if (t.name() != runTime_->constant())
        {
            found.append(t);
        }
    }
    return found;
}


void Foam::runOutCase::setTime(const instant& t, const label index)
{
    runTime_->setTime(t, index);
    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                fvMesh::defaultRegion,
                runTime_->timeName(),
                *runTime_,
                IOobject::MUST_READ
            )
        )
    );
    properties_.reset
    (
        new strictIOdictionary
        (
            IOobject
            (
                "dampmProperties",
                runTime_->constant(),
                *mesh_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE
            )
        )
    );
}


// ************************************************************************* //
