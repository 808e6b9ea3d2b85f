/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "knownKeywords.H"
#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <vector>

// * * * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A declared dictionary: its entries (keyword, line) and what its readers
//  declared
struct declared
{
    std::vector<std::pair<word, label>> entries;
    std::set<word> keywords;
};


//- The declared dictionaries by name (file and scope)
std::map<std::string, declared>& registry()
{
    static std::map<std::string, declared> dicts;
    return dicts;
}


declared& record(const dictionary& dict)
{
    declared& d = registry()[dict.name()];
    for (const entry& e : dict)
    {
        const word key(e.keyword());
        const bool listed = std::any_of
        (
            d.entries.begin(), d.entries.end(),
            [&key](const std::pair<word, label>& x) { return x.first == key; }
        );
        if (!e.keyword().isPattern() && !listed)
        {
            d.entries.emplace_back(key, e.startLineNumber());
        }
    }
    return d;
}


//- The name of another declared dictionary of the same file that declares
//  keyword (a coefficient put beside its Coeffs dictionary), or empty
std::string readIn(const std::string& name, const word& keyword)
{
    const std::string file = name.substr(0, name.find('.', name.rfind('/')));
    for (const auto& other : registry())
    {
        if
        (
            other.first != name
         && other.first.compare(0, file.size(), file) == 0
         && other.second.keywords.count(keyword)
        )
        {
            return other.first;
        }
    }
    return std::string();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::knownKeywords::add
(
    const dictionary& dict,
    const wordList& keywords
)
{
    if (dict.name().empty())
    {
        return;
    }
    declared& d = record(dict);
    d.keywords.insert(keywords.begin(), keywords.end());
}


void Foam::knownKeywords::addSelector
(
    const dictionary& dict,
    const word& keyword,
    const wordList& models
)
{
    wordList keywords(1, keyword);
    for (const word& model : models)
    {
        keywords.append(model + "Coeffs");
    }
    add(dict, keywords);
}


Foam::label Foam::knownKeywords::warnUnknown(const fileName& caseDir)
{
    // The dictionaries of files in the case
    const std::string inCase = caseDir + "/";
    label nWarnings = 0;
    for (const auto& named : registry())
    {
        if (named.first.compare(0, inCase.size(), inCase) != 0)
        {
            continue;
        }
        const declared& d = named.second;
        const wordList allowed(d.keywords.begin(), d.keywords.end());
        for (const std::pair<word, label>& e : d.entries)
        {
            if (d.keywords.count(e.first))
            {
                continue;
            }
            ++nWarnings;
            const word near = nearest(e.first, allowed);
            OSstream& os = Warning
            (
                FUNCTION_NAME, __FILE__, __LINE__, named.first, e.second
            );
            os  << "unknown keyword " << e.first;
            if (!near.empty())
            {
                os  << " (did you mean " << near << "?)";
            }
            const std::string elsewhere = readIn(named.first, e.first);
            if (!elsewhere.empty())
            {
                os  << " (a keyword of " << elsewhere.c_str() << ')';
            }
            os  << ", ignored; allowed keywords:";
            for (const word& key : allowed)
            {
                os  << ' ' << key;
            }
            os  << endl;
        }
    }
    registry().clear();
    return nWarnings;
}


Foam::word Foam::knownKeywords::nearest
(
    const word& unknown,
    const wordList& allowed
)
{
    // Near: at most a quarter of the letters wrong, and at least 2 allowed
    const label tolerance = max(label(2), label(unknown.size()/4));
    word best;
    label bestDistance = tolerance + 1;
    for (const word& key : allowed)
    {
        const label d = distance(unknown, key);
        if (d < bestDistance)
        {
            best = key;
            bestDistance = d;
        }
    }
    return best;
}


Foam::label Foam::knownKeywords::distance
(
    const std::string& a,
    const std::string& b
)
{
    // Optimal string alignment: d[i][j] for the first i letters of a and
    // the first j of b
    const size_t n = a.size(), m = b.size();
    std::vector<std::vector<label>> d(n + 1, std::vector<label>(m + 1));
    auto same = [](const char x, const char y)
    {
        return std::tolower(static_cast<unsigned char>(x))
            == std::tolower(static_cast<unsigned char>(y));
    };
    for (size_t i = 0; i <= n; ++i)
    {
        d[i][0] = label(i);
    }
    for (size_t j = 0; j <= m; ++j)
    {
        d[0][j] = label(j);
    }
    for (size_t i = 1; i <= n; ++i)
    {
        for (size_t j = 1; j <= m; ++j)
        {
            d[i][j] = min
            (
                min(d[i - 1][j] + 1, d[i][j - 1] + 1),
                d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)
            );
            if
            (
                i > 1 && j > 1
             && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1])
            )
            {
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}


// ************************************************************************* //
