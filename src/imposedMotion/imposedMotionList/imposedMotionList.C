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

#include "imposedMotionList.H"
#include "StringStream.H"
#include "imposedMotionKey.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::imposedMotionList::readMotions
(
    const dictionary& motionsDict,
    const word& key
)
{
    for (const entry& e : motionsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(motionsDict)
                << "Entry '" << e.keyword() << "' of '" << key
                << "' is not a dictionary: each entry is one motion"
                << " { type ...; ... }" << nl
                << exit(FatalIOError);
        }

        append(imposedMotion::New(e.keyword(), e.dict()));
    }
}


void Foam::imposedMotionList::checkJoint
(
    const label motioni,
    const label j,
    const labelUList& jointDoF,
    const labelUList& ownerMotion
) const
{
    const imposedMotion& motion = operator[](motioni);
    const label nDoF = jointDoF.size();

    if (j < 0 || j >= nDoF)
    {
        FatalIOErrorInFunction(motion.dict())
            << "Entry '" << motion.jointsKey() << "' of '"
            << motion.name() << "': joint " << j
            << " is out of range: the model has " << nDoF
            << " degrees of freedom, allowed 0.." << nDoF - 1 << nl
            << exit(FatalIOError);
    }

    if (jointDoF[j] != 1)
    {
        FatalIOErrorInFunction(motion.dict())
            << "Entry '" << motion.jointsKey() << "' of '"
            << motion.name() << "': joint " << j
            << " belongs to a joint with " << jointDoF[j]
            << " degrees of freedom; only 1-DoF joints can be"
            << " prescribed" << nl
            << exit(FatalIOError);
    }

    if (ownerMotion[j] >= 0)
    {
        const imposedMotion& other = operator[](ownerMotion[j]);

        OStringStream by;
        if (ownerMotion[j] == motioni)
        {
            by  << "it appears twice in '" << motion.jointsKey()
                << "' of '" << motion.name() << "'";
        }
        else
        {
            by  << "by '" << other.name() << "' ('"
                << other.jointsKey() << "') and by '"
                << motion.name() << "' ('" << motion.jointsKey()
                << "')";
        }

        FatalIOErrorInFunction(motion.dict())
            << "Entry '" << motion.jointsKey() << "' of '"
            << motion.name() << "': joint " << j
            << " is prescribed twice: " << by.str().c_str() << nl
            << exit(FatalIOError);
    }
}


void Foam::imposedMotionList::findOwners
(
    const labelUList& jointDoF,
    labelList& ownerMotion,
    labelList& ownerLocal
) const
{
    const label nDoF = jointDoF.size();

    ownerMotion.setSize(nDoF);
    ownerMotion = -1;
    ownerLocal.setSize(nDoF);
    ownerLocal = -1;

    forAll(*this, motioni)
    {
        const labelList& joints = operator[](motioni).joints();

        forAll(joints, locali)
        {
            const label j = joints[locali];

            checkJoint(motioni, j, jointDoF, ownerMotion);

            ownerMotion[j] = motioni;
            ownerLocal[j] = locali;
        }
    }
}


void Foam::imposedMotionList::setJoints
(
    const labelUList& ownerMotion,
    const labelUList& ownerLocal
)
{
    // Prescribed joints, ascending
    label nPrescribed = 0;
    for (const label motioni : ownerMotion)
    {
        if (motioni >= 0)
        {
            ++nPrescribed;
        }
    }

    joints_.setSize(nPrescribed);
    motionI_.setSize(nPrescribed);
    localI_.setSize(nPrescribed);

    label k = 0;
    forAll(ownerMotion, j)
    {
        if (ownerMotion[j] >= 0)
        {
            joints_[k] = j;
            motionI_[k] = ownerMotion[j];
            localI_[k] = ownerLocal[j];
            ++k;
        }
    }
}


