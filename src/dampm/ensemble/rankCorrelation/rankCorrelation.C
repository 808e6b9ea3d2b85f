/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "rankCorrelation.H"
#include "standardNormal.H"
#include "knownKeywords.H"
#include "tokenList.H"
#include "mathematicalConstants.H"
#include "OStringStream.H"
#include "exactPrecision.H"
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numeric>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

const char* const pairForm =
    "; allowed: (<parameter> <parameter> <rho>), two different parameters"
    " and -1 < rho < 1, each pair once";


//- An entry of correlations on one line, its numbers as written whatever
//  the stream's precision: (xi phi -0.6)
Foam::string entryText(const Foam::tokenList& entry)
{
    Foam::OStringStream os;
    os  << '(';
    forAll(entry, i)
    {
        os  << (i ? " " : "");
        if (entry[i].isNumber())
        {
            os  << Foam::exactText(entry[i].number()).c_str();
        }
        else
        {
            os  << entry[i];
        }
    }
    os  << ')';
    return os.str();
}


//- The indices of x in increasing order of its values (ties: by index)
std::vector<Foam::label> ascendingOrder(const std::vector<double>& x)
{
    std::vector<Foam::label> order(x.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&](const Foam::label i, const Foam::label j) { return x[i] < x[j]; }
    );
    return order;
}


//- The ranks of x, 0 for the smallest; equal values share their mean rank
std::vector<double> ranks(const std::vector<double>& x)
{
    const std::vector<Foam::label> order(ascendingOrder(x));
    std::vector<double> r(x.size());
    for (size_t first = 0; first < order.size();)
    {
        size_t last = first + 1;
        while (last < order.size() && x[order[last]] == x[order[first]])
        {
            ++last;
        }
        for (size_t k = first; k < last; ++k)
        {
            r[order[k]] = 0.5*(first + last - 1);
        }
        first = last;
    }
    return r;
}


//- The Pearson correlation matrix of the columns of s
Eigen::MatrixXd correlationMatrix(const Eigen::MatrixXd& s)
{
    const Eigen::MatrixXd centred = s.rowwise() - s.colwise().mean();
    const Eigen::MatrixXd covariance = centred.transpose()*centred;
    const Eigen::VectorXd scale =
        covariance.diagonal().cwiseSqrt().cwiseInverse();
    return scale.asDiagonal()*covariance*scale.asDiagonal();
}


//- The target Pearson correlation matrix of the scores: 1 on the
//  diagonal, 2 sin(pi rho/6) for a pair given rho, 0 elsewhere (set-up
//  only: a dynamic size costs nothing here)
Eigen::MatrixXd targetMatrix
(
    const Foam::label nParameters,
    const std::vector<Foam::rankCorrelation::pair>& pairs
)
{
    Eigen::MatrixXd c = Eigen::MatrixXd::Identity(nParameters, nParameters);
    for (const Foam::rankCorrelation::pair& p : pairs)
    {
        c(p.a, p.b) = c(p.b, p.a) =
            2*std::sin(Foam::constant::mathematical::pi*p.rho/6);
    }
    return c;
}


