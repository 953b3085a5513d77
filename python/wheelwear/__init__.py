"""wheelwear: railway wheel profile wear prediction with non-elliptic (SDEC) contact.

The C++ library of Liu, Fu & Bruni's (2022) method for Python, with numpy arrays in and out
and SI units throughout (m, N, Pa, rad, s). The same code answers as the ``wheelwear`` command:
the same inputs give the same numbers, and bad inputs raise ``ValueError`` with the command
line's message (naming its option, e.g. ``--N``, for the keyword of the same name).

Functions:
    creep         creep forces of SDEC patches, any tangential method, broadcast over arrays
    wheel_profile a standard (S1002) or measured wheel profile, Sh/Sd/qR, the curve as arrays
    rail_profile  a standard (60E1) or measured rail profile
    contact       the contact patches of one wheel on its rail (normal problem, SDEC)
    wear          one wheel position's wear: T gamma map and worn depth per patch
    curving       the quasi-static curving of a vehicle in a constant curve
    run           a scene's wear-evolution run into an HDF5 results file (or its resume)
    read_results  a results file's steps as arrays

Long calls release the GIL and take ``threads=`` (None: all cores); Ctrl-C stops them with
KeyboardInterrupt. Numerical statuses (a contact that did not converge, a curving without a
balance) are attributes of the result, not exceptions.
"""

from __future__ import annotations

import os as _os
from pathlib import Path as _Path
from typing import Any, Callable, Dict, List, Optional, Union

import numpy as _np

# An installed package finds its data (the book of creep tables) at <prefix>/share/wheelwear:
# it lives in <prefix>/lib/python3/dist-packages/wheelwear.
_parents = _Path(__file__).resolve().parents
if len(_parents) > 4 and "WHEELWEAR_DATA_DIR" not in _os.environ:
    _installed_data = _parents[4] / "share" / "wheelwear"
    if (_installed_data / "creep_table.h5").is_file():
        _os.environ["WHEELWEAR_DATA_DIR"] = str(_installed_data)

from . import _wheelwear  # noqa: E402
from .results import Results, Step, read_results  # noqa: E402

__version__: str = _wheelwear.__version__

ArrayLike = Union[float, "_np.typing.NDArray[_np.float64]", List[float]]
PathLike = Union[str, "_os.PathLike[str]"]

#: The tangential methods of creep(), as the command line names them.
CREEP_METHODS = (
    "fastsim-sdec",
    "fastsim-eql",
    "fastsim-eqe",
    "fastsim-eqe-shifted",
    "fastsim-elliptic",
    "linear-sdec",
    "she-sdec",
    "table",
    "best",
    "exact",
)


class Record(dict):  # type: ignore[type-arg]
    """A dict whose keys are also attributes (``patch.area`` is ``patch["area"]``)."""

    def __getattr__(self, name: str) -> Any:
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self) -> List[str]:
        return list(self.keys())


def _records(value: Any) -> Any:
    if isinstance(value, dict):
        return Record({k: _records(v) for k, v in value.items()})
    if isinstance(value, list):
        return [_records(v) for v in value]
    return value


class CreepResult:
    """Creep forces of creep(): floats for scalar inputs, arrays of the broadcast shape else.

    Attributes:
        Fx, Fy: longitudinal and lateral creep force on the wheel [N] (they oppose the creepages).
        Mz: spin moment about O [N m]; NaN where the method does not define it (linear-sdec).
        rigid_slip_work: the frictional work per rolled distance of the rigid slip,
            -(Fx vx + Fy vy + Mz phi) [J/m]; NaN without Mz. The exact theory's cells sum to it
            as its grid is refined (the command line's rigid_slip_work).
        status: "ok"; for the exact theory its iteration's status as the command line gives
            it ("converged", or why not).
        cells, slip_cells: cells of the method's grid (FASTSIM) or contact elements (exact), and
            of them those that slip.
        from_table: method best: True where the book of tables answered (with
            ``inside_table="table"``), False where the exact theory or FASTSIM-SDEC did.
        extrapolated: True where a coefficient table was used beyond its range.
        warnings: the implausible inputs (each once), as the command line warns of them.
    """

    Fx: Any
    Fy: Any
    Mz: Any
    rigid_slip_work: Any
    status: Any
    cells: Any
    slip_cells: Any
    from_table: Any
    extrapolated: Any
    warnings: List[str]

    def __init__(self, fields: Dict[str, Any], shape: tuple, mu_N: Any) -> None:
        for key in ("Fx", "Fy", "Mz", "rigid_slip_work", "cells", "slip_cells", "from_table",
                    "extrapolated", "status"):
            value = _np.asarray(fields[key]).reshape(shape)
            setattr(self, key, value.item() if shape == () else value)
        self.warnings = list(fields["warnings"])
        self._mu_N = mu_N

    @property
    def Fx_muN(self) -> Any:
        """Fx / (mu N)."""
        return self.Fx / self._mu_N

    @property
    def Fy_muN(self) -> Any:
        """Fy / (mu N)."""
        return self.Fy / self._mu_N

    def __repr__(self) -> str:
        return f"CreepResult(Fx={self.Fx!r}, Fy={self.Fy!r})"


