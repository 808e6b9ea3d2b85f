/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "ensembleSummary.H"
#include "OSspecific.H"
#include "exactPrecision.H"
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::ensembleSummary::write
(
    const fileName& file,
    const ensembleSample& sample,
    const PtrList<ensembleMember>& members,
    const List<ensembleMaps::memberFigures>& figures,
    const word& application
)
{
    std::istringstream rows(sample.csv());
    std::string row;
    std::getline(rows, row);

    mkDir(file.path());
    std::ofstream os(file);
    os  << row << ",status,runTime,runOutLength,affectedArea,maxSpeed,"
        << "depositVolume\n";
    label donei = 0;
    for (const ensembleMember& member : members)
    {
        std::getline(rows, row);
        os  << row << ','
            << ensembleMember::statusTypeNames[member.status()] << ','
            << exactText(member.runTime());
        if (member.status() == ensembleMember::statusType::done)
        {
            const ensembleMaps::memberFigures& f = figures[donei++];
            const scalar volume = member.finalVolume(application);
            os  << ',' << exactText(f.runOutLength) << ','
                << exactText(f.affectedArea) << ',' << exactText(f.maxSpeed)
                << ',';
            if (volume >= 0)
            {
                os  << exactText(volume);
            }
        }
        else
        {
            os  << ",,,,";
        }
        os  << '\n';
    }
    if (!os)
    {
        FatalErrorInFunction
            << "could not write " << file << exit(FatalError);
    }
}


// ************************************************************************* //
