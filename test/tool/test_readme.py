"""The README's tool block, line by line, as a user runs it: in a folder where its file names are
real files (character.glb, Fox.glb, query.glb: the shared Fox; Knight.glb; rest.obj and anim.pc2 a
tube's point cache; cat/ frames of the same tube; motions.csv the labels of five of their clips;
a.dot, b.graphml and graphs/ the tests' graphs), with `deformseg` first on PATH. Each line must
succeed; the line naming `<command>` is a pattern, not a command."""

import os
import re
import shutil
import subprocess
from pathlib import Path

from conftest import GRAPHS, succeeds

README = Path(__file__).resolve().parents[2] / "README.md"


def tool_block():
    """The lines of the README's block under "The `deformseg` tool"."""
    text = README.read_text()
    section = text[text.index("## The `deformseg` tool"):]
    block = re.search(r"```sh\n(.*?)```", section, re.S).group(1)
    return [line for line in block.splitlines() if line.strip() and "<command>" not in line]


def prepare(tool, folder, characters):
    """The files the README's lines name, made real in `folder`."""
    folder.mkdir()
    for name, source in [("character.glb", "Fox.glb"), ("Fox.glb", "Fox.glb"), ("query.glb", "Fox.glb"),
                         ("Knight.glb", "Knight.glb")]:
        os.symlink(characters / source, folder / name)
    succeeds(tool("convert", characters / "Fox.glb", folder / "path" / "to" / "frames", "--clip", "Walk", "--format", "obj"))
    succeeds(tool("synth", folder / "cache", "--format", "pc2"))
    shutil.copy(folder / "cache" / "tube.pc2", folder / "anim.pc2")
    shutil.copy(folder / "cache" / "tube.obj", folder / "rest.obj")
    succeeds(tool("synth", folder / "cat", "--format", "obj", "--schedule", "5:0", "10:60", "5:"))
    for name, schedule in [("other", ["5:0", "8:90", "8:0"]), ("third", ["4:0", "12:45", "4:"])]:
        succeeds(tool("synth", folder / name, "--format", "ply", "--schedule", *schedule))
    (folder / "motions.csv").write_text("file,clip,motion,rig\nFox.glb,Walk,walk,fox\nFox.glb,Run,run,fox\n"
                                        "Fox.glb,Survey,-,fox\nKnight.glb,Walking_A,walk,kaykit\n"
                                        "Knight.glb,Running_A,run,kaykit\n")
    shutil.copy(GRAPHS / "path.dot", folder / "a.dot")
    shutil.copy(GRAPHS / "triangle.graphml", folder / "b.graphml")
    (folder / "graphs").mkdir()
    shutil.copy(GRAPHS / "path.dot", folder / "graphs" / "path.dot")
    shutil.copy(GRAPHS / "ring.gv", folder / "graphs" / "ring.dot")


def test_every_line_of_the_tool_block_runs(tool, scratch, characters):
    lines = tool_block()
    assert len(lines) >= 20 and all(line.startswith("deformseg ") for line in lines), lines
    folder = scratch / "readme"
    prepare(tool, folder, characters)
    environment = dict(os.environ, PATH=os.pathsep.join([str(Path(os.environ["DEFORMSEG_TOOL"]).parent),
                                                         os.environ["PATH"]]))
    for line in lines:
        done = subprocess.run(["bash", "-c", line], cwd=folder, env=environment, capture_output=True, text=True,
                              timeout=600)
        assert done.returncode == 0, f"{line}\nexit status {done.returncode}\n{done.stdout[-2000:]}{done.stderr[-2000:]}"


def test_no_registry_address_in_the_repository():
    # Test-time npm packages come through the npm client and its configuration (scripts/
    # fetch-fbx2gltf runs `npm pack`), so that a machine's registry or mirror serves them.
    root = README.parent
    hosts = ["registry." + "npmjs.org", "registry." + "yarnpkg.com"]  # spelled apart: not found here
    listed = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True)
    if listed.returncode != 0:
        return  # not a clone: nothing to look through
    for name in listed.stdout.splitlines():
        path = root / name
        if path.is_file() and path.stat().st_size < 1 << 20:
            text = path.read_bytes().decode("utf-8", "replace")
            assert not any(host in text for host in hosts), name
