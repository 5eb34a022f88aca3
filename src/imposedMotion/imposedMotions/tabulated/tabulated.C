/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
-------------------------------------------------------------------------------
    Copyright (C) 2025-2026 flapFoam developers
-------------------------------------------------------------------------------
License
    This file is part of flapFoam, derived from OpenFOAM.

    flapFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    flapFoam is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with flapFoam (COPYING).  If not, see <http://www.gnu.org/licenses/>.
\*---------------------------------------------------------------------------*/

#include "tabulated.H"
#include "IFstream.H"
#include "DynamicList.H"
#include "StringStream.H"
#include "addToRunTimeSelectionTable.H"

#include <algorithm>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace imposedMotions
{
    defineTypeNameAndDebug(tabulated, 0);
    addToRunTimeSelectionTable(imposedMotion, tabulated, dictionary);

    // The keys of the Usage table besides type
    static const imposedMotion::addTypeKeys addtabulatedKeys_
    (
        imposedMotions::tabulated::typeName,
        {
            "joint",
            wordList({"values", "file", "offset"}),
            wordList(),
            nullptr         // nothing to check first
        }
    );
}
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::imposedMotions::tabulated::solveCyclicTridiagonal
(
    const scalarList& a,
    const scalarList& b,
    const scalarList& c,
    const scalarList& d,
    scalarList& x
)
{
    const label m = b.size();

    if (m < 3 || a.size() != m || c.size() != m || d.size() != m)
    {
        FatalErrorInFunction
            << "Cyclic tridiagonal system of size " << m
            << " with sub/super/rhs sizes " << a.size() << '/' << c.size()
            << '/' << d.size() << ": need equal sizes >= 3"
            << exit(FatalError);
    }

    // Corners of A: A(0, m-1) = beta = a_0, A(m-1, 0) = alpha = c_{m-1}.
    // A = T + u v^T with u = (gamma, 0 .. 0, alpha), v = (1, 0 .. 0,
    // beta/gamma); T is tridiagonal with b_0 -> b_0 - gamma and
    // b_{m-1} -> b_{m-1} - alpha beta/gamma.  gamma = -b_0 keeps T's
    // diagonal away from cancellation.
    const scalar alpha = c[m-1];
    const scalar beta = a[0];
    const scalar gamma = -b[0];

    // Thomas sweeps of T for the two right-hand sides d and u at once:
    // forward elimination into (cPrime, y, z), then back substitution
    scalarList cPrime(m);
    scalarList y(m);
    scalarList z(m);

    auto diagT = [&](const label i)
    {
        if (i == 0)
        {
            return b[0] - gamma;
        }
        if (i == m-1)
        {
            return b[m-1] - alpha*beta/gamma;
        }
        return b[i];
    };

    auto u = [&](const label i)
    {
        return i == 0 ? gamma : (i == m-1 ? alpha : scalar(0));
    };

    {
        const scalar piv = diagT(0);
        cPrime[0] = c[0]/piv;
        y[0] = d[0]/piv;
        z[0] = u(0)/piv;
    }
    for (label i = 1; i < m; ++i)
    {
        const scalar piv = diagT(i) - a[i]*cPrime[i-1];
        cPrime[i] = (i < m-1) ? c[i]/piv : 0;
        y[i] = (d[i] - a[i]*y[i-1])/piv;
        z[i] = (u(i) - a[i]*z[i-1])/piv;
    }
    for (label i = m-2; i >= 0; --i)
    {
        y[i] -= cPrime[i]*y[i+1];
        z[i] -= cPrime[i]*z[i+1];
    }

    // x = y - z (v.y)/(1 + v.z)
    const scalar factor =
        (y[0] + beta*y[m-1]/gamma)/(1 + z[0] + beta*z[m-1]/gamma);

    x.setSize(m);
    forAll(x, i)
    {
        x[i] = y[i] - factor*z[i];
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::Tuple2<Foam::scalar, Foam::scalar>>
Foam::imposedMotions::tabulated::readFile
(
    const dictionary& dict,
    const fileName& file
)
{
    fileName path(file);
    path.expand();

    IFstream is(path);

    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' = " << file << ": cannot open " << path << nl
            << exit(FatalIOError);
    }

    DynamicList<Tuple2<scalar, scalar>> points;

    std::string line;
    label lineNo = 0;

    while (std::getline(is.stdStream(), line))
    {
        ++lineNo;

        // '#' starts a comment
        const auto hash = line.find('#');
        if (hash != std::string::npos)
        {
            line.erase(hash);
        }

        std::istringstream ls(line);
        ls >> std::ws;
        if (ls.eof())
        {
            continue;   // blank line
        }

        scalar t = 0;
        scalar q = 0;
        ls >> t >> q;
        const bool ok = !ls.fail() && (ls >> std::ws).eof();

        if (!ok)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'file' = " << file << ": line " << lineNo
                << " of " << path << " is not two numbers 't q': \""
                << line.c_str() << '"' << nl
                << exit(FatalIOError);
        }

        points.append(Tuple2<scalar, scalar>(t, q));
    }

    return List<Tuple2<scalar, scalar>>(std::move(points));
}


