"""Shared fixtures: the command line of the same build, to compare the module with."""

import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """Runs the build's `wheelwear` with the given arguments and returns its parsed JSON."""
    program = os.environ.get("WHEELWEAR_CLI", "build/wheelwear")
    if not os.path.exists(program):
        pytest.fail(f"WHEELWEAR_CLI = {program}: no such program; build first")

    def run(*args):
        done = subprocess.run([program, *map(str, args), "--json"], capture_output=True, text=True)
        if done.returncode not in (0, 3):
            raise AssertionError(f"wheelwear {' '.join(map(str, args))}: {done.stderr}")
        return json.loads(done.stdout)

    def error(*args):
        done = subprocess.run([program, *map(str, args)], capture_output=True, text=True)
        assert done.returncode != 0
        prefix = "wheelwear: error: "
        lines = [l for l in done.stderr.splitlines() if l.startswith(prefix)]
        assert len(lines) == 1, done.stderr
        return lines[0][len(prefix):]

    run.error = error
    return run


@pytest.fixture(scope="session")
def source_dir():
    return os.environ.get("WHEELWEAR_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
