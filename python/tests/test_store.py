"""The motion store from Python: describe_to_store, open_store and MotionStore, and similarity_matrix
and evaluate given a store. Made of a few shared clips (a labels CSV written from motions.csv into
a scratch folder): the store's values equal those of similarity_matrix on the animations read now
and the tool's on the same store, bit for bit; unchanged clips are skipped; a missing, truncated
or corrupted store is refused naming the file."""
import csv
import doctest
import os
import pickle
import re
import zlib

import numpy as np
import pytest

import deformseg
from deformseg import store_format

from conftest import REPOSITORY, data_dir

# A few of the shared clips: two small characters, several motions each, a distractor.
ROWS = {("Fox.glb", "Walk"), ("Fox.glb", "Run"), ("Fox.glb", "Survey"), ("RobotExpressive.glb", "Walking"),
        ("RobotExpressive.glb", "Running"), ("RobotExpressive.glb", "Idle"), ("RobotExpressive.glb", "Dance")}


def write_labels(characters, path, rows=ROWS):
    """The rows of the shared motions.csv among `rows`, their files made absolute, into `path`."""
    with open(characters / "motions.csv", newline="") as f:
        listed = [r for r in csv.DictReader(f) if (r["file"], r["clip"]) in rows]
    assert len(listed) == len(rows)
    with open(path, "w", newline="") as f:
        out = csv.DictWriter(f, fieldnames=list(listed[0]))
        out.writeheader()
        for row in listed:
            out.writerow(dict(row, file=str(characters / row["file"])))
    return path


@pytest.fixture(scope="module")
def described(characters, tmp_path_factory):
    """(labels CSV, store folder, the report of describing it, the animations of the rows in order)."""
    root = tmp_path_factory.mktemp("store")
    labels = write_labels(characters, root / "labels.csv")
    report = deformseg.describe_to_store(labels, root / "S")
    animations = [deformseg.read_animation(row["file"], clip=row["clip"])
                  for row in deformseg.read_motion_labels(labels)]
    return labels, root / "S", report, animations


# ---- describing ---------------------------------------------------------------------------------

def test_describe_skips_unreadable_inputs_and_keeps_what_it_described(characters, tmp_path):
    # Files that are not glTF among good ones: a clip of one fails when it is described (after the
    # fox's clips, which come first as their file does), the other when its clips are listed.
    # Without skip_unreadable the call raises naming the file, the fox's clips stored; with it, the
    # rest go in and both are listed.
    labels = write_labels(characters, tmp_path / "labels.csv")
    bad, unlisted = tmp_path / "bad.glb", tmp_path / "unlisted.glb"
    bad.write_bytes(b"not a glTF file")
    unlisted.write_bytes(b"not a glTF file either")
    inputs = [str(characters / "Fox.glb") + "#Walk", str(bad) + "#Walk", str(labels)]
    with pytest.raises(deformseg.InvalidInput, match="bad.glb"):
        deformseg.describe_to_store(inputs, tmp_path / "S")
    assert len(deformseg.open_store(tmp_path / "S")) == 3
    report = deformseg.describe_to_store(inputs + [unlisted], tmp_path / "S", skip_unreadable=True)
    assert [line.split(": ")[0] for line in report["unreadable"]] == [str(unlisted), str(bad.resolve()) + "#Walk"]
    assert len(report["skipped"]) == 3 and report["clips"] == len(ROWS)


def test_describe_reports_the_clips_and_skips_them_the_second_time(described):
    labels, folder, report, animations = described
    rows = deformseg.read_motion_labels(labels)
    names = [f"{os.path.realpath(r['file'])}#{r['clip']}" for r in rows]
    assert report == {"store": str(folder), "clips": len(rows), "described": names, "redescribed": [],
                      "skipped": [], "unreadable": [], "poses_left_out": []}
    again = deformseg.describe_to_store([str(labels)], folder)
    assert again["skipped"] == names and again["described"] == again["redescribed"] == []
    assert again["clips"] == len(rows)


