"""Reading a wear run's results file (HDF5, docs/results.md) into numpy arrays."""

from __future__ import annotations

import os
import dataclasses
from dataclasses import dataclass
from typing import Any, Dict, List

import numpy as np


@dataclass
class Step:
    """One wear step of a run: the profile it reached and what the run recorded for it.

    Lengths in m, forces in N; ``group`` is the step's HDF5 group name (``/steps/NNNNNN``).
    With separate wheels the profile is the first one the file holds (the left wheel, or
    wheelset 1's left wheel); ``Results.array("wheel_right/Sd")`` and the like read the others.
    """

    index: int
    distance: float  #: running distance reached [m]
    y: np.ndarray  #: wheel profile points, lateral [m] (+ towards the field side)
    z: np.ndarray  #: wheel profile points, vertical [m] (+ down)
    Sh: float  #: flange height, EN 15313 [m]
    Sd: float  #: flange thickness, EN 15313 [m]
    qR: float  #: flange slope measure qR, EN 15313 [m]
    equivalent_conicity: float
    #: arc length on the step-0 profile from its flange end [m], every 0.1 mm
    wear_s: np.ndarray
    #: depth worn since step 0 along the step-0 profile's inward normal [m] (> 0 worn)
    wear_depth: np.ndarray
    group: str

    def arc_length(self) -> np.ndarray:
        """Arc length along this step's profile points from the flange end [m] (chords)."""
        return np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(self.y), np.diff(self.z)))])


@dataclass
class Results:
    """A results file's steps, in order, and its run's information.

    ``steps[k]`` is step k (``steps[0]`` the new profile). The attributes ``distance``,
    ``Sd``, ``Sh``, ``qR`` and ``equivalent_conicity`` are arrays over the steps, for plotting
    against each other. ``array(name)`` reads any per-step dataset (e.g. ``"states/dy"``) of every
    step into a list of arrays.
    """

    path: str
    steps: List[Step]
    run_info: Dict[str, Any] = dataclasses.field(default_factory=dict)

    @property
    def distance(self) -> np.ndarray:
        return np.array([s.distance for s in self.steps])

    @property
    def Sd(self) -> np.ndarray:
        return np.array([s.Sd for s in self.steps])

    @property
    def Sh(self) -> np.ndarray:
        return np.array([s.Sh for s in self.steps])

    @property
    def qR(self) -> np.ndarray:
        return np.array([s.qR for s in self.steps])

    @property
    def equivalent_conicity(self) -> np.ndarray:
        return np.array([s.equivalent_conicity for s in self.steps])

    def array(self, name: str) -> List[np.ndarray]:
        import h5py

        with h5py.File(self.path, "r") as f:
            return [np.asarray(f[s.group][name][()]) for s in self.steps]


def _first_wheel(step: Any) -> str:
    """The group of the step's first wheel profile: the shared one, else the left wheel's,
    else (a vehicle run's separate wheels) wheelset 1's left wheel (docs/results.md)."""
    for name in ("wheel", "wheel_left", "wheelsets/1/wheel_left"):
        if name in step:
            return name
    raise ValueError(f"{step.name}: no wheel profile (wheel, wheel_left or wheelsets/1/wheel_left)")


def read_results(path: str | os.PathLike[str]) -> Results:
    """Read a results file written by ``wheelwear run`` or :func:`wheelwear.run`.

    Raises ``ValueError`` naming the file when it is not a wheelwear results file.
    """
    import h5py

    path = os.fspath(path)
    try:
        f = h5py.File(path, "r")
    except OSError as error:
        raise ValueError(f"{path}: not a readable HDF5 results file ({error})") from None
    with f:
        if "steps" not in f:
            raise ValueError(f"{path}: no /steps group; is it a wheelwear results file?")
        steps = []
        for name in sorted(f["steps"].keys()):
            g = f["steps"][name]
            w = g[_first_wheel(g)]
            steps.append(
                Step(
                    index=int(name),
                    distance=float(g["distance"][()]),
                    y=np.asarray(w["y"][()]),
                    z=np.asarray(w["z"][()]),
                    Sh=float(w["Sh"][()]),
                    Sd=float(w["Sd"][()]),
                    qR=float(w["qR"][()]),
                    equivalent_conicity=float(g["equivalent_conicity"][()]),
                    wear_s=np.asarray(w["cumulative_wear/s"][()]),
                    wear_depth=np.asarray(w["cumulative_wear/depth"][()]),
                    group=f"/steps/{name}",
                )
            )
        info: Dict[str, Any] = {}
        if "run_info" in f:
            for key, item in f["run_info"].items():
                value = item[()]
                info[key] = value.decode() if isinstance(value, bytes) else value
    return Results(path=path, steps=steps, run_info=info)
