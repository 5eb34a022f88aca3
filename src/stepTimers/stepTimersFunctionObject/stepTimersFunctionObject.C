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

#include "stepTimersFunctionObject.H"
#include "functionObjectKeys.H"
#include "addToRunTimeSelectionTable.H"
#include "MinMax.H"
#include "OFstream.H"
#include "IOmanip.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(stepTimers, 0);

    addToRunTimeSelectionTable
    (
        functionObject,
        stepTimers,
        dictionary
    );
}
}


const Foam::wordList Foam::functionObjects::stepTimers::measured
({
    "rbd", "overset", "pimple", "total", "preUpdate"
});


const Foam::wordList Foam::functionObjects::stepTimers::groupPrefixes
({
    "rbd", "overset"
});


const Foam::word Foam::functionObjects::stepTimers::syncPart("pimpleSync");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Median of a list (0 if empty)
Foam::scalar median(const Foam::UList<Foam::scalar>& values)
{
    if (values.empty())
    {
        return 0;
    }

    Foam::scalarList sorted(values);
    Foam::sort(sorted);

    const Foam::label n = sorted.size();

    return n % 2 ? sorted[n/2] : 0.5*(sorted[n/2 - 1] + sorted[n/2]);
}


//- Mean of a list (0 if empty)
Foam::scalar mean(const Foam::UList<Foam::scalar>& values)
{
    Foam::scalar sum = 0;

    for (const Foam::scalar v : values)
    {
        sum += v;
    }

    return values.size() ? sum/values.size() : 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::functionObjects::stepTimers::reserved(const word& part)
{
    return part == "time" || measured.found(part);
}


void Foam::functionObjects::stepTimers::syncParts()
{
    const DynamicList<word>& all = timers_.parts();

    DynamicList<word> fresh;

    for (label i = nSeen_; i < all.size(); ++i)
    {
        if (!reserved(all[i]) && !parts_.found(all[i]))
        {
            fresh.append(all[i]);
        }
    }

    nSeen_ = all.size();

    List<wordList> perRank(Pstream::nProcs());
    perRank[Pstream::myProcNo()] = fresh;
    Pstream::gatherList(perRank);
    Pstream::scatterList(perRank);

    for (const wordList& names : perRank)
    {
        for (const word& name : names)
        {
            if (!parts_.found(name))
            {
                parts_.append(name);
            }
        }
    }
}


Foam::scalarList Foam::functionObjects::stepTimers::gather
(
    const scalar total,
    const scalar pimple,
    const scalar preUpdate
)
{
    const label nMeasured = measured.size();

    scalarList values(nMeasured + parts_.size() + 1, Zero);

    // Group sums over every part of this rank (rbd, overset)
    for (const word& part : timers_.parts())
    {
        forAll(groupPrefixes, groupi)
        {
            if (part.starts_with(groupPrefixes[groupi]))
            {
                values[groupi] += timers_[part];
            }
        }
    }

    values[pimpleI] = pimple;
    values[totalI] = total;
    values[preUpdateI] = preUpdate;

    forAll(parts_, parti)
    {
        values[nMeasured + parti] = timers_[parts_[parti]];
    }

    values.last() = own_;

    if (nSteps_ + 1 > nStartup_)
    {
        rankSums_.resize(values.size() - 1, Zero);
        forAll(rankSums_, coli)
        {
            rankSums_[coli] += values[coli];
        }
    }

    // The maximum over the ranks, on the master
    Pstream::listCombineGather(values, maxEqOp<scalar>());

    return values;
}


void Foam::functionObjects::stepTimers::writeColumns(Ostream& os)
{
    if (nHeader_ < 0)
    {
        writeHeader
        (
            os,
            "Step timers: wall-clock seconds per time step"
          + string(Pstream::parRun() ? ", maximum over the ranks" : "")
        );
        writeHeader
        (
            os,
            "pimple: from the end of the mesh update to the end of the step;"
            " preUpdate: from the start of the step to the mesh update;"
            " rbd, overset: sums of the parts rbd*, overset*"
        );
    }
    else
    {
        writeHeader(os, "New part(s): the columns from here on");
    }

    writeCommented(os, "time");

    for (const word& name : measured)
    {
        writeTabbed(os, name);
    }

    for (const word& name : parts_)
    {
        writeTabbed(os, name);
    }

    os  << endl;

    nHeader_ = measured.size() + parts_.size();
}


void Foam::functionObjects::stepTimers::record(const scalarList& values)
{
    const label nColumns = measured.size() + parts_.size();
    const label nPrevious = other_.size();

    while (history_.size() < nColumns)
    {
        // A new part: zero in the steps before its first use
        history_.append(DynamicList<scalar>(nPrevious, Zero));
    }

    for (label coli = 0; coli < nColumns; ++coli)
    {
        history_[coli].append(values[coli]);
    }

    other_.append
    (
        values[totalI] - values[rbdI] - values[oversetI] - values[pimpleI]
    );
    ownHistory_.append(values[nColumns]);

    if (nPrevious == 0)
    {
        summaryStart_ = time_.timeOutputValue();
    }
    summaryEnd_ = time_.timeOutputValue();
}


void Foam::functionObjects::stepTimers::writeSummary(Ostream& os) const
{
    const label w = 26;
    const scalar totalMean = history_.size() ? mean(history_[totalI]) : 0;

    os  << "# Step timers summary: wall-clock seconds per time step";
    if (Pstream::parRun())
    {
        os  << ", maximum over " << Pstream::nProcs() << " ranks";
    }
    os  << nl
        << "# nSteps " << other_.size()
        << " nStartup " << nStartup_
        << " nProcs " << Pstream::nProcs()
        << " firstTime " << Time::timeName(summaryStart_)
        << " lastTime " << Time::timeName(summaryEnd_) << nl;

    if (other_.empty())
    {
        os  << "# No steps after the start-up steps" << endl;
        return;
    }

    os  << "# share = mean/mean(total); other = total - rbd - overset - pimple"
        << " (preUpdate is in it); pimple* parts lie inside pimple; counts"
        << " (iterations) have no share" << nl
        << "# " << setf(ios_base::left) << setw(w - 2) << "part"
        << tab << setw(16) << "mean"
        << tab << setw(16) << "median"
        << tab << "share" << nl;

    auto row = [&](const word& name, const UList<scalar>& values)
    {
        const scalar m = mean(values);

        os  << setf(ios_base::left) << setw(w) << name
            << tab << setw(16) << m
            << tab << setw(16) << median(values)
            << tab;
        if (timers_.isCount(name))
        {
            os  << "-" << nl;
        }
        else
        {
            os  << (totalMean > 0 ? m/totalMean : 0) << nl;
        }
    };

    forAll(history_, coli)
    {
        row
        (
            coli < measured.size()
          ? measured[coli]
          : parts_[coli - measured.size()],
            history_[coli]
        );

        if (coli == totalI)
        {
            row("other", other_);
        }
    }

    row("stepTimersCost", ownHistory_);

    os  << flush;
}


void Foam::functionObjects::stepTimers::writeRanksFile() const
{
    List<scalarList> perRank(Pstream::nProcs());
    perRank[Pstream::myProcNo()] = rankSums_;
    Pstream::gatherList(perRank);

    if (!writeToFile() || !filePtr_.valid())
    {
        return;
    }
    OFstream os(filePtr_->name().path()/(typeName + "Ranks.dat"));
    os.setf(ios_base::scientific, ios_base::floatfield);
    os.precision(writePrecision_);

    const label n = max(label(other_.size()), label(1));
    os  << "# Per rank: its own mean per step over the " << other_.size()
        << " summarised steps" << nl << "# rank" << tab << "nSteps";
    for (const word& name : measured)
    {
        os  << tab << name;
    }
    for (const word& name : parts_)
    {
        os  << tab << name;
    }
    os  << nl;
    forAll(perRank, proci)
    {
        os  << proci << tab << other_.size();
        for (const scalar sum : perRank[proci])
        {
            os  << tab << sum/n;
        }
        os  << nl;
    }
}


void Foam::functionObjects::stepTimers::writeSummaryFile() const
{
    if (!writeToFile() || !filePtr_.valid())
    {
        return;
    }

    OFstream os(filePtr_->name().path()/(typeName + "Summary.dat"));
    os.setf(ios_base::scientific, ios_base::floatfield);
    os.precision(writePrecision_);

    writeSummary(os);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::stepTimers::stepTimers
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime),
    writeFile(runTime, name, typeName, dict),
    timers_(Foam::stepTimers::New(runTime)),
    nStartup_(2),
    parts_(),
    nSeen_(0),
    nHeader_(-1),
    previous_(Foam::stepTimers::now()),
    own_(0),
    previousTimeIndex_(-1),
    nSteps_(0),
    warnedInterval_(false),
    summaryStart_(0),
    summaryEnd_(0)
{
    read(dict);

    // Whatever was timed before the first step (solver set-up) is not part
    // of a step
    timers_.reset();

    // The first step starts at the same instant on all ranks (every rank
    // constructs the function objects)
    returnReduce(true, andOp<bool>());
    previous_ = Foam::stepTimers::now();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::stepTimers::read(const dictionary& dict)
{
    timeFunctionObject::read(dict);
    writeFile::read(dict);
    functionObjectKeys::check
    (
        dict,
        wordList({"nStartup", "writePrecision", "writeToFile", "useUserTime"})
    );

    nStartup_ = dict.getCheckOrDefault<label>
    (
        "nStartup",
        2,
        labelMinMax::ge(0)
    );

    return true;
}


Foam::scalar Foam::functionObjects::stepTimers::pimpleTime
(
    const clock::time_point& now,
    const scalar total
) const
{
    return
    (
        timers_.stamped(Foam::stepTimers::meshUpdated)
      ? Foam::stepTimers::seconds
        (
            timers_.stampTime(Foam::stepTimers::meshUpdated),
            now
        )
      : total
    );
}


Foam::scalar Foam::functionObjects::stepTimers::preUpdateTime() const
{
    return
    (
        timers_.stamped(Foam::stepTimers::meshUpdateStart)
      ? Foam::stepTimers::seconds
        (
            previous_,
            timers_.stampTime(Foam::stepTimers::meshUpdateStart)
        )
      : 0
    );
}


void Foam::functionObjects::stepTimers::checkInterval()
{
    if
    (
        previousTimeIndex_ >= 0
     && time_.timeIndex() != previousTimeIndex_ + 1
     && !warnedInterval_
    )
    {
        WarningInFunction
            << "Executed after " << time_.timeIndex() - previousTimeIndex_
            << " time steps: each row of " << name() << " covers that many"
            << " steps.  Use the default executeControl (timeStep, 1)."
            << endl;

        warnedInterval_ = true;
    }
}


void Foam::functionObjects::stepTimers::writeRow(const scalarList& values)
{
    const label nColumns = measured.size() + parts_.size();

    OFstream& os = file();

    if (nHeader_ < nColumns)
    {
        writeColumns(os);
    }

    writeCurrentTime(os);

    for (label coli = 0; coli < nColumns; ++coli)
    {
        os  << tab << values[coli];
    }

    os  << endl;
}


void Foam::functionObjects::stepTimers::publish(const scalarList& values)
{
    wordList columns(measured);
    columns.append(parts_);
    timers_.setLast
    (
        time_.timeIndex(),
        columns,
        SubList<scalar>(values, columns.size())
    );
}


bool Foam::functionObjects::stepTimers::execute()
{
    // The stretch still open (Foam::fv::pimpleTimers: the turbulence); with
    // laps the synchronisation below is a lap of its own, registered first
    // so that the ranks learn of it with the other new parts
    const bool lapped = timers_.endLap();
    if (lapped)
    {
        timers_.add(syncPart, 0);
    }

    // Synchronise the ranks, so that the step ends at the same instant on
    // all of them (the wait of the faster ranks counts in their pimple),
    // and learn whether a rank used a part that is not a column yet
    const bool newParts = returnReduce
    (
        timers_.parts().size() > nSeen_,
        orOp<bool>()
    );

    // The end of the step: with laps, the end of the sync lap itself, so
    // that the laps and the parts inside them add up to pimple exactly
    const clock::time_point now =
    (
        lapped ? timers_.lap(syncPart) : Foam::stepTimers::now()
    );

    const scalar total = Foam::stepTimers::seconds(previous_, now);
    const scalar pimple = pimpleTime(now, total);
    const scalar preUpdate = preUpdateTime();

    if (newParts)
    {
        syncParts();
    }

    const scalarList values(gather(total, pimple, preUpdate));

    checkInterval();

    previousTimeIndex_ = time_.timeIndex();
    ++nSteps_;

    if (writeToFile())
    {
        writeRow(values);
    }

    if (Pstream::master() && nSteps_ > nStartup_)
    {
        record(values);
    }

    // The row, for other function objects of this step (flightData)
    publish(values);

    timers_.reset();

    previous_ = now;
    own_ = Foam::stepTimers::seconds(now, Foam::stepTimers::now());

    return true;
}


bool Foam::functionObjects::stepTimers::write()
{
    return true;
}


bool Foam::functionObjects::stepTimers::end()
{
    if (Pstream::master())
    {
        Info<< nl;
        writeSummary(Info);
        Info<< endl;
    }

    writeSummaryFile();
    writeRanksFile();

    return true;
}


// ************************************************************************* //
