"""The examples run (headless) and draw; the type hints match the module and the examples."""

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("WHEELWEAR_SOURCE", Path(__file__).resolve().parents[2]))
EXAMPLES = sorted((SOURCE / "examples").glob("*.py"))


def test_there_are_examples():
    assert {p.stem for p in EXAMPLES} >= {"creep_curves", "contact_patch", "run_evolution"}


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_example_draws_its_png(example, tmp_path):
    spec = importlib.util.spec_from_file_location(example.stem, example)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = module.main(tmp_path)
    assert out.suffix == ".png" and out.stat().st_size > 20_000  # a drawn figure, not a blank


def run_mypy(*args):
    env = dict(os.environ, MYPYPATH=os.environ.get("PYTHONPATH", ""))
    return subprocess.run([sys.executable, "-m", *args], capture_output=True, text=True, env=env,
                          cwd=os.environ.get("PYTHONPATH", "."))


def test_stubs_match_the_module():
    done = run_mypy("mypy.stubtest", "wheelwear", "--ignore-missing-stub", "--allowlist",
                    str(SOURCE / "python" / "stubtest_allowlist.txt"),
                    "--mypy-config-file", str(SOURCE / "python" / "mypy.ini"))
    assert done.returncode == 0, done.stdout + done.stderr


def test_examples_type_check_against_the_stubs():
    done = run_mypy("mypy", "--config-file", str(SOURCE / "python" / "mypy.ini"),
                    *map(str, EXAMPLES))
    assert done.returncode == 0, done.stdout + done.stderr
