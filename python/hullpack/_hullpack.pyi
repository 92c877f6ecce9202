# Type stubs for the compiled module (docstrings: help(hullpack.<function>)).
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

VHACD_VERSION: int
STREAM_VERSION: str

class Cancelled(RuntimeError): ...

Progress = Optional[Callable[[float, str], Optional[bool]]]
Hull = Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32]]
BytesLike = Union[bytes, bytearray, memoryview, npt.NDArray[np.uint8]]

def decompose(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    *,
    method: str = "vhacd",
    preset: str = "default",
    concavity: Optional[float] = None,
    max_vertices_per_hull: Optional[int] = None,
    num_threads: Optional[int] = None,
    compute_report: bool = True,
    # V-HACD only (method="vhacd").
    resolution: Optional[int] = None,
    depth: Optional[int] = None,
    plane_downsampling: Optional[int] = None,
    convexhull_downsampling: Optional[int] = None,
    alpha: Optional[float] = None,
    beta: Optional[float] = None,
    gamma: Optional[float] = None,
    pca: Optional[bool] = None,
    mode: Optional[str] = None,
    min_volume_per_hull: Optional[float] = None,
    max_convex_hulls: Optional[int] = None,
    max_distance: Optional[float] = None,
    max_concavity: Optional[float] = None,
    hulls: Optional[int] = None,
    min_opening: Optional[float] = None,
    points_in_place: Optional[bool] = None,
    # HACD only (method="hacd").
    target_triangles: Optional[int] = None,
    scale_factor: Optional[float] = None,
    small_cluster_threshold: Optional[float] = None,
    add_face_points: Optional[bool] = None,
    add_extra_dist_points: Optional[bool] = None,
    invert_input_faces: Optional[bool] = None,
    min_clusters: Optional[int] = None,
    connect_distance: Optional[float] = None,
    volume_weight: Optional[float] = None,
    compacity_weight: Optional[float] = None,
    flat_region_threshold: Optional[float] = None,
    computation_weight: Optional[float] = None,
    progress: Progress = None,
) -> Tuple[List[Hull], Dict[str, Any]]: ...
def simplify(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    *,
    target_triangles: Optional[int] = None,
    target_error: Optional[float] = None,
    lock_boundary: bool = False,
    progress: Progress = None,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32], Dict[str, Any]]: ...
def encode(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    *,
    normals: Optional[npt.ArrayLike] = None,
    uvs: Optional[npt.ArrayLike] = None,
    colors: Optional[npt.ArrayLike] = None,
    position_bits: int = 14,
    normal_bits: int = 10,
    uv_bits: int = 12,
    color_bits: int = 10,
    keep_order: bool = False,
    fast_decode: bool = False,
    max_compression: bool = False,
    ascii: bool = False,
    progress: Progress = None,
) -> bytes: ...
def decode(
    data: BytesLike,
    *,
    verify_checksum: bool = True,
    max_vertices: int = 268435456,
    max_triangles: int = 268435456,
    progress: Progress = None,
) -> Dict[str, Any]: ...
def stream_info(data: BytesLike) -> Dict[str, Any]: ...
def pack(
    input: str,
    output: str,
    *,
    max_error: float = 0.0005,
    hull_error: float = 0.002,
    position_bits: Optional[int] = None,
    normal_bits: int = 10,
    uv_bits: int = 12,
    ascii: bool = False,
    keep_order: bool = False,
    fast_decode: bool = False,
    max_compression: bool = False,
    part_triangles: int = 600000,
    fallback: bool = False,
    quantized_hulls: bool = False,
    plain_animations: bool = False,
    hulls: Union[str, int] = "auto",
    physics: str = "omi",
    method: str = "vhacd",
    quality: str = "default",
    resolution: Optional[int] = None,
    max_hulls: Optional[int] = None,
    max_vertices: Optional[int] = None,
    concavity: Optional[float] = None,
    max_concavity: Optional[float] = None,
    force: bool = False,
    progress: Progress = None,
) -> Dict[str, Any]: ...
def unpack(input: str, output: str, *, force: bool = False) -> Dict[str, Any]: ...
def info(path: str) -> Dict[str, Any]: ...
def load_mesh(path: str) -> Dict[str, Any]: ...
def collision(
    input: str,
    output_dir: str,
    *,
    format: str = "urdf",
    name: Optional[str] = None,
    density: float = 1000.0,
    max_hull_vertices: Optional[int] = None,
    quality: str = "default",
    resolution: Optional[int] = None,
    max_hulls: Optional[int] = None,
    concavity: Optional[float] = None,
    force: bool = False,
    progress: Progress = None,
) -> Dict[str, Any]: ...
