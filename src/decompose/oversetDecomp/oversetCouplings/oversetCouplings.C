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

#include "oversetCouplings.H"
#include "cellCellStencilObject.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(oversetCouplings, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::oversetCouplings::sortPairs()
{
    List<labelPair> pairs(pairPoses_.sortedToc());
    acceptors_.setSize(pairs.size());
    donors_.setSize(pairs.size());
    poses_.setSize(pairs.size());
    forAll(pairs, i)
    {
        acceptors_[i] = pairs[i].first();
        donors_[i] = pairs[i].second();
        poses_[i] = pairPoses_[pairs[i]];
    }
}


template<class Type>
void Foam::oversetCouplings::readEntry
(
    Istream& is,
    const word& key,
    Type& value
)
{
    const word found(is);
    if (found == key)
    {
        is >> value;
    }
    const token end(is);
    if (found != key || end != token::END_STATEMENT)
    {
        FatalIOErrorInFunction(is)
            << "entry '" << found << "' where '" << key << "' ended by ';'"
            << " is expected"
            << " (an oversetCouplings file lists nCells, nPoses,"
            << " acceptorPoses, donorPoses, holePoses, acceptors, donors,"
            << " poses, sampleEvery, samplePoseStart, sampleAcceptors,"
            << " sampleDonorStart, sampleDonors in this order)"
            << exit(FatalIOError);
    }
}


