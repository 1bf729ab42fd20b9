"""Reads a deformseg motion store with NumPy alone (no compiled module): the format's second reader.

A motion store is a folder of ``.npy`` files and a JSON manifest, ``store.json``, written by
``deformseg::store::Store_append`` (C++, ``include/deformseg/store/motion_store.h``) and described
field by field in ``doc/store_format.md``. ``read_store(folder)`` checks it as the C++ reader
does (the manifest's format, version and checksum, every listed file's size, the ``.npy`` headers,
every clip's ranges; with ``verify=True`` also every file's and clip's CRC-32) and returns a
``Store`` whose arrays are memory-mapped, read-only::

    store = read_store("S")
    signatures, frames = store.clip(0)   # (R, W) float32 view, (R,) uint32
    store.clips["fps"]                   # the clip table, a structured array

The file imports nothing of deformseg: copied alone beside a program, it reads stores on a machine
without deformseg (``import deformseg.store_format`` loads the package, compiled module included).
"""
import json
import pathlib
import zlib

import numpy as np

FORMAT = "deformseg-motion-store"
VERSION = 2  # version 2 keys a clip by its body too: five strings per clip, version 1's four
_CHARACTER_EXTENSIONS = (".glb", ".gltf", ".fbx", ".dae", ".bvh")  # io::is_character_file
BLOCK_ALIGNMENT_FLOATS = 16

#: The clip table's dtype: one packed little-endian record per clip, in index order.
CLIP_DTYPE = np.dtype([
    ("segment", "<u8"), ("offset", "<u8"), ("rows", "<u4"), ("frames_offset", "<u8"), ("summary_row", "<u8"),
    ("frame_count", "<u4"), ("fps", "<f8"), ("block_crc32", "<u4"), ("source_size", "<u8"),
    ("source_mtime_ns", "<i8"), ("source_hash", "<u8"), ("topology_size", "<u8"), ("topology_mtime_ns", "<i8"),
    ("strings", "<u8"), ("strings_length", "<u4")])


class StoreError(ValueError):
    """A folder that is not a readable motion store; the message names the file (and the clip)."""


def file_name(kind, generation):
    """The name of the store file of ``kind`` ("signatures", "frames", "summaries", "clips",
    "strings") and ``generation``: ``signatures-000003.npy``."""
    return f"{kind}-{generation:06d}.npy"


def _fail(path, message):
    raise StoreError(f"{path}: {message}")


def _count(manifest, key, path, most=2**64 - 1):
    value = manifest.get(key)
    if type(value) is not int or not 0 <= value <= most:
        _fail(path, f'the manifest\'s "{key}" is not a count of at most {most}')
    return value


def _checksum_suffix(covered):
    """The manifest's end after the bytes ``covered``: its "checksum" member, the closing brace, a newline."""
    return f'"checksum": "crc32:{zlib.crc32(covered):08x}"}}\n'.encode()


def _read_manifest(folder):
    path = folder / "store.json"
    if not folder.is_dir():
        _fail(folder, "not a motion store: no such folder")
    if not path.exists():
        _fail(folder, "not a motion store: the folder has no store.json")
    raw = path.read_bytes()
    try:
        manifest = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        _fail(path, f"not valid JSON: {error}")
    except RecursionError:
        _fail(path, "not valid here: JSON nested too deep")
    if not isinstance(manifest, dict) or manifest.get("format") != FORMAT:
        _fail(path, f'not a motion store: its manifest has no "format": "{FORMAT}"')
    version = manifest.get("version")
    if type(version) is not int or version < 1:
        _fail(path, 'the manifest\'s "version" is missing or not a positive count')
    # The manifest ends with its last member, "checksum", in one fixed form; the checksum covers
    # every byte before it.
    covered = raw[:-len(_checksum_suffix(b""))]
    named = list(manifest)[-1:] == ["checksum"]
    sums = named and raw == covered + _checksum_suffix(covered)
    if version > VERSION:
        newer = f"store version {version} is newer than this deformseg, which reads version {VERSION}"
        _fail(path, newer if sums else newer + " (or its manifest is corrupted: its checksum does not match)")
    if not sums:
        _fail(path, "its checksum does not match its contents: the manifest is corrupted" if named
              else 'the manifest does not end with its "checksum": it is corrupted or not written by deformseg')
    return manifest


