"""The README's Python block, whole, as a user runs it: saved as a script in a folder where the
files it names are real (Fox.glb the shared Fox, motions.csv the labels of its clips), run by a
Python of its own that imports the package under test. Saved as a script, not given to
``python -c``: Dask's worker processes import a script again, which ``-c`` has not."""
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
    assert 'if __name__ == "__main__":' in code
    script = tmp_path / "readme.py"
    script.write_text(code + "    print(len(nearest['neighbours']), len(graph))\n")  # behind the guard
    done = subprocess.run([sys.executable, script], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-4000:]
    assert done.stdout.split()[-2:] == ["3", "3"], done.stdout  # every clip found; a node per clip


def test_the_spawn_pool_block_of_chapter_12_runs_as_a_script(fox, tmp_path):
    chapter = (README.parent / "doc" / "chapters" / "12_python.md").read_text()
    code = next(block for block in re.findall(r"@code\{\.py\}\n(.*?)@endcode", chapter, re.S)
                if "ProcessPoolExecutor" in block)
    assert 'if __name__ == "__main__":' in code
    os.symlink(fox, tmp_path / "Fox.glb")
    script = tmp_path / "pool.py"
    script.write_text(code + "    print([round(r.value, 3) for r in results])\n")  # behind the guard
    done = subprocess.run([sys.executable, script], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-4000:]
    assert done.stdout.split("\n")[-2].startswith("[1.0, 0."), done.stdout


def test_the_first_session_of_chapter_12_runs_as_written():
    # Its figures are the program's: the similarity, the z-score against shuffled copies (a
    # fixed seed) and the alignment's length.
    import doctest

    import deformseg
    from conftest import data_dir

    chapter = (README.parent / "doc" / "chapters" / "12_python.md").read_text()
    section = chapter[chapter.index("## A session"):]
    session = re.search(r"@code\{\.py\}\n(.*?)@endcode", section, re.S).group(1)
    session = session.replace('"../shared/data/', f'"{data_dir()}/')
    test = doctest.DocTestParser().get_doctest(session, {"deformseg": deformseg}, "chapter 12", None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.summarize(verbose=False) == doctest.TestResults(0, len(test.examples)) and test.examples
