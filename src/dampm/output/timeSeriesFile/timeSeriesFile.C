/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "timeSeriesFile.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::timeSeriesFile::timeSeriesFile
(
    const Time& runTime,
    const word& name,
    const word& file,
    const wordList& columns,
    const wordList& description,
    const word& timeName
)
:
    columns_(columns),
    path_
    (
        runTime.globalPath()/"postProcessing"/name
       /(
            timeName.empty()
          ? runTime.timeName(runTime.startTime().value())
          : timeName
        )/(file + ".dat")
    )
{
    // Written once, by the master, on a decomposed run as on a serial one
    if (!Pstream::master())
    {
        return;
    }
    os_.reset(new fastOFstream(path_));
    os_->precision(16);

    fastOFstream& os = *os_;
    os  << "# " << name << ": " << file << nl;
    for (const word& line : description)
    {
        os  << "# " << line.c_str() << nl;
    }
    os  << '#';
    for (const word& c : columns_)
    {
        os  << ' ' << c;
    }
    os  << endl;
    checkWritten();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::timeSeriesFile::checkWritten() const
{
    if (!os_->good() || !os_->stdStream().good())
    {
        FatalErrorInFunction
            << "cannot write " << os_->name() << " (disk full, or the"
            << " directory not writable?): the run stops"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::timeSeriesFile::write(const UList<scalar>& row)
{
    if (!os_)
    {
        return;
    }
    if (row.size() != columns_.size())
    {
        FatalErrorInFunction
            << row.size() << " values for the " << columns_.size()
            << " columns of " << os_->name() << abort(FatalError);
    }
    // Formatted first and written in one piece: a failed write (a full
    // disk) comes to checkWritten, not to OpenFOAM's own stream check
    const int precision = os_->precision();
    char buffer[fastOFstream::numberSize];
    line_.clear();
    forAll(row, i)
    {
        if (i)
        {
            line_ += ' ';
        }
        line_.append
        (
            buffer, fastOFstream::numberText(buffer, row[i], precision)
        );
    }
    line_ += '\n';
    std::ostream& os = os_->stdStream();
    os.write(line_.data(), line_.size());
    os.flush();
    checkWritten();
}


// ************************************************************************* //
