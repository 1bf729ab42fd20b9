"""glTF characters of the shared data: a clip by name, by index or after a '#' in the input
(FILE.glb#CLIP, for every command that reads an animation); the file's clips, skins and meshes;
what the repair did; a file of several clips with none named is refused, naming them."""

import json
import re
import struct

import pytest

from conftest import matches_all, fails, succeeds


@pytest.fixture(scope="session")
def fox(characters):
    return characters / "Fox.glb"


@pytest.fixture(scope="session")
def fox_walk(fox):
    return f"{fox}#Walk"


def test_info_gltf_fox(tool, fox):
    matches_all(succeeds(tool("info", fox, "--clip", "Walk")).output,
                r"clip +\"Walk\"", r"frames +23\n", r"vertices +290\n", r"triangles +576\n", r"format +glb\n",
                r"1438 vertices welded", r"skins +1 \(24 joints\)", r"Survey +3\.417 s +104 frames")


def test_info_gltf_robot(tool, characters):
    info = tool("info", characters / "RobotExpressive.glb", "--clip", "Dance", "--json", "-").json()
    assert info["repair"]["degenerate_triangles"] == 3
    assert info["gltf"]["clip"]["name"] == "Dance" and info["frames"] == 101


def test_info_gltf_clip_by_index(tool, fox):
    matches_all(succeeds(tool("info", fox, "--clip", "2")).output, r"clip +\"Run\"", r"frames +36\n")


def test_info_gltf_fps(tool, fox):
    matches_all(succeeds(tool("info", fox, "--clip", "Walk", "--fps", "15")).output, r"frames +12\n")


def test_info_gltf_no_weld(tool, fox):
    matches_all(succeeds(tool("info", fox, "--clip", "Walk", "--no-weld")).output,
                r"vertices +1728\n", r"repair +nothing")


def test_info_gltf_unknown_clip(tool, fox):
    fails(tool("info", fox, "--clip", "Jog"), "Fox.glb", "Jog", "Survey", "Walk", "Run")


def test_info_gltf_refuse_defects(tool, characters):
    fails(tool("info", characters / "RobotExpressive.glb", "--refuse-defects"), "RobotExpressive.glb", "repeats")


def test_strain_gltf(tool, fox):
    strain = tool("strain", fox, "--clip", "Walk", "--json", "-").json()
    assert (strain["frames"], strain["triangles"]) == (23, 576)


# convert --no-weld keeps the file's vertices in order: the OBJ frames read back as the clip.
@pytest.fixture(scope="module")
def fox_obj(tool, scratch, fox):
    folder = scratch / "fox-walk"
    return folder, tool("convert", fox, folder, "--clip", "Walk", "--no-weld", "--format", "obj", "--json", "-")


def test_convert_fox_obj(fox_obj):
    result = fox_obj[1].json()
    assert (result["frames"], result["vertices"]) == (23, 1728)


def test_convert_fox_obj_reads_back(tool, fox_obj):
    succeeds(fox_obj[1])
    matches_all(succeeds(tool("info", fox_obj[0])).output,
                r"frames +23\n", r"vertices +1728\n", r"triangles +576\n", r"repair +nothing")


def test_convert_fox_obj_welds(tool, fox_obj):
    succeeds(fox_obj[1])
    matches_all(succeeds(tool("info", fox_obj[0], "--weld")).output, r"vertices +290\n")


@pytest.fixture(scope="module")
def fox_pc2(tool, scratch, fox):
    folder = scratch / "fox-pc2"
    return folder, tool("convert", fox, folder, "--clip", "Walk", "--format", "pc2", "--json", "-")


def test_convert_fox_pc2(fox_pc2):
    result = fox_pc2[1].json()
    assert result["frames"] == 23
    assert [f.endswith(name) for f, name in zip(sorted(result["files"]), ["Fox.obj", "Fox.pc2"])] == [True, True]


def test_convert_fox_pc2_reads_back(tool, fox_pc2):
    succeeds(fox_pc2[1])
    folder = fox_pc2[0]
    matches_all(succeeds(tool("info", folder / "Fox.pc2", "--topology", folder / "Fox.obj")).output,
                r"frames +23\n", r"vertices +290\n", r"triangles +576\n")


# FILE.glb#CLIP names the clip for every command that reads an animation, as --clip does (info
# reads the first when none is named, and says which, with the list of clips).
def test_info_clip_suffix(tool, fox_walk):
    matches_all(succeeds(tool("info", fox_walk)).output, r"input +[^\n]*Fox.glb\n", r"format +glb\n",
                r"clip +\"Walk\"", r"frames +23\n", r"vertices +290\n")


