/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "imposedMotion.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::imposedMotion> Foam::imposedMotion::New
(
    const word& name,
    const dictionary& dict
)
{
    const word motionType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(motionType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "imposedMotion",
            motionType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<imposedMotion>(cstrIter()(name, dict));
}


// ************************************************************************* //
