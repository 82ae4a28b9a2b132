"""PCD files (PCL's format) to and from numpy: the x y z and colour of each point.

Reads DATA ascii, binary and binary_compressed with FIELDS x y z and rgb or rgba
(other fields are skipped); writes ascii or binary with x y z rgb. Points come as the
structured array of :mod:`relmap.cloud` (fields x, y, z float32, r, g, b uint8), shaped
(HEIGHT, WIDTH) for an organized cloud and (POINTS,) otherwise.
"""

from __future__ import annotations

import os
import struct
from typing import Dict, List, Tuple, Union

import numpy as np

from relmap import lzf
from relmap.cloud import POINT_DTYPE, as_points

PathLike = Union[str, "os.PathLike[str]"]
_TYPES = {("F", 4): "<f4", ("F", 8): "<f8", ("U", 1): "u1", ("U", 2): "<u2", ("U", 4): "<u4",
          ("I", 1): "i1", ("I", 2): "<i2", ("I", 4): "<i4", ("U", 8): "<u8", ("I", 8): "<i8"}


def _header(data: bytes) -> Tuple[Dict[str, List[str]], int]:
    """The header's lines as name -> values, and the offset of the data."""
    header: Dict[str, List[str]] = {}
    offset = 0
    while offset < len(data):
        end = data.find(b"\n", offset)
        if end < 0:
            raise ValueError("PCD: header without DATA")
        line = data[offset:end].decode("ascii", "replace").strip()
        offset = end + 1
        if not line or line.startswith("#"):
            continue
        name, *values = line.split()
        header[name.upper()] = values
        if name.upper() == "DATA":
            return header, offset
    raise ValueError("PCD: header without DATA")


def _field_dtype(header: Dict[str, List[str]]) -> np.dtype:
    fields = header["FIELDS"]
    sizes = [int(s) for s in header["SIZE"]]
    types = header["TYPE"]
    counts = [int(c) for c in header.get("COUNT", ["1"] * len(fields))]
    if not len(fields) == len(sizes) == len(types) == len(counts):
        raise ValueError("PCD: FIELDS, SIZE, TYPE and COUNT differ in length")
    entries = []
    for index, (name, size, kind, count) in enumerate(zip(fields, sizes, types, counts)):
        if (kind, size) not in _TYPES:
            raise ValueError(f"PCD: field {name} has TYPE {kind} SIZE {size}")
        # "_" is PCL's padding field, possibly repeated: give each a unique name.
        unique = name if name != "_" else f"_{index}"
        entries.append((unique, _TYPES[(kind, size)], (count,)) if count > 1
                       else (unique, _TYPES[(kind, size)]))
    return np.dtype(entries)


def _columns(body: bytes, encoding: str, dtype: np.dtype, count: int) -> np.ndarray:
    if encoding == "binary":
        if len(body) < count * dtype.itemsize:
            raise ValueError("PCD: binary data shorter than POINTS says")
        return np.frombuffer(body, dtype=dtype, count=count)
    if encoding == "binary_compressed":
        if len(body) < 8:
            raise ValueError("PCD: binary_compressed data without sizes")
        compressed, size = struct.unpack("<II", body[:8])
        if size != count * dtype.itemsize:
            raise ValueError("PCD: decompressed size does not match POINTS")
        raw = lzf.decompress(body[8:8 + compressed], size)
        # Field by field (all x, then all y, ...), not point by point.
        points = np.empty(count, dtype=dtype)
        offset = 0
        for name in dtype.names:
            field = dtype.fields[name][0]
            values = count * int(np.prod(field.shape or (1,)))
            points[name] = np.frombuffer(raw, dtype=field.base, count=values,
                                         offset=offset).reshape(points[name].shape)
            offset += values * field.base.itemsize
        return points
    if encoding == "ascii":
        rows = body.decode("ascii").split()
        width = sum(int(np.prod(dtype.fields[n][0].shape or (1,))) for n in dtype.names)
        if len(rows) < count * width:
            raise ValueError("PCD: ascii data shorter than POINTS says")
        table = np.array(rows[:count * width], dtype=object).reshape(count, width)
        points = np.empty(count, dtype=dtype)
        column = 0
        for name in dtype.names:
            field = dtype.fields[name][0]
            span = int(np.prod(field.shape or (1,)))
            values = table[:, column:column + span].astype(np.float64 if field.base.kind == "f" else np.int64)
            points[name] = values.reshape(points[name].shape).astype(field.base)
            column += span
        return points
    raise ValueError(f"PCD: DATA {encoding} is not supported")


