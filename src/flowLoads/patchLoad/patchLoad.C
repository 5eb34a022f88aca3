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

#include "patchLoad.H"
#include "dictionaryRead.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "turbulenceModel.H"
#include "incompressibleTurbulenceModel.H"
#include "transportModel.H"
#include "patchLoadKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyLoads
{
    defineTypeNameAndDebug(patchLoad, 0);
    addToRunTimeSelectionTable(bodyLoad, patchLoad, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bodyLoads::patchLoad::readBodies(const dictionary& dict)
{
    const dictionary& bodiesDict = dict.subDict("bodies");
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    DynamicList<label> bodyIDs;
    DynamicList<labelList> patchIDs;

    for (const entry& e : bodiesDict)
    {
        if (!e.isDict() || !e.dict().found("patches"))
        {
            continue;
        }

        const dictionary& bodyDict = e.dict();
        const word& name = e.keyword();
        bodyIDs.append(treeBodyID(model_, name, bodyDict));

        const wordRes patchNames(bodyDict.get<wordRes>("patches"));
        patchIDs.append(patches.patchSet(patchNames).sortedToc());

        if (patchIDs.last().empty())
        {
            FatalIOErrorInFunction(bodyDict)
                << "patches " << patchNames << " of body " << name
                << " match no patch; the mesh has " << patches.names()
                << exit(FatalIOError);
        }
    }

    bodyIDs_.transfer(bodyIDs);
    patchIDs_.transfer(patchIDs);
}


Foam::scalar Foam::bodyLoads::patchLoad::rhoP(const volScalarField& p) const
{
    if (p.dimensions() == dimPressure)
    {
        return 1;
    }

    if (rhoName_ != "rhoInf")
    {
        FatalErrorInFunction
            << "p " << pName_ << " is kinematic (" << p.dimensions()
            << "): the density must be rhoInf, not the field " << rhoName_
            << exit(FatalError);
    }

    return rhoInf_;
}


Foam::tmp<Foam::scalarField>
Foam::bodyLoads::patchLoad::rho(const label patchi) const
{
    if (rhoName_ == "rhoInf")
    {
        return tmp<scalarField>::New
        (
            mesh_.boundary()[patchi].size(),
            rhoInf_
        );
    }

    return mesh_.lookupObject<volScalarField>(rhoName_).boundaryField()[patchi];
}


Foam::tmp<Foam::scalarField> Foam::bodyLoads::patchLoad::viscosity
(
    const label patchi,
    const bool kinematic
) const
{
    const turbulenceModel* turb =
        mesh_.cfindObject<turbulenceModel>(turbulenceModel::propertiesName);

    if (turb)
    {
        if (kinematic)
        {
            return turb->nuEff(patchi);
        }
        if (isA<incompressibleTurbulenceModel>(*turb))
        {
            return rho(patchi)*turb->nuEff(patchi);
        }
        return turb->muEff(patchi);
    }

    const transportModel* laminar =
        mesh_.cfindObject<transportModel>("transportProperties");

    if (laminar)
    {
        if (kinematic)
        {
            return laminar->nu(patchi);
        }
        return rho(patchi)*laminar->nu(patchi);
    }

    FatalErrorInFunction
        << "no viscosity: neither a turbulence model ("
        << turbulenceModel::propertiesName << ") nor a laminar transport"
        << " model (transportProperties) is registered"
        << exit(FatalError);

    return nullptr;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyLoads::patchLoad::patchLoad
(
    const objectRegistry& db,
    const RBD::rigidBodyModel& model,
    const dictionary& dict
)
:
    bodyLoad(db, model),
    mesh_(refCast<const fvMesh>(db)),
    pName_(dict.getOrDefault<word>("p", "p")),
    UName_(dict.getOrDefault<word>("U", "U")),
    rhoName_(dict.getOrDefault<word>("rho", "rhoInf")),
    rhoInf_(0)
{
    if (rhoName_ == "rhoInf")
    {
        rhoInf_ = readAllowed(dict, "rhoInf", allowed::above(0.0));
    }

    readBodies(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::bodyLoads::patchLoad::keys()
{
    return patchLoadKeys::coeffs();
}


void Foam::bodyLoads::patchLoad::loads
(
    const RBD::rigidBodyModelState&,
    Field<spatialVector>& fx
) const
{
    fx = Zero;

    const volScalarField& p = mesh_.lookupObject<volScalarField>(pName_);
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    const bool kinematic = (p.dimensions() != dimPressure);
    const scalar rhoP = this->rhoP(p);

    forAll(bodyIDs_, i)
    {
        vector force(Zero);
        vector moment(Zero);

        for (const label patchi : patchIDs_[i])
        {
            const vectorField& Sf = mesh_.Sf().boundaryField()[patchi];
            const scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
            const vectorField& Cf = mesh_.Cf().boundaryField()[patchi];

            // Pressure on the body (Sf points out of the fluid, into the
            // body) and the wall shear from the patch normal gradient
            const vectorField dF
            (
                rhoP
               *(
                   p.boundaryField()[patchi]*Sf
                 - viscosity(patchi, kinematic)*magSf
                  *U.boundaryField()[patchi].snGrad()
                )
            );

            force += sum(dF);
            moment += sum(Cf ^ dF);
        }

        reduce(force, sumOp<vector>());
        reduce(moment, sumOp<vector>());

        fx[bodyIDs_[i]] = spatialVector(moment, force);
    }
}


// ************************************************************************* //