def creep(
    method: str = "fastsim-sdec",
    *,
    a: ArrayLike,
    b: ArrayLike,
    psi: ArrayLike = 0.0,
    vx: ArrayLike = 0.0,
    vy: ArrayLike = 0.0,
    phi: ArrayLike = 0.0,
    N: ArrayLike,
    G: ArrayLike = 80e9,
    nu: ArrayLike = 0.25,
    mu: ArrayLike = 0.3,
    nx: Optional[int] = None,
    ny: Optional[int] = None,
    bound: Optional[str] = None,
    scheme: Optional[str] = None,
    target_error: Optional[float] = None,
    exact_grid: Optional[int] = None,
    beyond_table: Optional[str] = None,
    inside_table: Optional[str] = None,
    threads: Optional[int] = None,
) -> CreepResult:
    """Creep forces of SDEC contact patches (Liu, Fu & Bruni 2022), as ``wheelwear creep``.

    The patch is two half-ellipses joined at the initial contact point O: semi-length ``a``
    along the rolling direction x and semi-width ``b`` [m], shape number ``psi`` (|psi| < 1;
    > 0: the patch reaches further on the +y side of O; 0: the ellipse). Creepages at O:
    ``vx``, ``vy`` [-] and spin ``phi`` [1/m]; normal force ``N`` [N], combined shear modulus
    ``G`` [Pa], Poisson's ratio ``nu``, friction coefficient ``mu``.

    Every one of these may be an array: they broadcast (numpy's rules) and the result has the
    broadcast shape, so a creep curve of a thousand points is one call, solved in parallel on
    ``threads`` worker threads (None: all cores) without the GIL.

    Methods (``method``): fastsim-sdec (default), fastsim-eql, fastsim-eqe,
    fastsim-eqe-shifted, fastsim-elliptic, linear-sdec, she-sdec (Shen-Hedrick-Elkins),
    table (the book of exact-theory tables: a/b 0.2-10, 0.2-25 at nu 0.25, |psi| <= 0.8, 1-3 us a
    patch), best (the
    most accurate answer for one patch: by default Kalker's exact theory on 40 elements across the
    patch, elements at most twice as long as wide, 10 ms - 2 s a patch for a/b 0.05-25, within
    0.5 % of mu N of the same on twice as fine a grid; ``inside_table="table"`` takes the table's
    totals where it covers the patch, as runs do, and outside it, as ``beyond_table`` says,
    "exact" or "fastsim-sdec") and exact (Kalker's exact theory on ``exact_grid`` x
    ``exact_grid`` elements, default 40, about 16 ms a patch).

    FASTSIM options: ``nx``, ``ny`` (cells, default 50 x 50) or ``target_error`` (the cheapest
    n x n grid within that fraction of mu N of the converged answer), ``bound``
    ("parabolic" or "semi-elliptic"), ``scheme`` ("kalker" or "second-order"). An option that
    does not apply to the method raises ``ValueError``, as the command line refuses it.

    Example (the paper's reference case, pure spin):

    >>> r = wheelwear.creep(a=4.25e-3, b=4.25e-3, psi=0.6, phi=1.0, N=37830, mu=0.35)
    >>> r.Fx, r.Fy                       # N
    >>> phi = numpy.linspace(-2, 2, 1001)
    >>> curve = wheelwear.creep("table", a=6e-3, b=3e-3, phi=phi, N=50e3)   # arrays of 1001
    """
    inputs = _np.broadcast_arrays(
        *(_np.asarray(v, dtype=float) for v in (a, b, psi, vx, vy, phi, N, G, nu, mu))
    )
    shape = inputs[0].shape
    flat = [_np.ascontiguousarray(v).reshape(-1) for v in inputs]
    fields = _wheelwear.creep_arrays(
        method, nx, ny, bound, scheme, target_error, exact_grid, beyond_table, inside_table, flat,
        threads,
    )
    mu_N = inputs[9] * inputs[6]
    result = CreepResult(fields, shape, mu_N.item() if shape == () else mu_N)
    if result.warnings:
        import warnings as _warnings

        for text in result.warnings:
            _warnings.warn(text, RuntimeWarning, stacklevel=2)
    return result


