/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(stepTimers, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepTimers::stepTimers(const objectRegistry& db)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            db.time().timeName(),
            db.time(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            true
        )
    )
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::stepTimers& Foam::stepTimers::New(const objectRegistry& db)
{
    const Time& runTime = db.time();

    stepTimers* ptr = runTime.getObjectPtr<stepTimers>(typeName);

    if (!ptr)
    {
        ptr = new stepTimers(runTime);
        ptr->store();
    }

    return *ptr;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::stepTimers::add(const word& part, const scalar s)
{
    auto iter = seconds_.find(part);

    if (iter.found())
    {
        *iter += s;
    }
    else
    {
        seconds_.insert(part, s);
        parts_.append(part);
    }
}


void Foam::stepTimers::reset()
{
    forAllIters(seconds_, iter)
    {
        *iter = 0;
    }
}


// ************************************************************************* //
