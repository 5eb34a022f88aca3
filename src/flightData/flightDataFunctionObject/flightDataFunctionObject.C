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

#include "flightDataFunctionObject.H"
#include "flapFoamCommit.H"
#include "fvMesh.H"
#include "functionObjectKeys.H"
#include "dictionaryKeys.H"
#include "dictionaryRead.H"
#include "addToRunTimeSelectionTable.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "Time.H"
#include "OStringStream.H"

#include <cstdio>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(flightData, 0);
    addToRunTimeSelectionTable(functionObject, flightData, dictionary);
}
}

const Foam::word Foam::functionObjects::flightData::folderName("flightData");
const Foam::word Foam::functionObjects::flightData::fileNameH5
(
    "flightData.h5"
);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The value of an attribute entry: a word, string or number, as written
string attributeValue(const dictionary& dict, const word& key)
{
    ITstream& is = dict.lookup(key);
    const token t(is);
    if (t.isWord())
    {
        return t.wordToken();
    }
    if (t.isString())
    {
        return t.stringToken();
    }
    if (!t.isNumber())
    {
        FatalIOErrorInFunction(dict)
            << "attributes: " << key << " must be a word, string or"
            << " number" << exit(FatalIOError);
    }
    OStringStream os;
    os << t;
    return os.str();
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::RBD::motionRecord&
Foam::functionObjects::flightData::findMotion() const
{
    const HashTable<const RBD::motionRecord*> records
    (
        obr_.lookupClass<RBD::motionRecord>()
    );
    if (records.size() != 1)
    {
        FatalErrorInFunction
            << type() << " " << name() << ": the registry " << obr_.name()
            << " has " << records.size()
            << " multibody motions (" << RBD::motionRecord::typeName
            << "); flightData needs exactly one"
            << " (dynamicMeshDict: motionSolver eABAMeshMotion)"
            << exit(FatalError);
    }
    return *records.cbegin()();
}


Foam::fileName Foam::functionObjects::flightData::filePath() const
{
    const fileName base
    (
        time_.globalPath()/functionObject::outputPrefix/folderName
    );
    const scalar startTime = time_.startTime().value();

    // The latest start at or before this one that has a file
    const fileNameList dirs(readDir(base, fileName::DIRECTORY));
    scalar best = -GREAT;
    fileName bestPath;
    for (const fileName& d : dirs)
    {
        scalar t;
        if
        (
            readScalar(d, t)
         && t <= startTime + 1e-12*max(mag(startTime), VSMALL)
         && t > best
         && isFile(base/d/fileNameH5)
        )
        {
            best = t;
            bestPath = base/d/fileNameH5;
        }
    }
    return bestPath.size() ? bestPath : base/time_.timeName()/fileNameH5;
}


Foam::fileName Foam::functionObjects::flightData::keepAside
(
    const fileName& path,
    const string& damage
) const
{
    fileName aside(path + ".damaged");
    for (label i = 1; exists(aside); ++i)
    {
        aside = path + ".damaged" + Foam::name(i);
    }
    if (!mv(path, aside))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, path)
            << path << " is damaged (" << damage.c_str() << ") and cannot"
            << " be renamed to " << aside << ": move it away"
            << exit(FatalIOError);
    }

    const fileName fresh
    (
        time_.globalPath()/functionObject::outputPrefix/folderName
       /time_.timeName()/fileNameH5
    );
    WarningInFunction
        << type() << " " << name() << ": " << path << " is damaged ("
        << damage.c_str() << "): kept as " << aside << "; the flight data"
        << " of this start go to a new file " << fresh
        << " (the rows before time " << time_.timeName()
        << " are only in the damaged file)" << endl;

    return fresh;
}


