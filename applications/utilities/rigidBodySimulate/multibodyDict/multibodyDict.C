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

#include "multibodyDict.H"
#include "eABAMotion.H"
#include "eABAMeshMotionKeys.H"
#include "StringStream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// " a b c" for error messages
Foam::string listed(const Foam::wordList& names)
{
    Foam::OStringStream os;
    for (const Foam::word& n : names)
    {
        os << ' ' << n;
    }
    return os.str();
}

const Foam::word coeffsName("eABAMeshMotionCoeffs");

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::multibodyDict::dictIO
(
    const Time& runTime,
    const argList& args
)
{
    const IOobject defaultIO
    (
        "dynamicMeshDict",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );

    const fileName file(args.getOrDefault<fileName>("dict", fileName()));
    const IOobject io(IOobject::selectIO(defaultIO, file));

    if (!isFile(io.objectPath()))
    {
        FatalErrorInFunction
            << (file.empty() ? "" : "Option -dict " + file + ": ")
            << "no file " << io.objectPath().c_str() << nl
            << "    allowed: a dictionary file (absolute, ./ or ../ from the"
            << " working directory, else relative to the case)" << nl
            << exit(FatalError);
    }

    return io;
}


const Foam::dictionary* Foam::multibodyDict::modelOf(const dictionary& d)
{
    const dictionary* coeffsPtr = d.findDict(coeffsName, keyType::LITERAL);

    if (coeffsPtr && coeffsPtr->found("bodies", keyType::LITERAL))
    {
        return coeffsPtr;
    }

    return d.found("bodies", keyType::LITERAL) ? &d : nullptr;
}


Foam::wordList Foam::multibodyDict::modelSolvers() const
{
    wordList names;

    const dictionary* solversPtr =
        meshDict_.findDict("solvers", keyType::LITERAL);

    if (solversPtr)
    {
        for (const entry& e : *solversPtr)
        {
            if (e.isDict() && modelOf(e.dict()))
            {
                names.append(e.keyword());
            }
        }
    }

    return names;
}


void Foam::multibodyDict::selectSolver(const word& name)
{
    const wordList names(modelSolvers());
    const dictionary* solverPtr =
        names.found(name)
      ? meshDict_.subDict("solvers").findDict(name, keyType::LITERAL)
      : nullptr;

    if (!solverPtr)
    {
        FatalIOErrorInFunction(meshDict_)
            << "Option -solver " << name << ": "
            << meshDict_.objectPath().c_str()
            << " has no sub-dictionary solvers/" << name
            << " with a multibody model ('bodies'): allowed"
            << (names.empty() ? " none" : listed(names).c_str()) << nl
            << exit(FatalIOError);
    }

    modelDictPtr_ = modelOf(*solverPtr);
    location_ = "solvers/" + name;
    if (modelDictPtr_ != solverPtr)
    {
        location_ += "/" + coeffsName;
    }
}


void Foam::multibodyDict::findModel()
{
    modelDictPtr_ = modelOf(meshDict_);

    if (modelDictPtr_)
    {
        location_ = modelDictPtr_ == &meshDict_ ? "" : coeffsName;
        return;
    }

    const wordList names(modelSolvers());

    if (names.size() == 1)
    {
        selectSolver(names.first());
        return;
    }

    const fileName file(meshDict_.objectPath());

    FatalIOErrorInFunction(meshDict_)
        << (
               names.empty()
             ? "No multibody model ('bodies') in " + file
             + ": looked at the top level, in " + coeffsName
             + " and in the sub-dictionaries of solvers"
             : "Several multibody models in solvers of " + file
             + ":" + listed(names) + "; choose one with -solver NAME"
           ).c_str()
        << nl << exit(FatalIOError);
}


void Foam::multibodyDict::checkKeys() const
{
    const dictionary& model = dict();

    // The dictionary of the mesh motion solver that holds the model, if any
    const bool inCoeffs = location_.ends_with(coeffsName);
    const dictionary& owner = inCoeffs ? model.parent() : model;
    const word motionSolver
    (
        owner.getOrDefault<word>("motionSolver", word::null)
    );

    if (motionSolver.empty() && !inCoeffs)
    {
        // rigidBodySimulate's own dictionary: the model's keys and those
        // of the loads it can take without a mesh
        wordList loadKeys(bodyLoad::keys());
        loadKeys.append(bodyLoads::aerodynamics::keys());
        RBD::multibodyKeys(loadKeys, wordList(), "those of the loads")
            .check(model);
        return;
    }

    if (motionSolver == "eABAMeshMotion" || motionSolver.empty())
    {
        // The mesh motion's own check: what the CFD refuses is refused
        // here (the keys only the mesh reads are allowed, not used)
        eABAMeshMotionKeys::check(owner, model);
    }
    else
    {
        wordList unused;
        for (const entry& e : model)
        {
            if (!RBD::eABAMotion::keys().found(e.keyword()))
            {
                unused.append(e.keyword());
            }
        }

        IOWarningInFunction(owner)
            << "motionSolver " << motionSolver << " in "
            << location_.c_str()
            << " is not flapFoam's (eABAMeshMotion): rigidBodySimulate runs"
            << " its multibody model without a mesh and ignores the keys"
            << listed(unused).c_str()
            << " (docs/paperCode.md)" << endl;
    }

    reportOtherSolvers();
}


void Foam::multibodyDict::reportOtherSolvers() const
{
    wordList notRun;
    const dictionary* solversPtr =
        meshDict_.findDict("solvers", keyType::LITERAL);
    if (solversPtr)
    {
        for (const entry& e : *solversPtr)
        {
            if (!location_.starts_with("solvers/" + e.keyword() + "/")
             && location_ != "solvers/" + e.keyword())
            {
                notRun.append(e.keyword());
            }
        }
    }
    if (notRun.size())
    {
        IOWarningInFunction(*solversPtr)
            << "Mesh motions in solvers that rigidBodySimulate does not"
            << " run:" << listed(notRun).c_str() << endl;
    }
}



// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::multibodyDict::addOptions()
{
    argList::addOption
    (
        "dict",
        "file",
        "The dictionary with the multibody model"
        " (default: constant/dynamicMeshDict)"
    );
    argList::addOption
    (
        "solver",
        "name",
        "The sub-dictionary of solvers with the multibody model (needed"
        " when several have bodies)"
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::multibodyDict::multibodyDict(const Time& runTime, const argList& args)
:
    meshDict_(dictIO(runTime, args)),
    location_(),
    modelDictPtr_(nullptr)
{
    word name;
    if (args.readIfPresent("solver", name))
    {
        selectSolver(name);
    }
    else
    {
        findModel();
    }

    Info<< "Multibody model: " << meshDict_.objectPath().c_str() << ' '
        << (location_.empty() ? "(top level)" : location_.c_str()) << nl;

    checkKeys();
}


// ************************************************************************* //