Foam::label Foam::imposedMotionList::findEntry(const word& entryName) const
{
    forAll(*this, motioni)
    {
        if (operator[](motioni).name() == entryName)
        {
            return motioni;
        }
    }

    OStringStream names;
    for (const imposedMotion& motion : *this)
    {
        names << ' ' << motion.name();
    }

    FatalErrorInFunction
        << "No imposedMotion entry '" << entryName << "': the entries are"
        << (size() ? names.str().c_str() : " none") << nl
        << exit(FatalError);

    return -1;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::imposedMotionList::imposedMotionList
(
    const dictionary& modelDict,
    const labelUList& jointDoF
)
:
    PtrList<imposedMotion>(),
    joints_(),
    motionI_(),
    localI_(),
    blends_()
{
    const word key(imposedMotionKey(modelDict));

    if (key.empty())
    {
        return;     // no prescribed joint
    }

    const dictionary* motionsDictPtr =
        modelDict.findDict(key, keyType::LITERAL);

    if (!motionsDictPtr)
    {
        FatalIOErrorInFunction(modelDict)
            << "Entry '" << key << "' is not a dictionary" << nl
            << exit(FatalIOError);
    }

    // Read the motions: one per sub-dictionary
    readMotions(*motionsDictPtr, key);

    // Check the driven joints against the model.  For each q index: the
    // motion driving it (-1: none) and the index in that motion's joints()
    labelList ownerMotion;
    labelList ownerLocal;
    findOwners(jointDoF, ownerMotion, ownerLocal);

    setJoints(ownerMotion, ownerLocal);

    blends_.setSize(size());
    forAll(*this, motioni)
    {
        blends_.set(motioni, new imposedMotionBlend(operator[](motioni)));
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

void Foam::imposedMotionList::evaluate
(
    const scalar t,
    scalarField& q,
    scalarField& qDot,
    scalarField& qDdot
) const
{
    if
    (
        joints_.size()
     && (
            joints_.last() >= q.size()
         || joints_.last() >= qDot.size()
         || joints_.last() >= qDdot.size()
        )
    )
    {
        FatalErrorInFunction
            << "State of sizes " << q.size() << ' ' << qDot.size() << ' '
            << qDdot.size() << " too small for the prescribed joint "
            << joints_.last() << exit(FatalError);
    }

    forAll(joints_, k)
    {
        const label j = joints_[k];

        blends_[motionI_[k]].evaluate
        (
            localI_[k],
            t,
            q[j],
            qDot[j],
            qDdot[j]
        );
    }
}


void Foam::imposedMotionList::write(Ostream& os) const
{
    os.beginBlock("imposedMotion");

    forAll(*this, motioni)
    {
        const imposedMotion& motion = operator[](motioni);

        os.beginBlock(motion.name());
        motion.write(os);
        os.endBlock();
    }

    os.endBlock();
}


const Foam::imposedMotionBlend& Foam::imposedMotionList::blend
(
    const word& entryName
) const
{
    return blends_[findEntry(entryName)];
}


Foam::wordList Foam::imposedMotionList::names() const
{
    wordList entries(size());
    forAll(*this, motioni)
    {
        entries[motioni] = operator[](motioni).name();
    }
    return entries;
}


const Foam::imposedMotion& Foam::imposedMotionList::current
(
    const dictionary& dict,
    const word& key
) const
{
    const word entryName(dict.get<word>(key));
    const wordList entries(names());
    if (!entries.found(entryName))
    {
        FatalIOErrorInFunction(dict)
            << key << " " << entryName << " of " << dict.name()
            << " is not an imposedMotion entry: the entries are "
            << flatOutput(entries) << exit(FatalIOError);
    }
    return blend(entryName).current();
}


Foam::scalar Foam::imposedMotionList::get
(
    const word& entryName,
    const word& parameter
) const
{
    return blend(entryName).get(parameter);
}


void Foam::imposedMotionList::set
(
    const word& entryName,
    const word& parameter,
    const scalar value,
    const scalar t0,
    const scalar blendTime
)
{
    blends_[findEntry(entryName)].set(parameter, value, t0, blendTime);
}


void Foam::imposedMotionList::writeState(dictionary& stateDict) const
{
    dictionary motionsDict;

    forAll(blends_, motioni)
    {
        dictionary entryDict;
        blends_[motioni].writeState(entryDict);
        motionsDict.add(operator[](motioni).name(), entryDict);
    }

    stateDict.set("imposedMotionState", motionsDict);
}


void Foam::imposedMotionList::readState(const dictionary& stateDict)
{
    const dictionary* motionsDictPtr =
        stateDict.findDict("imposedMotionState", keyType::LITERAL);

    if (!motionsDictPtr)
    {
        return;     // a fresh start
    }

    forAll(blends_, motioni)
    {
        blends_[motioni].readState
        (
            motionsDictPtr->subDict(operator[](motioni).name())
        );
    }
}


// ************************************************************************* //
