/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "cloudReconstruction.H"
#include "particleCloudIO.H"
#include "mpmTime.H"
#include "exactPrecision.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "cloud.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::cloudReconstruction::procTimePath
(
    const label proci,
    const word& timeName
) const
{
    return procTimes_[proci].path()/timeName;
}


void Foam::cloudReconstruction::checkComplete(const word& timeName) const
{
    forAll(procTimes_, proci)
    {
        const fileName dir(procTimePath(proci, timeName));
        if (mpmTime::state(dir) != mpmTime::directoryState::complete)
        {
            FatalErrorInFunction
                << "time " << timeName << " is not complete on processor"
                << proci << " (" << dir << " has no uniform/"
                << mpmTime::recordName << ": the run was stopped while"
                << " writing it, or never wrote it): its clouds cannot be"
                << " reconstructed; allowed: a time complete on every"
                << " processor (-time)" << exit(FatalError);
        }
    }
}


void Foam::cloudReconstruction::addFieldsOnDisk
(
    particleArrays& particles,
    const fileName& cloudDir
) const
{
    typedef particleArrays::fieldKind kind;
    static const HashTable<kind> kinds
    ({
        {"scalarField", kind::scalar},
        {"vectorField", kind::vector},
        {"symmTensorField", kind::symmTensor},
        {"tensorField", kind::tensor},
        {"tensor2DField", kind::tensor2D}
    });
    for (const fileName& f : readDir(cloudDir, fileName::FILE))
    {
        if (f == "positions" || particles.found(f))
        {
            continue;
        }
        IFstream is(cloudDir/f);
        IOobject header(f, "", procTimes_[0]);
        if (!(is.good() && header.readHeader(is)))
        {
            FatalErrorInFunction
                << "cannot read the header of particle field " << cloudDir/f
                << exit(FatalError);
        }
        const word& type = header.headerClassName();
        if (!kinds.found(type))
        {
            FatalErrorInFunction
                << "particle field " << cloudDir/f << " is of class " << type
                << "; allowed: " << kinds.sortedToc() << exit(FatalError);
        }
        particles.addField(f, kinds[type]);
    }
}


Foam::label Foam::cloudReconstruction::reconstructCloud
(
    const word& cloudName
) const
{
    const word& timeName = grid_.mesh().time().timeName();
    const fileName dir0(procTimePath(0, timeName)/cloud::prefix/cloudName);

    particleArrays all;
    addFieldsOnDisk(all, dir0);
    Info<< "    cloud " << cloudName << ":";
    forAll(procTimes_, proci)
    {
        particleArrays part;
        addFieldsOnDisk(part, dir0);
        particleCloudIO::read(part, procTimes_[proci], cloudName, timeName);
        const label first = all.append(part.size());
        for (label c = 0; c < all.nComponentArrays(); ++c)
        {
            std::copy_n
            (
                part.component(c), part.size(), all.component(c) + first
            );
        }
        Info<< ' ' << part.size();
    }
    Info<< " particles (processor0 ..), " << all.size() << " in all" << endl;

    particleCloudIO::checkCloud
    (
        all, grid_, particleCloudIO::cloudDir(grid_.mesh(), cloudName)
    );
    const particleCloudIO cloudIO(cloudName, all, grid_);
    if (!cloudIO.write())
    {
        FatalErrorInFunction
            << "cannot write cloud " << cloudName << " at time " << timeName
            << " (" << particleCloudIO::cloudDir(grid_.mesh(), cloudName)
            << ")" << exit(FatalError);
    }
    return all.size();
}


void Foam::cloudReconstruction::reconstructState(const fileName& file) const
{
    const Time& runTime = grid_.mesh().time();
    const word& timeName = runTime.timeName();

    // Every processor's entries, processor0's order
    PtrList<dictionary> dicts(procTimes_.size());
    forAll(procTimes_, proci)
    {
        const fileName path(procTimePath(proci, timeName)/"uniform"/file);
        IFstream is(path);
        IOobject header(file, "", procTimes_[proci]);
        if (!(is.good() && header.readHeader(is)))
        {
            FatalErrorInFunction
                << "cannot read " << path << exit(FatalError);
        }
        dicts.set(proci, new dictionary(is));
    }

    const exactPrecision exact;
    IOdictionary merged
    (
        IOobject
        (
            file, timeName, "uniform", runTime, IOobject::NO_READ,
            IOobject::NO_WRITE, false
        )
    );
    for (const entry& e : dicts[0])
    {
        const word& key = e.keyword();
        if (processorSum(key))
        {
            scalar sum = 0;
            forAll(dicts, proci)
            {
                sum += dicts[proci].get<scalar>(key);
            }
            merged.add(key, sum);
            continue;
        }
        OStringStream first;
        first << e;
        for (label proci = 1; proci < dicts.size(); ++proci)
        {
            OStringStream other;
            const entry* ep = dicts[proci].findEntry(key, keyType::LITERAL);
            if (ep)
            {
                other << *ep;
            }
            if (!ep || other.str() != first.str())
            {
                FatalIOErrorInFunction(dicts[proci])
                    << "uniform/" << file << " of time " << timeName
                    << ": entry " << key << " of processor" << proci << " ("
                    << (ep ? other.str().c_str() : "missing") << ") differs"
                    << " from processor0's (" << first.str().c_str() << "),"
                    << " while it is a value of the whole run; the"
                    << " processor directories are not of one run"
                    << exit(FatalIOError);
            }
        }
        merged.add(e.clone(merged).ptr());
    }
    merged.regIOobject::writeObject
    (
        IOstream::ASCII, IOstream::currentVersion, IOstream::UNCOMPRESSED,
        true
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cloudReconstruction::cloudReconstruction
(
    const mpmGrid& grid,
    const label nProcs
)
:
    grid_(grid),
    procTimes_(nProcs)
{
    const Time& runTime = grid.mesh().time();
    forAll(procTimes_, proci)
    {
        procTimes_.set
        (
            proci,
            new Time
            (
                Time::controlDictName,
                runTime.rootPath(),
                runTime.caseName()/("processor" + Foam::name(proci))
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::cloudReconstruction::processorSum(const word& key)
{
    // The state entries of the solvers' writeState that tally particles
    // (depthAveragedFlow, mpm3dFlow): the outflow, a barrier's passed outflow
    static const std::string passed("PassedOutflow");
    return
        key == "outflowMass"
     || (
            key.size() > passed.size()
         && key.compare(key.size() - passed.size(), passed.size(), passed) == 0
        );
}


Foam::label Foam::cloudReconstruction::reconstruct() const
{
    const Time& runTime = grid_.mesh().time();
    const word& timeName = runTime.timeName();
    checkComplete(timeName);

    // The record goes first and comes back last: a reconstruction stopped
    // half way leaves an incomplete directory, never a wrong one
    const fileName record(runTime.timePath()/"uniform"/mpmTime::recordName);
    mkDir(runTime.timePath()/"uniform");
    rm(record);

    label nParticles = 0;
    const fileName lagrangian(procTimePath(0, timeName)/cloud::prefix);
    for (const fileName& cloudName : readDir(lagrangian, fileName::DIRECTORY))
    {
        nParticles += reconstructCloud(cloudName);
    }
    const fileName uniform(procTimePath(0, timeName)/"uniform");
    for (const fileName& file : readDir(uniform, fileName::FILE))
    {
        if (file != mpmTime::recordName)
        {
            reconstructState(file);
        }
    }
    reconstructState(mpmTime::recordName);
    return nParticles;
}


// ************************************************************************* //
