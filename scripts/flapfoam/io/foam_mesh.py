# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Minimal reader of an OpenFOAM polyMesh (ascii or binary, label 32 bit,
scalar 64 bit) and of volScalarField internal fields, for the checks of
the drone cases.  numpy only.
"""

import os
import re

import numpy as np

_HEADER_END = re.compile(rb"^\s*FoamFile\s*\{.*?\}", re.S | re.M)


def _read(path):
    if os.path.exists(path):
        with open(path, "rb") as fh:
            return fh.read()
    if os.path.exists(path + ".gz"):
        import gzip
        with gzip.open(path + ".gz", "rb") as fh:
            return fh.read()
    raise FileNotFoundError(path)


def _header(data):
    m = _HEADER_END.search(data)
    if not m:
        raise ValueError("no FoamFile header")
    hdr = data[m.start():m.end()].decode("latin-1")
    fmt = re.search(r"format\s+(\w+)", hdr).group(1)
    cls = re.search(r"class\s+([\w<>:]+)", hdr).group(1)
    return fmt, cls, m.end()


def _strip_comments(text):
    text = re.sub(rb"/\*.*?\*/", b" ", text, flags=re.S)
    return re.sub(rb"//[^\n]*", b" ", text)


def _list_start(data, pos):
    """Position after 'N (' (or 'N{'), and N."""
    m = re.compile(rb"\s*(\d+)\s*([({])").match(data, pos)
    while not m:
        # skip comment lines / blank lines between header and list
        nl = data.index(b"\n", pos) + 1
        pos = nl
        m = re.compile(rb"\s*(\d+)\s*([({])").match(data, pos)
    return int(m.group(1)), m.end(), m.group(2)


def _ascii_numbers(block, dtype):
    cleaned = re.sub(rb"[()]", b" ", block)
    return np.array(cleaned.split(), dtype=dtype)


def read_points(path):
    data = _read(path)
    fmt, _, pos = _header(data)
    n, start, _ = _list_start(data, pos)
    if fmt == "binary":
        return np.frombuffer(data, dtype="<f8", count=3*n,
                             offset=start).reshape(n, 3).copy()
    end = data.index(b"\n)", start)
    return _ascii_numbers(data[start:end], float).reshape(n, 3)


def read_labels(path):
    data = _read(path)
    fmt, _, pos = _header(data)
    n, start, br = _list_start(data, pos)
    if br == b"{":          # uniform list N{value}
        end = data.index(b"}", start)
        return np.full(n, int(data[start:end]), dtype=np.int64)
    if fmt == "binary":
        return np.frombuffer(data, dtype="<i4", count=n,
                             offset=start).astype(np.int64)
    end = data.index(b")", start)
    return np.array(data[start:end].split(), dtype=np.int64)


def read_faces(path):
    """(offsets, vertices) of the faces (faceCompactList)."""
    data = _read(path)
    fmt, cls, pos = _header(data)
    if fmt == "binary" and "Compact" in cls:
        n, start, _ = _list_start(data, pos)
        offs = np.frombuffer(data, dtype="<i4", count=n, offset=start)
        pos2 = start + 4*n + 1
        m, start2, _ = _list_start(data, pos2)
        verts = np.frombuffer(data, dtype="<i4", count=m, offset=start2)
        return offs.astype(np.int64), verts.astype(np.int64)
    if fmt == "binary":
        raise ValueError("binary faceList (not compact) not supported")
    n, start, _ = _list_start(data, pos)
    end = data.rindex(b")")
    body = data[start:end]
    lines = body.split(b"\n")
    sizes = np.empty(n, dtype=np.int64)
    flat = []
    k = 0
    for ln in lines:
        ln = ln.strip()
        if not ln:
            continue
        p = ln.index(b"(")
        sizes[k] = int(ln[:p])
        flat.append(ln[p + 1:-1])
        k += 1
        if k == n:
            break
    verts = np.array(b" ".join(flat).split(), dtype=np.int64)
    offs = np.concatenate([[0], np.cumsum(sizes)])
    return offs, verts


def read_boundary(path):
    text = _strip_comments(_read(path)).decode("latin-1")
    _, _, pos = _header(text.encode("latin-1"))
    body = text[pos:]
    out = {}
    for m in re.finditer(r"(\w+)\s*\{([^{}]*)\}", body):
        d = m.group(2)
        get = lambda k: re.search(r"\b%s\s+([^;]+);" % k, d)  # noqa: E731
        out[m.group(1)] = dict(type=get("type").group(1).strip(),
                               nFaces=int(get("nFaces").group(1)),
                               startFace=int(get("startFace").group(1)))
    return out


def read_zone_sizes(path):
    """{zoneName: nCells} of a cellZones file (sizes from the list headers)."""
    data = _read(path)
    fmt, _, pos = _header(data)
    out = {}
    for m in re.finditer(rb"\n\s*(\w+)\s*\n\s*\{\s*type\s+cellZone;"
                         rb"\s*cellLabels\s+List<label>\s*(\d+)", data[pos:]):
        out[m.group(1).decode()] = int(m.group(2))
    if not out:
        for m in re.finditer(rb"(\w+)\s*\{\s*type\s+cellZone;\s*cellLabels\s+"
                             rb"List<label>\s*(\d+)", data[pos:]):
            out[m.group(1).decode()] = int(m.group(2))
    return out


def read_n_cells(owner_path):
    data = _read(owner_path)
    m = re.search(rb"nCells:\s*(\d+)", data[:2000])
    if m:
        return int(m.group(1))
    return int(read_labels(owner_path).max()) + 1


def face_areas_vec(points, offs, verts, faces):
    """Vectorised face area vectors (faces of any size)."""
    faces = np.asarray(faces)
    sizes = offs[faces + 1] - offs[faces]
    area = np.zeros((len(faces), 3))
    for n in np.unique(sizes):
        sel = np.where(sizes == n)[0]
        idx = offs[faces[sel]][:, None] + np.arange(n)[None, :]
        p = points[verts[idx]]                       # (m, n, 3)
        c = p.mean(axis=1, keepdims=True)
        q = np.roll(p, -1, axis=1)
        area[sel] = 0.5*np.cross(p - c, q - c).sum(axis=1)
    return area


def read_scalar_field(path):
    """Internal field of a volScalarField (uniform or nonuniform)."""
    data = _read(path)
    fmt, _, pos = _header(data)
    m = re.search(rb"internalField\s+(uniform|nonuniform)", data[pos:])
    p = pos + m.end()
    if m.group(1) == b"uniform":
        val = float(re.match(rb"\s*([^;]+);", data[p:]).group(1))
        return val
    m2 = re.compile(rb"\s*List<scalar>\s*").match(data, p)
    p = m2.end()
    n, start, br = _list_start(data, p)
    if br == b"{":
        end = data.index(b"}", start)
        return np.full(n, float(data[start:end]))
    if fmt == "binary":
        return np.frombuffer(data, dtype="<f8", count=n, offset=start).copy()
    end = data.index(b")", start)
    return np.array(data[start:end].split(), dtype=float)
