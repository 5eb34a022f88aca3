# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Per-rank tables of a decomposition, for the scaling bench (bench/scaling):

- read_tables(FILE, PREFIX): the tables (RankTable records) that lines "PREFIX: ..." of a log
  hold, in the format of couplingReport (oversetCouplingsReport,
  oversetGraph) and of oversetRankReport: a header line "rank NAME...",
  one row per rank, rows total/max/mean, and lines of "key value" pairs
  (e.g. "imbalance cells 1.02 ... remotePairShare 0.33", "cellImbalance
  1.02 remoteShare 0.55", "time 1e-05 stencil octreeInverseDistance ranks
  8");
- cell_decomposition(cellDist, out): the volScalarField cellDist of
  decomposePar -dry-run -cellDist (ascii or binary) as the labelList
  constant/cellDecomposition that decomposePar -cellDist writes;
- neighbour_ranks(polyMesh, decomposition): per rank, the ranks it shares
  faces with (the messages of one halo exchange);
- cell_order_gap(polyMesh, decomposition): per rank, the mean distance
  between the two cells of a face in the rank's own cell numbering.

    flapfoam rank_tables -cellDist CELLDIST OUT
    flapfoam rank_tables -cellOrder POLYMESH DECOMPOSITION...
"""

import argparse
from dataclasses import dataclass, field

import numpy as np

from flapfoam.io import foam_mesh
from flapfoam.errors import run_tool

SUMMARIES = ("total", "max", "mean")


def _value(word):
    """A number where it is one, else the word."""
    try:
        return float(word)
    except ValueError:
        return word


@dataclass
class RankTable:
    """A per-rank table of a log: its columns, a row per rank (index =
    rank; {column: value}), the summary rows (total, max, mean: None where
    absent), the "key value" pairs of its other lines (info: the file's
    keys) and line, the index in the file of its first line."""
    columns: list = field(default_factory=list)
    rows: list = field(default_factory=list)
    info: dict = field(default_factory=dict)
    line: int = 0
    total: dict = None
    max: dict = None
    mean: dict = None


def read_tables(fname, prefix):
    """The RankTables of the lines "PREFIX: ..." of FILE, in order (a line
    of another form than "key value" pairs, e.g. "48 ranks, 29732 cells,
    ...", is kept in info word by word too).  A line "time ..."
    (oversetRankReport's title) starts a table, and so does a header line
    unless it follows such a title."""
    tables = []
    tag = prefix + ":"

    with open(fname, errors="replace") as f:
        for i, line in enumerate(f):
            if not line.startswith(tag):
                continue
            words = line[len(tag):].split()
            if not words:
                continue
            if words[0] == "time" or not tables:
                tables.append(RankTable(line=i))
            t = tables[-1]
            if words[0] == "rank":
                if t.columns or t.rows:
                    t = RankTable(line=i)
                    tables.append(t)
                t.columns = words[1:]
                continue
            is_row = (words[0].isdigit() and t.columns
                      and len(words) == len(t.columns) + 1)
            if is_row or words[0] in SUMMARIES:
                if len(words) != len(t.columns) + 1:
                    raise ValueError("%s: '%s': %d values for the columns %s"
                                     % (fname, line.strip(), len(words) - 1,
                                        t.columns))
                row = dict(zip(t.columns, map(float, words[1:])))
                if words[0].isdigit():
                    t.rows.append(row)
                else:
                    setattr(t, words[0], row)
            else:
                pairs = words[1:] if len(words) % 2 else words
                t.info.update((k, _value(v))
                              for k, v in zip(pairs[::2], pairs[1::2]))
    return tables


def read_table(fname, prefix):
    """The last table of FILE's lines "PREFIX: ...", or ValueError."""
    tables = [t for t in read_tables(fname, prefix) if t.rows]
    if not tables:
        raise ValueError("%s: no table of lines '%s: ...'" % (fname, prefix))
    return tables[-1]


def column(table, name):
    """One column of a table's rank rows as an array."""
    return np.array([row[name] for row in table.rows])


def cell_decomposition(cell_dist, out):
    """Write the ranks of cellDist (a volScalarField) as a labelList."""
    ranks = np.asarray(foam_mesh.read_scalar_field(cell_dist))
    labels = np.rint(ranks).astype(int)
    if ranks.ndim != 1 or np.any(np.abs(ranks - labels) > 1e-6) \
            or labels.min() < 0:
        raise ValueError("%s: not a list of rank numbers" % cell_dist)
    with open(out, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class labelList; "
                "location \"constant\"; object cellDecomposition; }\n")
        f.write("%d\n(\n" % len(labels))
        f.write("\n".join(map(str, labels)))
        f.write("\n)\n")


def read_decomposition(fname):
    """A labelList file (cell to rank) as an array."""
    return np.asarray(foam_mesh.read_labels(fname))


def neighbour_ranks(poly_mesh, decomposition):
    """Per rank (array, index = rank): the number of other ranks it shares
    internal faces with."""
    owner = np.asarray(foam_mesh.read_labels(poly_mesh + "/owner"))
    neighbour = np.asarray(foam_mesh.read_labels(poly_mesh + "/neighbour"))
    a = decomposition[owner[:len(neighbour)]]
    b = decomposition[neighbour]
    cut = a != b
    pairs = np.unique(np.stack([np.concatenate([a[cut], b[cut]]),
                                np.concatenate([b[cut], a[cut]])]), axis=1)
    n = int(decomposition.max()) + 1
    return np.bincount(pairs[0], minlength=n)


def cell_order_gap(poly_mesh, decomposition):
    """Per rank (array, index = rank): the mean distance |i - j| between
    the two cells of its internal faces in the rank's own numbering (its
    cells in the mesh's order, as decomposePar keeps them): the spread of
    the rank's matrix around its diagonal (0 for a rank without such a
    face)."""
    owner = np.asarray(foam_mesh.read_labels(poly_mesh + "/owner"))
    neighbour = np.asarray(foam_mesh.read_labels(poly_mesh + "/neighbour"))
    owner = owner[:len(neighbour)]
    local = np.empty(len(decomposition), dtype=int)
    n = int(decomposition.max()) + 1
    for r in range(n):
        cells = np.flatnonzero(decomposition == r)
        local[cells] = np.arange(len(cells))
    inside = decomposition[owner] == decomposition[neighbour]
    gap = np.abs(local[owner[inside]] - local[neighbour[inside]])
    rank = decomposition[owner[inside]]
    faces = np.bincount(rank, minlength=n)
    return np.bincount(rank, weights=gap, minlength=n)/np.maximum(faces, 1)


def main(argv=None):
    p = argparse.ArgumentParser(
        prog="flapfoam rank_tables",
        description="cellDist as constant/cellDecomposition, or the cell "
                    "order gap of decompositions")
    how = p.add_mutually_exclusive_group(required=True)
    how.add_argument("-cellDist", dest="cell_dist", nargs=2,
                     metavar=("CELLDIST", "OUT"))
    how.add_argument("-cellOrder", dest="cell_order", nargs="+",
                     metavar="POLYMESH DECOMPOSITION")
    a = p.parse_args(argv)
    if a.cell_dist:
        cell_decomposition(*a.cell_dist)
        return
    if len(a.cell_order) < 2:
        p.error("-cellOrder: POLYMESH and at least one DECOMPOSITION")
    for fname in a.cell_order[1:]:
        gap = cell_order_gap(a.cell_order[0], read_decomposition(fname))
        print("%s: mean cell distance of a face, largest rank %.0f, "
              "mean over ranks %.0f" % (fname, gap.max(), gap.mean()))


if __name__ == "__main__":
    run_tool(main)