def _colour(points: np.ndarray) -> np.ndarray:
    """rgb (a float holding 0x00RRGGBB) or rgba (uint32) as uint32 0xAARRGGBB."""
    for name in ("rgb", "rgba"):
        if name in points.dtype.names:
            values = np.ascontiguousarray(points[name])
            if values.dtype.kind == "f":
                values = values.astype("<f4").view("<u4")
            return values.astype(np.uint32)
    raise ValueError("PCD: no rgb or rgba field")


def parse_pcd(data: bytes) -> np.ndarray:
    """The points of a PCD file's bytes (see the module's docstring)."""
    header, offset = _header(data)
    for name in ("FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT"):
        if name not in header:
            raise ValueError(f"PCD: no {name} line")
    width, height = int(header["WIDTH"][0]), int(header["HEIGHT"][0])
    count = int(header.get("POINTS", [str(width * height)])[0])
    if count != width * height:
        raise ValueError("PCD: POINTS is not WIDTH x HEIGHT")
    raw = _columns(data[offset:], header["DATA"][0].lower(), _field_dtype(header), count)
    for axis in ("x", "y", "z"):
        if axis not in raw.dtype.names:
            raise ValueError(f"PCD: no {axis} field")
    points = np.empty(count, dtype=POINT_DTYPE)
    for axis in ("x", "y", "z"):
        points[axis] = raw[axis]
    colour = _colour(raw)
    points["r"] = (colour >> 16) & 0xFF
    points["g"] = (colour >> 8) & 0xFF
    points["b"] = colour & 0xFF
    return points.reshape(height, width) if height > 1 else points


def read_pcd(path: PathLike) -> np.ndarray:
    """The points of the PCD file at ``path``.

    Example::

        points = relmap.read_pcd("/work/shared/data/real/table_scene_mug_stereo_textured.pcd")
        points.shape          # (480, 640): organized
        points["z"][240, 320] # depth of the centre pixel, metres (NaN: a hole)
    """
    with open(path, "rb") as file:
        return parse_pcd(file.read())


def format_pcd(points: np.ndarray, binary: bool = True) -> bytes:
    """A PCD file of ``points`` (anything :func:`relmap.cloud.as_points` takes) with
    FIELDS x y z rgb, organized if ``points`` is 2-D; DATA binary or ascii."""
    grid = as_points(points)
    height, width = grid.shape if grid.ndim == 2 else (1, grid.shape[0])
    flat = grid.reshape(-1)
    rgb = ((flat["r"].astype(np.uint32) << 16) | (flat["g"].astype(np.uint32) << 8)
           | flat["b"].astype(np.uint32)).view("<f4")
    header = ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgb\n"
              "SIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
              f"WIDTH {width}\nHEIGHT {height}\nVIEWPOINT 0 0 0 1 0 0 0\n"
              f"POINTS {width * height}\nDATA {'binary' if binary else 'ascii'}\n")
    if binary:
        table = np.empty(flat.shape[0], dtype=[("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("rgb", "<f4")])
        for name in ("x", "y", "z"):
            table[name] = flat[name]
        table["rgb"] = rgb
        return header.encode("ascii") + table.tobytes()
    lines = [f"{x!r} {y!r} {z!r} {c!r}" for x, y, z, c in zip(
        flat["x"].astype(float), flat["y"].astype(float), flat["z"].astype(float),
        rgb.astype(float))]
    return (header + "\n".join(lines) + "\n").encode("ascii")


def write_pcd(path: PathLike, points: np.ndarray, binary: bool = True) -> None:
    """Writes :func:`format_pcd` of ``points`` to ``path``."""
    with open(path, "wb") as file:
        file.write(format_pcd(points, binary))