def test_info_clip_suffix_json(tool, fox_walk):
    info = tool("info", fox_walk, "--json", "-").json()
    assert info["format"] == "glb" and info["gltf"]["clip"]["name"] == "Walk" and info["frames"] == 23


def test_info_first_clip(tool, fox):
    matches_all(succeeds(tool("info", fox)).output, r"clip +\"Survey\"", r"clips +3\n", r"Walk ", r"Run ")


def test_convert_clip_suffix(tool, scratch, fox_walk):
    result = tool("convert", fox_walk, scratch / "fox-walk-pc2", "--format", "pc2", "--json", "-").json()
    assert result["frames"] == 23
    folder = scratch / "fox-walk-pc2"
    assert sorted(result["files"]) == [str(folder / "Fox.obj"), str(folder / "Fox.pc2")]


def test_strain_clip_suffix(tool, fox_walk):
    strain = tool("strain", fox_walk, "--json", "-").json()
    assert (strain["frames"], strain["triangles"]) == (23, 576)


def test_temporal_clip_suffix(tool, fox_walk):
    result = tool("temporal", fox_walk, "--json", "-").json()
    assert result["frames"] == 23 and result["segments"][-1]["last"] == 22


def test_spatiotemporal_clip_suffix(tool, fox_walk):
    graph = tool("spatiotemporal", fox_walk, "--json", "-").json()
    assert graph["frames"] == 23 and isinstance(graph["key_frames"], list)


def test_similarity_clip_suffix(tool, fox_walk):
    matches_all(succeeds(tool("similarity", fox_walk, fox_walk)).output, r"similarity +1\.000\n", r"aligned +23 frame pairs")


def test_matrix_clip_suffix(tool, fox, fox_walk):
    matches_all(succeeds(tool("matrix", fox_walk, f"{fox}#Run")).output,
                r"Fox.glb#Walk\n +1 0\.[0-9]+\n", r"Fox.glb#Run\n")


def test_find_clip_suffix(tool, fox, fox_walk):
    matches_all(succeeds(tool("find", fox_walk, f"{fox}#Survey")).output, r"frames [0-9]+ to [0-9]+ +similarity")


def test_evaluate_clip_suffix(tool, scratch, fox):
    labels = scratch / "clip-suffix.csv"
    labels.write_text(f"file,clip,motion\n{fox}#Walk,,walk\n{fox}#Run,,run\n{fox},Walk,walk\n")
    matches_all(succeeds(tool("evaluate", labels)).output,
                r"items +3\n", r"walk +2 / 2 +1.000\n", r"median same +1.000")


NEEDS_CLIP = "the file holds 3 clips"


@pytest.mark.parametrize("command", ["strain", "temporal", "spatiotemporal", "convert"])
def test_needs_clip(tool, scratch, fox, command):
    out = [scratch / "fox-no-clip"] if command == "convert" else []
    run = fails(tool(command, fox, *out), 'as in "Fox.glb#Survey"', "'Survey', 'Walk', 'Run'")
    assert re.search(r"deformseg: error: [^\n]*Fox.glb: the file holds 3 clips: name the one to read", run.err)


def test_similarity_needs_clip(tool, fox, fox_walk):
    fails(tool("similarity", fox_walk, fox), f"Fox.glb: {NEEDS_CLIP}")


def test_matrix_needs_clip(tool, fox, fox_walk):
    fails(tool("matrix", fox_walk, fox), f"Fox.glb: {NEEDS_CLIP}")


def test_find_needs_clip(tool, fox, fox_walk):
    fails(tool("find", fox_walk, fox), f"Fox.glb: {NEEDS_CLIP}")


def test_view_needs_clip(tool, scratch, fox):
    fails(tool("view", fox, "--out", scratch / "view-no-clip"), f"Fox.glb: {NEEDS_CLIP}")


def test_evaluate_needs_clip(tool, scratch, fox):
    labels = scratch / "no-clip.csv"
    labels.write_text(f"file,clip,motion\n{fox},,walk\n{fox},Run,run\n")
    fails(tool("evaluate", labels), f"Fox.glb: {NEEDS_CLIP}")


def test_clip_given_twice(tool, fox_walk):
    fails(tool("strain", fox_walk, "--clip", "Run"), "the clip is given twice")


# Two-input commands take the clip after '#' or by one --clip, for every input that names none;
# their JSON records the clip each input was read as.
def test_similarity_clip_for_every_input(tool, fox):
    both = tool("similarity", fox, fox, "--clip", "Walk", "--significance", "0", "--json", "-").json()
    assert both["similarity"] == 1
    assert [s["clip"] for s in both["sources"]] == ["Walk", "Walk"]
    mixed = tool("similarity", fox, f"{fox}#Run", "--clip", "Walk", "--significance", "0", "--json", "-").json()
    assert [s["clip"] for s in mixed["sources"]] == ["Walk", "Run"] and mixed["similarity"] < 1


