/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "processorClouds.H"
#include "particleCloudIO.H"
#include "mpmTime.H"
#include "exactPrecision.H"
#include "IOdictionary.H"
#include "labelIOList.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "cloud.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::processorClouds::procTimePath(const label proci) const
{
    return procTimes_[proci].path()/grid_.mesh().time().timeName();
}


void Foam::processorClouds::checkComplete(const fileName& timeDir)
{
    if (mpmTime::state(timeDir) != mpmTime::directoryState::complete)
    {
        FatalErrorInFunction
            << "time directory " << timeDir << " is not complete (no"
            << " uniform/" << mpmTime::recordName << ": the run was stopped"
            << " while writing it, or never wrote it): its clouds cannot be"
            << " used; allowed: a complete time (-time)" << exit(FatalError);
    }
}


void Foam::processorClouds::addFieldsOnDisk
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


void Foam::processorClouds::writeCloud
(
    const word& cloudName,
    const particleArrays& particles,
    const mpmGrid& grid
)
{
    const fileName dir(particleCloudIO::cloudDir(grid.mesh(), cloudName));
    rmDir(dir);
    const particleCloudIO cloudIO(cloudName, particles, grid);
    if (!cloudIO.write())
    {
        FatalErrorInFunction
            << "cannot write cloud " << dir << exit(FatalError);
    }
}


Foam::PtrList<Foam::dictionary> Foam::processorClouds::readProcStates
(
    const fileName& file
) const
{
    PtrList<dictionary> dicts(procTimes_.size());
    forAll(procTimes_, proci)
    {
        const fileName path(procTimePath(proci)/"uniform"/file);
        IFstream is(path);
        IOobject header(file, "", procTimes_[proci]);
        if (!(is.good() && header.readHeader(is)))
        {
            FatalErrorInFunction
                << "cannot read " << path << ", which processor0's time "
                << procTimePath(0).name() << " has: the processor"
                << " directories are not of one run" << exit(FatalError);
        }
        dicts.set(proci, new dictionary(is));
    }
    return dicts;
}


void Foam::processorClouds::writeState
(
    const Time& runTime,
    const fileName& file,
    const dictionary& entries
)
{
    const exactPrecision exact;
    IOdictionary state
    (
        IOobject
        (
            file, runTime.timeName(), "uniform", runTime, IOobject::NO_READ,
            IOobject::NO_WRITE, false
        )
    );
    state.merge(entries);
    if
    (
        !state.regIOobject::writeObject
        (
            IOstream::ASCII, IOstream::currentVersion,
            IOstream::UNCOMPRESSED, true
        )
    )
    {
        FatalErrorInFunction
            << "cannot write " << state.objectPath() << exit(FatalError);
    }
}


void Foam::processorClouds::readProcMeshes() const
{
    if (procGrids_.size())
    {
        return;
    }
    const fvMesh& mesh = grid_.mesh();
    procMeshes_.setSize(procTimes_.size());
    procGrids_.setSize(procTimes_.size());
    cellProc_.setSize(mesh.nCells());
    cellProc_ = -1;
    forAll(procTimes_, proci)
    {
        const Time& procTime = procTimes_[proci];
        procMeshes_.set
        (
            proci,
            new fvMesh
            (
                IOobject
                (
                    fvMesh::defaultRegion, procTime.timeName(), procTime,
                    IOobject::MUST_READ
                )
            )
        );
        const fvMesh& procMesh = procMeshes_[proci];
        procGrids_.set(proci, new mpmGrid(procMesh));
        const labelIOList addressing
        (
            IOobject
            (
                "cellProcAddressing", procMesh.facesInstance(),
                procMesh.meshSubDir, procMesh, IOobject::MUST_READ,
                IOobject::NO_WRITE, false
            )
        );
        for (const label celli : addressing)
        {
            if (celli >= 0 && celli < cellProc_.size())
            {
                cellProc_[celli] = proci;
            }
        }
    }
    const label missing = cellProc_.find(-1);
    if (missing >= 0)
    {
        FatalErrorInFunction
            << "cell " << missing << " of " << mesh.time().path() << " is on"
            << " no processor (processor*/constant/polyMesh/"
            << "cellProcAddressing): the processor directories are not a"
            << " decomposition of this mesh; run decomposePar -force"
            << exit(FatalError);
    }
}


Foam::label Foam::processorClouds::reconstructCloud
(
    const word& cloudName
) const
{
    const word& timeName = grid_.mesh().time().timeName();
    const fileName dir0(procTimePath(0)/cloud::prefix/cloudName);

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
    writeCloud(cloudName, all, grid_);
    return all.size();
}


void Foam::processorClouds::reconstructState(const fileName& file) const
{
    const word& timeName = grid_.mesh().time().timeName();
    const PtrList<dictionary> dicts(readProcStates(file));

    const exactPrecision exact;
    dictionary merged;
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
    writeState(grid_.mesh().time(), file, merged);
}


