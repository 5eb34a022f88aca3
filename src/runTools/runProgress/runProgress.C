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

#include "runProgress.H"
#include "imposedMotionKey.H"
#include "functionObjectKeys.H"
#include "dictionaryRead.H"
#include "addToRunTimeSelectionTable.H"
#include "IOdictionary.H"
#include "Time.H"

#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(runProgress, 0);
    addToRunTimeSelectionTable(functionObject, runProgress, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::functionObjects::runProgress::mark
Foam::functionObjects::runProgress::now() const
{
    return mark{clock::now(), time_.timeIndex(), time_.value()};
}


Foam::scalar Foam::functionObjects::runProgress::motionPeriod
(
    const word& entry
) const
{
    const IOdictionary meshDict
    (
        IOobject
        (
            "dynamicMeshDict",
            time_.constant(),
            time_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const word solver(meshDict.getOrDefault<word>("motionSolver", "none"));
    const dictionary& coeffs = meshDict.optionalSubDict(solver + "Coeffs");
    const word key(imposedMotionKey(coeffs));
    const dictionary* motions = key.empty() ? nullptr : coeffs.findDict(key);
    if (!motions || !motions->isDict(entry))
    {
        FatalIOErrorInFunction(meshDict)
            << type() << " " << name() << ": cycleMotion " << entry
            << ": no such entry in " << solver << "Coeffs/"
            << (key.empty() ? word("imposedMotion") : key)
            << " (entries: "
            << (motions ? motions->toc() : wordList()) << ");"
            << " name one of them, or give the period instead"
            << exit(FatalIOError);
    }
    return
        1/readAllowed
        (
            motions->subDict(entry), "frequency", allowed::above(0.0)
        );
}


void Foam::functionObjects::runProgress::report
(
    const mark& m,
    const char* title
) const
{
    const scalar endTime = time_.endTime().value();
    const scalar wallLast = clockSeconds(last_.wall, m.wall);
    const scalar wallStart = clockSeconds(start_.wall, m.wall);
    const label nLast = m.index - last_.index;
    const label nStart = m.index - start_.index;

    // 6 digits, whatever the precision of the log
    std::ostringstream os;
    os << title << ": t = " << m.t << " s of " << endTime;
    if (endTime > 0)
    {
        os << " (" << 100*m.t/endTime << " %)";
    }
    if (period_ > 0)
    {
        os << ", cycle " << m.t/period_ << " of " << endTime/period_;
    }
    os << ", step " << m.index << "; wall ";
    if (nLast > 0 && last_.index != start_.index)
    {
        os << wallLast/nLast << " s/step (last " << duration(wallLast)
           << ", " << nLast << " steps), ";
    }
    os << (nStart > 0 ? wallStart/nStart : 0) << " s/step (this start, "
       << nStart << " steps); to endTime " << endTime - m.t << " s: ";

    // The rate of the last interval, else of this start
    const scalar dt = m.t - last_.t;
    const scalar rate =
        dt > 0 && wallLast > 0 ? dt/wallLast
      : (wallStart > 0 ? (m.t - start_.t)/wallStart : 0);
    if (m.t >= endTime)
    {
        os << "reached";
    }
    else if (rate > 0)
    {
        os << "about " << duration((endTime - m.t)/rate);
    }
    else
    {
        os << "not known yet";
    }
    Info<< os.str().c_str() << endl;
}


Foam::scalar Foam::functionObjects::runProgress::clockSeconds
(
    const clock::time_point& from,
    const clock::time_point& to
)
{
    return std::chrono::duration<scalar>(to - from).count();
}


std::string Foam::functionObjects::runProgress::duration
(
    const scalar seconds
)
{
    std::ostringstream os;
    const label s = std::lround(seconds);
    if (s >= 3600)
    {
        os << s/3600 << " h " << (s % 3600)/60 << " min";
    }
    else if (s >= 60)
    {
        os << s/60 << " min " << s % 60 << " s";
    }
    else
    {
        os.precision(3);
        os << seconds << " s";
    }
    return os.str();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::runProgress::runProgress
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime),
    interval_(300),
    period_(0),
    start_(now()),
    last_(start_)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::functionObjects::runProgress::keys()
{
    static const wordList k({"progressInterval", "period", "cycleMotion"});
    return k;
}


bool Foam::functionObjects::runProgress::read(const dictionary& dict)
{
    timeFunctionObject::read(dict);
    functionObjectKeys::check(dict, keys());

    interval_ =
        readAllowed(dict, "progressInterval", 300.0, allowed::above(0.0));

    if (dict.found("period") && dict.found("cycleMotion"))
    {
        FatalIOErrorInFunction(dict)
            << "period and cycleMotion: give one of them (the period [s],"
            << " or the imposedMotion entry whose frequency gives it)"
            << exit(FatalIOError);
    }
    period_ = 0;
    if (dict.found("cycleMotion"))
    {
        period_ = motionPeriod(dict.get<word>("cycleMotion"));
    }
    else if (dict.found("period"))
    {
        period_ = readAllowed(dict, "period", allowed::above(0.0));
    }

    Info<< type() << " " << name() << ": a line every "
        << duration(interval_).c_str();
    if (period_ > 0)
    {
        Info<< ", cycle period " << Foam::name(period_).c_str() << " s";
    }
    Info<< endl;

    return true;
}


bool Foam::functionObjects::runProgress::execute()
{
    const mark m(now());
    if (clockSeconds(last_.wall, m.wall) >= interval_)
    {
        report(m, "Progress");
        last_ = m;
    }
    return true;
}


bool Foam::functionObjects::runProgress::write()
{
    return true;
}


bool Foam::functionObjects::runProgress::end()
{
    report(now(), "Progress (end of the run)");
    return true;
}


// ************************************************************************* //