# The motion signatures describe a character's clip frame by frame (the clip named by index here),
# its connectivity repaired from what the file fixes, as the matrix of the clips read whole gives
# it, to the last bit; another policy reads the clips whole.
def test_similarity_streams_character_clips(tool, fox, characters):
    knight = characters / "Knight.glb"
    inputs = [f"{fox}#2", f"{knight}#Running_A"]
    run = succeeds(tool("similarity", *inputs, "--significance", "4", "--json", "-"))
    matches_all(run.err, r"Fox.glb#2: clip \"Run\", 36 frames at 30\.0 fps", r"repaired: 1438 vertices welded",
                r"each described frame by frame")
    streamed = run.json()
    assert [s["clip"] for s in streamed["sources"]] == ["Run", "Running_A"]
    whole = succeeds(tool("matrix", *inputs, "--json", "-")).json()
    assert streamed["similarity"] == whole["similarity"][0][1] and streamed["z_score"] is not None
    histogram = succeeds(tool("similarity", *inputs, "--policy", "histogram", "--significance", "0"))
    assert "frame by frame" not in histogram.err


def test_find_clip_by_index(tool, fox):
    found = tool("find", f"{fox}#1", f"{fox}#Walk", "--json", "-").json()
    assert [s["clip"] for s in found["sources"]] == ["Walk", "Walk"]
    assert found["matches"][0]["similarity"] == pytest.approx(1)


def test_strain_records_the_clip_and_fps(tool, fox):
    summary = tool("strain", f"{fox}#Run", "--fps", "12", "--json", "-").json()
    assert summary["sources"] == [{"file": str(fox), "clip": "Run", "fps": 12}]


def test_clips_played_on_another_body(tool, scratch, characters):
    # The Knight's clips on the Barbarian's body (one rig, byte-identical clips) are the Barbarian's
    # own, to the byte of a point cache; info says how many joints the clip moves.
    knight, barbarian = characters / "Knight.glb", characters / "Barbarian.glb"
    for name, inputs in [("own", [f"{barbarian}#Idle"]), ("bound", [f"{knight}#Idle", "--body", barbarian])]:
        succeeds(tool("convert", *inputs, scratch / f"body-{name}", "--format", "pc2"))
    own, bound = scratch / "body-own", scratch / "body-bound"
    assert (bound / "Knight.pc2").read_bytes() == (own / "Barbarian.pc2").read_bytes()
    info = succeeds(tool("info", knight, "--clip", "Idle", "--body", barbarian, "--json", "-")).json()
    assert info["gltf"]["body"] == str(barbarian)
    assert 0 < info["gltf"]["animated_joints"] <= info["gltf"]["joints"]
    # Clips that move nothing of the body, and a body for frames, are refused, named.
    fails(tool("info", f"{characters / 'Fox.glb'}#Walk", "--body", knight), "moves nothing of the body",
          str(knight), "Fox.glb", "it animates 'b_Hip_01'")
    fails(tool("info", f"{knight}#Walking_A", "--body", characters / "Fox.glb"), "moves nothing of the body",
          "the body's joints are '_rootJoint'")
    succeeds(tool("synth", scratch / "body-frames"))
    fails(tool("info", scratch / "body-frames", "--body", knight), "--body applies to character files")


def glb_with(source, target, edit):
    """Writes the glTF binary `source` to `target` with its JSON document changed by `edit`."""
    data = source.read_bytes()
    length = struct.unpack_from("<I", data, 12)[0]
    document = json.loads(data[20:20 + length])
    edit(document)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    rest = data[20 + length:]
    body = struct.pack("<I4s", len(text), b"JSON") + text + rest
    target.write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)
    return target


def test_a_clip_that_moves_few_joints_of_its_body_is_warned_of(tool, scratch, fox):
    # The fox's walk reduced to its head and neck: played on the fox, it moves 2 of its 24 joints.
    def head_and_neck(document):
        names = [node.get("name", "") for node in document["nodes"]]
        for clip in document["animations"]:
            clip["channels"] = [c for c in clip["channels"] if names[c["target"]["node"]] in ("b_Neck_04", "b_Head_05")]
    clips = glb_with(fox, scratch / "fox-head-and-neck.glb", head_and_neck)
    warned = succeeds(tool("info", f"{clips}#Walk", "--body", fox))
    assert f"clip 'Walk' moves 2 of the 24 joints of the body {fox}" in warned.err, warned.describe()
    whole = succeeds(tool("info", f"{fox}#Walk", "--body", fox))
    assert "joints of the body" not in whole.err, whole.describe()