Foam::label Foam::processorClouds::decomposeCloud(const word& cloudName) const
{
    const fvMesh& mesh = grid_.mesh();
    const word& timeName = mesh.time().timeName();
    const fileName dir(particleCloudIO::cloudDir(mesh, cloudName));

    particleArrays all;
    addFieldsOnDisk(all, dir);
    particleCloudIO::read(all, mesh, cloudName, timeName);
    particleCloudIO::checkCloud(all, grid_, dir);

    // Each particle's processor: that of its cell
    const gridGeometry& g = grid_.geometry();
    const double* x = all.component(particleArrays::X);
    const double* y = all.component(particleArrays::Y);
    const double* z = all.component(particleArrays::Z);
    labelList proc(all.size());
    labelList count(procTimes_.size(), Zero);
    forAll(proc, i)
    {
        proc[i] = cellProc_[grid_.meshCell()[g.cellOf(x[i], y[i], z[i])]];
        ++count[proc[i]];
    }

    Info<< "    cloud " << cloudName << ": " << all.size() << " particles,";
    forAll(procTimes_, proci)
    {
        particleArrays part;
        addFieldsOnDisk(part, dir);
        part.append(count[proci]);
        for (label c = 0; c < all.nComponentArrays(); ++c)
        {
            const double* from = all.component(c);
            double* to = part.component(c);
            label k = 0;
            forAll(proc, i)
            {
                if (proc[i] == proci)
                {
                    to[k++] = from[i];
                }
            }
        }
        writeCloud(cloudName, part, procGrids_[proci]);
        Info<< ' ' << part.size();
    }
    Info<< " on the processors (processor0 ..)" << endl;
    return all.size();
}


void Foam::processorClouds::decomposeState(const fileName& file) const
{
    const Time& runTime = grid_.mesh().time();
    const fileName path(runTime.timePath()/"uniform"/file);
    IFstream is(path);
    IOobject header(file, "", runTime);
    if (!(is.good() && header.readHeader(is)))
    {
        FatalErrorInFunction << "cannot read " << path << exit(FatalError);
    }
    const dictionary whole(is);

    const exactPrecision exact;
    forAll(procTimes_, proci)
    {
        dictionary part(whole);
        if (proci)
        {
            // processor0 holds the sums of what has left so far
            for (const entry& e : whole)
            {
                if (processorSum(e.keyword()))
                {
                    part.set(e.keyword(), scalar(0));
                }
            }
        }
        writeState(procTimes_[proci], file, part);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::processorClouds::processorClouds
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

bool Foam::processorClouds::processorSum(const word& key)
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


Foam::label Foam::processorClouds::reconstruct() const
{
    const Time& runTime = grid_.mesh().time();
    forAll(procTimes_, proci)
    {
        // A time decomposePar made, not a decomposed run: its uniform/ is
        // the case's own, through a link
        const fileName uniform(procTimePath(proci)/"uniform");
        if (Foam::type(uniform, false) == fileName::LINK)
        {
            Info<< "    not written by a decomposed run (" << uniform
                << " is decomposePar's link to the case's): left as it is"
                << endl;
            return 0;
        }
        checkComplete(procTimePath(proci));
    }

    const fileName uniform(runTime.timePath()/"uniform");
    if (Foam::type(uniform, false) == fileName::LINK)
    {
        rm(uniform);
    }
    mkDir(uniform);
    rm(uniform/mpmTime::recordName);

    label nParticles = 0;
    const fileName lagrangian(procTimePath(0)/cloud::prefix);
    for (const fileName& cloudName : readDir(lagrangian, fileName::DIRECTORY))
    {
        nParticles += reconstructCloud(cloudName);
    }
    for
    (
        const fileName& file
      : readDir(procTimePath(0)/"uniform", fileName::FILE)
    )
    {
        if (file != mpmTime::recordName)
        {
            reconstructState(file);
        }
    }
    reconstructState(mpmTime::recordName);
    return nParticles;
}


Foam::label Foam::processorClouds::decompose() const
{
    const Time& runTime = grid_.mesh().time();
    checkComplete(runTime.timePath());
    forAll(procTimes_, proci)
    {
        procTimes_[proci].setTime(runTime);
    }
    readProcMeshes();
    forAll(procTimes_, proci)
    {
        // decomposePar links the processor's uniform/ to the case's: a
        // processor's state is its own
        const fileName uniform(procTimePath(proci)/"uniform");
        if (Foam::type(uniform, false) == fileName::LINK)
        {
            rm(uniform);
        }
        mkDir(uniform);
        rm(uniform/mpmTime::recordName);
    }

    label nParticles = 0;
    const fileName lagrangian(runTime.timePath()/cloud::prefix);
    for (const fileName& cloudName : readDir(lagrangian, fileName::DIRECTORY))
    {
        nParticles += decomposeCloud(cloudName);
    }
    for
    (
        const fileName& file
      : readDir(runTime.timePath()/"uniform", fileName::FILE)
    )
    {
        if (file != mpmTime::recordName)
        {
            decomposeState(file);
        }
    }
    decomposeState(mpmTime::recordName);
    return nParticles;
}


// ************************************************************************* //
