"""run() and read_results(): the command line's file, Ctrl-C and resume."""

import os
import signal
import subprocess
import threading

import h5py
import numpy as np
import pytest

import wheelwear


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """The folder --export-default-scene writes: the built-in scene and the frozen-collective
    scene with its collective."""
    folder = tmp_path_factory.mktemp("scene")
    program = os.environ.get("WHEELWEAR_CLI", "build/wheelwear")
    subprocess.run([program, "run", "--export-default-scene", str(folder)], check=True,
                   capture_output=True)
    return folder


@pytest.fixture(scope="module")
def short_scene(exported):
    """The frozen-collective scene over 10 km in 5 km steps (two wear steps, a few seconds)."""
    scene = exported / "frozen_short.toml"
    text = (exported / "frozen_collective.toml").read_text()
    text = text.replace("distance_m = 100e3", "distance_m = 10e3")
    assert "distance_m = 10e3" in text
    scene.write_text(text)
    return scene


def datasets(path):
    """Every dataset of a results file outside /run_info, by name."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, item):
            if isinstance(item, h5py.Dataset) and not name.startswith("run_info"):
                out[name] = item[()]
        f.visititems(visit)
    return out


def assert_same_files(a, b):
    left, right = datasets(a), datasets(b)
    assert left.keys() == right.keys()
    compared = 0
    for name in left:
        x, y = np.asarray(left[name]), np.asarray(right[name])
        assert x.shape == y.shape, name
        if x.dtype.kind == "f":
            assert np.array_equal(x, y, equal_nan=True), name
        else:
            assert np.array_equal(x, y), name
        compared += 1
    assert compared > 50


def test_run_writes_the_command_lines_file(tmp_path, short_scene):
    program = os.environ.get("WHEELWEAR_CLI", "build/wheelwear")
    subprocess.run([program, "run", str(short_scene), "-o", str(tmp_path / "cli.h5"), "-q"],
                   check=True)
    summary = wheelwear.run(short_scene, tmp_path / "py.h5", threads=2)
    assert summary.steps == 2 and summary.distance == 10e3
    assert_same_files(tmp_path / "cli.h5", tmp_path / "py.h5")
    results = wheelwear.read_results(tmp_path / "py.h5")
    assert len(results.steps) == 3 and results.distance.tolist() == [0.0, 5e3, 10e3]
    # Wear lowers the tread: Sh grows (EN 15313 measures it from the running circle).
    assert results.Sh[-1] > results.Sh[0]
    assert results.steps[-1].y.shape == results.steps[-1].z.shape


def test_ctrl_c_stops_after_a_step_and_resume_finishes_the_same_file(tmp_path, exported):
    # The frozen-collective scene (20 steps, about 4 s): Ctrl-C one second in, with no progress
    # callback, so that only the module's own check after each step can stop it.
    scene = exported / "frozen_collective.toml"
    whole = tmp_path / "whole.h5"
    wheelwear.run(scene, output=whole)
    stopped = tmp_path / "stopped.h5"
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt, match="resume="):
            wheelwear.run(scene, output=stopped)
    finally:
        timer.cancel()
    kept = len(wheelwear.read_results(stopped).steps)
    assert 1 <= kept < len(wheelwear.read_results(whole).steps)
    wheelwear.run(resume=stopped)
    assert_same_files(whole, stopped)


def test_read_results_of_separate_wheels(tmp_path, short_scene):
    scene = tmp_path / "separate.toml"
    text = short_scene.read_text().replace('wheels = "shared"', 'wheels = "separate"')
    assert 'wheels = "separate"' in text
    text = text.replace('file = "frozen_collective.csv"',
                        f'file = "{short_scene.parent / "frozen_collective.csv"}"')
    scene.write_text(text)
    wheelwear.run(scene, tmp_path / "separate.h5")
    r = wheelwear.read_results(tmp_path / "separate.h5")
    right = r.array("wheel_right/Sh")
    assert len(r.steps) == len(right) == 3
    # Each wheel wears its own profile: both lose tread, by different amounts.
    assert r.Sh[-1] > r.Sh[0] and float(right[-1]) > float(right[0])


def test_ctrl_c_stops_a_long_creep_call():
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            # 400 exact solves, about 6 s on two cores: stopped within a few of them.
            wheelwear.creep("exact", a=5e-3, b=5e-3, phi=np.linspace(0.1, 1, 400), N=5e4)
    finally:
        timer.cancel()


def test_run_errors(tmp_path, short_scene):
    with pytest.raises(ValueError, match="output: give the results file"):
        wheelwear.run(short_scene)
    existing = tmp_path / "exists.h5"
    existing.write_bytes(b"keep me")
    with pytest.raises(ValueError, match="--overwrite"):
        wheelwear.run(short_scene, existing)
    assert existing.read_bytes() == b"keep me"
    with pytest.raises(ValueError, match="not a readable HDF5"):
        wheelwear.read_results(existing)
