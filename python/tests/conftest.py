"""Shared fixtures: the CLI of the same build (TUMBLE_BIN, set by ctest) and the source tree."""
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("TUMBLE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
TUMBLE_BIN = os.environ.get("TUMBLE_BIN", str(SOURCE_DIR / "build/release/src/app/tumble"))
SCENES = SOURCE_DIR / "scenes"


def run_cli(*args, check=True):
    """Runs the command line; returns the CompletedProcess (text)."""
    p = subprocess.run([TUMBLE_BIN, *map(str, args)], capture_output=True, text=True, cwd=SOURCE_DIR)
    if check and p.returncode != 0:
        raise AssertionError(f"tumble {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
    return p


@pytest.fixture
def cli():
    return run_cli
