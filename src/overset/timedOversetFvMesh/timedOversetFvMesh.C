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

#include "timedOversetFvMesh.H"
#include "cellCellStencilObject.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "coupledFvPatchField.H"
#include "oversetRankReport.H"
#include "dictionaryRead.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(timedOversetFvMesh, 0);

    addToRunTimeSelectionTable(dynamicFvMesh, timedOversetFvMesh, IOobject);
}

const Foam::Enum<Foam::timedOversetFvMesh::rankReportMode>
Foam::timedOversetFvMesh::rankReportModeNames
({
    { rankReportMode::none, "none" },
    { rankReportMode::first, "first" },
    { rankReportMode::every, "every" },
});

const Foam::word Foam::timedOversetFvMesh::movePointsPart
(
    "oversetMovePoints"
);

const Foam::word Foam::timedOversetFvMesh::addressingPart
(
    "oversetAddressing"
);

const Foam::word Foam::timedOversetFvMesh::interpolatePart
(
    "oversetInterpolate"
);

const Foam::word Foam::timedOversetFvMesh::waitPart
(
    "oversetWait"
);

const Foam::word Foam::timedOversetFvMesh::pimpleInterpolatePart
(
    "pimpleOversetInterpolate"
);

const Foam::word Foam::timedOversetFvMesh::preUpdateInterpolatePart
(
    "preUpdateOversetInterpolate"
);

const Foam::word Foam::timedOversetFvMesh::pressureSolvePart
(
    "pimplePressureSolve"
);

const Foam::word Foam::timedOversetFvMesh::momentumSolvePart
(
    "pimpleMomentumSolve"
);

const Foam::word Foam::timedOversetFvMesh::otherSolvePart
(
    "pimpleOtherSolve"
);

const Foam::word Foam::timedOversetFvMesh::pimpleInterpolationsPart
(
    "pimpleInterpolations"
);

const Foam::word Foam::timedOversetFvMesh::pressureIterationsPart
(
    "pIterations"
);


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::timedOversetFvMesh::timedInterpolate(Field<Type>& psi) const
{
    if (updating_)
    {
        interpolateField(psi);
    }
    else if (timers_.stamped(stepTimers::meshUpdated))
    {
        stepTimers::scope timer(timers_, pimpleInterpolatePart);
        interpolateField(psi);
        timers_.count(pimpleInterpolationsPart, 1);
    }
    else
    {
        // Before the update: the function objects after stepTimers (e.g.
        // flightData's forces), within the next step's preUpdate
        stepTimers::scope timer(timers_, preUpdateInterpolatePart);
        interpolateField(psi);
    }
}


template<class Type>
void Foam::timedOversetFvMesh::interpolateField(Field<Type>& psi) const
{
    if (!compact_)
    {
        dynamicOversetFvMesh::interpolate(psi);
        return;
    }
    const cellCellStencil& overlap = Stencil::New(*this);
    if (overlap.cellStencil().size() != nCells())
    {
        return;     // as the base: no stencil yet
    }
    if (!compactPtr_.valid())
    {
        compactPtr_.reset(new compactInterpolation(overlap));
    }
    if (compactPtr_->valid())
    {
        compactPtr_->interpolate(overlap, psi);
    }
    else
    {
        dynamicOversetFvMesh::interpolate(psi);
    }
}


template<class Type>
const Foam::word& Foam::timedOversetFvMesh::solvePart(const fvMatrix<Type>& m)
{
    if (std::is_same<Type, vector>::value)
    {
        return momentumSolvePart;
    }
    const word& name = m.psi().name();
    if (std::is_same<Type, scalar>::value && (name == "p" || name == "p_rgh"))
    {
        return pressureSolvePart;
    }
    return otherSolvePart;
}


template<class Type>
Foam::SolverPerformance<Type> Foam::timedOversetFvMesh::timedSolve
(
    fvMatrix<Type>& m,
    const dictionary& dict
) const
{
    stepTimers::scope timer(timers_, solvePart(m));
    return dynamicOversetFvMesh::solve(m, dict);
}


template<class GeoField>
void Foam::timedOversetFvMesh::correctCoupledPatches()
{
    typedef typename GeoField::value_type Type;

    for (const word& name : this->sortedNames<GeoField>())
    {
        GeoField& fld = this->lookupObjectRef<GeoField>(name);
        correctBoundaryConditions<GeoField, coupledFvPatchField<Type>>
        (
            fld.boundaryFieldRef(),
            true
        );
    }
}


