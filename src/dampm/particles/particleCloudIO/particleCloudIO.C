/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "particleCloudIO.H"
#include "cloud.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "IFstream.H"
#include "symmTensor.H"
#include "tensor.H"
#include "tensor2D.H"

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

    //- Fewest significant digits for particle data
    static const unsigned minParticlePrecision = 12;
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


void Foam::particleCloudIO::writeCloudProperties() const
{
    IOdictionary props
    (
        fileIO("cloudProperties", "uniform"/cloud::prefix/this->name())
    );
    props.add("geometry", word("positions"));
    props.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
}


void Foam::particleCloudIO::writePositions() const
{
    const IOobject io(fileIO("positions", cloud::prefix/this->name()));
    mkDir(io.path());
    OFstream os(io.objectPath());
    os.precision(max(IOstream::defaultPrecision(), minParticlePrecision));
    io.writeHeader(os, "Cloud<passiveParticle>");

    const gridGeometry& g = grid_.geometry();
    const labelList& meshCell = grid_.meshCell();
    const double* x = particles_.column(particleArrays::X);
    const double* y = particles_.column(particleArrays::Y);
    const double* z = particles_.column(particleArrays::Z);

    os  << particles_.size() << nl << token::BEGIN_LIST << nl;
    for (label i = 0; i < particles_.size(); ++i)
    {
        os  << point(x[i], y[i], z[i]) << token::SPACE
            << meshCell[g.cellOf(x[i], y[i], z[i])] << nl;
    }
    os  << token::END_LIST << nl;
    IOobject::writeEndDivider(os);
}


template<class Type>
void Foam::particleCloudIO::writeTypedField
(
    const particleArrays::fieldInfo& f
) const
{
    IOField<Type> fld
    (
        fileIO(f.name, cloud::prefix/this->name()),
        particles_.size()
    );
    for (direction c = 0; c < pTraits<Type>::nComponents; ++c)
    {
        const double* col = particles_.column(f.first + c);
        forAll(fld, i)
        {
            setComponent(fld[i], c) = col[i];
        }
    }

    const unsigned oldPrecision = IOstream::defaultPrecision();
    IOstream::defaultPrecision(max(oldPrecision, minParticlePrecision));
    fld.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
    IOstream::defaultPrecision(oldPrecision);
}


void Foam::particleCloudIO::writeField
(
    const particleArrays::fieldInfo& f
) const
{
    typedef particleArrays::fieldKind kind;
    switch (f.kind)
    {
        case kind::scalar: writeTypedField<scalar>(f); break;
        case kind::vector: writeTypedField<vector>(f); break;
        case kind::symmTensor: writeTypedField<symmTensor>(f); break;
        case kind::tensor: writeTypedField<tensor>(f); break;
        case kind::tensor2D: writeTypedField<tensor2D>(f); break;
        case kind::internal: break;
    }
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
        double* col = particles.column(f.first + c);
        forAll(fld, i)
        {
            col[i] = component(fld[i], c);
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
    grid_(grid)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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


Foam::wordList Foam::particleCloudIO::read
(
    particleArrays& particles,
    const fvMesh& mesh,
    const word& cloudName,
    const word& timeName
)
{
    const IOobject posIO
    (
        "positions",
        timeName,
        cloud::prefix/cloudName,
        mesh,
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

    // Format of Cloud<passiveParticle> in geometry positions: (x y z) celli
    const label n = readLabel(is);
    particles.clear();
    particles.append(n);
    double* x = particles.column(particleArrays::X);
    double* y = particles.column(particleArrays::Y);
    double* z = particles.column(particleArrays::Z);
    is.readBegin("positions");
    for (label i = 0; i < n; ++i)
    {
        point p;
        label celli;
        is >> p >> celli;
        x[i] = p.x();
        y[i] = p.y();
        z[i] = p.z();
    }
    is.readEnd("positions");
    is.check(FUNCTION_NAME);

    wordList missing;
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
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!isFile(io.objectPath()))
        {
            missing.append(f.name);
            continue;
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
    return missing;
}


bool Foam::particleCloudIO::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    writeCloudProperties();
    writePositions();
    for (const particleArrays::fieldInfo& f : particles_.fields())
    {
        if (f.name != "positions")
        {
            writeField(f);
        }
    }
    return true;
}


bool Foam::particleCloudIO::readStartTime
(
    particleArrays& particles,
    const fvMesh& mesh,
    const word& cloudName,
    wordList& missing
)
{
    const word timeName = mesh.time().timeName();
    if (!found(mesh, cloudName, timeName))
    {
        return false;
    }
    missing = read(particles, mesh, cloudName, timeName);
    Info<< "Read " << particles.size() << " particles of cloud " << cloudName
        << " at time " << timeName << endl;
    if (!missing.empty())
    {
        WarningInFunction
            << "fields " << missing << " of cloud " << cloudName
            << " are missing at time " << timeName
            << ": started from their initial values" << endl;
    }
    return true;
}


// ************************************************************************* //
