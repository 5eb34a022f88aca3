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

#include "runInputCheck.H"
#include "IFstream.H"
#include "dictionary.H"
#include "OSspecific.H"
#include "dictionaryRead.H"

#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <regex>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A line with its comments and strings blanked (inComment: inside a
//- block comment at the start, updated for the next line)
std::string code(const std::string& line, bool& inComment)
{
    std::string out(line.size(), ' ');
    bool inString = false;
    for (std::size_t i = 0; i < line.size(); ++i)
    {
        const char c = line[i];
        const char next = i + 1 < line.size() ? line[i + 1] : '\0';
        if (inComment)
        {
            if (c == '*' && next == '/')
            {
                inComment = false;
                ++i;
            }
        }
        else if (inString)
        {
            inString = (c != '"' || line[i - 1] == '\\');
        }
        else if (c == '/' && next == '/')
        {
            break;
        }
        else if (c == '/' && next == '*')
        {
            inComment = true;
            ++i;
        }
        else if (c == '"')
        {
            inString = true;
        }
        else
        {
            out[i] = c;
        }
    }
    return out;
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::runInputCheck::read(const std::string& text, scalar& value)
{
    std::fenv_t env;
    std::feholdexcept(&env);
    char* end = nullptr;
    const double parsed = std::strtod(text.c_str(), &end);
    std::fesetenv(&env);

    const bool ok =
        !text.empty() && end && *end == '\0' && !std::isinf(parsed)
     && !std::isnan(parsed);
    if (ok)
    {
        value = parsed;
    }
    return ok;
}


bool Foam::runInputCheck::read(const std::string& text, label& value)
{
    return readLabel(text, value);
}


void Foam::runInputCheck::numbers(const fileName& file)
{
    static const std::regex number
    (
        "(^|[\\s(){};,\\[\\]])"
        "([-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?)"
        "(?=$|[\\s(){};,\\[\\]])"
    );
    static const std::regex keyword("^\\s*([A-Za-z_][A-Za-z0-9_]*)");

    std::ifstream is(file.c_str());
    std::string line;
    label lineNo = 0;
    bool inComment = false;
    while (std::getline(is, line))
    {
        ++lineNo;
        const std::string text(code(line, inComment));
        for
        (
            std::sregex_iterator m(text.begin(), text.end(), number), e;
            m != e;
            ++m
        )
        {
            scalar value;
            if (read((*m)[2].str(), value))
            {
                continue;
            }
            std::smatch key;
            const std::string name
            (
                std::regex_search(text, key, keyword) ? key[1].str() : "line"
            );
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, file, lineNo
            )   << name.c_str() << " " << (*m)[2].str().c_str()
                << ": beyond the range of a double"
                << " (magnitude at most "
                << std::numeric_limits<double>::max() << ")"
                << exit(FatalIOError);
        }
    }
}


void Foam::runInputCheck::controls(const fileName& controlDict)
{
    IFstream is(controlDict);
    const dictionary dict(is);

    readAllowed(dict, "deltaT", 1.0, allowed::above(0.0).noting("seconds"));
    readAllowed
    (
        dict,
        "writeInterval",
        1.0,
        allowed::above(0.0).noting
        (
            "steps for writeControl timeStep, else seconds"
        )
    );
}


void Foam::runInputCheck::check(const argList& args, const wordList& files)
{
    const fileName caseDir(args.rootPath()/args.globalCaseName());
    const fileName controlDict(caseDir/"system"/"controlDict");

    numbers(controlDict);
    for (const word& f : files)
    {
        if (isFile(caseDir/f))
        {
            numbers(caseDir/f);
        }
    }
    controls(controlDict);
}


// ************************************************************************* //
