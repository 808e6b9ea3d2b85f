/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    basalTerms of the bed friction and rheology models: the solver zeroes
    and scatters only the basal coefficients (s, k1, k2) that the selected
    models name, and hands the models a null pointer for the others. So
    every model must add to exactly the coefficients it names: each named
    one changes at every column, and the others are not touched.

\*---------------------------------------------------------------------------*/

#include "bedFrictionModel.H"
#include "rheologyModel.H"
#include "columnArrays.H"
#include <gtest/gtest.h>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace Foam;

namespace
{

//- Columns of different heights, areas and slopes whose coefficients all
//  start at a sentinel, after one addResistance of a model naming terms:
//  expect the named coefficients changed at every column and the others
//  the sentinel to the bit
template<class Model>
void expectAddsToItsTerms(const Model& model, const std::string& what)
{
    const double sentinel = 7.25;
    columnArrays col({0.5, 2, 1e-6}, {1, 3, 0.25}, {1, 0.8, 0.5}, 1800);
    for (std::vector<double>* c : {&col.s, &col.k1, &col.k2})
    {
        c->assign(col.m.size(), sentinel);
    }
    model.addResistance(col.view());

    const unsigned terms = model.basalTerms();
    const std::vector<double>* coefficients[3] = {&col.s, &col.k1, &col.k2};
    const unsigned bits[3] = {basalTerm::s, basalTerm::k1, basalTerm::k2};
    const char* names[3] = {"s", "k1", "k2"};
    for (int k = 0; k < 3; ++k)
    {
        for (size_t i = 0; i < col.m.size(); ++i)
        {
            const double c = (*coefficients[k])[i];
            if (terms & bits[k])
            {
                EXPECT_NE(c, sentinel) << what << ": " << names[k] << i;
            }
            else
            {
                EXPECT_EQ(c, sentinel) << what << ": " << names[k] << i;
            }
        }
    }
}


//- expectAddsToItsTerms for each model of a family, by its type and
//  coefficients under keyword; every type the family can select is among
//  them (a model added later is tested too)
template<class Family>
void expectEachAddsToItsTerms
(
    const std::string& keyword,
    const std::vector<std::pair<std::string, std::string>>& models
)
{
    std::set<std::string> tested;
    for (const auto& [type, coeffs] : models)
    {
        expectAddsToItsTerms
        (
            Family::New(modelDict(keyword, type, coeffs))(),
            type + " " + coeffs
        );
        tested.insert(type);
    }
    for (const word& type : Family::dictionaryConstructorTablePtr_->sortedToc())
    {
        EXPECT_TRUE(tested.count(type)) << keyword << " " << type;
    }
}

} // End anonymous namespace


TEST(basalTerms, EveryBedFrictionAddsToExactlyTheTermsItNames)
{
    expectEachAddsToItsTerms<bedFrictionModel>
    (
        "bedFriction",
        {
            {"none", ""},
            {"Coulomb", "phi 20;"},
            {"Coulomb", "phi 20; pA 50;"},
            {"Voellmy", "phi 20; xi 500;"}
        }
    );
    EXPECT_EQ
    (
        bedFrictionModel::New
        (
            modelDict("bedFriction", "Voellmy", "phi 20; xi 500;")
        )->basalTerms(),
        basalTerm::s | basalTerm::k2
    );
}


TEST(basalTerms, EveryRheologyAddsToExactlyTheTermsItNames)
{
    expectEachAddsToItsTerms<rheologyModel>
    (
        "rheology",
        {
            {"inviscid", ""},
            {"Newtonian", "mu 30;"},
            {"Newtonian", "mu 30; basalShear true;"},
            {"Bingham", "mu 50; tauY 2000; shearModulus 0;"},
            {"Bingham", "mu 50; tauY 2000; basalShear true; shearModulus 0;"},
            {"Bingham", "mu 50; tauY 2000; basalShear true;"}
        }
    );
    EXPECT_EQ
    (
        rheologyModel::New
        (
            modelDict("rheology", "Bingham",
                "mu 50; tauY 2000; basalShear true; shearModulus 0;")
        )->basalTerms(),
        basalTerm::s | basalTerm::k1
    );
}


// ************************************************************************* //
