"""setup.py, as pip runs it: a Python that cannot build a wheel is told what to install before any
compiling (a pyenv Python without the `wheel` package failed with "invalid command 'bdist_wheel'"),
at pip's metadata step (dist_info) as at the build (bdist_wheel)."""
import pathlib
import subprocess
import sys

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]

# setup.py run as `pip install --no-build-isolation` runs it, in a Python whose setuptools predates
# its own bdist_wheel (70.1) and that has no `wheel` package.
WITHOUT_WHEEL = """
import runpy, sys
sys.modules["wheel"] = None
sys.modules["setuptools.command.bdist_wheel"] = None
sys.argv = ["setup.py", sys.argv[1]]
runpy.run_path("setup.py", run_name="__main__")
"""


@pytest.mark.parametrize("command", ["dist_info", "bdist_wheel"])
def test_a_python_without_wheel_is_told_what_to_install(command):
    done = subprocess.run([sys.executable, "-c", WITHOUT_WHEEL, command], cwd=REPOSITORY, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode != 0, done.stdout + done.stderr
    assert f"{sys.executable} has no 'wheel' package" in done.stderr, done.stderr
    assert f"'{sys.executable} -m pip install wheel'" in done.stderr and "python3-wheel" in done.stderr
    assert "cmake" not in done.stdout.lower(), done.stdout  # refused before any configuring
