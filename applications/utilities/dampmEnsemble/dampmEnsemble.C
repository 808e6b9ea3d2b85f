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
    Runs an ensemble of this case (doc/ensembles.md): draws the sample of
    system/ensembleDict and writes it to ensemble/samples.csv, makes each
    member's case, ensemble/member.NNNN, runs the members jobs at a time on
    this machine, and writes the ensemble's hazard maps to
    ensemble/postProcessing/hazardMaps/ and a line per member to
    ensemble/postProcessing/summary.csv.

    Everything in ensembleDict is checked before any member runs. Run again,
    it resumes: members done are not rerun, members stopped part way
    continue from their last complete time; failed members are reported,
    left out of the maps and not rerun unless -retryFailed.

    \verbatim
        dampmEnsemble [-case dir] [-jobs N] [-threads N] [-retryFailed]
        dampmEnsemble -sample         # ensemble/samples.csv only
        dampmEnsemble -setup          # the sample and the members' cases
        dampmEnsemble -member i       # run member i only (a job array's task)
        dampmEnsemble -maps           # the maps and summary.csv only
    \endverbatim

    Exit code 0 when every member is done and the maps are written; 1 when
    members failed or are not done (the maps are written from those done);
    128 + the signal when stopped by SIGINT or SIGTERM.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "strictIOdictionary.H"
#include "ensembleSample.H"
#include "ensembleMember.H"
#include "ensembleRunner.H"
#include "ensembleMaps.H"
#include "ensembleSummary.H"
#include "knownKeywords.H"
#include "OSspecific.H"
#include <fstream>
#include <sstream>
#include <thread>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- Write the sample to ensemble/samples.csv, or check that the one there is
//  the same (the ensemble resumes only with the sample its members have)
void writeOrCheckSample(const ensembleSample& sample, const fileName& csv)
{
    if (isFile(csv))
    {
        std::ifstream is(csv);
        std::stringstream text;
        text << is.rdbuf();
        if (text.str() != sample.csv())
        {
            FatalErrorInFunction
                << "ensemble/samples.csv holds another sample than"
                << " system/ensembleDict"
                << " draws now (the dictionary changed since its members"
                << " were made): restore the dictionary to resume, or remove"
                << " the folder ensemble/ for a new ensemble"
                << exit(FatalError);
        }
        return;
    }
    sample.write(csv);
    Info<< "Wrote ensemble/samples.csv" << nl;
}


//- A positive count from an option (default if absent)
label positiveOption(const argList& args, const word& name, const label deflt)
{
    const label n = args.getOrDefault<label>(name, deflt);
    if (n < 1)
    {
        FatalErrorInFunction
            << "-" << name << ' ' << n << " is invalid; allowed: an integer"
            << " >= 1" << exit(FatalError);
    }
    return n;
}


//- Should member run: not done, failed only when retrying
bool toRun(const ensembleMember& member, const bool retryFailed)
{
    typedef ensembleMember::statusType statusType;
    return
        member.status() != statusType::done
     && (retryFailed || member.status() != statusType::failed);
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Run the ensemble of this case drawn from system/ensembleDict and"
        " write its hazard maps (ensemble/)"
    );
    argList::noParallel();
    argList::addBoolOption
    (
        "sample", "draw the sample and write ensemble/samples.csv only"
    );
    argList::addBoolOption
    (
        "setup", "draw the sample and make the members' cases, run nothing"
    );
    argList::addOption
    (
        "member", "i", "run member i only (0 for the first; a scheduler"
        " job array's task), without the maps"
    );
    argList::addBoolOption
    (
        "maps", "write the maps and summary.csv from the members done, run"
        " nothing"
    );
    argList::addOption
    (
        "jobs", "N", "members run at once (default: the cores over -threads)"
    );
    argList::addOption("threads", "N", "threads of each member (default 1)");
    argList::addBoolOption("retryFailed", "run the failed members again");
    #include "setRootCase.H"
    #include "createTime.H"

    #include "readEnsembleDict.H"

    const bool runs = !args.found("sample") && !args.found("maps");
    const label single = args.getOrDefault<label>("member", -1);
    #include "checkRunOptions.H"

    const fileName ensembleDir(runTime.path()/"ensemble");
    writeOrCheckSample(sample, ensembleDir/"samples.csv");
    if (args.found("sample"))
    {
        Info<< nl << "End\n" << endl;
        return 0;
    }

    PtrList<ensembleMember> members(sample.size());
    forAll(members, memberi)
    {
        members.set
        (
            memberi,
            new ensembleMember
            (
                runTime.path(),
                ensembleSample::memberName(memberi, sample.size())
            )
        );
    }

    const word application(runTime.controlDict().get<word>("application"));
    if (runs)
    {
        #include "runMembers.H"
    }

    #include "writeEnsembleMaps.H"

    Info<< nl << "End\n" << endl;

    // Not return: destroying argList ends the process with exit code 0
    Pstream::exit(exitCode);
    return exitCode;
}


// ************************************************************************* //
