/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Application
    dampmEnsemble

Group
    grpMPMUtilities

Description
    Draws the sample of an ensemble of runs of this case from
    system/ensembleDict (doc/ensembles.md): checks every parameter (its
    entries exist in the case's files, its distribution's coefficients,
    the number of members), draws the values with the seed's random
    numbers, writes them to ensemble/samples.csv (member,<name>,...; one
    row per member) and prints each parameter's minimum, mean and maximum.

    \verbatim
        dampmEnsemble [-case dir]
    \endverbatim

    It does not run the members yet: this is the sampling step.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "strictIOdictionary.H"
#include "ensembleSample.H"
#include "knownKeywords.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Draw the sample of an ensemble of runs of this case from"
        " system/ensembleDict and write it to ensemble/samples.csv"
    );
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"

    const strictIOdictionary ensembleDict
    (
        IOobject
        (
            "ensembleDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    const ensembleSample sample(ensembleDict, runTime.path());
    knownKeywords::warnUnknown(runTime.path());

    const fileName csv(runTime.path()/"ensemble"/"samples.csv");
    sample.write(csv);
    Info<< nl;
    sample.report(Info);
    Info<< nl << "Wrote " << csv.relative(runTime.path()).c_str() << nl
        << nl << "End\n" << endl;

    return 0;
}


// ************************************************************************* //
