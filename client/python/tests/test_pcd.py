"""PCD files and the packed layout, without a server: what the client sends is what the
API specifies."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import relmap
from relmap import lzf


def test_packed_layout_is_16_little_endian_bytes_per_point_holes_nan_in_all_three():
    points = np.array([[1.0, -2.0, 0.5, 255, 128, 0], [np.nan, 3.0, 4.0, 1, 2, 3]])
    cloud = relmap.packed_cloud(points)
    assert (cloud.packed.width, cloud.packed.height) == (2, 1)
    expected = (struct.pack("<fffBBBB", 1.0, -2.0, 0.5, 255, 128, 0, 255)
                + struct.pack("<fffBBBB", float("nan"), float("nan"), float("nan"), 1, 2, 3, 255))
    assert cloud.packed.points == expected


def test_structured_and_n_by_6_arrays_pack_alike_and_2d_keeps_rows():
    rows = np.array([[[0.1, 0.2, 0.9, 10, 20, 30], [0.2, 0.2, 0.9, 40, 50, 60]]] * 3)  # 3×2×6
    structured = relmap.as_points(rows)
    assert structured.shape == (3, 2)
    assert relmap.packed_cloud(rows) == relmap.packed_cloud(structured)
    assert (relmap.packed_cloud(rows).packed.width, relmap.packed_cloud(rows).packed.height) == (2, 3)


@pytest.mark.parametrize("bad", [np.zeros((4, 5)), np.zeros(6), np.array([[0, 0, 1, 256, 0, 0]])])
def test_arrays_that_are_not_points_are_refused_before_sending(bad):
    with pytest.raises(ValueError):
        relmap.packed_cloud(bad)


def test_lzf_literal_run_and_overlapping_reference():
    # Literal "ab" (control 1), then a reference of length 2+4=6 at distance 2 (control
    # (4 << 5) | 0, offset byte 1): "ababab" -> "abababab".
    assert lzf.decompress(b"\x01ab\x80\x01", 8) == b"abababab"
    with pytest.raises(ValueError):
        lzf.decompress(b"\x01ab\x80\x05", 8)  # distance 6 before the start


def test_real_binary_compressed_kinect_cloud(mug_points):
    assert mug_points.shape == (480, 640)
    finite = np.isfinite(mug_points["z"])
    assert 0.5 < finite.mean() < 1.0  # a Kinect frame: mostly points, some holes
    assert 0.3 < np.nanmedian(mug_points["z"]) < 3.0  # metres in front of the camera
    assert mug_points["r"][finite].std() > 0  # colours were read, not left at zero


@pytest.mark.parametrize("binary", [True, False])
def test_written_pcd_reads_back_the_same_points(mug_points, binary):
    small = mug_points[::8, ::8]
    again = relmap.parse_pcd(relmap.format_pcd(small, binary=binary))
    assert again.shape == small.shape
    for name in ("x", "y", "z"):
        np.testing.assert_array_equal(again[name], small[name])  # NaNs in the same places
    for name in ("r", "g", "b"):
        np.testing.assert_array_equal(again[name], small[name])


def test_ascii_pcd_with_rgba_as_integer():
    text = (b"VERSION 0.7\nFIELDS x y z rgba\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
            b"WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n0.1 0.2 0.3 4278255360\nnan nan nan 0\n")
    points = relmap.parse_pcd(text)
    assert points["z"][0] == np.float32(0.3)
    assert (points["r"][0], points["g"][0], points["b"][0]) == (0, 255, 0)  # 0xFF00FF00
    assert np.isnan(points["x"][1])


def test_truncated_pcd_is_a_value_error():
    with pytest.raises(ValueError):
        relmap.parse_pcd(b"VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\n"
                         b"WIDTH 10\nHEIGHT 1\nDATA binary\n\x00\x00")
