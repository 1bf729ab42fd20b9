"""The README's Python block, whole, as a user runs it: in a folder where the files it names are
real (Fox.glb the shared Fox, motions.csv the labels of its clips), in a Python of its own that
imports the package under test."""
import os
import pathlib
import re
import subprocess
import sys

README = pathlib.Path(__file__).resolve().parents[2] / "README.md"


def python_block():
    return re.search(r"```python\n(.*?)```", README.read_text(), re.S).group(1)


def test_the_python_block_runs(fox, tmp_path):
    os.symlink(fox, tmp_path / "Fox.glb")
    (tmp_path / "motions.csv").write_text("file,clip,motion\nFox.glb,Walk,walk\nFox.glb,Run,run\nFox.glb,Survey,-\n")
    code = python_block()
    assert "import deformseg" in code and "distributed.knn_graph" in code
    done = subprocess.run([sys.executable, "-c", code + "\nprint(len(nearest['neighbours']), len(graph))\n"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-4000:]
    assert done.stdout.split()[-2:] == ["3", "3"], done.stdout  # every clip found; a node per clip