std::string Foam::imposedMotions::tabulated::source(const word& key) const
{
    OStringStream srcStream;
    srcStream << "Entry '" << key << "'";
    if (!file_.empty())
    {
        srcStream << " = " << file_;
    }
    return srcStream.str();
}


void Foam::imposedMotions::tabulated::checkPoints
(
    const dictionary& dict,
    const std::string& src,
    const List<Tuple2<scalar, scalar>>& points
)
{
    const label nPoints = points.size();

    if (nPoints < 4)
    {
        FatalIOErrorInFunction(dict)
            << src.c_str() << ": " << nPoints << " points (t q), at least"
            << " 4 are needed (one period, the last point closing it)" << nl
            << exit(FatalIOError);
    }

    // Times strictly increasing
    for (label k = 1; k < nPoints; ++k)
    {
        if (!(points[k].first() > points[k-1].first()))
        {
            FatalIOErrorInFunction(dict)
                << src.c_str() << ": the times must be strictly increasing,"
                << " but point " << k << " has t = " << points[k].first()
                << " after t = " << points[k-1].first() << nl
                << exit(FatalIOError);
        }
    }

    // One period: q at the last time equals q at the first time
    scalar scale = 0;
    for (const auto& p : points)
    {
        scale = max(scale, mag(p.second()));
    }
    const scalar qFirst = points.first().second();
    const scalar qLast = points.last().second();

    if (mag(qLast - qFirst) > 1e-12*scale)
    {
        FatalIOErrorInFunction(dict)
            << src.c_str() << ": not periodic: q = " << qLast
            << " at the last time " << points.last().first()
            << " differs from q = " << qFirst
            << " at the first time " << points.first().first()
            << " (allowed difference 1e-12 max|q| = " << 1e-12*scale
            << "); the points must cover exactly one period" << nl
            << exit(FatalIOError);
    }
}


void Foam::imposedMotions::tabulated::setKnots
(
    const List<Tuple2<scalar, scalar>>& points
)
{
    const label nPoints = points.size();
    const label n = nPoints - 1;    // number of intervals = unknowns M_i

    t0_ = points.first().first();
    period_ = points.last().first() - t0_;
    tRel_.setSize(nPoints);
    q_.setSize(nPoints);
    forAll(points, k)
    {
        tRel_[k] = points[k].first() - t0_;
        q_[k] = points[k].second();
    }
    q_[n] = q_[0];              // exactly periodic
    tRel_[n] = period_;
}


