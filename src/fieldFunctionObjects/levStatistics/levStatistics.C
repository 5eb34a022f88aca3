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

#include "levStatistics.H"
#include "addToRunTimeSelectionTable.H"
#include "functionObjectKeys.H"
#include "rigidFit.H"
#include "referencePoints.H"
#include "cellCellStencilObject.H"
#include "fvcGrad.H"
#include "volFields.H"
#include "bitSet.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(levStatistics, 0);
    addToRunTimeSelectionTable(functionObject, levStatistics, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::levStatistics::readZone()
{
    const label zonei = mesh_.cellZones().findZoneID(zoneName_);
    if (zonei < 0)
    {
        FatalErrorInFunction
            << type() << " " << name() << ": cellZone " << zoneName_
            << " not found; the mesh's cell zones are "
            << mesh_.cellZones().names() << exit(FatalError);
    }
    cells_ = mesh_.cellZones()[zonei];

    bitSet isZonePoint(mesh_.nPoints());
    for (const label celli : cells_)
    {
        isZonePoint.set(mesh_.cellPoints(celli));
    }
    points_ = isZonePoint.sortedToc();

    points0_ = referencePoints(mesh_, points_, type() + " " + name());
}


Foam::vector Foam::functionObjects::levStatistics::currentAxis() const
{
    const pointField points(mesh_.points(), points_);
    return rigidFit::rotation(points0_, points) & spanAxis_;
}


Foam::labelList Foam::functionObjects::levStatistics::solvedCells() const
{
    if (!mesh_.foundObject<cellCellStencilObject>(cellCellStencilObject::typeName))
    {
        return cells_;
    }
    const labelUList& types = Stencil::New(mesh_).cellTypes();
    DynamicList<label> solved(cells_.size());
    for (const label celli : cells_)
    {
        if (types[celli] != cellCellStencil::HOLE)
        {
            solved.append(celli);
        }
    }
    return labelList(std::move(solved));
}


void Foam::functionObjects::levStatistics::writeFileHeader(Ostream& os) const
{
    writeHeader(os, "Leading-edge vortex of cellZone " + zoneName_);
    writeHeader
    (
        os,
        "cells with Q > 0 and omega . e_span > 0: volume [m^3], circulation"
        " (sum of omega . e_span V) [m^3/s]"
    );
    writeCommented(os, "Time");
    for (const char* title :
        {"volume", "circulation", "nCells", "zoneVolume", "eSpan_x",
         "eSpan_y", "eSpan_z"})
    {
        writeTabbed(os, title);
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::levStatistics::levStatistics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    zoneName_(),
    spanAxis_(Zero),
    UName_("U"),
    cells_(),
    points_(),
    points0_(),
    noFieldSaid_(false)
{
    read(dict);
    readZone();
    writeFileHeader(file());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::functionObjects::levStatistics::keys()
{
    static const wordList k
    ({
        "cellZone", "spanAxis", "U", "writePrecision", "writeToFile",
        "useUserTime"
    });
    return k;
}


Foam::functionObjects::levStatistics::sums
Foam::functionObjects::levStatistics::sum
(
    const UList<tensor>& gradU,
    const scalarUList& V,
    const labelUList& cells,
    const vector& axis
)
{
    sums s{0, 0, 0};
    for (const label celli : cells)
    {
        const tensor& G = gradU[celli];
        const scalar Q = 0.5*(magSqr(skew(G)) - magSqr(symm(G)));

        // omega = curl U: omega_x = dU_z/dy - dU_y/dz, ...
        const vector omega(G.yz() - G.zy(), G.zx() - G.xz(), G.xy() - G.yx());
        const scalar omegaSpan = omega & axis;

        if (Q > 0 && omegaSpan > 0)
        {
            s.volume += V[celli];
            s.circulation += omegaSpan*V[celli];
            ++s.nCells;
        }
    }
    return s;
}


bool Foam::functionObjects::levStatistics::read(const dictionary& dict)
{
    functionObjectKeys::check(dict, keys());
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    zoneName_ = dict.get<word>("cellZone");
    spanAxis_ = dict.get<vector>("spanAxis");
    if (mag(spanAxis_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "spanAxis " << spanAxis_ << ": must be a non-zero vector"
            << " (the wing's spanwise axis at the reference points)"
            << exit(FatalIOError);
    }
    spanAxis_.normalise();
    UName_ = dict.getOrDefault<word>("U", "U");
    return true;
}


bool Foam::functionObjects::levStatistics::execute()
{
    return true;
}


bool Foam::functionObjects::levStatistics::write()
{
    if (!foundObject<volVectorField>(UName_))
    {
        // A run without flow (oversetMotionCheck): said once
        if (!noFieldSaid_)
        {
            noFieldSaid_ = true;
            WarningInFunction
                << type() << " " << name() << ": no field " << UName_
                << " (a run without flow): no rows written" << endl;
        }
        return true;
    }
    const volVectorField& U = lookupObject<volVectorField>(UName_);
    const tmp<volTensorField> tgradU(fvc::grad(U));
    const vector axis(currentAxis());

    sums s(sum(tgradU().primitiveField(), mesh_.V(), solvedCells(), axis));
    reduce(s.volume, sumOp<scalar>());
    reduce(s.circulation, sumOp<scalar>());
    reduce(s.nCells, sumOp<label>());

    scalar zoneVolume = 0;
    for (const label celli : cells_)
    {
        zoneVolume += mesh_.V()[celli];
    }
    reduce(zoneVolume, sumOp<scalar>());

    Log << type() << " " << name() << " at t = "
        << time_.timeName() << ": volume " << s.volume << " m^3 ("
        << s.nCells << " cells), circulation " << s.circulation
        << " m^3/s, span axis " << axis << endl;

    if (Pstream::master())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << s.volume << tab << s.circulation << tab << s.nCells
            << tab << zoneVolume << tab << axis.x() << tab << axis.y()
            << tab << axis.z() << endl;
    }
    return true;
}


// ************************************************************************* //