def test_a_touched_source_is_described_again_unless_its_hash_is_the_same(fox, tmp_path):
    copy = tmp_path.resolve() / "Fox.glb"
    copy.write_bytes(fox.read_bytes())
    store = tmp_path / "S"
    first = deformseg.describe_to_store(copy, store, hash=True)
    assert first["described"] == [f"{copy}#Survey", f"{copy}#Walk", f"{copy}#Run"]
    stat = copy.stat()
    os.utime(copy, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    assert deformseg.describe_to_store(copy, store, hash=True)["skipped"] == first["described"]
    touched = deformseg.describe_to_store(f"{copy}#Walk", store)  # by its time: changed
    assert touched["redescribed"] == [f"{copy}#Walk"] and touched["clips"] == 3


def test_describe_refuses_what_the_tool_refuses(fox, tmp_path):
    with pytest.raises(deformseg.InvalidInput, match="Nope") as error:
        deformseg.describe_to_store(fox, tmp_path / "S", clip="Nope")
    assert error.value.file == os.path.realpath(fox)  # canonical, as the store records it
    missing = tmp_path / "missing.glb"
    with pytest.raises(deformseg.InvalidInput) as error:
        deformseg.describe_to_store(missing, tmp_path / "S")
    assert str(missing) in str(error.value)
    with pytest.raises(TypeError, match=r"inputs\[1\]: expected a path \(str or os.PathLike\), got int"):
        deformseg.describe_to_store([fox, 3], tmp_path / "S")
    with pytest.raises(deformseg.InvalidInput, match="up must be"):
        deformseg.describe_to_store(fox, tmp_path / "S", up="z")
    assert not (tmp_path / "S").exists() or not any((tmp_path / "S").glob("signatures-*"))
    deformseg.describe_to_store(f"{fox}#Walk", tmp_path / "T")
    with pytest.raises(deformseg.InvalidInput, match="other options"):  # one description per store
        deformseg.describe_to_store(f"{fox}#Run", tmp_path / "T", up="+x")


# ---- the store's contents -----------------------------------------------------------------------

def test_the_store_holds_the_clips_in_the_rows_order(described):
    labels, folder, report, animations = described
    store = deformseg.open_store(folder)
    assert len(store) == len(animations) and store.folder == str(folder)
    assert store.names == report["described"] and store.generation == 1
    assert store.description["policy"] == "motion-signature" and store.description["width"] == store.width
    for i, (record, animation) in enumerate(zip(store.records, animations)):
        assert record["index"] == i and record["name"] == store.names[i]
        assert (record["frames"], record["fps"]) == (animation.num_frames, animation.fps)
        assert store.index_of(record["path"], record["clip"]) == i
    assert store.index_of("/no/such/file.glb") is None
    assert repr(store) == f"<deformseg.MotionStore {folder}: {len(animations)} clips>"


def test_signatures_are_read_only_views_of_the_mapping_equal_to_the_numpy_reader(described):
    folder = described[1]
    store = deformseg.open_store(folder)
    reader = store_format.read_store(folder, verify=True)
    assert len(reader) == len(store)
    for i in range(len(store)):
        signatures, frames = store.signatures(i), store.frames(i)
        block, reader_frames = reader.clip(i)
        assert signatures.dtype == np.float32 and signatures.shape == (store.records[i]["rows"], store.width)
        assert not signatures.flags.writeable and not frames.flags.writeable
        assert signatures.strides == (4, 4 * signatures.shape[0])  # the store's layout, not a copy
        assert signatures.tobytes() == block.tobytes() and np.array_equal(frames, reader_frames)
        assert reader.find(store.records[i]["path"], store.records[i]["clip"]) == i
    # The view keeps the store open: it outlives every reference to the object.
    view = deformseg.open_store(folder).signatures(0)
    assert view.tobytes() == reader.clip(0)[0].tobytes()
    with pytest.raises(deformseg.InvalidInput, match=f"no clip {len(store)}: the store holds {len(store)} clips"):
        store.signatures(len(store))


# ---- searching: the values of similarity_matrix ---------------------------------------------------

def ranked(row, leave_out=None):
    """(index, value) of a matrix row by decreasing value, ties by index, as the search ranks them."""
    order = sorted((i for i in range(len(row)) if i != leave_out), key=lambda i: (-row[i], i))
    return [(i, float(row[i])) for i in order]


def test_the_matrix_of_a_store_is_similarity_matrix_of_the_animations(described):
    folder, animations = described[1], described[3]
    store = deformseg.open_store(folder)
    m = deformseg.similarity_matrix(animations)
    assert np.array_equal(store.matrix(), m)
    assert np.array_equal(deformseg.similarity_matrix(store), m)
    steps = []
    store.matrix(progress=lambda done, total: steps.append((done, total)))
    assert steps and steps[-1][0] == steps[-1][1]
    with pytest.raises(deformseg.SimilarityStopped):
        deformseg.similarity_matrix(store, progress=lambda done, total: False)


def test_search_knn_graph_and_nearest_to_clip_equal_the_sorted_matrix_rows(described):
    folder, animations = described[1], described[3]
    store = deformseg.open_store(folder)
    m = deformseg.similarity_matrix(animations)
    n = len(store)
    for q, query in enumerate(animations[:3]):
        found = store.search(query, k=4, threads=1)
        assert [(x["index"], x["value"]) for x in found["neighbours"]] == ranked(m[q])[:4]
        assert [x["rank"] for x in found["neighbours"]] == [1, 2, 3, 4]
        assert [x["name"] for x in found["neighbours"]] == [store.names[x["index"]] for x in found["neighbours"]]
        p = found["pruning"]
        assert p["candidates"] == n and p["aligned"] + p["pruned_by_summary"] + p["pruned_by_rows"] + \
            p["abandoned"] == n
        assert store.search(query, k=4, threads=2) == found  # the counts too
    everything = store.search(animations[0], k=n + 5)["neighbours"]  # k above the size: every clip
    assert [(x["index"], x["value"]) for x in everything] == ranked(m[0])
    graph = store.knn_graph(k=3)
    assert len(graph) == n
    for i, node in enumerate(graph):
        assert [(x["index"], x["value"]) for x in node["neighbours"]] == ranked(m[i], leave_out=i)[:3]
        assert store.nearest_to_clip(i, 3)["neighbours"] == node["neighbours"]


def test_tiles_blocks_of_rows_and_candidates_are_blocks_of_the_whole(described):
    folder, animations = described[1], described[3]
    store = deformseg.open_store(folder)
    m, n = store.matrix(), len(store)
    assert np.array_equal(store.matrix(threads=1), m)
    for rows, columns in [(range(0, 3), range(2, 7)), (range(4, 7), range(0, 4)), (range(5, 5), range(0, n))]:
        assert np.array_equal(store.matrix(rows=rows, columns=columns, threads=1), m[rows.start:rows.stop,
                                                                                      columns.start:columns.stop])
    assert np.array_equal(store.matrix(rows=range(1, 3)), m[1:3])  # columns default to all
    graph = store.knn_graph(3)
    assert store.knn_graph(3, rows=range(2, 5)) == graph[2:5]
    block = range(0, 4)
    found = store.knn_graph(3, candidates=block)
    for i, node in enumerate(found):
        expected = [(j, m[i, j]) for j in block if j != i]
        expected.sort(key=lambda x: (-x[1], x[0]))
        assert [(x["index"], x["value"]) for x in node["neighbours"]] == expected[:3]
        assert node["pruning"]["candidates"] == len(block) - (i in block)
    in_block = store.search(animations[0], k=2, candidates=range(3, n))["neighbours"]
    assert [(x["index"], x["value"]) for x in in_block] == [p for p in ranked(m[0]) if p[0] >= 3][:2]
    assert store.nearest_to_clip(1, 2, candidates=range(0, 2))["neighbours"][0]["index"] == 0


def test_a_query_described_by_the_store_searches_as_the_animation(described):
    store = deformseg.open_store(described[1])
    query = described[3][2]
    description = store.describe(query)
    assert description.dtype == np.float32 and description.shape[1] == store.width
    assert description.flags.f_contiguous
    assert store.search(description, k=4) == store.search(query, k=4)
    assert store.search(np.ascontiguousarray(description), k=4) == store.search(query, k=4)  # copied to its layout
    with pytest.raises(deformseg.InvalidInput, match=f"have 3 values, the collection's {store.width}"):
        store.search(description[:, :3])
    with pytest.raises(deformseg.InvalidInput, match="an .R, W. float32 array of R >= 1 rows"):
        store.search(description[:0])
    with pytest.raises(TypeError, match="query: expected an Animation or an .R, W. float32 array, got list"):
        store.search([1.0])


def test_merge_nearest_makes_searches_of_blocks_the_search_of_all(described):
    store = deformseg.open_store(described[1])
    n, query = len(store), described[3][1]
    whole = store.search(query, k=4)
    for size in (1, 3):
        parts = [store.search(query, k=4, candidates=range(b, min(n, b + size))) for b in range(0, n, size)]
        merged = deformseg.merge_nearest(parts, 4)
        assert merged["neighbours"] == whole["neighbours"]  # the dicts too, ranks renumbered
        assert merged["pruning"]["candidates"] == n
    graph = store.knn_graph(2)
    rows = [store.knn_graph(2, candidates=block) for block in (range(0, 3), range(3, n))]
    assert [deformseg.merge_nearest([rows[0][i], rows[1][i]], 2)["neighbours"] for i in range(n)] == \
        [row["neighbours"] for row in graph]
    with pytest.raises(deformseg.InvalidInput, match=r"parts.1.: clip \d+ is in two parts"):
        deformseg.merge_nearest([whole, whole])
    with pytest.raises(TypeError, match="parts.0.: expected a dict as MotionStore.search gives, got int"):
        deformseg.merge_nearest([3])


def test_blocks_of_clips_are_ranges_of_the_store(described):
    store = deformseg.open_store(described[1])
    n = len(store)
    for call in (lambda: store.matrix(rows=range(0, n + 1)), lambda: store.knn_graph(rows=range(2, n + 3)),
                 lambda: store.search(described[3][0], candidates=range(1, n + 1))):
        with pytest.raises(deformseg.InvalidInput, match=rf"are not clips of the store, which holds {n}") as error:
            call()
        assert error.value.file == str(described[1])
    with pytest.raises(deformseg.InvalidInput, match=r"columns: expected range\(begin, end\) with .* step 1"):
        store.matrix(columns=range(0, 4, 2))
    with pytest.raises(TypeError, match="rows: expected a range of clips"):
        store.knn_graph(rows=(0, 2))


def test_the_search_refuses_bad_arguments(described, grid):
    store = deformseg.open_store(described[1])
    faces, frames = grid(3, 3, 4)
    cases = [(lambda: store.search(described[3][0], k=0), r"k must be a whole number in \[1, 1000000\], got 0"),
             (lambda: store.search(described[3][0], k=-3), r"k must be a whole number in \[1, 1000000\], got -3"),
             (lambda: store.search(deformseg.Animation(faces, frames[:1])), "query: an animation of 1 frame"),
             (lambda: store.search(described[3][0], threads=-1), r"threads must be a whole number in \[0, 1024\]"),
             (lambda: store.nearest_to_clip(-1), "no clip -1: the store holds"),
             (lambda: store.knn_graph(k=0), "k must be a whole number in"),
             (lambda: store.nearest_to_clip(0, k=-1), "k must be a whole number in"),
             (lambda: deformseg.merge_nearest([], k=-1), "k must be a whole number in"),
             (lambda: deformseg.similarity_matrix(store, described[3]), "database: a MotionStore's matrix"),
             (lambda: deformseg.similarity_matrix(store, policy="histogram"), "motion signatures aligned by dtw")]
    for call, message in cases:
        with pytest.raises(deformseg.InvalidInput, match=message):
            call()
    other = "none" if store.description["up"] is not None else "+y"
    with pytest.raises(deformseg.InvalidInput, match="differs from the store's up direction") as error:
        deformseg.similarity_matrix(store, up=other)
    assert error.value.file == str(described[1])
    with pytest.raises(TypeError, match="animations: expected a sequence of Animation or a MotionStore, got int"):
        deformseg.similarity_matrix(3)


def test_a_store_of_height_bands_records_them_and_searches_under_them(characters, tmp_path):
    # Described with bands=3, the store's matrix is the banded policy's, its description says so,
    # describing into it otherwise or asking for other bands is refused naming the store.
    labels = write_labels(characters, tmp_path / "labels.csv")
    deformseg.describe_to_store(labels, tmp_path / "S", bands=3)
    store = deformseg.open_store(tmp_path / "S")
    assert store.description["bands"] == 3 and store.description["width"] == 3 * 64
    animations = [deformseg.read_animation(row["file"], clip=row["clip"])
                  for row in deformseg.read_motion_labels(labels)]
    m = deformseg.similarity_matrix(animations, bands=3)
    assert np.array_equal(store.matrix(), m) and np.array_equal(deformseg.similarity_matrix(store, bands=3), m)
    for q in (0, len(animations) // 2):  # the pruned search, its bounds on banded rows, ranks as the matrix
        found = store.search(animations[q], k=5, threads=1)["neighbours"]
        assert [(x["index"], x["value"]) for x in found] == ranked(m[q])[:5]
    with pytest.raises(deformseg.InvalidInput, match="bands 1 differs from the store's 3"):
        deformseg.similarity_matrix(store, bands=1)
    with pytest.raises(deformseg.InvalidInput, match="other options"):
        deformseg.describe_to_store(labels, tmp_path / "S")


# ---- evaluate -------------------------------------------------------------------------------------

def test_evaluate_on_a_store_equals_evaluate_on_the_matrix_of_the_animations(described):
    labels, folder, _, animations = described
    store = deformseg.open_store(folder)
    expected = deformseg.evaluate(deformseg.similarity_matrix(animations), deformseg.read_motion_labels(labels))
    got = deformseg.evaluate(store, labels)
    for name in ("queries", "nn_accuracy", "mean_average_precision", "roc_auc", "median_same", "median_different",
                 "same_pairs", "different_pairs", "labels", "confusion", "per_motion", "per_query"):
        assert getattr(got, name) == getattr(expected, name), name
    assert got.queries > 0


def test_evaluate_on_a_store_names_the_clips_it_lacks(described, characters, tmp_path):
    folder = described[1]
    labels = write_labels(characters, tmp_path / "more.csv", ROWS | {("RobotExpressive.glb", "Jump")})
    with pytest.raises(deformseg.InvalidInput, match=r"1 missing \(.*RobotExpressive.glb#Jump\)") as error:
        deformseg.evaluate(deformseg.open_store(folder), labels)
    assert error.value.file == str(folder)
    with pytest.raises(TypeError, match="labels: with a MotionStore, expected the path of a labels CSV"):
        deformseg.evaluate(deformseg.open_store(folder), [{"motion": "walk"}])


def test_evaluate_on_a_store_refuses_a_clip_changed_since(fox, tmp_path):
    copy = tmp_path / "Fox.glb"
    copy.write_bytes(fox.read_bytes())
    labels = tmp_path / "labels.csv"
    labels.write_text(f"file,clip,motion,rig,body\n{copy},Walk,walk,fox,a\n{copy},Run,walk,fox,b\n")
    deformseg.describe_to_store(labels, tmp_path / "S")
    store = deformseg.open_store(tmp_path / "S")
    assert deformseg.evaluate(store, labels).queries == 2
    stat = copy.stat()
    os.utime(copy, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    with pytest.raises(deformseg.InvalidInput, match="2 changed since described"):
        deformseg.evaluate(store, labels)


def test_labels_with_body_files_play_each_clip_on_its_body(characters, tmp_path):
    # The Knight's Idle on the Barbarian's body is the Barbarian's Idle: identical signatures.
    knight, barbarian = characters / "Knight.glb", characters / "Barbarian.glb"
    labels = tmp_path / "labels.csv"
    labels.write_text(f"file,clip,motion,body_file\n{knight},Idle,idle,{barbarian}\n{barbarian},Idle,idle,\n")
    (row, own) = deformseg.read_motion_labels(labels)
    assert (row["body_file"], row["body"], own["body_file"]) == (str(barbarian), str(barbarian), "")
    deformseg.describe_to_store(labels, tmp_path / "S")
    store = deformseg.open_store(tmp_path / "S")
    assert [record["input_options"].get("body") for record in store.records] == [str(barbarian.resolve()), None]
    assert np.array_equal(store.signatures(0), store.signatures(1))


def test_one_clip_on_two_bodies_is_two_clips(characters, tmp_path):
    # The Knight's Idle on the Barbarian's body and on its own: two clips of the store, each found
    # by its body, named with it, and evaluated from the store.
    knight, barbarian = characters / "Knight.glb", characters / "Barbarian.glb"
    labels = tmp_path / "labels.csv"
    labels.write_text(f"file,clip,motion,body_file\n{knight},Idle,idle,{barbarian}\n{knight},Idle,idle,{knight}\n"
                      f"{barbarian},Idle,idle,\n")
    report = deformseg.describe_to_store(labels, tmp_path / "S")
    k, b = str(knight.resolve()), str(barbarian.resolve())
    assert report["described"] == [f"{k}#Idle on {b}", f"{k}#Idle on {k}", f"{b}#Idle"]
    store = deformseg.open_store(tmp_path / "S")
    assert [(r["path"], r["clip"], r["body"]) for r in store.records] == [(k, "Idle", b), (k, "Idle", k), (b, "Idle", "")]
    assert store.names == report["described"]
    assert [store.index_of(k, "Idle", body) for body in (b, k, "")] == [0, 1, None]
    assert store.index_of(barbarian.resolve(), "Idle") == 2
    found = store.search(deformseg.read_animation(f"{barbarian}#Idle"), 3)["neighbours"]
    assert {(n["index"], n["body"]) for n in found} == {(0, b), (1, k), (2, "")}
    assert all(n["name"] == store.names[n["index"]] for n in found)
    assert deformseg.evaluate(store, labels).queries == 3
    assert [strings[4] for strings in map(store_format.read_store(tmp_path / "S").strings, range(3))] == [b, k, ""]
    assert deformseg.describe_to_store(labels, tmp_path / "S")["skipped"] == report["described"]


def test_a_latin1_file_name_is_stored_escaped(characters, tmp_path):
    # A file name of Latin-1 bytes (os.fsdecode gives Python's str of it): kept as UTF-8, its byte E9
    # as \xE9, named so in the report and the records, and found again (skipped) by a second call.
    knight = tmp_path / os.fsdecode(b"Kn\xe9ight.glb")
    knight.write_bytes((characters / "Knight.glb").read_bytes())
    kept = str(tmp_path.resolve()) + "/Kn\\xE9ight.glb"
    report = deformseg.describe_to_store(f"{knight}#Idle", tmp_path / "S")
    assert report["described"] == [kept + "#Idle"]
    store = deformseg.open_store(tmp_path / "S")
    assert (store.records[0]["path"], store.index_of(kept, "Idle")) == (kept, 0)
    assert deformseg.describe_to_store(f"{knight}#Idle", tmp_path / "S")["skipped"] == [kept + "#Idle"]


def as_version_1(folder):
    """The store in `folder` (of one append) rewritten as version 1 of the format wrote it: 4 strings
    per clip (path, clip, input options, topology path), no body."""
    table_path, strings_path = (folder / store_format.file_name(kind, 1) for kind in ("clips", "strings"))
    table_bytes = table_path.read_bytes()
    table = np.load(table_path).copy()
    header = len(table_bytes) - table.nbytes
    strings, old = np.load(strings_path).tobytes(), bytearray()
    for row in table:
        start, length = int(row["strings"]), int(row["strings_length"])
        four = b"\0".join(strings[start:start + length].split(b"\0")[:4]) + b"\0"
        row["strings"], row["strings_length"] = len(old), len(four)
        old += four
    np.save(strings_path, np.frombuffer(bytes(old), dtype=np.uint8))
    table_path.write_bytes(table_bytes[:header] + table.tobytes())
    text = (folder / "store.json").read_text().replace('"version": 2', '"version": 1')
    for path in (table_path, strings_path):
        data = path.read_bytes()
        crc = zlib.crc32(data[len(data) - (table.nbytes if path == table_path else len(old)):])
        text = re.sub(rf'("name": "{path.name}",\s*"bytes": )\d+(,\s*"data_crc32": )\d+',
                      rf"\g<1>{len(data)}\g<2>{crc}", text)
    covered = text[:text.rindex('"checksum"')].encode()
    (folder / "store.json").write_bytes(covered + f'"checksum": "crc32:{zlib.crc32(covered):08x}"}}\n'.encode())


def test_a_store_of_version_1_is_read_its_bodies_from_the_topology(characters, tmp_path):
    # Version 1 kept the body a character file's clip played on as its topology path: both readers
    # read it as the clip's body, and the next describe finds the clips unchanged.
    knight, barbarian = characters / "Knight.glb", characters / "Barbarian.glb"
    labels = tmp_path / "labels.csv"
    labels.write_text(f"file,clip,motion,body_file\n{knight},Idle,idle,{barbarian}\n{knight},Walking_A,walk,\n")
    deformseg.describe_to_store(labels, tmp_path / "S")
    as_version_1(tmp_path / "S")
    b = str(barbarian.resolve())
    for verify in (False, True):
        old = store_format.read_store(tmp_path / "S", verify=verify)
        assert old.manifest["version"] == 1 and [old.strings(i)[4] for i in range(2)] == [b, ""]
    store = deformseg.open_store(tmp_path / "S", verify="checksums")
    assert [r["body"] for r in store.records] == [b, ""]
    deformseg.evaluate(store, labels)  # every labelled clip found on its body
    assert len(deformseg.describe_to_store(labels, tmp_path / "S")["skipped"]) == 2


# ---- a store that is not one ----------------------------------------------------------------------

def test_a_missing_truncated_or_corrupted_store_is_refused_naming_the_file(described, tmp_path):
    with pytest.raises(deformseg.InvalidInput, match="not a motion store") as error:
        deformseg.open_store(tmp_path / "missing")
    assert error.value.file == str(tmp_path / "missing")
    copy = tmp_path / "S"
    copy.mkdir()
    for f in described[1].iterdir():
        (copy / f.name).write_bytes(f.read_bytes())
    signatures = copy / store_format.file_name("signatures", 1)
    data = bytearray(signatures.read_bytes())
    data[-1] ^= 0xFF  # flipped bits in the last clip's data: opening does not read them
    signatures.write_bytes(bytes(data))
    opened = deformseg.open_store(copy)
    opened.signatures(0)
    last = len(opened) - 1
    with pytest.raises(deformseg.InvalidInput, match=rf"clip {last} \(.*\): its block's checksum does not match"):
        opened.signatures(last)  # as a search reads it: checked on its first read
    with pytest.raises(deformseg.InvalidInput, match="checksum") as error:
        deformseg.open_store(copy, verify="checksums")
    assert error.value.file == str(signatures)
    # A merge of parts (deformseg.distributed's last step) never carries the damaged clip on.
    with pytest.raises(deformseg.InvalidInput, match=rf"clip {last} \(.*\): its block's checksum does not match"):
        deformseg._deformseg._merge_stores(tmp_path / "merged", [copy])
    assert not (tmp_path / "merged" / "store.json").exists()
    signatures.write_bytes(bytes(data[:-4]))  # truncated
    with pytest.raises(deformseg.InvalidInput, match="truncated|bytes") as error:
        deformseg.open_store(copy)
    assert error.value.file == str(signatures)
    with pytest.raises(deformseg.InvalidInput, match="verify must be 'structure' or 'checksums', got 'all'"):
        deformseg.open_store(described[1], verify="all")


def test_a_merge_of_parts_that_hold_the_same_clip_replaces_it(described, tmp_path):
    # Parts described apart may overlap (a task retried on another worker): the clip met again
    # replaces the one of the part before it at its index, as in a store that held it already.
    store = deformseg.open_store(described[1])
    merged = deformseg._deformseg._merge_stores(tmp_path / "merged", [described[1], described[1]])
    assert merged["clips"] == len(store)
    assert len(merged["described"]) == len(store) and merged["redescribed"] == merged["described"]
    again = deformseg.open_store(tmp_path / "merged")
    assert [again.signatures(i).tobytes() for i in range(len(again))] == \
        [store.signatures(i).tobytes() for i in range(len(store))]


# ---- pickling ---------------------------------------------------------------------------------------

def test_a_store_pickles_as_its_folder(described):
    store = deformseg.open_store(described[1], verify="checksums")
    state = store.__getstate__()
    assert state == (1, str(described[1]), "checksums")
    restored = pickle.loads(pickle.dumps(store))
    assert restored.names == store.names and restored.signatures(1).tobytes() == store.signatures(1).tobytes()
    with pytest.raises(ValueError, match="^deformseg.MotionStore: cannot restore a pickled state"):
        deformseg.MotionStore.__new__(deformseg.MotionStore).__setstate__((2,) + state[1:])


# ---- the tool on the same store -------------------------------------------------------------------

def test_search_knn_graph_matrix_and_evaluate_equal_the_tools(tool, described, fox):
    labels, folder, _, animations = described
    store = deformseg.open_store(folder)
    searched = tool("search", f"{fox}#Walk", "--store", folder, "-k", 3, "--clip-index", 4, "--json", "-")
    by_query = [store.search(deformseg.read_animation(fox, clip="Walk"), 3), store.nearest_to_clip(4, 3)]
    for mine, theirs in zip(by_query, searched["queries"]):
        assert [(x["index"], x["path"], x["clip"], x["value"]) for x in mine["neighbours"]] == \
            [(x["index"], x["path"], x["clip"], x["value"]) for x in theirs["neighbours"]]
        assert mine["pruning"] == theirs["pruning"]
    graph = tool("knn-graph", "--store", folder, "-k", 2, "--json", "-")
    edges = [(i, x["index"], x["rank"], x["value"]) for i, node in enumerate(store.knn_graph(2))
             for x in node["neighbours"]]
    assert edges == [(e["source"], e["target"], e["rank"], e["value"]) for e in graph["edges"]]
    assert store.matrix().tolist() == tool("matrix", "--store", folder, "--json", "-")["similarity"]
    evaluated = tool("evaluate", labels, "--store", folder, "--json", "-")["scores"]
    scores = deformseg.evaluate(store, labels)
    assert evaluated["queries"] > 0
    for name, value in evaluated.items():  # the rows of each file are together: the same order
        assert getattr(scores, name) == value, name


def test_find_equals_the_tools_and_finds_a_clip_in_itself(tool, described, fox):
    labels, folder, _, animations = described
    store = deformseg.open_store(folder)
    walk = deformseg.read_animation(fox, clip="Walk")
    found = store.find(walk, 4, shortest=0.5, threads=1)
    theirs = tool("find", f"{fox}#Walk", "--store", folder, "--count", 4, "--json", "-")["matches"]
    assert [(m["index"], m["path"], m["clip"], m["first"], m["last"], m["value"], [list(p) for p in m["alignment"]])
            for m in found] == [(m["clip_index"], m["path"], m["clip"], m["first"], m["last"], m["similarity"],
                                 m["alignment"]) for m in theirs]
    own = store.index_of(os.path.realpath(fox), "Walk")
    assert found[0]["index"] == own and found[0]["value"] == 1.0 and found[0]["name"] == store.names[own]
    assert store.find(walk, 4, threads=2) == found
    with pytest.raises(deformseg.InvalidInput, match=r"count must be a whole number in \[1, 1000000\], got 0"):
        store.find(walk, 0)
    with pytest.raises(deformseg.InvalidInput, match=r"shortest must be in \(0, 1\]"):
        store.find(walk, shortest=0)


# ---- the manual's example -------------------------------------------------------------------------

def test_the_chapter_s_session_runs_as_written(fox, tmp_path, monkeypatch):
    """The session of chapter 12's "A motion store", run by doctest in a scratch folder, the shared
    data where it is."""
    chapter = (REPOSITORY / "doc" / "chapters" / "12_python.md").read_text()
    section = chapter[chapter.index("## A motion store"):]
    session = re.search(r"@code\{\.py\}\n(.*?)@endcode", section, re.S).group(1)
    session = session.replace('"../shared/data/', f'"{data_dir()}/')
    monkeypatch.chdir(tmp_path)
    test = doctest.DocTestParser().get_doctest(session, {"deformseg": deformseg}, "chapter 12", None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.summarize(verbose=False) == doctest.TestResults(0, len(test.examples)) and test.examples
