# Type stubs of the holefill package (the extension holefill._holefill): what help() shows, for
# editors and type checkers. test_stubs.py checks them against the module.
import os
from typing import Any, Callable, Iterable, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str

class Error(ValueError): ...
class HolefillWarning(UserWarning): ...

FILL_OPTIONS: dict[str, Any]

Record = dict[str, Any]
ArrayLike = npt.ArrayLike
Progress = Optional[Callable[[float], Optional[bool]]]

class Mesh:
    def __init__(
        self,
        vertices: ArrayLike,
        faces: ArrayLike,
        vertex_colors: Optional[ArrayLike] = None,
        vertex_normals: Optional[ArrayLike] = None,
        vertex_attributes: Optional[dict[str, ArrayLike]] = None,
        face_attributes: Optional[dict[str, ArrayLike]] = None,
    ) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def vertex_colors(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def vertex_normals(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def vertex_attributes(self) -> dict[str, npt.NDArray[np.float64]]: ...
    @property
    def face_attributes(self) -> dict[str, npt.NDArray[np.float64]]: ...
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def name(self) -> str: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...
    def copy(self) -> Mesh: ...
    def __copy__(self) -> Mesh: ...
    def __deepcopy__(self, memo: Any) -> Mesh: ...

def load(path: Union[str, os.PathLike[str]], *, threads: int = 0) -> Mesh: ...
def info(
    mesh: Mesh,
    *,
    stitch: bool = True,
    stitch_tolerance: Optional[float] = None,
    remove_small_components: int = 0,
    keep_borders: bool = False,
    **options: Any,
) -> dict[str, Any]: ...
def holes(
    mesh: Mesh,
    *,
    stitch: bool = True,
    stitch_tolerance: Optional[float] = None,
    remove_small_components: int = 0,
    keep_borders: bool = False,
    **options: Any,
) -> list[Record]: ...
def fill(
    mesh: Mesh,
    holes: Union[None, int, Iterable[int]] = None,
    *,
    progress: Progress = None,
    weight: str = "maxmin",
    fold_limit: float = 45.0,
    restricted_above: int = 800,
    tau: float = 1.4142135623730951,
    remesh: bool = False,
    smooth: str = "umbrella",
    fair_order: int = 2,
    fair_weights: str = "cotangent",
    smooth_iterations: int = 10,
    smooth_step: float = 0.5,
    max_boundary: int = 0,
    islands: bool = True,
    feature_angle: float = 40.0,
    bridge: Iterable[tuple[int, int]] = [],
    stage: str = "smooth",
    stitch: bool = True,
    stitch_tolerance: Optional[float] = None,
    remove_small_components: int = 0,
    keep_borders: bool = False,
    allow_intersections: bool = False,
    threads: int = 0,
) -> list[Record]: ...

class Fill:
    def __init__(
        self,
        mesh: Mesh,
        hole: int,
        *,
        weight: str = "maxmin",
        fold_limit: float = 45.0,
        restricted_above: int = 800,
        tau: float = 1.4142135623730951,
        remesh: bool = False,
        smooth: str = "umbrella",
        fair_order: int = 2,
        fair_weights: str = "cotangent",
        smooth_iterations: int = 10,
        smooth_step: float = 0.5,
        islands: bool = True,
        feature_angle: float = 40.0,
        bridge: Iterable[tuple[int, int]] = [],
        stitch: bool = True,
        stitch_tolerance: Optional[float] = None,
        remove_small_components: int = 0,
        keep_borders: bool = False,
        allow_intersections: bool = False,
        threads: int = 0,
    ) -> None: ...
    def triangulate(self) -> Record: ...
    def refine(self) -> Record: ...
    def smooth(self) -> Record: ...
    def undo(self) -> None: ...
    @property
    def record(self) -> Record: ...
    @property
    def hole(self) -> int: ...
    @property
    def joined_holes(self) -> list[int]: ...
    @property
    def stage(self) -> str: ...
    @property
    def patch_faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def new_vertices(self) -> npt.NDArray[np.int64]: ...
