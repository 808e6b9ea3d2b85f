/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "ensembleMember.H"
#include "Time.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include <fstream>
#include <map>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::ensembleMember::statusType>
Foam::ensembleMember::statusTypeNames
({
    {statusType::notRun, "notRun"},
    {statusType::running, "running"},
    {statusType::done, "done"},
    {statusType::failed, "failed"},
    {statusType::interrupted, "interrupted"},
});


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The lines of a text file (none if it cannot be read)
std::vector<std::string> readLines(const Foam::fileName& file)
{
    std::vector<std::string> lines;
    std::ifstream is(file);
    std::string line;
    while (std::getline(is, line))
    {
        lines.push_back(line);
    }
    return lines;
}


//- The latest of the time directories in dir ("" if none)
Foam::fileName latestTimeDir(const Foam::fileName& dir)
{
    const Foam::instantList times(Foam::Time::findTimes(dir, "constant"));
    return times.empty() ? Foam::fileName() : dir/times.last().name();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::ensembleMember::appendEntries
(
    const fileName& file,
    const word& name,
    const entryList& entries
)
{
    std::ofstream os(file, std::ios::app);
    os  << "\n\n// dampmEnsemble: the entries of member " << name
        << " (ensemble/samples.csv)\n#inputMode merge\n";
    for (const auto& e : entries)
    {
        const wordList& path = e.first;
        os << '\n';
        std::string indent;
        for (label i = 0; i + 1 < path.size(); ++i)
        {
            os << indent << path[i] << '\n' << indent << "{\n";
            indent += "    ";
        }
        os << indent << path.last() << ' ' << e.second << ";\n";
        for (label i = path.size() - 2; i >= 0; --i)
        {
            indent.resize(indent.size() - 4);
            os << indent << "}\n";
        }
    }
    if (!os)
    {
        FatalErrorInFunction
            << "could not write " << file << exit(FatalError);
    }
}


void Foam::ensembleMember::readStatus()
{
    const fileName file(dir_/"ensembleStatus");
    if (!isFile(file))
    {
        return;
    }
    IFstream is(file);
    const dictionary dict(is);
    status_ = statusTypeNames.get("status", dict);
    exitCode_ = dict.get<label>("exitCode");
    runTime_ = dict.get<scalar>("runTime");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ensembleMember::ensembleMember
(
    const fileName& baseCase,
    const word& name
)
:
    baseCase_(baseCase),
    name_(name),
    dir_(baseCase/"ensemble"/("member." + name)),
    status_(statusType::notRun),
    exitCode_(0),
    runTime_(0)
{
    readStatus();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::ensembleMember::exists() const
{
    return isDir(dir_);
}


void Foam::ensembleMember::create
(
    const std::vector<ensembleSample::setting>& settings
) const
{
    const fileName tmp(dir_ + ".tmp");
    if (isDir(tmp))
    {
        rmDir(tmp);
    }
    mkDir(tmp);
    cp(baseCase_/"system", tmp);
    cp(baseCase_/"constant", tmp);
    rm(tmp/"system"/"ensembleDict");

    IFstream controlDictFile(baseCase_/"system"/"controlDict");
    const dictionary controlDict(controlDictFile);
    const word startTime
    (
        Time::timeName(controlDict.getOrDefault<scalar>("startTime", 0))
    );
    if (isDir(baseCase_/startTime))
    {
        cp(baseCase_/startTime, tmp);
    }

    // The entries by file, in the sample's order; the member starts from
    // its latest time
    std::map<fileName, entryList> byFile;
    for (const ensembleSample::setting& s : settings)
    {
        fileName file;
        wordList keys;
        ensembleSample::splitEntryPath(s.path, tmp, file, keys);
        byFile[file].emplace_back(keys, s.value);
    }
    byFile[tmp/"system"/"controlDict"].emplace_back
    (
        wordList({"startFrom"}), "latestTime"
    );
    for (const auto& f : byFile)
    {
        appendEntries(f.first, name_, f.second);
    }

    if (!mv(tmp, dir_))
    {
        FatalErrorInFunction
            << "could not rename " << tmp << " to " << dir_
            << exit(FatalError);
    }
}


void Foam::ensembleMember::setStatus
(
    const statusType status,
    const label exitCode,
    const scalar addedRunTime
)
{
    status_ = status;
    exitCode_ = exitCode;
    runTime_ += addedRunTime;

    const fileName file(dir_/"ensembleStatus");
    {
        OFstream os(file + ".tmp");
        os.writeEntry("status", statusTypeNames[status_]);
        os.writeEntry("exitCode", exitCode_);
        os.writeEntry("runTime", runTime_);
        if (!os.good())
        {
            FatalErrorInFunction
                << "could not write " << os.name() << exit(FatalError);
        }
    }
    mv(file + ".tmp", file);
}


Foam::fileName Foam::ensembleMember::mapsDir() const
{
    return latestTimeDir(dir_/"postProcessing"/"hazardMaps");
}


bool Foam::ensembleMember::mapsAtEnd(string& why) const
{
    IFstream is(dir_/"system"/"controlDict");
    const scalar endTime = dictionary(is).get<scalar>("endTime");
    const fileName maps(mapsDir());
    const scalar last = maps.empty() ? -GREAT : readScalar(maps.name());
    // At endTime, or the step past it that ends the run when endTime is
    // no write time
    if (last >= endTime - 1e-5*max(mag(endTime), 1e-4))
    {
        return true;
    }
    why =
        "its last hazard maps are "
      + (maps.empty() ? "none" : "of time " + maps.name())
      + ", not of endTime " + Foam::name(endTime)
      + " (the run ended before it)";
    return false;
}


Foam::scalar Foam::ensembleMember::finalVolume
(
    const word& application
) const
{
    const fileName start
    (
        latestTimeDir(dir_/"postProcessing"/application)
    );
    if (start.empty())
    {
        return -1;
    }
    std::vector<std::string> header;
    std::string last;
    for (const std::string& line : readLines(start/"summary.dat"))
    {
        if (line.empty())
        {
            continue;
        }
        if (line[0] == '#')
        {
            header.clear();
            std::istringstream is(line.substr(1));
            for (std::string column; is >> column;)
            {
                header.push_back(column);
            }
        }
        else
        {
            last = line;
        }
    }
    std::istringstream row(last);
    for (const std::string& column : header)
    {
        double value;
        if (!(row >> value))
        {
            break;
        }
        if (column == "mass")
        {
            IFstream is(dir_/"constant"/"dampmProperties");
            return value/dictionary(is).get<scalar>("rho");
        }
    }
    return -1;
}


Foam::string Foam::ensembleMember::failure(const word& application) const
{
    const std::vector<std::string> lines
    (
        readLines(dir_/("log." + application))
    );
    std::string message;
    for (size_t i = 0; i < lines.size(); ++i)
    {
        if (lines[i].find("FOAM FATAL") == std::string::npos)
        {
            continue;
        }
        for (size_t j = i + 1; j < lines.size(); ++j)
        {
            if (lines[j].find_first_not_of(" \t") != std::string::npos)
            {
                message = lines[j];
                break;
            }
        }
    }
    return message;
}


// ************************************************************************* //
