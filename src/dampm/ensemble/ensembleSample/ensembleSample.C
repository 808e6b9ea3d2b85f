/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "ensembleSample.H"
#include "samplingDesign.H"
#include "rankCorrelation.H"
#include "knownKeywords.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "exactPrecision.H"
#include "primitiveEntry.H"
#include "OStringStream.H"
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::ensembleSample::samplingType>
Foam::ensembleSample::samplingTypeNames
({
    {samplingType::latinHypercube, "latinHypercube"},
    {samplingType::monteCarlo, "monteCarlo"},
    {samplingType::fullFactorial, "fullFactorial"},
});


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The parts of a path between its slashes
std::vector<std::string> pathParts(const std::string& path)
{
    std::vector<std::string> parts;
    std::istringstream is(path);
    std::string part;
    while (std::getline(is, part, '/'))
    {
        if (!part.empty())
        {
            parts.push_back(part);
        }
    }
    return parts;
}


//- The values in dict and their paths ("a/b/c" for a { b { c 1; } }), as
//  OpenFOAM reads a quoted keyword "a/b/c": into nested dictionaries
typedef std::vector<std::pair<std::string, const Foam::entry*>> valueList;

void collectValues
(
    const Foam::dictionary& dict,
    const std::string& prefix,
    valueList& values
)
{
    for (const Foam::entry& e : dict)
    {
        const std::string path = prefix + e.keyword();
        if (e.isDict())
        {
            collectValues(e.dict(), path + "/", values);
        }
        else
        {
            values.emplace_back(path, &e);
        }
    }
}


//- A number as OpenFOAM reads it back exactly: 17 significant digits
std::string numberText(const double x)
{
    const Foam::exactPrecision digits;
    Foam::OStringStream os;
    os << x;
    return os.str();
}


//- An entry's value as written, every number read back exactly
std::string valueText(const Foam::entry& e)
{
    const Foam::exactPrecision digits;
    Foam::OStringStream os;
    Foam::dynamicCast<const Foam::primitiveEntry>(e).write(os, true);
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::ensembleSample::samplingType Foam::ensembleSample::readSampling
(
    const dictionary& dict
)
{
    const word name(dict.getOrDefault<word>("sampling", "latinHypercube"));
    if (!samplingTypeNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "sampling " << name << " is invalid; allowed: sampling "
            << samplingTypeNames.sortedToc() << exit(FatalIOError);
    }
    const samplingType sampling = samplingTypeNames[name];
    if (sampling == samplingType::fullFactorial && dict.found("correlations"))
    {
        FatalIOErrorInFunction(dict)
            << "correlations are not possible with sampling fullFactorial,"
            << " which takes every combination of levels once; allowed:"
            << " correlations with sampling latinHypercube or monteCarlo"
            << exit(FatalIOError);
    }
    return sampling;
}


void Foam::ensembleSample::checkScenarios
(
    const word& name,
    const dictionary& dict,
    const parameterDistribution& distribution
) const
{
    if (!distribution.nValues())
    {
        FatalIOErrorInFunction(dict)
            << "parameter " << name << " has scenarios but"
            << " distribution " << dict.get<word>("distribution")
            << "; allowed: distribution discrete with scenarios"
            << exit(FatalIOError);
    }
    for (const entry& scenario : dict.subDict("scenarios"))
    {
        if (!scenario.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "scenario " << scenario.keyword() << " is not a"
                << " dictionary; allowed: scenarios { <name> {"
                << " \"<file>/<dictionary path>\" <value>; ... } }"
                << exit(FatalIOError);
        }
        valueList values;
        collectValues(scenario.dict(), "", values);
        if (values.empty())
        {
            FatalIOErrorInFunction(scenario.dict())
                << "scenario " << scenario.keyword() << " sets no"
                << " entry; allowed: \"<file>/<dictionary path>\""
                << " <value>; ..." << exit(FatalIOError);
        }
        for (const auto& value : values)
        {
            checkEntryPath
            (
                scenario.dict(), scenario.keyword(), value.first, caseDir_
            );
        }
    }
}


Foam::label Foam::ensembleSample::readLevels
(
    const dictionary& dict,
    const parameterDistribution& distribution
) const
{
    label levels = distribution.nValues();
    if (!levels)
    {
        levels = dict.get<label>("levels");
        if (levels < 1)
        {
            FatalIOErrorInFunction(dict)
                << "levels = " << levels << " is invalid; allowed:"
                << " levels >= 1" << exit(FatalIOError);
        }
    }
    return levels;
}


void Foam::ensembleSample::readParameters()
{
    const dictionary& parameters = dict_.subDict("parameters");
    for (const entry& e : parameters)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(parameters)
                << e.keyword() << " is not a dictionary; allowed: one"
                << " sub-dictionary per parameter" << exit(FatalIOError);
        }
        const dictionary& dict = e.dict();
        knownKeywords::add(dict, {"entry", "levels"});

        if (dict.found("entry") == dict.found("scenarios"))
        {
            FatalIOErrorInFunction(dict)
                << "parameter " << e.keyword() << " needs either entry or"
                << " scenarios; allowed: entry \"<file>/<dictionary path>\";"
                << " or distribution discrete with scenarios { <name> {"
                << " \"<file>/<dictionary path>\" <value>; ... } ... }"
                << exit(FatalIOError);
        }

        autoPtr<parameterDistribution> distribution
        (
            parameterDistribution::New(dict)
        );
        if (dict.found("entry"))
        {
            checkEntryPath
            (
                dict, "entry", dict.get<string>("entry"), caseDir_
            );
        }
        else
        {
            checkScenarios(e.keyword(), dict, *distribution);
        }

        const label levels =
            sampling_ == samplingType::fullFactorial
          ? readLevels(dict, *distribution)
          : 0;

        names_.append(e.keyword());
        distributions_.append(distribution.ptr());
        levels_.append(levels);
    }
    if (names_.empty())
    {
        FatalIOErrorInFunction(parameters)
            << "no parameters; allowed: at least one sub-dictionary"
            << " <name> { entry ...; distribution ...; }"
            << exit(FatalIOError);
    }
}


