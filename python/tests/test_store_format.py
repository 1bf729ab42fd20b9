"""deformseg.store_format, the motion store's reader in NumPy alone, on a store written by the C++
writer: the example program examples/motion_store.cpp, whose pattern of values is recomputed here
and compared bit for bit; then the damage the C++ reader names, named by the Python one."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

from deformseg.store_format import CLIP_DTYPE, StoreError, read_store


@pytest.fixture
def store(tmp_path):
    """A store written by the example program (12 clips over two appends, clip 5 replaced)."""
    build = os.environ.get("DEFORMSEG_BUILD_DIR")
    program = pathlib.Path(build) / "examples" / "motion_store" if build else None
    if program is None or not os.access(program, os.X_OK):
        pytest.skip("the example program motion_store is not built (DEFORMSEG_BUILD_DIR, -DDEFORMSEG_BUILD_EXAMPLES=ON)")
    folder = tmp_path / "store"
    subprocess.run([str(program), str(folder)], check=True, capture_output=True)
    return folder


def pattern(c):
    """The example's clip c: its (R, W) signatures, frames, summary (float32 arithmetic, as in C++)."""
    rows, width = 1 + c % 5, 4
    k, r = np.meshgrid(np.arange(width), np.arange(rows))
    values = (1000 * c + 10 * k + r).astype(np.float32) / np.float32(7)
    if c == 5:
        values = values + np.float32(0.5)
    summary = np.array([np.float32(c) / np.float32(3), -np.float32(c) / np.float32(3)], dtype=np.float32)
    return values, (2 * np.arange(rows)).astype(np.uint32), summary


@pytest.mark.parametrize("verify", [False, True])
def test_reads_what_the_cpp_writer_wrote_bit_for_bit(store, verify):
    s = read_store(store, verify=verify)
    assert len(s) == 12 and s.width == 4 and s.summary_width == 2
    assert s.manifest["description"] == {"policy": "example", "width": 4}
    assert s.manifest["summary"] == {"fields": ["third", "minus third"]}
    assert s.clips.dtype == CLIP_DTYPE
    for c in range(12):
        values, frames, summary = pattern(c)
        signatures, clip_frames = s.clip(c)
        assert signatures.dtype == np.float32 and signatures.shape == values.shape
        assert signatures.tobytes() == values.tobytes()
        assert clip_frames.tobytes() == frames.tobytes()
        assert s.summary(c).tobytes() == summary.tobytes()
        assert s.strings(c) == (f"/motions/set{c // 4}.glb", f"Take{c % 4}", "weld=1", "", "")
        assert s.find(f"/motions/set{c // 4}.glb", f"Take{c % 4}") == c
        record = s.clips[c]
        assert (record["source_size"], record["source_mtime_ns"], record["fps"]) == \
            (4096 + c, 1_700_000_000_000_000_000 + c, 30.0)
        assert record["frame_count"] == 2 * len(frames)
        assert record["segment"] == (2 if c in (5, 10, 11) else 1)  # the replaced clip keeps its index
    assert s.find("/motions/nowhere.glb") is None


def test_numpy_alone_reads_a_block(store):
    """The layout as documented: np.load of a data file, a block reshaped (W, R) and transposed."""
    s = read_store(store)
    record = s.clips[7]
    data = np.load(store / f"signatures-{int(record['segment']):06d}.npy", mmap_mode="r")
    rows, offset = int(record["rows"]), int(record["offset"])
    assert offset % 16 == 0
    block = data[offset:offset + rows * 4].reshape(4, rows).T
    assert block.tobytes() == pattern(7)[0].tobytes()


def flip(path, position):
    data = bytearray(path.read_bytes())
    data[position] ^= 0x10
    path.write_bytes(bytes(data))


def test_damage_is_named(store):
    manifest = store / "store.json"
    original = manifest.read_bytes()
    manifest.write_bytes(original.replace(b'"policy": "example"', b'"policy": "exbmple"'))
    with pytest.raises(StoreError, match="store.json: its checksum does not match its contents"):
        read_store(store)
    manifest.write_bytes(original)

    flip(store / "clips-000002.npy", -3)
    with pytest.raises(StoreError, match="clips-000002.npy: its checksum does not match the manifest's"):
        read_store(store)
    flip(store / "clips-000002.npy", -3)

    flip(store / "signatures-000001.npy", -2)
    read_store(store)  # the data is checked with verify only
    with pytest.raises(StoreError, match="signatures-000001.npy: its checksum does not match the manifest's"):
        read_store(store, verify=True)
    flip(store / "signatures-000001.npy", -2)

    data = (store / "frames-000001.npy").read_bytes()
    (store / "frames-000001.npy").write_bytes(data[:-4])
    with pytest.raises(StoreError, match=f"frames-000001.npy: {len(data) - 4} bytes, the manifest says "
                                         f"{len(data)}: truncated"):
        read_store(store)

    with pytest.raises(StoreError, match="not a motion store: the folder has no store.json"):
        read_store(store / "..")