#: A wheel or rail profile (from wheel_profile() and rail_profile()).
Profile = _wheelwear.Profile


def wheel_profile(
    spec: PathLike = "S1002",
    *,
    radius: Optional[float] = None,
    origin: Optional[str] = None,
    taping_line_distance: Optional[float] = None,
    max_drop: Optional[float] = None,
    smoothing: Optional[float] = None,
) -> Any:
    """A wheel profile: "S1002" (generated, EN 13715) or a profile file (CSV, Simpack, MiniProf).

    ``radius``: nominal rolling radius at the taping line [m] (default half the diameter a
    file's header states, else 0.46). For files only: ``origin`` ("auto", "taping-line",
    "internal-face"), ``taping_line_distance`` [m] for an internal-face origin, ``max_drop`` (the
    share of points cleaning may discard, default 0.2), ``smoothing`` (the fit's smoothing
    length [m], default 0.3e-3; 2e-3 for a record wavy on the scale of a millimetre, which
    loading warns of). Loading warnings are issued as ``RuntimeWarning``. Returns a
    :class:`Profile` (``.sample()``, ``.parameters()`` for Sh, Sd, qR, ...).
    """
    profile, warnings = _wheelwear.wheel_profile(
        _os.fspath(spec), radius, origin, taping_line_distance, max_drop, smoothing
    )
    _warn_all(warnings)
    return profile


def rail_profile(
    spec: PathLike = "60E1",
    *,
    inclination: Optional[Union[str, float]] = None,
    gauge_side: Optional[str] = None,
    max_drop: Optional[float] = None,
    smoothing: Optional[float] = None,
) -> Any:
    """A rail profile: "60E1" (generated, EN 13674-1) or a profile file.

    ``inclination``: "1:40", a slope such as 0.025, or "none" (default 1:40 for 60E1, none for
    files). For files only: ``gauge_side`` ("auto", "left", "right"), ``max_drop``,
    ``smoothing`` (as the wheel's).
    """
    incl = None if inclination is None else str(inclination)
    profile, warnings = _wheelwear.rail_profile(
        _os.fspath(spec), incl, gauge_side, max_drop, smoothing
    )
    _warn_all(warnings)
    return profile


def _warn_all(texts: List[str]) -> None:
    if texts:
        import warnings as _warnings

        for text in texts:
            _warnings.warn(text, RuntimeWarning, stacklevel=3)


def _contact_inputs(**kw: Any) -> Dict[str, Any]:
    for key in ("wheel", "rail"):
        if key in kw and kw[key] is not None:
            kw[key] = _os.fspath(kw[key])
    if kw.get("inclination") is not None:
        kw["inclination"] = str(kw["inclination"])
    return kw


