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
    Tests of Foam::oversetRankReport on hand-made inputs: the acceptors and
    their remote donors (local, mixed, all remote, an empty stencil, donor
    slots of non-acceptors ignored), the cells and messages of a map's
    exchange with three ranks (the rank's own part left out), the total,
    max, mean, cell imbalance and remote share of a table, and the written
    lines (prefix, header, one row per rank, total/max/mean, summary).
    The report of a real stencil, serial and -np 2, is checked in the
    solver logs by checkRankReport (Alltest).  Linked into
    flapFoamTest-overset (main in Test-overset.C).

\*---------------------------------------------------------------------------*/

#include "oversetRankReport.H"
#include "cellCellStencil.H"
#include "OStringStream.H"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

typedef oversetRankReport report;

//- The lines of a written report, each split into words (prefix removed)
std::vector<std::vector<std::string>> writtenLines(const report& r)
{
    OStringStream os;
    r.write(os);
    std::istringstream in(os.str());
    std::vector<std::vector<std::string>> lines;
    std::string line;
    while (std::getline(in, line))
    {
        std::istringstream words(line);
        std::vector<std::string> split;
        std::string word;
        while (words >> word)
        {
            split.push_back(word);
        }
        EXPECT_EQ(report::prefix, split.at(0)) << line;
        split.erase(split.begin());
        lines.push_back(split);
    }
    return lines;
}

//- A row from values in column order
report::row makeRow(std::initializer_list<label> values)
{
    report::row r(Zero);
    label coli = 0;
    for (const label v : values)
    {
        r[coli++] = v;
    }
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * * //

TEST(oversetRankReport, acceptorsLocalMixedAllRemote)
{
    const label C = cellCellStencil::CALCULATED;
    const label I = cellCellStencil::INTERPOLATED;
    const label H = cellCellStencil::HOLE;

    // Slots 0-5: this rank's cells; 6 from rank 1, 7 from rank 2
    const labelList slotRank({0, 0, 0, 0, 0, 0, 1, 2});
    const labelList types({C, I, I, I, H, I});
    const labelListList stencil
    ({
        {6},        // calculated: not counted
        {0, 4},     // local
        {0, 6},     // mixed
        {6, 7},     // all remote
        {},
        {}          // interpolated without a stencil: not remote
    });

    report::row counts(Zero);
    report::countAcceptors(types, stencil, slotRank, 0, counts);

    EXPECT_EQ(4, counts[report::ACCEPTORS]);
    EXPECT_EQ(2, counts[report::REMOTE]);
    EXPECT_EQ(1, counts[report::MIXED]);
    EXPECT_EQ(1, counts[report::ALL_REMOTE]);
    EXPECT_EQ(3, counts[report::REMOTE_SLOTS]);

    // Seen from rank 1 (slot 6 is its own) the counts differ
    report::row other(Zero);
    report::countAcceptors(types, stencil, slotRank, 1, other);
    EXPECT_EQ(3, other[report::REMOTE]);
    EXPECT_EQ(2, other[report::MIXED]);
    EXPECT_EQ(1, other[report::ALL_REMOTE]);
}


TEST(oversetRankReport, exchangeLeavesOutTheRanksOwnPart)
{
    // Rank 0 of 3: keeps its 4 cells, sends 3 cells to rank 1, none to
    // rank 2; receives 1 cell from rank 1 and 2 from rank 2
    labelListList subMap({identity(4), {0, 1, 3}, {}});
    labelListList constructMap({identity(4), {4}, {5, 6}});
    const mapDistributeBase map(7, std::move(subMap), std::move(constructMap));

    report::row counts(Zero);
    report::countExchange(map, 0, counts);

    EXPECT_EQ(3, counts[report::SENT]);
    EXPECT_EQ(1, counts[report::SEND_RANKS]);
    EXPECT_EQ(3, counts[report::RECEIVED]);
    EXPECT_EQ(2, counts[report::RECV_RANKS]);
}


TEST(oversetRankReport, tableFiguresAndWrittenLines)
{
    // cells procFaces procPatches haloBytes acceptors remote mixed allRemote
    // remoteSlots sent received sendRanks recvRanks
    const List<report::row> rows
    ({
        makeRow({100, 10, 1, 80, 20, 5, 4, 1, 6, 7, 3, 1, 1}),
        makeRow({300, 10, 1, 80, 60, 15, 15, 0, 15, 3, 7, 1, 1})
    });
    const report r("0.5", "octreeInverseDistance", rows);

    EXPECT_EQ(400, r.total()[report::CELLS]);
    EXPECT_EQ(80, r.total()[report::ACCEPTORS]);
    EXPECT_EQ(300, r.max()[report::CELLS]);
    EXPECT_EQ(7, r.max()[report::RECEIVED]);
    EXPECT_DOUBLE_EQ(1.5, r.cellImbalance());
    EXPECT_DOUBLE_EQ(0.25, r.remoteShare());

    const auto lines = writtenLines(r);
    ASSERT_EQ(8u, lines.size());
    EXPECT_EQ
    (
        (std::vector<std::string>
        {"time", "0.5", "stencil", "octreeInverseDistance", "ranks", "2"}),
        lines[0]
    );
    ASSERT_EQ(size_t(report::N_COLUMNS + 1), lines[1].size());
    EXPECT_EQ("rank", lines[1][0]);
    for (label coli = 0; coli < report::N_COLUMNS; ++coli)
    {
        EXPECT_EQ(report::columnNames[coli], lines[1][coli + 1]);
    }
    const char* labels[] = {"0", "1", "total", "max", "mean"};
    const List<report::row> expected({rows[0], rows[1], r.total(), r.max()});
    for (label linei = 2; linei < 7; ++linei)
    {
        ASSERT_EQ(size_t(report::N_COLUMNS + 1), lines[linei].size());
        EXPECT_EQ(labels[linei - 2], lines[linei][0]);
        for (label coli = 0; coli < report::N_COLUMNS; ++coli)
        {
            const scalar value = std::stod(lines[linei][coli + 1]);
            const scalar want =
                linei < 6
              ? scalar(expected[linei - 2][coli])
              : 0.5*r.total()[coli];
            EXPECT_DOUBLE_EQ(want, value) << lines[linei][0] << " " << coli;
        }
    }
    EXPECT_EQ
    (
        (std::vector<std::string>
        {"cellImbalance", "1.5", "remoteShare", "0.25"}),
        lines[7]
    );
}


TEST(oversetRankReport, noAcceptorsNoCells)
{
    const report empty("0", "inverseDistance", List<report::row>(1, Zero));
    EXPECT_DOUBLE_EQ(0, empty.remoteShare());
    EXPECT_DOUBLE_EQ(1, empty.cellImbalance());
}


// ************************************************************************* //
