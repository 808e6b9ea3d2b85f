/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "backgroundFileOperation.H"
#include "backgroundWriter.H"
#include "fastOFstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(backgroundFileOperation, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::backgroundFileOperation::backgroundFileOperation()
:
    fileOperations::uncollatedFileOperation(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::backgroundFileOperation::install()
{
    if (fileHandler().type() != fileOperations::uncollatedFileOperation::typeName)
    {
        return;
    }
    autoPtr<fileOperation> handler(new backgroundFileOperation());
    fileHandler(handler);
}


bool Foam::backgroundFileOperation::writeObject
(
    const regIOobject& io,
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    if (!backgroundWriter::collecting())
    {
        return
            fileOperations::uncollatedFileOperation::writeObject
            (
                io, fmt, ver, cmp, valid
            );
    }
    return !valid || fastOFstream::writeObject(io, fmt, ver, cmp);
}


// ************************************************************************* //