def contact(
    wheel: PathLike = "S1002",
    rail: PathLike = "60E1",
    *,
    dy: float,
    load: float,
    yaw: float = 0.0,
    roll: float = 0.0,
    inclination: Optional[Union[str, float]] = None,
    gauge: float = 1.435,
    back_to_back: float = 1.360,
    wheel_radius: Optional[float] = None,
    E: float = 200e9,
    nu: float = 0.25,
    strip_width: float = 0.1e-3,
    normal_method: str = "hertz-calibrated",
    contact_plane: str = "initial-point",
    epsilon: float = 0.55,
    origin: Optional[str] = None,
    taping_line_distance: Optional[float] = None,
    max_drop: Optional[float] = None,
    gauge_side: Optional[str] = None,
    smoothing: Optional[float] = None,
) -> Any:
    """The contact patches of one wheel (the left one) of a wheelset on its rail, as
    ``wheelwear contact``: lateral shift ``dy`` [m] (+ towards this wheel's flange contact),
    vertical ``load`` on the wheel [N], ``yaw`` and ``roll`` [rad], track ``gauge`` and
    ``back_to_back`` [m], Young's modulus ``E`` [Pa], ``nu``, the gap's lateral sampling
    ``strip_width`` [m], and the normal problem: ``normal_method`` "hertz-calibrated" (each
    patch's virtual penetration from Hertz's ellipse for its curvature ratio; the default) or
    "kik-piotrowski" (one factor ``epsilon``), solved in ``contact_plane`` "initial-point" (the
    tangent plane at O; the default) or "weighted" (CONTACT's planar contact). Profile files are
    read as :func:`wheel_profile`
    and :func:`rail_profile` read them: ``origin``, ``taping_line_distance`` (wheel files),
    ``gauge_side`` (rail files), ``max_drop`` and ``smoothing`` (either), refused for the
    standard profiles.

    Returns a record with ``status`` ("ok", or why not: a status, not an exception), ``message``,
    ``vertical_force``, ``lateral_force`` [N], ``approach`` [m] and ``patches``: each with
    ``area`` [m^2], ``length``, ``width``, SDEC ``a``, ``b``, ``psi``, ``y_wheel``, ``y_rail``
    (profile frames, + towards the field side), ``contact_angle`` (at O),
    ``contact_angle_centre`` (as CONTACT reports it), ``plane_angle`` (the planar contact's)
    [rad], ``N`` [N], ``pmax`` [Pa], ``rolling_radius`` [m], and its Kik-Piotrowski ``strips``
    (arrays ``s`` [m] from O, + towards the gauge side; half-length ``x_lead`` [m]; peak
    pressure ``p_peak`` [Pa]).
    """
    kw = _contact_inputs(**locals())
    result = _records(_wheelwear.contact(kw))
    _warn_all(result.warnings)
    return result


def wear(
    wheel: PathLike = "S1002",
    rail: PathLike = "60E1",
    *,
    dy: float,
    load: float,
    vx: float = 0.0,
    vy: float = 0.0,
    phi: float = 0.0,
    V: float = 20.0,
    mu: float = 0.3,
    law: str = "usfd",
    model: str = "sdec",
    cells: int = 50,
    yaw: float = 0.0,
    roll: float = 0.0,
    inclination: Optional[Union[str, float]] = None,
    gauge: float = 1.435,
    back_to_back: float = 1.360,
    wheel_radius: Optional[float] = None,
    E: float = 200e9,
    nu: float = 0.25,
    strip_width: float = 0.1e-3,
    normal_method: str = "hertz-calibrated",
    contact_plane: str = "initial-point",
    epsilon: float = 0.55,
    origin: Optional[str] = None,
    taping_line_distance: Optional[float] = None,
    max_drop: Optional[float] = None,
    gauge_side: Optional[str] = None,
    smoothing: Optional[float] = None,
    exact_grid: int = 40,
    exact_margin: float = 1.3,
    exact_radius_variation: bool = False,
) -> Any:
    """One wheel position's wear, as ``wheelwear wear``: the contact of :func:`contact`, each
    patch's tangential problem with the contact ``model`` (sdec, eql, eqe, eqe-shifted, hertz)
    on ``cells`` x ``cells`` FASTSIM cells at the creepages ``vx``, ``vy`` [-], ``phi`` [1/m]
    and friction ``mu``, the wear ``law`` (usfd: T gamma; archard: the KTH map) at speed ``V``
    [m/s]. Profile files are read as for :func:`contact`.

    ``model="exact"`` is the exact chain of ``wheelwear wear --exact``: Kalker's exact theory on
    the patch's undeformed distance, on ``exact_grid`` x ``exact_grid`` elements over
    ``exact_margin`` times the patch (``tgamma`` then holds its elements), with
    ``exact_radius_variation`` the wheel's rolling radius across the patch in the slip; the
    reference for where the SDEC chain puts the wear (0.02-2 s per patch).

    A contact that carries no load (a flange climb, say) has no wear: its ``status`` and
    ``message`` say why and each patch's ``wear`` is None. Otherwise each patch has ``wear``
    with ``Fx``, ``Fy`` [N], ``frictional_work`` [J/m] (the FASTSIM cells' sum),
    ``worn_volume_per_metre`` [m^3/m], ``peak_depth_per_metre`` [m/m], ``peak_y_wheel`` [m],
    ``tgamma`` (arrays ``x``, ``y`` [m] of the cells in the patch frame and ``work``, the
    frictional work density per metre rolled [J/m^2/m]) and ``depth`` (arrays ``s_wheel``,
    ``y_wheel`` [m] and ``depth_per_metre`` [m/m] on 0.1 mm bins of the wheel profile).
    """
    args = dict(locals())
    law_name, model_name, n = args.pop("law"), args.pop("model"), args.pop("cells")
    exact = (args.pop("exact_grid"), args.pop("exact_margin"), args.pop("exact_radius_variation"))
    kw = _contact_inputs(**args)
    result = _records(_wheelwear.wear(kw, law_name, model_name, n, *exact))
    _warn_all(result.warnings)
    return result