//- The lower Cholesky factor of a correlation matrix, false when it is not
//  positive definite: a pivot, the root of the part of a column's variance
//  that the previous columns do not explain (1 when independent), below
//  tol is linear dependence within round-off
bool cholesky(const Eigen::MatrixXd& c, Eigen::MatrixXd& l)
{
    constexpr double tol = 1e-6;
    const Eigen::LLT<Eigen::MatrixXd> llt(c);
    if (llt.info() != Eigen::Success)
    {
        return false;
    }
    l = llt.matrixL();
    return l.diagonal().minCoeff() > tol;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rankCorrelation::readPairs
(
    const dictionary& dict,
    const wordList& names
)
{
    const List<tokenList> entries(dict.get<List<tokenList>>("correlations"));
    for (const tokenList& tokens : entries)
    {
        const string entry(entryText(tokens));
        if
        (
            tokens.size() != 3 || !tokens[0].isWord() || !tokens[1].isWord()
         || !tokens[2].isNumber()
        )
        {
            FatalIOErrorInFunction(dict)
                << "correlations entry " << entry.c_str() << " is invalid"
                << pairForm << exit(FatalIOError);
        }
        const pair p
        {
            names.find(tokens[0].wordToken()),
            names.find(tokens[1].wordToken()),
            tokens[2].number()
        };
        for (const label k : {0, 1})
        {
            if ((k ? p.b : p.a) < 0)
            {
                FatalIOErrorInFunction(dict)
                    << "correlations entry " << entry.c_str()
                    << ": no parameter " << tokens[k].wordToken()
                    << "; allowed: the parameters " << names
                    << exit(FatalIOError);
            }
        }
        if (p.a == p.b)
        {
            FatalIOErrorInFunction(dict)
                << "correlations entry " << entry.c_str() << " correlates "
                << names[p.a] << " with itself" << pairForm
                << exit(FatalIOError);
        }
        if (!(std::abs(p.rho) < 1))
        {
            FatalIOErrorInFunction(dict)
                << "correlations entry " << entry.c_str() << ": rho = "
                << exactText(p.rho).c_str() << " is invalid" << pairForm
                << exit(FatalIOError);
        }
        for (const pair& q : pairs_)
        {
            if (std::min(q.a, q.b) == std::min(p.a, p.b)
             && std::max(q.a, q.b) == std::max(p.a, p.b))
            {
                FatalIOErrorInFunction(dict)
                    << "correlations entry " << entry.c_str() << ": the pair "
                    << names[p.a] << ' ' << names[p.b] << " is given twice"
                    << pairForm << exit(FatalIOError);
            }
        }
        pairs_.push_back(p);
    }
}


void Foam::rankCorrelation::checkTarget(const dictionary& dict) const
{
    Eigen::MatrixXd p;
    if (!cholesky(targetMatrix(nParameters_, pairs_), p))
    {
        FatalIOErrorInFunction(dict)
            << "the correlations given do not make a positive definite"
            << " matrix (1 on the diagonal, 0 for the pairs not given);"
            << " allowed: correlations that the parameters can have"
            << " together, e.g. (a b 0.8) (b c 0.8) need (a c rho) with"
            << " rho > 0.31" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rankCorrelation::rankCorrelation
(
    const dictionary& ensembleDict,
    const wordList& names,
    const label nMembers
)
:
    nParameters_(names.size())
{
    knownKeywords::add(ensembleDict, {"correlations"});
    if (!ensembleDict.found("correlations"))
    {
        return;
    }
    readPairs(ensembleDict, names);
    if (pairs_.empty())
    {
        return;
    }
    checkTarget(ensembleDict);

    // The scores' correlation matrix must be positive definite: K columns
    // of N scores whose mean is 0 are independent only if K < N
    if (nMembers <= names.size())
    {
        FatalIOErrorInFunction(ensembleDict)
            << "correlations among " << names.size() << " parameters need"
            << " more members than parameters, members = " << nMembers
            << "; allowed: members >= " << names.size() + 1
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::rankCorrelation::spearman
(
    const std::vector<double>& x,
    const std::vector<double>& y
)
{
    // The Pearson correlation of the ranks, whose mean is (N - 1)/2
    const std::vector<double> rx(ranks(x));
    const std::vector<double> ry(ranks(y));
    const double mean = 0.5*(rx.size() - 1);
    double xy = 0, xx = 0, yy = 0;
    for (size_t i = 0; i < rx.size(); ++i)
    {
        xy += (rx[i] - mean)*(ry[i] - mean);
        xx += sqr(rx[i] - mean);
        yy += sqr(ry[i] - mean);
    }
    return xy/std::sqrt(xx*yy);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rankCorrelation::induce
(
    std::mt19937_64& rng,
    samplingDesign::probabilities& u
) const
{
    if (pairs_.empty())
    {
        return;
    }
    const label nParameters = nParameters_;
    const label nMembers = u[0].size();

    std::vector<double> scores(nMembers);
    for (label k = 0; k < nMembers; ++k)
    {
        scores[k] = standardNormal::quantile((k + 1.0)/(nMembers + 1));
    }

    // Permuted scores with independent columns: with few members a draw
    // can repeat a column (or its reverse) and is drawn again
    Eigen::MatrixXd s(nMembers, nParameters);
    Eigen::MatrixXd q;
    do
    {
        for (label parami = 0; parami < nParameters; ++parami)
        {
            const std::vector<label> order
            (
                samplingDesign::permutation(rng, nMembers)
            );
            for (label memberi = 0; memberi < nMembers; ++memberi)
            {
                s(memberi, parami) = scores[order[memberi]];
            }
        }
    } while (!cholesky(correlationMatrix(s), q));

    Eigen::MatrixXd p;
    cholesky(targetMatrix(nParameters, pairs_), p);

    // T = S (P Q^-1)^T = S Q^-T P^T; corr(T) = P Q^-1 E Q^-T P^T = P P^T
    const Eigen::MatrixXd t =
        q.transpose().triangularView<Eigen::Upper>()
        .solve<Eigen::OnTheRight>(s)*p.transpose();

    for (label parami = 0; parami < nParameters; ++parami)
    {
        const std::vector<double> column
        (
            t.col(parami).data(), t.col(parami).data() + nMembers
        );
        std::vector<double> sorted(u[parami]);
        std::sort(sorted.begin(), sorted.end());
        const std::vector<label> order(ascendingOrder(column));
        for (label k = 0; k < nMembers; ++k)
        {
            u[parami][order[k]] = sorted[k];
        }
    }
}


// ************************************************************************* //
