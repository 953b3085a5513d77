# Type hints of the wheelwear package (hand-written; checked against the module by
# `python3 -m mypy.stubtest wheelwear` in the tests). SI units throughout.
import os
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .results import Results as Results
from .results import Step as Step
from .results import read_results as read_results

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

__version__: str

ArrayLike = Union[float, npt.NDArray[np.float64], List[float]]
PathLike = Union[str, os.PathLike[str]]

CREEP_METHODS: Tuple[str, ...]

class Record(Dict[str, Any]):
    """A dict whose keys are also attributes."""

    def __getattr__(self, name: str) -> Any: ...
    def __dir__(self) -> List[str]: ...

class CreepResult:
    Fx: Any  # float, or an array of the broadcast shape [N]
    Fy: Any  # [N]
    Mz: Any  # [N m], NaN where the method has none
    rigid_slip_work: Any  # [J/m], NaN without Mz
    status: Any
    cells: Any
    slip_cells: Any
    from_table: Any
    extrapolated: Any
    warnings: List[str]
    def __init__(self, fields: Dict[str, Any], shape: tuple, mu_N: Any) -> None: ...
    @property
    def Fx_muN(self) -> Any: ...
    @property
    def Fy_muN(self) -> Any: ...

class Profile:
    """A wheel or rail profile in its own frame (y + towards the field side, z + down) [m]."""

    def __init__(self, *args: Any, **kwargs: Any) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def body(self) -> str: ...
    @property
    def nominal_radius(self) -> float: ...
    @property
    def length(self) -> float: ...
    @property
    def y_range(self) -> Tuple[float, float]: ...
    def sample(self, spacing: float = ...) -> npt.NDArray[np.float64]: ...
    def knots(self) -> npt.NDArray[np.float64]: ...
    def position(self, s: ArrayLike) -> Any: ...
    def height(self, s: ArrayLike) -> Any: ...
    def curvature(self, s: ArrayLike) -> Any: ...
    def parameters(self) -> Dict[str, float]: ...

def creep(
    method: str = ...,
    *,
    a: ArrayLike,
    b: ArrayLike,
    psi: ArrayLike = ...,
    vx: ArrayLike = ...,
    vy: ArrayLike = ...,
    phi: ArrayLike = ...,
    N: ArrayLike,
    G: ArrayLike = ...,
    nu: ArrayLike = ...,
    mu: ArrayLike = ...,
    nx: Optional[int] = ...,
    ny: Optional[int] = ...,
    bound: Optional[str] = ...,
    scheme: Optional[str] = ...,
    target_error: Optional[float] = ...,
    exact_grid: Optional[int] = ...,
    beyond_table: Optional[str] = ...,
    inside_table: Optional[str] = ...,
    threads: Optional[int] = ...,
) -> CreepResult: ...
def wheel_profile(
    spec: PathLike = ...,
    *,
    radius: Optional[float] = ...,
    origin: Optional[str] = ...,
    taping_line_distance: Optional[float] = ...,
    max_drop: Optional[float] = ...,
    smoothing: Optional[float] = ...,
) -> Profile: ...
def rail_profile(
    spec: PathLike = ...,
    *,
    inclination: Optional[Union[str, float]] = ...,
    gauge_side: Optional[str] = ...,
    max_drop: Optional[float] = ...,
    smoothing: Optional[float] = ...,
) -> Profile: ...
def contact(
    wheel: PathLike = ...,
    rail: PathLike = ...,
    *,
    dy: float,
    load: float,
    yaw: float = ...,
    roll: float = ...,
    inclination: Optional[Union[str, float]] = ...,
    gauge: float = ...,
    back_to_back: float = ...,
    wheel_radius: Optional[float] = ...,
    E: float = ...,
    nu: float = ...,
    strip_width: float = ...,
    normal_method: str = ...,
    contact_plane: str = ...,
    epsilon: float = ...,
    origin: Optional[str] = ...,
    taping_line_distance: Optional[float] = ...,
    max_drop: Optional[float] = ...,
    gauge_side: Optional[str] = ...,
    smoothing: Optional[float] = ...,
) -> Record: ...
def wear(
    wheel: PathLike = ...,
    rail: PathLike = ...,
    *,
    dy: float,
    load: float,
    vx: float = ...,
    vy: float = ...,
    phi: float = ...,
    V: float = ...,
    mu: float = ...,
    law: str = ...,
    model: str = ...,
    cells: int = ...,
    yaw: float = ...,
    roll: float = ...,
    inclination: Optional[Union[str, float]] = ...,
    gauge: float = ...,
    back_to_back: float = ...,
    wheel_radius: Optional[float] = ...,
    E: float = ...,
    nu: float = ...,
    strip_width: float = ...,
    normal_method: str = ...,
    contact_plane: str = ...,
    epsilon: float = ...,
    origin: Optional[str] = ...,
    taping_line_distance: Optional[float] = ...,
    max_drop: Optional[float] = ...,
    gauge_side: Optional[str] = ...,
    smoothing: Optional[float] = ...,
    exact_grid: int = ...,
    exact_margin: float = ...,
    exact_radius_variation: bool = ...,
) -> Record: ...
def curving(
    scene: Optional[PathLike] = ...,
    *,
    radius: float,
    cant: float = ...,
    speed: float,
    friction: Optional[float] = ...,
    traction: float = ...,
    vehicle: Optional[PathLike] = ...,
    contact_table: bool = ...,
    threads: Optional[int] = ...,
) -> Record: ...
def run(
    scene: Optional[PathLike] = ...,
    output: Optional[PathLike] = ...,
    *,
    resume: Optional[PathLike] = ...,
    overwrite: bool = ...,
    allow_hook: bool = ...,
    resume_stored: bool = ...,
    progress: Optional[Callable[[int, float, float, float], None]] = ...,
    threads: Optional[int] = ...,
) -> Record: ...