Foam::label Foam::ensembleSample::readMembers() const
{
    knownKeywords::add(dict_, {"members"});

    if (sampling_ != samplingType::fullFactorial)
    {
        const label n = dict_.get<label>("members");
        if (n < 1 || n > maxMembers)
        {
            FatalIOErrorInFunction(dict_)
                << "members = " << n << " is invalid; allowed: 1 <= members"
                << " <= " << maxMembers << exit(FatalIOError);
        }
        return n;
    }

    // The product in double: no overflow before the check
    double product = 1;
    for (const label n : levels_)
    {
        product *= n;
    }
    if (product > maxMembers)
    {
        FatalIOErrorInFunction(dict_)
            << "the full factorial's levels " << levels_ << " make " << product
            << " members; allowed: at most " << maxMembers
            << exit(FatalIOError);
    }
    const label n = label(product);
    if (dict_.found("members") && dict_.get<label>("members") != n)
    {
        FatalIOErrorInFunction(dict_)
            << "members = " << dict_.get<label>("members") << " but the"
            << " full factorial's levels " << levels_ << " make " << n
            << " members; allowed: members " << n << ", or no members"
            << exit(FatalIOError);
    }
    return n;
}


void Foam::ensembleSample::sample()
{
    const label nParameters = names_.size();
    values_.assign(nParameters, std::vector<double>(nMembers_));

    if (sampling_ == samplingType::fullFactorial)
    {
        const std::vector<labelList> index
        (
            samplingDesign::fullFactorial(levels_)
        );
        for (label parami = 0; parami < nParameters; ++parami)
        {
            for (label memberi = 0; memberi < nMembers_; ++memberi)
            {
                values_[parami][memberi] = distributions_[parami].level
                (
                    index[parami][memberi], levels_[parami]
                );
            }
        }
        return;
    }

    knownKeywords::add(dict_, {"seed"});
    const label seed = dict_.get<label>("seed");
    if (seed < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "seed = " << seed << " is invalid; allowed: an integer"
            << " 0 <= seed <= " << labelMax << exit(FatalIOError);
    }
    const rankCorrelation correlation(dict_, names_, nMembers_);
    correlations_ = correlation.pairs();

    std::mt19937_64 rng(seed);
    samplingDesign::probabilities u
    (
        sampling_ == samplingType::latinHypercube
      ? samplingDesign::latinHypercube(rng, nParameters, nMembers_)
      : samplingDesign::monteCarlo(rng, nParameters, nMembers_)
    );
    correlation.induce(rng, u);
    for (label parami = 0; parami < nParameters; ++parami)
    {
        for (label memberi = 0; memberi < nMembers_; ++memberi)
        {
            values_[parami][memberi] =
                distributions_[parami].value(u[parami][memberi]);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ensembleSample::ensembleSample
(
    const dictionary& ensembleDict,
    const fileName& caseDir
)
:
    dict_(ensembleDict),
    caseDir_(caseDir),
    sampling_(readSampling(ensembleDict)),
    nMembers_(0)
{
    knownKeywords::add(dict_, {"sampling", "parameters"});
    readParameters();
    nMembers_ = readMembers();
    sample();
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::label Foam::ensembleSample::splitEntryPath
(
    const string& path,
    const fileName& caseDir,
    fileName& file,
    wordList& keys
)
{
    const std::vector<std::string> parts(pathParts(path));

    // The file: the longest leading part of the path that is a file
    size_t nFile = parts.size();
    for (; nFile > 0; --nFile)
    {
        file = caseDir;
        for (size_t i = 0; i < nFile; ++i)
        {
            file = file/parts[i];
        }
        if (isFile(file))
        {
            break;
        }
    }
    keys.clear();
    for (size_t i = nFile; nFile && i < parts.size(); ++i)
    {
        keys.append(word(parts[i]));
    }
    return nFile;
}


void Foam::ensembleSample::checkEntryPath
(
    const dictionary& dict,
    const word& keyword,
    const string& path,
    const fileName& caseDir
)
{
    fileName file;
    wordList keys;
    const label nFile = splitEntryPath(path, caseDir, file, keys);
    const std::string example =
        "; allowed: \"<file>/<dictionary path>\" of an existing entry, e.g."
        " \"constant/dampmProperties/VoellmyCoeffs/xi\"";
    if (keys.empty())
    {
        FatalIOErrorInFunction(dict)
            << keyword << " \"" << path.c_str() << "\": "
            << (nFile ? "names a file, not an entry in it" : "no leading part"
                " of it is a file of the case " + caseDir).c_str()
            << example.c_str() << exit(FatalIOError);
    }

    if (file.relative(caseDir) == "system/blockMeshDict")
    {
        FatalIOErrorInFunction(dict)
            << keyword << " \"" << path.c_str() << "\": the members copy the"
            << " base case's mesh, so an entry of system/blockMeshDict would"
            << " not change it" << example.c_str() << " in another file"
            << exit(FatalIOError);
    }

    IFstream is(file);
    const dictionary fileDict(is);
    const dictionary* scope = &fileDict;
    std::string where = file.relative(caseDir);
    forAll(keys, i)
    {
        const word& part = keys[i];
        const entry* ePtr = scope->findEntry(part, keyType::LITERAL);
        const bool last = i + 1 == keys.size();
        if (!ePtr || ePtr->isDict() == last)
        {
            FatalIOErrorInFunction(dict)
                << keyword << " \"" << path.c_str() << "\": " << where.c_str()
                << (ePtr ? " has the dictionary " : " has no ") << part
                << (ePtr ? ", not a value" : "") << " (it has "
                << scope->toc() << ")" << example.c_str()
                << exit(FatalIOError);
        }
        if (!last)
        {
            scope = &ePtr->dict();
            where += "/" + part;
        }
    }
}


Foam::word Foam::ensembleSample::memberName
(
    const label memberi,
    const label nMembers
)
{
    const int width = std::max<int>(4, std::to_string(nMembers - 1).size());
    std::ostringstream os;
    os << std::setw(width) << std::setfill('0') << memberi;
    return os.str();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<Foam::ensembleSample::setting> Foam::ensembleSample::settings
(
    const label memberi
) const
{
    std::vector<setting> entries;
    const dictionary& parameters = dict_.subDict("parameters");
    forAll(names_, parami)
    {
        const dictionary& dict = parameters.subDict(names_[parami]);
        const double value = values_[parami][memberi];
        if (dict.found("entry"))
        {
            entries.push_back({dict.get<string>("entry"), numberText(value)});
            continue;
        }
        const label scenarioi = label(value);
        label i = 0;
        for (const entry& scenario : dict.subDict("scenarios"))
        {
            if (i++ == scenarioi)
            {
                valueList values;
                collectValues(scenario.dict(), "", values);
                for (const auto& v : values)
                {
                    entries.push_back({v.first, valueText(*v.second)});
                }
            }
        }
    }
    return entries;
}


std::string Foam::ensembleSample::csv() const
{
    std::ostringstream os;
    os << "member";
    for (const word& name : names_)
    {
        os << ',' << name;
    }
    os << '\n' << std::setprecision(17);
    for (label memberi = 0; memberi < nMembers_; ++memberi)
    {
        os << memberName(memberi, nMembers_);
        for (const std::vector<double>& v : values_)
        {
            os << ',' << v[memberi];
        }
        os << '\n';
    }
    return os.str();
}


void Foam::ensembleSample::write(const fileName& file) const
{
    mkDir(file.path());
    std::ofstream os(file);
    os << csv();
    if (!os)
    {
        FatalErrorInFunction
            << "could not write " << file << exit(FatalError);
    }
}


void Foam::ensembleSample::report(Ostream& os) const
{
    os  << samplingTypeNames[sampling_] << " sample of " << nMembers_
        << " members" << nl
        << "parameter            min              mean             max" << nl;
    forAll(names_, parami)
    {
        const std::vector<double>& v = values_[parami];
        double sum = 0;
        for (const double x : v)
        {
            sum += x;
        }
        std::ostringstream line;
        line<< std::left << std::setw(20) << names_[parami] << ' '
            << std::setprecision(8)
            << std::setw(16) << *std::min_element(v.begin(), v.end()) << ' '
            << std::setw(16) << sum/v.size() << ' '
            << *std::max_element(v.begin(), v.end());
        os  << line.str().c_str() << nl;
    }
    if (correlations_.empty())
    {
        return;
    }
    os  << nl << "rank correlation                 target           sample"
        << nl;
    for (const rankCorrelation::pair& p : correlations_)
    {
        std::ostringstream line;
        line<< std::left << std::setw(32)
            << names_[p.a] + ' ' + names_[p.b] << ' '
            << std::setprecision(8) << std::setw(16) << p.rho << ' '
            << rankCorrelation::spearman(values_[p.a], values_[p.b]);
        os  << line.str().c_str() << nl;
    }
}


// ************************************************************************* //
