/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "particleCloudIO.H"
#include "fastOFstream.H"
#include "mpmTime.H"
#include "exactPrecision.H"
#include "speedLimit.H"
#include "particle.H"
#include "cloud.H"
#include "IOField.H"
#include "localIOdictionary.H"
#include "OFstream.H"
#include "IFstream.H"
#include "symmTensor.H"
#include "tensor.H"
#include "tensor2D.H"
#include <cstring>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleCloudIO, 0);

    // OpenFOAM defines no IOField of tensor2D: name it as the other fields
    typedef IOField<tensor2D> tensor2DIOField;
    defineTemplateTypeNameAndDebugWithName
    (
        tensor2DIOField,
        "tensor2DField",
        0
    );
}



// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::particleCloudIO::fileIO
(
    const word& name,
    const fileName& local
) const
{
    return IOobject
    (
        name,
        time().timeName(),
        local,
        grid_.mesh(),
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
}


bool Foam::particleCloudIO::writeCloudProperties() const
{
    // A dictionary (localIOdictionary reads it) written straight through a
    // fastOFstream: a dictionary's entry is formatted and parsed back when
    // it is added, slow for the bins' lists
    const IOobject io
    (
        fileIO("cloudProperties", "uniform"/cloud::prefix/this->name())
    );
    fastOFstream os(io.objectPath(), IOstream::ASCII);
    io.writeHeader(os, localIOdictionary::typeName);
    os.writeEntry("geometry", word("positions"));

    // The particles' bins, run-length coded (bins are in storage order): a
    // restart continues with them, bit for bit (particleArrays::sortByCell
    // keeps bins a particle has moved from)
    if (particles_.binned())
    {
        const std::vector<label>& cell = particles_.cell();
        DynamicList<label> cells, counts;
        for (label i = 0; i < particles_.size(); ++i)
        {
            if (!i || cell[i] != cell[i - 1])
            {
                cells.append(cell[i]);
                counts.append(0);
            }
            ++counts.last();
        }
        os.writeEntry("binCells", cells);
        os.writeEntry("binCounts", counts);
    }
    IOobject::writeEndDivider(os);
    os.flush();
    return os.good();
}


bool Foam::particleCloudIO::writePositions
(
    IOstream::streamFormat fmt
) const
{
    const IOobject io(fileIO("positions", cloud::prefix/this->name()));
    fastOFstream os(io.objectPath(), fmt);
    io.writeHeader(os, "Cloud<passiveParticle>");

    const gridGeometry& g = grid_.geometry();
    const labelList& meshCell = grid_.meshCell();
    const double* x = particles_.component(particleArrays::X);
    const double* y = particles_.component(particleArrays::Y);
    const double* z = particles_.component(particleArrays::Z);

    os  << particles_.size() << nl << token::BEGIN_LIST << nl;
    if (fmt == IOstream::ASCII)
    {
        for (label i = 0; i < particles_.size(); ++i)
        {
            os  << point(x[i], y[i], z[i]) << token::SPACE
                << meshCell[g.cellOf(x[i], y[i], z[i])] << nl;
        }
    }
    else
    {
        // As OpenFOAM's particle::writePosition and Cloud: per particle
        // '(', the position and cell of the 1706 layout, ')' and a newline;
        // made in memory and written as one block
        particle::positionsCompat1706 record;
        const std::size_t recordSize =
            offsetof(particle::positionsCompat1706, facei)
          - offsetof(particle::positionsCompat1706, position);
        const std::size_t lineSize = recordSize + 3;
        std::vector<char> lines(lineSize*particles_.size());
        for (label i = 0; i < particles_.size(); ++i)
        {
            record.position = point(x[i], y[i], z[i]);
            record.celli = meshCell[g.cellOf(x[i], y[i], z[i])];
            char* line = lines.data() + i*lineSize;
            line[0] = token::BEGIN_LIST;
            std::memcpy
            (
                line + 1, reinterpret_cast<const char*>(&record.position),
                recordSize
            );
            line[recordSize + 1] = token::END_LIST;
            line[recordSize + 2] = token::NL;
        }
        os.writeRaw(lines.data(), lines.size());
    }
    os  << token::END_LIST << nl;
    IOobject::writeEndDivider(os);
    os.flush();
    return os.good();
}


template<class Type>
bool Foam::particleCloudIO::writeTypedField
(
    const particleArrays::fieldInfo& f,
    IOstream::streamFormat fmt
) const
{
    fastWriteIO<IOField<Type>> fld
    (
        fileIO(f.name, cloud::prefix/this->name()),
        particles_.size()
    );
    for (direction c = 0; c < pTraits<Type>::nComponents; ++c)
    {
        const double* array = particles_.component(f.first + c);
        forAll(fld, i)
        {
            setComponent(fld[i], c) = array[i];
        }
    }

    return fastOFstream::writeObject
    (
        fld, fmt, IOstream::currentVersion, IOstream::UNCOMPRESSED
    );
}


bool Foam::particleCloudIO::writeField
(
    const particleArrays::fieldInfo& f,
    IOstream::streamFormat fmt
) const
{
    typedef particleArrays::fieldKind kind;
    switch (f.kind)
    {
        case kind::scalar: return writeTypedField<scalar>(f, fmt);
        case kind::vector: return writeTypedField<vector>(f, fmt);
        case kind::symmTensor: return writeTypedField<symmTensor>(f, fmt);
        case kind::tensor: return writeTypedField<tensor>(f, fmt);
        case kind::tensor2D: return writeTypedField<tensor2D>(f, fmt);
        case kind::internal: break;
    }
    return true;
}


template<class Type>
void Foam::particleCloudIO::readTypedField
(
    particleArrays& particles,
    const IOobject& io,
    const particleArrays::fieldInfo& f
)
{
    const IOField<Type> fld(io);
    if (fld.size() != particles.size())
    {
        FatalErrorInFunction
            << io.objectPath() << " has " << fld.size() << " values for "
            << particles.size() << " particles in positions"
            << exit(FatalError);
    }
    for (direction c = 0; c < pTraits<Type>::nComponents; ++c)
    {
        double* array = particles.component(f.first + c);
        forAll(fld, i)
        {
            array[i] = component(fld[i], c);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleCloudIO::particleCloudIO
(
    const word& cloudName,
    const particleArrays& particles,
    const mpmGrid& grid
)
:
    regIOobject
    (
        IOobject
        (
            cloudName,
            grid.mesh().time().timeName(),
            cloud::prefix,
            grid.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    particles_(particles),
    grid_(grid),
    format_(cloudFormat(grid.mesh().time()))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::IOstream::streamFormat Foam::particleCloudIO::cloudFormat
(
    const Time& runTime
)
{
    const dictionary& dict = runTime.controlDict();
    const word key("cloudFormat");
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return IOstream::BINARY;
    }
    const word name(e->get<word>());
    if (!IOstream::formatNames.found(name))
    {
        FatalIOErrorInFunction(e->stream())
            << key << " " << name << " is invalid; allowed: ascii or"
            << " binary (the default)" << exit(FatalIOError);
    }
    return IOstream::formatNames[name];
}


Foam::fileName Foam::particleCloudIO::cloudDir
(
    const fvMesh& mesh,
    const word& cloudName
)
{
    return mesh.time().timePath()/mesh.dbDir()/cloud::prefix/cloudName;
}


bool Foam::particleCloudIO::found
(
    const fvMesh& mesh,
    const word& cloudName,
    const word& timeName
)
{
    return isFile
    (
        mesh.time().path()/timeName/mesh.dbDir()/cloud::prefix/cloudName
       /"positions"
    );
}


void Foam::particleCloudIO::read
(
    particleArrays& particles,
    const objectRegistry& db,
    const word& cloudName,
    const word& timeName
)
{
    const IOobject posIO
    (
        "positions",
        timeName,
        cloud::prefix/cloudName,
        db,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    IFstream is(posIO.objectPath());
    if (!is.good())
    {
        FatalErrorInFunction
            << "cannot read particle positions " << posIO.objectPath()
            << exit(FatalError);
    }
    IOobject header(posIO);
    if (!header.readHeader(is))
    {
        FatalIOErrorInFunction(is)
            << "no FoamFile header in " << posIO.objectPath()
            << exit(FatalIOError);
    }

    // Cloud<passiveParticle> with geometry positions: N ( (x y z) celli ...)
    // in ASCII, or the position and cell of particle::positionsCompat1706
    // per particle in binary
    const label n = readLabel(is);
    if (n < 0 || !is.good())
    {
        FatalIOErrorInFunction(is)
            << "particle count " << n << " is invalid; allowed: >= 0"
            << exit(FatalIOError);
    }
    particles.clear();
    particles.append(n);
    double* x = particles.component(particleArrays::X);
    double* y = particles.component(particleArrays::Y);
    double* z = particles.component(particleArrays::Z);
    particle::positionsCompat1706 record;
    const std::size_t recordSize =
        offsetof(particle::positionsCompat1706, facei)
      - offsetof(particle::positionsCompat1706, position);
    is.readBegin("positions");
    for (label i = 0; i < n; ++i)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> record.position >> record.celli;
        }
        else
        {
            is.read(reinterpret_cast<char*>(&record.position), recordSize);
        }
        if (!is.good())
        {
            FatalIOErrorInFunction(is)
                << "particle " << i << " of the " << n << " the file"
                << " announces cannot be read" << exit(FatalIOError);
        }
        x[i] = record.position.x();
        y[i] = record.position.y();
        z[i] = record.position.z();
    }
    is.readEnd("positions");
    is.check(FUNCTION_NAME);

    typedef particleArrays::fieldKind kind;
    for (const particleArrays::fieldInfo& f : particles.fields())
    {
        if (f.kind == kind::internal || f.name == "positions")
        {
            continue;
        }
        const IOobject io
        (
            f.name,
            timeName,
            cloud::prefix/cloudName,
            db,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!isFile(io.objectPath()))
        {
            FatalErrorInFunction
                << "cloud " << cloudName << " at time " << timeName
                << " has no field " << f.name << ": " << io.objectPath()
                << " is missing. Every field of the cloud is required to"
                << " continue it (" << fieldNames(particles) << ")"
                << exit(FatalError);
        }
        switch (f.kind)
        {
            case kind::scalar: readTypedField<scalar>(particles, io, f); break;
            case kind::vector: readTypedField<vector>(particles, io, f); break;
            case kind::symmTensor:
                readTypedField<symmTensor>(particles, io, f); break;
            case kind::tensor: readTypedField<tensor>(particles, io, f); break;
            case kind::tensor2D:
                readTypedField<tensor2D>(particles, io, f); break;
            case kind::internal: break;
        }
    }
}


Foam::wordList Foam::particleCloudIO::fieldNames
(
    const particleArrays& particles
)
{
    wordList names;
    for (const particleArrays::fieldInfo& f : particles.fields())
    {
        if (f.kind != particleArrays::fieldKind::internal)
        {
            names.append(f.name);
        }
    }
    return names;
}


void Foam::particleCloudIO::checkRange
(
    const particleArrays& particles,
    const fileName& dir,
    const word& field,
    const scalar lo,
    const bool loIncluded,
    const scalar hi
)
{
    const particleArrays::fieldInfo& f = particles.field(field);
    const label nCmpt = particles.nComponents(f.kind);
    for (label i = 0; i < particles.size(); ++i)
    {
        // A scalar by its value, a vector by its magnitude (by its largest
        // component when that is out of range: its square may overflow)
        scalar v = particles.component(f.first)[i];
        if (nCmpt > 1)
        {
            scalar largest = 0;
            for (label c = 0; c < nCmpt; ++c)
            {
                const double a = std::abs(particles.component(f.first + c)[i]);
                largest = a > largest || std::isnan(a) ? a : largest;
            }
            v = largest;
            if (largest > 0 && largest <= hi)
            {
                scalar sumSqr = 0;
                for (label c = 0; c < nCmpt; ++c)
                {
                    const double r = particles.component(f.first + c)[i]/largest;
                    sumSqr += r*r;
                }
                v = largest*std::sqrt(sumSqr);
            }
        }
        if (!(loIncluded ? v >= lo : v > lo) || !(v <= hi))
        {
            const std::string name
            (
                nCmpt == 1 ? std::string(field) : "|" + field + "|"
            );
            FatalErrorInFunction
                << dir/field << ": particle " << i << " has " << name.c_str()
                << " = " << v << "; allowed: " << lo
                << (loIncluded ? " <= " : " < ") << name.c_str();
            if (hi < GREAT)
            {
                FatalError<< " <= " << hi;
            }
            FatalError<< ". The cloud is corrupt" << exit(FatalError);
        }
    }
}


void Foam::particleCloudIO::checkCloud
(
    const particleArrays& particles,
    const mpmGrid& grid,
    const fileName& dir
)
{
    // Every value finite
    for (const particleArrays::fieldInfo& f : particles.fields())
    {
        if (f.kind == particleArrays::fieldKind::internal)
        {
            continue;
        }
        for (label c = 0; c < particles.nComponents(f.kind); ++c)
        {
            const double* v = particles.component(f.first + c);
            for (label i = 0; i < particles.size(); ++i)
            {
                if (!std::isfinite(v[i]))
                {
                    FatalErrorInFunction
                        << dir/f.name << ": particle " << i << " has a"
                        << " value that is not finite (" << v[i] << ");"
                        << " allowed: finite values. The cloud is corrupt"
                        << exit(FatalError);
                }
            }
        }
    }

    // Inside the grid (a 2D grid: its x-y extent)
    const gridGeometry& g = grid.geometry();
    const double* x = particles.component(particleArrays::X);
    const double* y = particles.component(particleArrays::Y);
    const double* z = particles.component(particleArrays::Z);
    for (label i = 0; i < particles.size(); ++i)
    {
        if (!g.inside(x[i], y[i], z[i]))
        {
            FatalErrorInFunction
                << dir/"positions" << ": particle " << i << " lies outside"
                << " the mesh at " << point(x[i], y[i], z[i]) << "; allowed:"
                << " the mesh's box from "
                << point(g.lower(0), g.lower(1), g.lower(2)) << " to "
                << point(g.upper(0), g.upper(1), g.upper(2))
                << (grid.is2D() ? " in x and y" : "") << " m. The cloud is"
                << " corrupt or of another mesh" << exit(FatalError);
        }
    }

    checkRange(particles, dir, "m", 0, false, GREAT);
    checkRange(particles, dir, "V", 0, false, GREAT);
    checkRange(particles, dir, "U", 0, true, speedLimit::maximum);
}


void Foam::particleCloudIO::readBins
(
    particleArrays& particles,
    const mpmGrid& grid,
    const word& cloudName
)
{
    const localIOdictionary props
    (
        IOobject
        (
            "cloudProperties",
            grid.mesh().time().timeName(),
            "uniform"/cloud::prefix/cloudName,
            grid.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    if (!props.found("binCells"))
    {
        return;
    }
    const labelList cells(props.get<labelList>("binCells"));
    const labelList counts(props.get<labelList>("binCounts"));
    std::vector<label> bins;
    bins.reserve(particles.size());
    for (label k = 0; k < min(cells.size(), counts.size()); ++k)
    {
        if (counts[k] < 0 || label(bins.size()) + counts[k] > particles.size())
        {
            break;
        }
        bins.insert(bins.end(), counts[k], cells[k]);
    }
    if
    (
        cells.size() != counts.size()
     || !particles.setBins(grid.geometry(), bins)
    )
    {
        FatalIOErrorInFunction(props)
            << "binCells and binCounts do not bin the " << particles.size()
            << " particles of the cloud in the "
            << grid.geometry().nCellsTotal() << " cells of the mesh: the"
            << " cloud is corrupt or of another mesh" << exit(FatalIOError);
    }
}


bool Foam::particleCloudIO::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    // Restart state: the same doubles when read back, in ASCII too
    const exactPrecision exact;
    bool ok = writeCloudProperties() && writePositions(format_);
    for (const particleArrays::fieldInfo& f : particles_.fields())
    {
        if (f.name != "positions")
        {
            ok = writeField(f, format_) && ok;
        }
    }
    return ok;
}


bool Foam::particleCloudIO::readStartTime
(
    particleArrays& particles,
    const mpmGrid& grid,
    const word& cloudName
)
{
    const fvMesh& mesh = grid.mesh();
    const Time& runTime = mesh.time();
    const word timeName = runTime.timeName();
    const fileName dir(cloudDir(mesh, cloudName));
    switch (mpmTime::state(runTime.timePath()))
    {
        case mpmTime::directoryState::fresh:
        {
            return false;
        }
        case mpmTime::directoryState::incomplete:
        {
            FatalErrorInFunction
                << "time directory " << runTime.timePath() << " is"
                << " incomplete (no uniform/" << mpmTime::recordName
                << ": the run that wrote it was stopped while writing, or"
                << " the disk was full); its cloud " << cloudName
                << " cannot be used" << exit(FatalError);
            break;
        }
        case mpmTime::directoryState::complete:
        {
            break;
        }
    }
    if (!found(mesh, cloudName, timeName))
    {
        FatalErrorInFunction
            << "time directory " << runTime.timePath() << " was written"
            << " completely but has no cloud " << cloudName << " ("
            << dir/"positions" << " is missing): it cannot be"
            << " continued"
            << (
                   isDir(runTime.path()/"processor0")
                 ? "; the run ran decomposed: reconstructClouds puts its"
                   " processors' clouds there"
                 : ""
               )
            << exit(FatalError);
    }
    read(particles, mesh, cloudName, timeName);
    // (A processor of a decomposed run may hold none)
    const label nTotal = returnReduce(particles.size(), sumOp<label>());
    if (nTotal == 0)
    {
        FatalErrorInFunction
            << "cloud " << dir << " holds no particle: nothing to"
            << " simulate (all the mass had left the domain)"
            << exit(FatalError);
    }
    checkCloud(particles, grid, dir);
    readBins(particles, grid, cloudName);
    Info<< "Read " << nTotal << " particles of cloud " << cloudName
        << " at time " << timeName << endl;
    return true;
}


// ************************************************************************* //
