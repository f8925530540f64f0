"""Shared fixtures of the Python module's tests: the gkt program to compare with and the scenes.

CTest runs these with Debian's interpreter and the module's folder on PYTHONPATH
(tests/python/CMakeLists.txt); GKT_CLI and GKT_SOURCE_DIR name the program and the repository.
"""

import csv
import io
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("GKT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENES = SOURCE_DIR / "tables" / "scenes"


def cli_path():
    path = os.environ.get("GKT_CLI")
    if not path:
        pytest.fail("GKT_CLI is not set: run these tests through ctest (tests/python/CMakeLists.txt)")
    return path


def run_cli(*args):
    """Returns (exit code, stdout, stderr) of the gkt program with the given arguments."""
    done = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def cli_columns(*args):
    """Returns the CSV table the gkt program prints as {column: [cell text, ...]}; fails on a non-zero exit."""
    code, out, err = run_cli(*args)
    assert code == 0, f"gkt {' '.join(map(str, args))} failed: {err}"
    rows = list(csv.reader(io.StringIO(out)))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def cli_error(*args):
    """Returns the one-line message of a gkt program run that must fail with exit code 2."""
    code, out, err = run_cli(*args)
    assert code == 2, f"expected exit code 2 from gkt {' '.join(map(str, args))}, got {code}: {out}{err}"
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("gkt: error: "), err
    return lines[0][len("gkt: error: "):]
