"""Clouds for ComputeMaps and PostOutcome: numpy points in the API's packed layout, or
the bytes of a PCD file.

The packed layout (PackedCloud in relevance_service.proto, as sim_backend/packed_cloud.cpp
writes it): per point float32 x, y, z then uint8 r, g, b, a (16 bytes, little endian),
row-major; a point with any non-finite coordinate is a hole, NaN in all three.
"""

from __future__ import annotations

import os
from typing import Union

import numpy as np

from relmap.v1 import relevance_service_pb2 as pb

# One point as the API packs it; also what relmap.pcd returns.
POINT_DTYPE = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"),
                        ("r", "u1"), ("g", "u1"), ("b", "u1")])
_PACKED_DTYPE = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"),
                          ("r", "u1"), ("g", "u1"), ("b", "u1"), ("a", "u1")])
assert _PACKED_DTYPE.itemsize == 16

# What compute_maps and post_outcome take as a cloud: points (see as_points), the path
# of a PCD file, a PCD file's bytes, or a Cloud message as it is.
CloudLike = Union[np.ndarray, str, "os.PathLike[str]", bytes, pb.Cloud]


def as_points(points: np.ndarray) -> np.ndarray:
    """``points`` as a structured POINT_DTYPE array of shape (N,) or (H, W).

    Takes a structured array with fields x, y, z, r, g, b (any shape of 1 or 2
    dimensions; extra fields are ignored), an N×6 array of x, y, z, r, g, b, or an
    H×W×6 array (an organized cloud, row-major). Colours are 0-255.

    Example::

        xyzrgb = np.array([[0.1, 0.0, 0.8, 255, 0, 0], [0.1, 0.01, 0.8, 250, 5, 0]])
        relmap.as_points(xyzrgb)["z"]   # array([0.8, 0.8], dtype=float32)
    """
    array = np.asarray(points)
    if array.dtype.names is not None:
        missing = [name for name in POINT_DTYPE.names if name not in array.dtype.names]
        if missing:
            raise ValueError(f"points need fields x, y, z, r, g, b; missing {missing}")
        if array.ndim not in (1, 2):
            raise ValueError(f"structured points must be 1-D or 2-D, got shape {array.shape}")
        out = np.empty(array.shape, dtype=POINT_DTYPE)
        for name in POINT_DTYPE.names:
            if name in ("r", "g", "b"):
                _check_colour(np.asarray(array[name]), name)
            out[name] = array[name]
        return out
    if array.ndim not in (2, 3) or array.shape[-1] != 6:
        raise ValueError(f"points must be N×6 or H×W×6 (x, y, z, r, g, b), got shape {array.shape}")
    out = np.empty(array.shape[:-1], dtype=POINT_DTYPE)
    for index, name in enumerate(POINT_DTYPE.names):
        column = array[..., index]
        if name in ("r", "g", "b"):
            _check_colour(column, name)
        out[name] = column
    return out


def _check_colour(values: np.ndarray, name: str) -> None:
    if values.size and (not np.all(np.isfinite(values)) or values.min() < 0 or values.max() > 255):
        raise ValueError(f"colour {name} must lie in [0, 255]")


def packed_cloud(points: np.ndarray) -> pb.Cloud:
    """A Cloud message in the packed layout; 2-D points keep their rows (organized).

    Example::

        cloud = relmap.packed_cloud(relmap.read_pcd("scene.pcd"))
        cloud.packed.width, cloud.packed.height    # (640, 480)
    """
    grid = as_points(points)
    height, width = grid.shape if grid.ndim == 2 else (1, grid.shape[0])
    flat = grid.reshape(-1)
    packed = np.empty(flat.shape[0], dtype=_PACKED_DTYPE)
    # A hole is a hole in all three coordinates, whatever the camera left in the others.
    hole = ~(np.isfinite(flat["x"]) & np.isfinite(flat["y"]) & np.isfinite(flat["z"]))
    for name in POINT_DTYPE.names:
        packed[name] = flat[name]
    for axis in ("x", "y", "z"):
        packed[axis][hole] = np.nan
    packed["a"] = 255
    return pb.Cloud(packed=pb.PackedCloud(width=width, height=height, points=packed.tobytes()))


def pcd_cloud(pcd: Union[str, "os.PathLike[str]", bytes]) -> pb.Cloud:
    """A Cloud message carrying a PCD file (its path, or its bytes) as it is: the server
    decodes it (ascii, binary or binary_compressed, x y z and rgb or rgba)."""
    if isinstance(pcd, bytes):
        return pb.Cloud(pcd=pcd)
    with open(pcd, "rb") as file:
        return pb.Cloud(pcd=file.read())


def to_cloud(cloud: CloudLike) -> pb.Cloud:
    """Any CloudLike as the Cloud message a request carries."""
    if isinstance(cloud, pb.Cloud):
        return cloud
    if isinstance(cloud, (str, bytes, os.PathLike)):
        return pcd_cloud(cloud)
    return packed_cloud(cloud)
