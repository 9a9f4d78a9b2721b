"""Shared fixtures of the Python module's tests: where the data, the CLI and the shared data are.

ctest (python/CMakeLists.txt) sets PYTHONPATH to <build>/python and SEXTANT_BINARY to the
`sextant` executable; SEXTANT_SHARED_DATA (the MulRan excerpt) defaults to <source>/../shared/data.
"""
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
DATA = SOURCE / "data"


@pytest.fixture(scope="session")
def data_dir():
    assert DATA.is_dir(), f"the repository's data folder is missing: {DATA}"
    return DATA


@pytest.fixture(scope="session")
def sextant_binary():
    """The `sextant` CLI: SEXTANT_BINARY, else the one of the build tree the module comes from
    (<build>/python/sextant → <build>/app/sextant); tests comparing against it skip without."""
    path = os.environ.get("SEXTANT_BINARY")
    if not path:
        import sextant

        beside = pathlib.Path(sextant.__file__).resolve().parents[2] / "app" / "sextant"
        if not beside.is_file():
            pytest.skip("no `sextant` CLI: set SEXTANT_BINARY (ctest sets it to the built one)")
        path = str(beside)
    assert os.access(path, os.X_OK), f"SEXTANT_BINARY={path} is not an executable"
    return path


@pytest.fixture(scope="session")
def mulran(request):
    """The MulRan Riverside02 excerpt (166 keyframes, poses.txt, times.txt), or skip when absent."""
    root = pathlib.Path(os.environ.get("SEXTANT_SHARED_DATA", SOURCE.parent / "shared" / "data"))
    folder = root / "mulran_riverside02"
    if not (folder / "scans").is_dir():
        pytest.skip(f"no shared data at {folder} (set SEXTANT_SHARED_DATA)")
    return folder


def run(args, **kwargs):
    """Runs a command, returns its CompletedProcess; text output, no exception on exit status."""
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, check=False, **kwargs)


def python_env():
    """The environment of a child Python that must import the same sextant module."""
    import sextant

    env = dict(os.environ)
    env["PYTHONPATH"] = str(pathlib.Path(sextant.__file__).resolve().parents[1])
    return env


PYTHON = sys.executable