void Foam::imposedMotions::tabulated::setCoefficients()
{
    const label n = q_.size() - 1;  // number of intervals = unknowns M_i

    // Interval widths h_i, i = 0 .. n-1
    scalarList h(n);
    for (label i = 0; i < n; ++i)
    {
        h[i] = tRel_[i+1] - tRel_[i];
    }

    // Cyclic system for M_0 .. M_{n-1} (see the header)
    scalarList a(n), b(n), c(n), d(n);
    for (label i = 0; i < n; ++i)
    {
        const label iPrev = (i + n - 1) % n;
        const scalar hPrev = h[iPrev];

        a[i] = hPrev;
        b[i] = 2*(hPrev + h[i]);
        c[i] = h[i];
        d[i] =
            6*((q_[i+1] - q_[i])/h[i] - (q_[i] - q_[iPrev])/hPrev);
    }

    scalarList M;
    solveCyclicTridiagonal(a, b, c, d, M);

    // Cubic coefficients per interval, M_n = M_0
    B_.setSize(n);
    C_.setSize(n);
    D_.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar Mi = M[i];
        const scalar Mi1 = M[(i + 1) % n];

        B_[i] = (q_[i+1] - q_[i])/h[i] - h[i]*(2*Mi + Mi1)/6;
        C_[i] = Mi/2;
        D_[i] = (Mi1 - Mi)/(6*h[i]);
    }
}


void Foam::imposedMotions::tabulated::build
(
    const dictionary& dict,
    const word& key,
    const List<Tuple2<scalar, scalar>>& points
)
{
    checkPoints(dict, source(key), points);

    setKnots(points);
    setCoefficients();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotions::tabulated::tabulated
(
    const word& name,
    const dictionary& dict
)
:
    imposedMotion(name, dict),
    file_(),
    offset_(dict.getOrDefault<scalar>("offset", 0)),
    tRel_(),
    t0_(0),
    period_(0),
    q_(),
    B_(),
    C_(),
    D_()
{
    const bool haveValues = dict.found("values");
    const bool haveFile = dict.found("file");

    if (haveValues == haveFile)
    {
        FatalIOErrorInFunction(dict)
            << (haveValues ? "Both entries" : "Neither entry")
            << " 'values' " << (haveValues ? "and" : "nor") << " 'file'"
            << " given: give exactly one of them" << nl
            << exit(FatalIOError);
    }

    if (haveValues)
    {
        build
        (
            dict,
            "values",
            dict.get<List<Tuple2<scalar, scalar>>>("values")
        );
    }
    else
    {
        file_ = dict.get<fileName>("file");
        build(dict, "file", readFile(dict, file_));
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotions::tabulated::evaluate
(
    const label,
    const scalar t,
    scalar& q,
    scalar& qDot,
    scalar& qDdot
) const
{
    // Wrap into the period: x = (t - t_0) mod P in [0, P)
    scalar x = t - t0_;
    x -= period_*::floor(x/period_);
    if (x >= period_)
    {
        x -= period_;
    }
    if (x < 0)
    {
        x = 0;
    }

    // Interval i with tRel_i <= x < tRel_{i+1}: binary search
    const label n = B_.size();
    const scalar* first = tRel_.cdata();
    const label upper = std::upper_bound(first, first + n + 1, x) - first;
    const label i = min(max(upper - 1, 0), n - 1);

    const scalar s = x - tRel_[i];

    // q = q_i + s (B + s (C + s D)) and its derivatives
    q = offset_ + q_[i] + s*(B_[i] + s*(C_[i] + s*D_[i]));
    qDot = B_[i] + s*(2*C_[i] + 3*D_[i]*s);
    qDdot = 2*C_[i] + 6*D_[i]*s;
}


void Foam::imposedMotions::tabulated::write(Ostream& os) const
{
    imposedMotion::write(os);

    if (file_.empty())
    {
        List<Tuple2<scalar, scalar>> values(q_.size());
        forAll(values, k)
        {
            values[k] = Tuple2<scalar, scalar>(t0_ + tRel_[k], q_[k]);
        }
        os.writeEntry("values", values);
    }
    else
    {
        os.writeEntry("file", file_);
    }

    os.writeEntry("offset", offset_);
}


// ************************************************************************* //
