# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The records of the mesh generators' parameters (dataclasses with Python
names) and their names in meshGen.json and the docs (camelCase: n_ref is
nRef; a field's metadata "key" where that rule does not give it, n0 is
N0).  file_entries gives a record as those entries, the unset (None)
fields left out.
"""

import dataclasses


def camel(name):
    """n_ref -> nRef, core_frac -> coreFrac."""
    first, *rest = name.split("_")
    return first + "".join(w[:1].upper() + w[1:] for w in rest)


def file_entries(record):
    """{file key: value} of a record's set fields, in field order."""
    return {f.metadata.get("key", camel(f.name)): getattr(record, f.name)
            for f in dataclasses.fields(record)
            if getattr(record, f.name) is not None}
