"""`cmake --install` puts an importable package below the prefix (the README's second route)."""
import os
import pathlib
import subprocess
import sys

import pytest


def test_install_gives_an_importable_package(tmp_path):
    build, cmake = os.environ.get("DEFORMSEG_BUILD_DIR"), os.environ.get("DEFORMSEG_CMAKE")
    if not build or not cmake:
        pytest.skip("DEFORMSEG_BUILD_DIR and DEFORMSEG_CMAKE are set by CTest")
    subprocess.run([cmake, "--install", build, "--component", "python", "--prefix", tmp_path],
                   check=True, capture_output=True)
    site = tmp_path / os.environ.get("DEFORMSEG_PYTHON_INSTALL_DIR", "lib/python3/dist-packages")
    installed = sorted(p.name for p in (site / "deformseg").iterdir())
    assert {"__init__.py", "__init__.pyi", "_graphs.py", "store_format.py", "py.typed"} <= set(installed)
    assert any(name.startswith("_deformseg") and name.endswith(".so") for name in installed)
    environment = dict(os.environ, PYTHONPATH=str(site))
    done = subprocess.run([sys.executable, "-c", "import deformseg; print(deformseg.__file__)"],
                          env=environment, cwd=tmp_path, check=True, capture_output=True, text=True)
    assert pathlib.Path(done.stdout.strip()).parent == site / "deformseg"