void Foam::timedOversetFvMesh::readOptions()
{
    IOobject dictHeader
    (
        "dynamicMeshDict",
        thisDb().time().constant(),
        thisDb(),
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!dictHeader.typeHeaderOk<IOdictionary>(false, false))
    {
        return;
    }
    const IOdictionary dict(dictHeader);
    timeWait_ =
        Pstream::parRun() && dict.getOrDefault<bool>("timeWait", false);
    compact_ = dict.getOrDefault<bool>("compactInterpolation", true);
    rankReport_ =
        readChoice
        (
            dict, "rankReport", rankReportModeNames, rankReportMode::first
        );
}


void Foam::timedOversetFvMesh::reportRanks()
{
    if
    (
        rankReport_ == rankReportMode::every
     || (rankReport_ == rankReportMode::first && !reported_)
    )
    {
        oversetRankReport(*this).write(Info);
        reported_ = true;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::timedOversetFvMesh::timedOversetFvMesh(const IOobject& io)
:
    dynamicOversetFvMesh(io),
    timers_(stepTimers::New(io.time())),
    updating_(false),
    timeWait_(false),
    rankReport_(rankReportMode::first),
    reported_(false),
    compact_(true),
    compactPtr_(),
    pressureSolvesIndex_(-1),
    nPressureSolves_(0)
{
    readOptions();

    // Register the parts in the order of a step, for the file header
    timers_.add(movePointsPart, 0);
    timers_.add(addressingPart, 0);
    timers_.add(interpolatePart, 0);
    if (timeWait_)
    {
        timers_.add(waitPart, 0);
    }
    timers_.add(pimpleInterpolatePart, 0);
    timers_.add(preUpdateInterpolatePart, 0);
    timers_.add(pressureSolvePart, 0);
    timers_.add(momentumSolvePart, 0);
    timers_.add(otherSolvePart, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::timedOversetFvMesh::interpolate(scalarField& psi) const
{
    timedInterpolate(psi);
}


void Foam::timedOversetFvMesh::interpolate(vectorField& psi) const
{
    timedInterpolate(psi);
}


void Foam::timedOversetFvMesh::interpolate(sphericalTensorField& psi) const
{
    timedInterpolate(psi);
}


void Foam::timedOversetFvMesh::interpolate(symmTensorField& psi) const
{
    timedInterpolate(psi);
}


void Foam::timedOversetFvMesh::interpolate(tensorField& psi) const
{
    timedInterpolate(psi);
}


Foam::SolverPerformance<Foam::scalar> Foam::timedOversetFvMesh::solve
(
    fvMatrix<scalar>& m,
    const dictionary& dict
) const
{
    const SolverPerformance<scalar> perf(timedSolve(m, dict));

    if (&solvePart(m) == &pressureSolvePart)
    {
        if (pressureSolvesIndex_ != time().timeIndex())
        {
            pressureSolvesIndex_ = time().timeIndex();
            nPressureSolves_ = 0;
        }
        timers_.count
        (
            pressureIterationsPart + Foam::name(++nPressureSolves_),
            perf.nIterations()
        );
    }

    return perf;
}


Foam::SolverPerformance<Foam::vector> Foam::timedOversetFvMesh::solve
(
    fvMatrix<vector>& m,
    const dictionary& dict
) const
{
    return timedSolve(m, dict);
}


Foam::SolverPerformance<Foam::symmTensor> Foam::timedOversetFvMesh::solve
(
    fvMatrix<symmTensor>& m,
    const dictionary& dict
) const
{
    return timedSolve(m, dict);
}


Foam::SolverPerformance<Foam::tensor> Foam::timedOversetFvMesh::solve
(
    fvMatrix<tensor>& m,
    const dictionary& dict
) const
{
    return timedSolve(m, dict);
}


bool Foam::timedOversetFvMesh::update()
{
    timers_.stamp(stepTimers::meshUpdateStart);

    updating_ = true;

    // The stencil changes with the motion: its compact exchange is built
    // again at the next interpolation
    compactPtr_.clear();

    bool changed = false;
    {
        stepTimers::scope timer(timers_, movePointsPart);
        changed = dynamicMotionSolverListFvMesh::update();
    }
    compactPtr_.clear();

    if (changed)
    {
        {
            stepTimers::scope timer(timers_, addressingPart);
            updateAddressing();
        }
        {
            stepTimers::scope timer(timers_, interpolatePart);
            interpolateFields();
            if (Pstream::parRun())
            {
                correctCoupledPatches<volScalarField>();
                correctCoupledPatches<volVectorField>();
                correctCoupledPatches<volSphericalTensorField>();
                correctCoupledPatches<volSymmTensorField>();
                correctCoupledPatches<volTensorField>();
            }
        }
    }

    if (timeWait_)
    {
        stepTimers::scope timer(timers_, waitPart);
        returnReduce(true, andOp<bool>());
    }

    updating_ = false;

    reportRanks();

    timers_.stamp(stepTimers::meshUpdated);

    return changed;
}


// ************************************************************************* //
