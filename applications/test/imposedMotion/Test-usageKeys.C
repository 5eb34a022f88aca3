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

Description
    flapFoamTest-imposedMotion: the Usage table of each imposedMotion
    type's header against the keys the type allows (imposedMotion::keys()
    and its ignoredKeys(), accepted with a warning): a key documented but
    not allowed, or allowed but not documented, fails (usageKeys.H).

\*---------------------------------------------------------------------------*/

#include "imposedMotionTests.H"
#include "usageKeys.H"

// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(usageKeys, imposedMotionTypes)
{
    const std::vector<std::pair<std::string, std::string>> types
    {
        {"harmonic", "type harmonic; joint 0; amplitude 1; frequency 2;"},
        {
            "wang",
            "type wang; joint 0; waveform flapping; amplitude 1;"
            " frequency 2; K 0.5;"
        },
        {
            "wangParametrization",
            "type wangParametrization; jointList (0 1); Aphi 1; fphi 20;"
            " Kphi 0.5; Aalpha 1; falpha 20; Kalpha 1;"
        },
        {"fourier", "type fourier; joint 0; frequency 2; a (1);"},
        {
            "tabulated",
            "type tabulated; joint 0;"
            " values ((0 0) (0.1 1) (0.2 -1) (0.3 0));"
        }
    };

    for (const auto& type : types)
    {
        SCOPED_TRACE(type.first);
        const autoPtr<imposedMotion> m(makeMotion(type.second));
        ASSERT_EQ(m->type(), type.first);

        wordList allowed(m->keys());
        allowed.append(m->ignoredKeys());
        expectUsageKeys
        (
            usageKeys
            ({
                "imposedMotion/imposedMotions/" + type.first + "/"
              + type.first + ".H"
            }),
            allowed
        );
    }
}


// ************************************************************************* //