def curving(
    scene: Optional[PathLike] = None,
    *,
    radius: float,
    cant: float = 0.0,
    speed: float,
    friction: Optional[float] = None,
    traction: float = 0.0,
    vehicle: Optional[PathLike] = None,
    contact_table: bool = False,
    threads: Optional[int] = None,
) -> Any:
    """Quasi-static curving of a vehicle in a constant curve, as ``wheelwear curving --json``:
    curve ``radius`` [m] (+ right-hand, left rail outer; 0 tangent track), ``cant`` [m] (outer
    rail above the inner), ``speed`` [m/s], ``friction`` (top of rail and flange alike; default
    the scene's), ``traction`` per powered axle [N]. Without ``scene`` the built-in profiles
    (S1002 on 60E1 1:40); without ``vehicle`` the scene's ``[vehicle]``, else the built-in
    Manchester benchmark coach. Where the vehicle file's wheel radius, lateral arm or proposed
    ``[contact]`` differ from the scene's, a ``RuntimeWarning`` names each (the scene's are used).

    Returns a record with ``converged`` (a status, not an exception), ``message``,
    ``cant_deficiency`` [m], and ``wheelsets`` in order of travel: ``dy`` [m],
    ``angle_of_attack`` [rad], ``Fx_axle`` [N], ``axle_torque`` [N m], ``status`` and
    ``wheels`` (left, right: ``Q``, ``Y``, ``Fx``, ``Fy``, ``N`` [N], ``contact_angle`` [rad]).
    It takes a second or less (more with ``contact_table``, which builds the table first) and
    is not interrupted by Ctrl-C.
    """
    result = _wheelwear.curving(
        "" if scene is None else _os.fspath(scene),
        "" if vehicle is None else _os.fspath(vehicle),
        radius, cant, speed, friction, traction, contact_table, threads,
    )
    _warn_all(result.pop("warnings"))
    return _records(result)


def run(
    scene: Optional[PathLike] = None,
    output: Optional[PathLike] = None,
    *,
    resume: Optional[PathLike] = None,
    overwrite: bool = False,
    allow_hook: bool = False,
    resume_stored: bool = False,
    progress: Optional[Callable[[int, float, float, float], None]] = None,
    threads: Optional[int] = None,
) -> Any:
    """A scene's wear-evolution run, as ``wheelwear run SCENE -o OUTPUT``; without ``scene``
    the built-in one. ``resume=FILE`` continues a run that stopped (give neither scene nor
    output then). ``progress(step, distance, total_distance, elapsed)`` is called after every
    step (m, s). Ctrl-C stops the run after the step in progress with KeyboardInterrupt; the
    file keeps every finished step and ``run(resume=FILE)`` continues it. One run's steps come
    from one program: a run the module started is resumed by the module (the command line
    refuses it, naming the program that wrote it), and the other way round.

    Returns the summary (``steps``, ``distance`` [m], ``worn_area`` [m^2], ``elapsed`` [s],
    ``evaluations``, ...); read the file with :func:`read_results`.
    """
    target = output if resume is None else resume
    try:
        summary = _wheelwear.run(
            None if scene is None else _os.fspath(scene),
            None if output is None else _os.fspath(output),
            None if resume is None else _os.fspath(resume),
            overwrite, allow_hook, resume_stored, progress, threads,
        )
    except KeyboardInterrupt:
        raise KeyboardInterrupt(
            f"run stopped; {target} keeps every finished step: continue it with "
            f"wheelwear.run(resume={str(target)!r})"
        ) from None
    return _records(summary)


__all__ = [
    "CREEP_METHODS",
    "CreepResult",
    "Profile",
    "Record",
    "Results",
    "Step",
    "contact",
    "creep",
    "curving",
    "rail_profile",
    "read_results",
    "run",
    "wear",
    "wheel_profile",
]