void Foam::oversetCouplings::checkRead(const label nCells) const
{
    const auto checkList =
        [&](const word& key, const labelList& list, label size, label max)
    {
        const bool inRange =
            list.empty() || (min(list) >= 0 && Foam::max(list) <= max);
        if (list.size() != size || !inRange)
        {
            FatalIOErrorInFunction(objectPath())
                << key << ": a list of " << list.size() << " labels, min "
                << (list.size() ? min(list) : 0) << ", max "
                << (list.size() ? Foam::max(list) : 0) << " where " << size
                << " labels in [0, " << max << "] are allowed (couplings"
                << " of a mesh of " << nCells << " cells over " << nPoses_
                << " poses)" << exit(FatalIOError);
        }
    };
    checkList("acceptorPoses", acceptorPoses_, nCells, nPoses_);
    checkList("holePoses", holePoses_, nCells, nPoses_);
    checkList("donorPoses", donorPoses_, nCells, labelMax);
    checkList("acceptors", acceptors_, acceptors_.size(), nCells - 1);
    checkList("donors", donors_, acceptors_.size(), nCells - 1);
    checkList("poses", poses_, acceptors_.size(), nPoses_);
    const label nEntries = sampleAcceptors_.size();
    checkList
    (
        "samplePoseStart", samplePoseStart_,
        max(1, samplePoseStart_.size()), nEntries
    );
    checkList("sampleAcceptors", sampleAcceptors_, nEntries, nCells - 1);
    checkList
    (
        "sampleDonorStart", sampleDonorStart_, nEntries + 1,
        sampleDonors_.size()
    );
    checkList
    (
        "sampleDonors", sampleDonors_, sampleDonors_.size(), nCells - 1
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::oversetCouplings::oversetCouplings
(
    const fvMesh& mesh,
    const label sampleEvery
)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    ),
    nPoses_(0),
    acceptorPoses_(mesh.nCells(), Zero),
    donorPoses_(mesh.nCells(), Zero),
    holePoses_(mesh.nCells(), Zero),
    sampleEvery_(sampleEvery),
    samplePoseStart_(1, Zero),
    sampleDonorStart_(1, Zero)
{
    if (sampleEvery_ < 1)
    {
        FatalErrorInFunction
            << "sampleEvery " << sampleEvery_ << ": a positive integer is"
            << " allowed" << exit(FatalError);
    }
}


Foam::oversetCouplings::oversetCouplings
(
    const objectRegistry& obr,
    const fileName& file,
    const label nCells
)
:
    regIOobject
    (
        IOobject
        (
            file.isAbsolute() ? file : obr.time().path()/file,
            obr,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    ),
    nPoses_(0),
    sampleEvery_(1)
{
    if (!typeHeaderOk<oversetCouplings>(true))
    {
        FatalErrorInFunction
            << "No oversetCouplings file " << objectPath() << nl
            << "Collect the couplings first: oversetMotionCheck -couplings"
            << " (a drone case: Allrun -motionOnly -couplings)"
            << exit(FatalError);
    }
    readData(readStream(typeName));
    close();
    if (acceptorPoses_.size() != nCells)
    {
        FatalIOErrorInFunction(objectPath())
            << "nCells " << acceptorPoses_.size() << ": the couplings of"
            << " another mesh; this mesh has " << nCells << " cells (collect"
            << " them again: oversetMotionCheck -couplings)"
            << exit(FatalIOError);
    }
    checkRead(nCells);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::oversetCouplings::addPose(const fvMesh& mesh)
{
    if (Pstream::parRun() || mesh.nCells() != acceptorPoses_.size())
    {
        FatalErrorInFunction
            << "couplings are collected on the undecomposed mesh of "
            << acceptorPoses_.size() << " cells in a serial run (this run: "
            << mesh.nCells() << " cells"
            << (Pstream::parRun() ? ", parallel)" : ")") << exit(FatalError);
    }
    const cellCellStencilObject& overlap = Stencil::New(mesh);
    const labelUList& types = overlap.cellTypes();
    const labelListList& stencil = overlap.cellStencil();
    const bool sample = (nPoses_ % sampleEvery_ == 0);
    forAll(types, celli)
    {
        if (types[celli] == cellCellStencil::HOLE)
        {
            ++holePoses_[celli];
        }
        else if (types[celli] == cellCellStencil::INTERPOLATED)
        {
            ++acceptorPoses_[celli];
            for (const label donori : stencil[celli])
            {
                ++donorPoses_[donori];
                ++pairPoses_(labelPair(celli, donori), 0);
            }
            if (sample)
            {
                sampleAcceptors_.append(celli);
                sampleDonors_.append(stencil[celli]);
                sampleDonorStart_.append(sampleDonors_.size());
            }
        }
    }
    if (sample)
    {
        samplePoseStart_.append(sampleAcceptors_.size());
    }
    ++nPoses_;
}


void Foam::oversetCouplings::keepOnly(const label sample)
{
    if (sample < 0 || sample >= nSamples())
    {
        FatalIOErrorInFunction(objectPath())
            << "pose " << sample << ": one of the " << nSamples()
            << " poses kept whole, 0 to " << nSamples() - 1 << ", is allowed"
            << " (kept pose k is pose k*" << sampleEvery_ << " of the "
            << nPoses_ << " collected)" << exit(FatalIOError);
    }
    acceptorPoses_ = Zero;
    donorPoses_ = Zero;
    holePoses_ = Zero;
    pairPoses_.clear();
    DynamicList<label> acceptors;
    DynamicList<label> donorStart(1, Zero);
    DynamicList<label> donors;
    for
    (
        label i = samplePoseStart_[sample];
        i < samplePoseStart_[sample + 1];
        ++i
    )
    {
        const label celli = sampleAcceptors_[i];
        ++acceptorPoses_[celli];
        acceptors.append(celli);
        for (label j = sampleDonorStart_[i]; j < sampleDonorStart_[i + 1]; ++j)
        {
            const label donori = sampleDonors_[j];
            ++donorPoses_[donori];
            ++pairPoses_(labelPair(celli, donori), 0);
            donors.append(donori);
        }
        donorStart.append(donors.size());
    }
    sortPairs();
    pairPoses_.clear();
    nPoses_ = 1;
    sampleEvery_ = 1;
    samplePoseStart_ = labelList({0, acceptors.size()});
    sampleAcceptors_.transfer(acceptors);
    sampleDonorStart_.transfer(donorStart);
    sampleDonors_.transfer(donors);
}


void Foam::oversetCouplings::writeCouplings()
{
    sortPairs();
    regIOobject::write();
    Info<< "Wrote " << objectPath() << ": " << nPoses_ << " poses, "
        << acceptors_.size() << " donor-acceptor pairs" << endl;
}


bool Foam::oversetCouplings::readData(Istream& is)
{
    label nCells = 0;
    readEntry(is, "nCells", nCells);
    readEntry(is, "nPoses", nPoses_);
    if (nCells < 0 || nPoses_ < 1)
    {
        FatalIOErrorInFunction(is)
            << "nCells " << nCells << ", nPoses " << nPoses_
            << ": nCells >= 0 and nPoses >= 1 are allowed"
            << exit(FatalIOError);
    }
    readEntry(is, "acceptorPoses", acceptorPoses_);
    if (acceptorPoses_.size() != nCells)
    {
        FatalIOErrorInFunction(is)
            << "nCells " << nCells << " but acceptorPoses lists "
            << acceptorPoses_.size() << " cells: one entry per cell is"
            << " allowed" << exit(FatalIOError);
    }
    readEntry(is, "donorPoses", donorPoses_);
    readEntry(is, "holePoses", holePoses_);
    readEntry(is, "acceptors", acceptors_);
    readEntry(is, "donors", donors_);
    readEntry(is, "poses", poses_);
    readEntry(is, "sampleEvery", sampleEvery_);
    readEntry(is, "samplePoseStart", samplePoseStart_);
    readEntry(is, "sampleAcceptors", sampleAcceptors_);
    readEntry(is, "sampleDonorStart", sampleDonorStart_);
    readEntry(is, "sampleDonors", sampleDonors_);
    return is.good();
}


bool Foam::oversetCouplings::writeData(Ostream& os) const
{
    os.writeEntry("nCells", nCells());
    os.writeEntry("nPoses", nPoses_);
    os.writeEntry("acceptorPoses", acceptorPoses_);
    os.writeEntry("donorPoses", donorPoses_);
    os.writeEntry("holePoses", holePoses_);
    os.writeEntry("acceptors", acceptors_);
    os.writeEntry("donors", donors_);
    os.writeEntry("poses", poses_);
    os.writeEntry("sampleEvery", sampleEvery_);
    os.writeEntry("samplePoseStart", samplePoseStart_);
    os.writeEntry("sampleAcceptors", sampleAcceptors_);
    os.writeEntry("sampleDonorStart", sampleDonorStart_);
    os.writeEntry("sampleDonors", sampleDonors_);
    return os.good();
}


// ************************************************************************* //
