"""BVH motion capture: every command reads a .bvh file on the body made from its skeleton (info
says so), a malformed file or one of no bone is refused with a message that says what to do, and
--body plays a clip on a character whose joints have its joints' names."""

import json
import math
import struct

import pytest

from conftest import fails, matches_all, succeeds

# A hips joint with a spine of two joints and a leg, each ending in an end site: 5 bones.
SKELETON = """HIERARCHY
ROOT Hips
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
  JOINT Spine
  {
    OFFSET 0 10 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    JOINT Head
    {
      OFFSET 0 10 0
      CHANNELS 3 Zrotation Xrotation Yrotation
      End Site
      {
        OFFSET 0 5 0
      }
    }
  }
  JOINT Leg
  {
    OFFSET 3 -2 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    End Site
    {
      OFFSET 0 -15 0
    }
  }
}
"""
BONES = 5
TUBE_VERTICES = 58


def motion(frames, amplitude, phase):
    """40 frames at 60 per second of the skeleton's joints turning by sines."""
    lines = [f"MOTION\nFrames: {frames}\nFrame Time: {1 / 60!r}"]
    for f in range(frames):
        angles = [amplitude * math.sin(f / 6 + phase + k) for k in range(12)]
        lines.append(" ".join(["0", "0", "0"] + [f"{a:.6f}" for a in angles]))
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="session")
def clips(scratch):
    """Two bends and two waves of the skeleton, each in a file."""
    files = {}
    for name, amplitude, phase in [("bend_a", 40, 0), ("bend_b", 40, 0.1), ("wave_a", 10, 2), ("wave_b", 10, 2.1)]:
        files[name] = scratch / f"{name}.bvh"
        files[name].write_text(SKELETON + motion(40, amplitude, phase))
    return files


def test_info_bvh_on_made_body(tool, clips):
    matches_all(succeeds(tool("info", clips["bend_a"], "--fps", "60")).output,
                r"format +bvh\n", r"frames +40\n", rf"vertices +{BONES * TUBE_VERTICES}\n",
                r"clip +\"Motion\"", r"body +made from the skeleton", r"repair +nothing")
    info = tool("info", clips["bend_a"], "--json", "-").json()
    assert info["gltf"]["skeleton_body"] is True
    assert info["gltf"]["meshes"][0]["skinned"] is True


def test_strain_bvh(tool, clips):
    strain = tool("strain", clips["wave_a"], "--fps", "60", "--json", "-").json()
    assert strain["frames"] == 40
    assert strain["triangles"] == BONES * 112


def test_describe_and_evaluate_bvh(tool, clips, scratch):
    store = scratch / "store"
    succeeds(tool("describe", *clips.values(), "--store", store))
    labels = scratch / "labels.csv"
    rows = [f"{path},,{name.split('_')[0]}" for name, path in clips.items()]
    labels.write_text("file,clip,motion\n" + "\n".join(rows) + "\n")
    matches_all(succeeds(tool("evaluate", labels)).output, r"bend +2 / 2", r"wave +2 / 2")


def test_bvh_of_no_bone_is_refused_with_the_hint(tool, scratch):
    path = scratch / "one_joint.bvh"
    path.write_text("HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
                    "MOTION\nFrames: 2\nFrame Time: 0.1\n0 0 0\n0 0 90\n")
    fails(tool("info", path), "one_joint.bvh", "no mesh: play it on a body with --body FILE")


def test_malformed_bvh_is_refused_naming_the_line(tool, scratch):
    path = scratch / "positions.bvh"
    path.write_text(SKELETON.replace("CHANNELS 3 Zrotation Xrotation Yrotation\n    JOINT Head",
                                     "CHANNELS 3 Xposition Yposition Zposition\n    JOINT Head") + motion(2, 10, 0))
    fails(tool("info", path), "positions.bvh:9: joint 'Spine' has 3 channels, some of them positions")


def fox_bvh(fox, path):
    """The Fox's skeleton in its rest pose, as BVH, its neck turning: 60 frames at 30 per second."""
    data = fox.read_bytes()
    length = struct.unpack("<I", data[12:16])[0]
    gltf = json.loads(data[20:20 + length])
    nodes, joints = gltf["nodes"], set(gltf["skins"][0]["joints"])

    def matrix(q):
        x, y, z, w = q
        return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]

    def turned(m, angle):  # m times a turn about z
        c, s = math.cos(angle), math.sin(angle)
        return [[row[0] * c + row[1] * s, -row[0] * s + row[1] * c, row[2]] for row in m]

    def zxy_degrees(m):  # m = Rz Rx Ry
        return [math.degrees(math.atan2(-m[0][1], m[1][1])), math.degrees(math.asin(max(-1, min(1, m[2][1])))),
                math.degrees(math.atan2(-m[2][0], m[2][2]))]

    order, lines = [], ["HIERARCHY"]

    def write(index, depth):
        node, indent = nodes[index], "  " * depth
        lines.extend([indent + ("ROOT " if depth == 0 else "JOINT ") + node["name"], indent + "{",
                      indent + "  OFFSET %r %r %r" % tuple(node.get("translation", [0, 0, 0])),
                      indent + "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation"])
        order.append(index)
        for child in node.get("children", []):
            if child in joints:
                write(child, depth + 1)
        lines.append(indent + "}")

    write(next(j for j in joints if not any(j in nodes[p].get("children", []) for p in joints)), 0)
    lines += ["MOTION", "Frames: 60", f"Frame Time: {1 / 30!r}"]
    for f in range(60):
        values = []
        for index in order:
            node = nodes[index]
            m = matrix(node.get("rotation", [0, 0, 0, 1]))
            if node["name"] == "b_Neck_04":
                m = turned(m, math.radians(30 * math.sin(f / 10)))
            values += list(node.get("translation", [0, 0, 0])) + zxy_degrees(m)
        lines.append(" ".join(f"{v:.9g}" for v in values))
    path.write_text("\n".join(lines) + "\n")
    return path


def test_bvh_played_on_a_body_by_joint_names(tool, characters, scratch):
    fox = characters / "Fox.glb"
    clip = fox_bvh(fox, scratch / "fox_neck.bvh")
    matches_all(succeeds(tool("info", clip, "--body", fox)).output,
                r"vertices +290\n", r"frames +60\n", r"24 of 24 joints moved")
    info = tool("info", clip, "--body", fox, "--json", "-").json()
    assert info["gltf"]["skeleton_body"] is False