def _load(folder, name, listed, dtype, ndim, columns, check_crc):
    """Maps the listed file ``name`` read-only and checks it against the manifest and the format."""
    path = folder / name
    if not path.exists():
        _fail(path, "cannot open: no such file, though the manifest lists it")
    size = path.stat().st_size
    if size != listed["bytes"]:
        _fail(path, f"{size} bytes, the manifest says {listed['bytes']}: "
                    + ("truncated" if size < listed["bytes"] else "longer than written"))
    with open(path, "rb") as f:
        try:
            if np.lib.format.read_magic(f) != (1, 0):
                _fail(path, "a .npy file of another version than 1.0")
            shape, fortran_order, file_dtype = np.lib.format.read_array_header_1_0(f)
        except ValueError as error:
            _fail(path, f"malformed .npy header: {error}")
        offset = f.tell()
    if fortran_order:
        _fail(path, "its array is in Fortran order; the store's arrays are in C order")
    if file_dtype != dtype or len(shape) != ndim or (ndim == 2 and shape[1] != columns):
        _fail(path, f"its array is {file_dtype} of shape {shape}, not {dtype} of {ndim} dimensions")
    nbytes = int(np.prod(shape, dtype=object)) * dtype.itemsize
    if offset + nbytes != size:
        _fail(path, f"its shape {shape} does not match its {size - offset} bytes of data")
    if offset % 64 != 0:
        _fail(path, f"its data starts at byte {offset}, not a multiple of 64")
    if check_crc:
        with open(path, "rb") as f:
            f.seek(offset)
            if zlib.crc32(f.read()) != listed["data_crc32"]:
                _fail(path, "its checksum does not match the manifest's: the file is corrupted")
    if nbytes == 0:  # mmap cannot map nothing
        return np.zeros(shape, dtype)
    return np.memmap(path, dtype=dtype, mode="r", offset=offset, shape=shape)


class Store:
    """A motion store opened by ``read_store``.

    Attributes: ``folder`` (a ``pathlib.Path``), ``manifest`` (the dict of ``store.json``), ``clips``
    (the clip table, a structured array of ``CLIP_DTYPE``, one record per clip), ``width`` (values
    per signature), ``summary_width`` (floats per summary).
    """

    def __init__(self, folder, manifest, clips, strings, segments):
        self.folder = folder
        self.manifest = manifest
        self.clips = clips
        self.width = manifest["width"]
        self.summary_width = manifest["summary_width"]
        self._strings = strings
        self._segments = segments  # generation -> (signatures, frames, summaries)
        self._index = {}  # (path, clip, body) -> index, filled by read_store as it checks each clip
        self._bodies = {}  # index -> body, filled alike

    def __len__(self):
        return len(self.clips)

    def clip(self, i):
        """Clip ``i``'s signatures, an (R, W) float32 view of the mapped file (dimension-major:
        ``values.reshape(W, R).T``), and its frame numbers, an (R,) uint32 view."""
        record = self.clips[i]
        signatures, frames, _ = self._segments[int(record["segment"])]
        rows, offset, first = int(record["rows"]), int(record["offset"]), int(record["frames_offset"])
        block = signatures[offset:offset + rows * self.width].reshape(self.width, rows).T
        return block, frames[first:first + rows]

    def summary(self, i):
        """Clip ``i``'s summary: ``summary_width`` float32 values."""
        record = self.clips[i]
        return self._segments[int(record["segment"])][2][int(record["summary_row"])]

    def strings(self, i):
        """Clip ``i``'s (path, clip, input options, topology path, body): its body "" for its own
        file's (a store of version 1 kept a character file's body as its topology path)."""
        record = self.clips[i]
        start = int(record["strings"])
        text = bytes(self._strings[start:start + int(record["strings_length"])])
        return tuple(part.decode("utf-8") for part in text.split(b"\0")[:4]) + (self._bodies[i],)

    def find(self, path, clip="", body=""):
        """The index of the clip of ``path`` and ``clip`` ("" for a single-animation file) played on
        ``body`` ("" for its own file's), or None: one clip on two bodies is two clips."""
        return self._index.get((path, clip, body))


