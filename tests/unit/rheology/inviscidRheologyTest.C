/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    inviscidRheology: selected by 'inviscid' and when rheology is not given,
    inactive (the solver computes no stress), no viscosity for the time step,
    and, were it called, a zero stress whatever the strain rate and the old
    stress, and no basal resistance.

\*---------------------------------------------------------------------------*/

#include "rheologyModel.H"
#include "columnArrays.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(inviscidRheology, SelectedByDefaultInactiveWithZeroStress)
{
    IStringStream empty("rho 1000;");
    for (const dictionary& dict : {modelDict("rheology", "inviscid", ""),
         dictionary(empty)})
    {
        const autoPtr<rheologyModel> rheology(rheologyModel::New(dict));
        EXPECT_EQ(word(rheology->type()), "inviscid");
        EXPECT_FALSE(rheology->active());
        EXPECT_EQ(rheology->basalTerms(), 0u);
        EXPECT_EQ(rheology->maxViscosity(), 0);
        EXPECT_EQ(rheology->shearModulus(), 0);

        columnArrays cols({1, 2}, {1, 1}, {1, 0.9});
        cols.setGradient({0.3, 1.2, -0.4, -0.7});
        cols.sigma[0] = {5, 6};
        cols.sigma[1] = {-2, 1};
        cols.s = {3, 4};
        rheology->stress(cols.view(), 0.01);
        rheology->addResistance(cols.view());
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_EQ(cols.sigma[k], std::vector<double>({0, 0})) << k;
        }
        EXPECT_EQ(cols.s, std::vector<double>({3, 4}));
        EXPECT_EQ(cols.k1, std::vector<double>({0, 0}));
    }
}


// ************************************************************************* //
