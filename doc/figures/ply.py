"""Reads the PLY files the deformseg tool writes (include/deformseg/io/ply.h), nothing more:
binary little-endian or ASCII, a `vertex` element of float or double `x y z`, and a `face`
element of triangles (`list uchar int vertex_indices`), optionally with `uchar red green blue`.
"""

from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import numpy as np

_TYPES = {"float": "<f4", "double": "<f8", "uchar": "u1", "int": "<i4"}


class PlyError(ValueError):
    """The file is not a PLY file of the layout the tool writes; the message names it."""


@dataclass
class Mesh:
    points: np.ndarray  # V x 3, float64
    faces: np.ndarray  # F x 3, int64
    colors: Optional[np.ndarray]  # F x 3, uint8, or None


@dataclass
class _Header:
    encoding: str
    vertices: int
    faces: int
    coordinate: str  # a numpy type
    colored: bool
    size: int  # bytes, end_header's newline included


def _parse_header(path: Path, data: bytes) -> _Header:
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        raise PlyError(f"{path}: not a PLY file (no 'ply' ... 'end_header')")
    lines = [line.split() for line in data[:end].decode("ascii").splitlines()[1:]]
    lines = [line for line in lines if line and line[0] != "comment"]
    elements = {}  # name -> (count, [property words])
    encoding, current = None, None
    for words in lines:
        if words[0] == "format":
            encoding = words[1]
        elif words[0] == "element":
            current = words[1]
            elements[current] = (int(words[2]), [])
        elif words[0] == "property" and current is not None:
            elements[current][1].append(words[1:])
        else:
            raise PlyError(f"{path}: unexpected header line {' '.join(words)!r}")
    if encoding not in ("binary_little_endian", "ascii"):
        raise PlyError(f"{path}: format {encoding!r}, expected binary_little_endian or ascii")
    if list(elements) != ["vertex", "face"]:
        raise PlyError(f"{path}: elements {list(elements)}, expected vertex then face")
    vertex_props, face_props = elements["vertex"][1], elements["face"][1]
    coordinate = {tuple(p[0] for p in vertex_props)}
    if [p[1] for p in vertex_props] != ["x", "y", "z"] or len(coordinate) != 1 or \
            next(iter(coordinate))[0] not in ("float", "double"):
        raise PlyError(f"{path}: vertex properties {vertex_props}, expected float or double x y z")
    colored = face_props[1:] == [["uchar", "red"], ["uchar", "green"], ["uchar", "blue"]]
    if face_props[:1] != [["list", "uchar", "int", "vertex_indices"]] or (len(face_props) > 1 and not colored):
        raise PlyError(f"{path}: face properties {face_props}, expected vertex_indices and "
                       "optionally uchar red green blue")
    return _Header(encoding, elements["vertex"][0], elements["face"][0],
                   _TYPES[vertex_props[0][0]], colored, end + len(b"end_header\n"))


def _read_binary(path: Path, data: bytes, h: _Header):
    points = np.frombuffer(data, dtype=h.coordinate, count=3 * h.vertices, offset=h.size)
    face_type = [("n", "u1"), ("v", "<i4", 3)] + ([("rgb", "u1", 3)] if h.colored else [])
    offset = h.size + points.nbytes
    expected = offset + h.faces * np.dtype(face_type).itemsize
    if len(data) != expected:
        raise PlyError(f"{path}: {len(data)} bytes, expected {expected} for {h.vertices} vertices "
                       f"and {h.faces} triangles")
    faces = np.frombuffer(data, dtype=face_type, count=h.faces, offset=offset)
    if np.any(faces["n"] != 3):
        raise PlyError(f"{path}: a face is not a triangle")
    return points.reshape(-1, 3), faces["v"], faces["rgb"] if h.colored else None


def _read_ascii(path: Path, data: bytes, h: _Header):
    lines = data[h.size:].decode("ascii").split("\n")
    if len(lines) < h.vertices + h.faces:
        raise PlyError(f"{path}: {len(lines)} lines, expected {h.vertices + h.faces}")
    points = np.array([line.split() for line in lines[:h.vertices]], dtype=np.float64)
    faces = np.array([line.split() for line in lines[h.vertices:h.vertices + h.faces]], dtype=np.int64)
    width = 4 + (3 if h.colored else 0)
    if points.shape != (h.vertices, 3) or faces.shape != (h.faces, width) or np.any(faces[:, 0] != 3):
        raise PlyError(f"{path}: the vertex or face lines are not as the header says")
    return points, faces[:, 1:4], faces[:, 4:7].astype(np.uint8) if h.colored else None


def read_ply(path) -> Mesh:
    """The points, triangles and face colours of a PLY file the tool wrote.
    Raises PlyError naming the file when it is of another layout or is cut short."""
    path = Path(path)
    data = path.read_bytes()
    header = _parse_header(path, data)
    reader = _read_binary if header.encoding == "binary_little_endian" else _read_ascii
    points, faces, colors = reader(path, data, header)
    faces = faces.astype(np.int64)
    if faces.size and (faces.min() < 0 or faces.max() >= header.vertices):
        raise PlyError(f"{path}: a vertex index is out of range")
    return Mesh(points.astype(np.float64), faces, None if colors is None else colors.copy())