Foam::List<Foam::Tuple2<Foam::word, Foam::string>>
Foam::functionObjects::flightData::attributes(const scalar startTime) const
{
    DynamicList<Tuple2<word, string>> a;

    a.append(Tuple2<word, string>("case", time_.globalCaseName()));

    // The overset stencil of a flow run ("none" without a mesh)
    word stencil("none");
    const fvMesh* mesh = isA<fvMesh>(obr_);
    if (mesh && mesh->schemesDict().found("oversetInterpolation"))
    {
        mesh->schemesDict().subDict("oversetInterpolation")
            .readIfPresent("method", stencil);
    }
    a.append(Tuple2<word, string>("stencil", stencil));
    a.append
    (
        Tuple2<word, string>("nRanks", Foam::name(Pstream::nProcs()))
    );

    string decomposition("none");
    if (Pstream::parRun())
    {
        const IOdictionary decomposeDict
        (
            IOobject
            (
                "decomposeParDict",
                time_.system(),
                time_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        decomposition =
            decomposeDict.getOrDefault<word>("method", "unknown") + " "
          + Foam::name(Pstream::nProcs());
    }
    a.append(Tuple2<word, string>("decomposition", decomposition));

    // The commit the libraries were built from (Allwmake's stamp)
    a.append(Tuple2<word, string>("commit", string(FLAPFOAM_COMMIT)));

    a.append(Tuple2<word, string>("level", "unknown"));
    for (const Tuple2<word, string>& e : extraAttributes_)
    {
        bool replaced = false;
        for (Tuple2<word, string>& old : a)
        {
            if (old.first() == e.first())
            {
                old.second() = e.second();
                replaced = true;
            }
        }
        if (!replaced)
        {
            a.append(e);
        }
    }

    return List<Tuple2<word, string>>(std::move(a));
}


void Foam::functionObjects::flightData::readCoefficients
(
    const dictionary& coeffs
)
{
    const wordList& loaded = motion_->bodies();
    const RBD::eABAMotion& model = motion_->model();

    bodies_ = loaded;
    bodyIDs_.setSize(loaded.size());
    area_.setSize(loaded.size());
    chord_.setSize(loaded.size());
    momentAbout_.setSize(loaded.size());

    for (const word& key : coeffs.toc())
    {
        if (!loaded.found(key))
        {
            FatalIOErrorInFunction(coeffs)
                << "coefficients: body " << key << " has no load or mesh;"
                << " the bodies with one are " << loaded
                << exit(FatalIOError);
        }
    }

    forAll(loaded, i)
    {
        const word& body = loaded[i];
        if (!coeffs.isDict(body))
        {
            FatalIOErrorInFunction(coeffs)
                << "coefficients: no entry for body " << body
                << " (area, chord): every body of " << loaded
                << " needs one" << exit(FatalIOError);
        }
        const dictionary& bd = coeffs.subDict(body);
        checkDictionaryKeys(bd, coefficientKeys());
        bodyIDs_[i] = model.bodyID(body);
        area_[i] = readAllowed(bd, "area", allowed::above(0.0));
        chord_[i] = readAllowed(bd, "chord", allowed::above(0.0));
        const word about(bd.getOrDefault<word>("momentAbout", body));
        momentAbout_[i] = -1;
        for (label b = 0; b < model.nBodies(); ++b)
        {
            if (model.name(b) == about)
            {
                momentAbout_[i] = b;
            }
        }
        if (momentAbout_[i] < 0)
        {
            FatalIOErrorInFunction(bd)
                << "momentAbout " << about << ": not a body of the model"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::flightData::flightData
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    regionFunctionObject(name, runTime, dict),
    rhoInf_(0),
    Uref_(0),
    motion_(nullptr)
{
    read(dict);

    // On every rank: reading decomposeParDict is collective
    const scalar startTime = time_.startTime().value();
    List<Tuple2<word, string>> a(attributes(startTime));
    a.append(Tuple2<word, string>("lastStart", time_.timeName()));

    if (Pstream::master())
    {
        fileName path(filePath());
        const string damage
        (
            isFile(path) ? flightDataFile::damage(path) : string()
        );
        if (damage.size())
        {
            path = keepAside(path, damage);
        }
        file_.reset(new flightDataFile(path, startTime));

        Info<< type() << " " << this->name() << ": " << path << " ("
            << file_->nRows() << " rows kept)" << endl;

        file_->setAttributes(a);

        // A fresh file (or one cut before this start): the initial state
        if (file_->nRows() == 0)
        {
            file_->append(makeRow(false));
        }

        if (tablesName_.size())
        {
            tables_.reset
            (
                new flightDataTables
                (
                    time_.globalPath()/functionObject::outputPrefix
                   /tablesName_/time_.timeName(),
                    *motion_
                )
            );

            // The start row of a fresh run; a restart's start row is the
            // last row of the run it continues (with its load)
            if (motion_->freshStart())
            {
                tables_->append();
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::functionObjects::flightData::keys()
{
    static const wordList k
    ({
        "rhoInf", "Uref", "coefficients", "attributes", "tables"
    });
    return k;
}


const Foam::wordList& Foam::functionObjects::flightData::coefficientKeys()
{
    static const wordList k({"area", "chord", "momentAbout"});
    return k;
}


bool Foam::functionObjects::flightData::read(const dictionary& dict)
{
    regionFunctionObject::read(dict);
    functionObjectKeys::check(dict, keys());

    rhoInf_ = readAllowed(dict, "rhoInf", allowed::above(0.0));
    Uref_ = readAllowed(dict, "Uref", allowed::above(0.0));
    tablesName_ = dict.getOrDefault<word>("tables", word::null);

    motion_ = &findMotion();
    readCoefficients(dict.subDict("coefficients"));

    extraAttributes_.clear();
    if (dict.isDict("attributes"))
    {
        const dictionary& ad = dict.subDict("attributes");
        for (const word& key : ad.toc())
        {
            extraAttributes_.append
            (
                Tuple2<word, string>(key, attributeValue(ad, key))
            );
        }
    }

    return true;
}


bool Foam::functionObjects::flightData::execute()
{
    if (Pstream::master())
    {
        file_->append(makeRow(true));
        if (tables_.valid())
        {
            tables_->append();
        }
    }
    return true;
}


bool Foam::functionObjects::flightData::write()
{
    return true;
}


// ************************************************************************* //