def _check_clip(store, i, verify, table_path):
    record = store.clips[i]
    start, length = int(record["strings"]), int(record["strings_length"])
    if start + length > len(store._strings):
        _fail(table_path, f"clip {i}: its strings at byte {start} ({length} bytes) run past the end of the strings")
    parts = bytes(store._strings[start:start + length]).split(b"\0")
    count = 5 if store.manifest["version"] >= 2 else 4
    if len(parts) != count + 1 or parts[count] != b"" or not parts[0]:
        _fail(table_path, f"clip {i}: its strings are not {count} NUL-terminated strings, the path not empty")
    try:
        path, clip, _, topology, *body = (part.decode("utf-8") for part in parts[:count])
    except UnicodeDecodeError:
        _fail(table_path, f"clip {i}: its strings are not valid UTF-8")
    if count == 4:  # version 1 kept a character file's body as its topology (it has no other)
        body = [topology if path.lower().endswith(_CHARACTER_EXTENSIONS) else ""]
    body = body[0]
    store._bodies[i] = body
    name = f"clip {i} ({path}{'#' + clip if clip else ''}{' on ' + body if body else ''})"
    generation = int(record["segment"])
    if generation not in store._segments:
        _fail(table_path, f"{name}: its generation {generation} is not among the store's segments")
    signatures, frames, summaries = store._segments[generation]
    rows, offset = int(record["rows"]), int(record["offset"])
    if rows == 0:
        _fail(table_path, f"{name}: 0 rows; a clip has at least one")
    if not (record["fps"] > 0 and np.isfinite(record["fps"])):
        _fail(table_path, f"{name}: its fps is not positive and finite")
    if offset % BLOCK_ALIGNMENT_FLOATS:
        _fail(table_path, f"{name}: its block at float {offset} is not 64-byte aligned")
    if offset + rows * store.width > len(signatures):
        _fail(table_path, f"{name}: {rows} rows of {store.width} floats at float {offset} run past the end of "
                          f"{store.folder / file_name('signatures', generation)}")
    if int(record["frames_offset"]) + rows > len(frames):
        _fail(table_path, f"{name}: {rows} frame numbers run past the end of "
                          f"{store.folder / file_name('frames', generation)}")
    if int(record["summary_row"]) >= len(summaries):
        _fail(table_path, f"{name}: its summary row would run past the end of "
                          f"{store.folder / file_name('summaries', generation)}")
    if verify:
        block, clip_frames = store.clip(i)
        crc = zlib.crc32(np.ascontiguousarray(block.T).tobytes())
        crc = zlib.crc32(clip_frames.tobytes(), crc)
        if zlib.crc32(store.summary(i).tobytes(), crc) != int(record["block_crc32"]):
            _fail(table_path, f"{name}: its block's checksum does not match: its data in generation "
                              f"{generation} is corrupted")
    return (path, clip, body)


def read_store(path, verify=False):
    """Opens the motion store in the folder ``path``, checked as the C++ reader checks it.

    ``verify``: also check the CRC-32 of every data file and every clip's block (reads every byte).
    Raises ``StoreError`` naming the file (and the clip) when the folder is not a store, is of a
    newer version, or is truncated or corrupted.
    """
    folder = pathlib.Path(path)
    manifest = _read_manifest(folder)
    manifest_path = folder / "store.json"
    generation = _count(manifest, "generation", manifest_path, 999_999_999)
    _count(manifest, "width", manifest_path, 1 << 16)
    summary_width = _count(manifest, "summary_width", manifest_path, 1 << 16)
    count = _count(manifest, "clips", manifest_path)
    segments = manifest.get("segments")
    if not isinstance(segments, list) or any(type(g) is not int for g in segments) \
            or segments != sorted(set(segments)) or (segments and not 1 <= segments[0] <= segments[-1] <= generation):
        _fail(manifest_path, 'the manifest\'s "segments" are not increasing generations from 1')
    listed = {f.get("name"): f for f in manifest.get("files", []) if isinstance(f, dict)}
    expected = {file_name("clips", generation), file_name("strings", generation)}
    expected |= {file_name(kind, g) for g in segments for kind in ("signatures", "frames", "summaries")}
    if set(listed) != expected or len(listed) != len(manifest.get("files", [])):
        _fail(manifest_path, f"the manifest lists {sorted(map(str, listed))}, not the store's files {sorted(expected)}")

    table_name = file_name("clips", generation)
    clips = _load(folder, table_name, listed[table_name], CLIP_DTYPE, 1, 1, True)
    if len(clips) != count:
        _fail(folder / table_name, f"it holds {len(clips)} clips, the manifest says {count}")
    strings = _load(folder, file_name("strings", generation), listed[file_name("strings", generation)],
                    np.dtype("u1"), 1, 1, True)
    data = {}
    for g in segments:
        data[g] = tuple(_load(folder, file_name(kind, g), listed[file_name(kind, g)], np.dtype(dtype), ndim,
                              summary_width, verify)
                        for kind, dtype, ndim in (("signatures", "<f4", 1), ("frames", "<u4", 1),
                                                  ("summaries", "<f4", 2)))
    store = Store(folder, manifest, clips, strings, data)
    keys = store._index
    for i in range(count):
        key = _check_clip(store, i, verify, folder / table_name)
        if key in keys:
            _fail(folder / table_name, f"clip {i} ({key[0]}{'#' + key[1] if key[1] else ''}"
                                       f"{' on ' + key[2] if key[2] else ''}): the same clip as clip {keys[key]}")
        keys[key] = i
    return store
