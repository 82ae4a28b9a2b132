"""ComputeMaps and PostOutcome with real Kinect clouds, against a real relmap-server."""

from __future__ import annotations

import grpc
import numpy as np
import pytest

import relmap


def test_maps_of_a_numpy_cloud_and_of_its_pcd_file_are_the_same(client, mug_path, mug_points):
    session = client.create_session(seed=1)
    from_numpy = client.compute_maps(session, mug_points)
    from_file = client.compute_maps(session, mug_path, point_labels=False)
    assert (from_numpy.frame_id, from_file.frame_id) == (1, 2)
    assert len(from_numpy.relevance) > 50  # a 640×480 table scene: hundreds of supervoxels
    np.testing.assert_array_equal(from_numpy.centroids, from_file.centroids)
    assert from_numpy.point_labels.shape == (640 * 480,)
    assert from_file.point_labels is None
    assert from_numpy.point_labels.max() == len(from_numpy.relevance) - 1
    # Before any sample every usable supervoxel maps to 0.5, and the choice map sums to 1.
    assert np.allclose(from_numpy.relevance, 0.5)
    assert from_numpy.choice.sum() == pytest.approx(1.0)
    assert 0 <= from_numpy.target < len(from_numpy.relevance)


@pytest.mark.parametrize("binary", [True, False])
def test_ascii_and_binary_pcd_give_the_maps_of_the_packed_points(client, mug_points, binary):
    small = mug_points[::2, ::2]  # 320×240, organized
    session = client.create_session(seed=1)
    packed = client.compute_maps(session, small, point_labels=False)
    pcd = client.compute_maps(session, relmap.format_pcd(small, binary=binary), point_labels=False)
    assert len(packed.relevance) > 10
    np.testing.assert_array_equal(packed.centroids, pcd.centroids)
    np.testing.assert_array_equal(packed.point_counts, pcd.point_counts)


def test_objects_are_numbered_in_the_order_of_their_lowest_supervoxel(client, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False)
    assert maps.objects.shape == maps.relevance.shape
    _, first_ids = np.unique(maps.objects, return_index=True)  # per object, its lowest id
    np.testing.assert_array_equal(np.sort(first_ids), first_ids)  # object k first seen before k+1
    assert maps.objects.max() + 1 == len(first_ids)  # 0, 1, ... with no gap
    assert 1 < len(first_ids) < len(maps.objects)  # a table scene: a few objects of many voxels


def test_features_come_when_asked(client, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False, features=True)
    assert maps.features.shape == (len(maps.relevance), 48)


def test_outcomes_are_learned_once_per_request_id(client, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False)
    answer = client.post_outcome(session, maps.frame_id, maps.target, moved=True, request_id="r1")
    assert answer.label == relmap.pb.LABEL_MOVEABLE
    again = client.post_outcome(session, maps.frame_id, maps.target, moved=True, request_id="r1")
    assert again.stats.moveable_samples == 1
    still = client.post_outcome(session, maps.frame_id, maps.target, moved=False)
    assert still.stats.non_moveable_samples == 1


def test_supervoxels_moved_with_the_target_are_learned_as_moveable(client, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False)
    usable = np.flatnonzero(maps.choice > 0)  # finite features: learnable
    target, others = int(usable[0]), [int(i) for i in usable[1:3]]
    answer = client.post_outcome(session, maps.frame_id, target, moved=True,
                                 moved_with_target=others)
    assert answer.moved_learned == 2
    assert answer.stats.moveable_samples == 1 + 2
    with pytest.raises(relmap.RelmapError) as raised:  # the target itself: refused, nothing learned
        client.post_outcome(session, maps.frame_id, target, moved=True, moved_with_target=[target])
    assert raised.value.code == grpc.StatusCode.INVALID_ARGUMENT
    assert client.get_session(session).stats.moveable_samples == 3


def test_the_rest_of_the_targets_object_is_learned_with_its_label(client, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False)
    usable = [int(i) for i in np.flatnonzero(maps.choice > 0)]
    still = client.post_outcome(session, maps.frame_id, usable[0], moved=False,
                                same_object=usable[1:3])
    assert still.object_learned == 2 and still.moved_learned == 0
    assert (still.stats.moveable_samples, still.stats.non_moveable_samples) == (0, 3)
    moved = client.post_outcome(session, maps.frame_id, usable[3], moved=True,
                                moved_with_target=[usable[4]], same_object=[usable[5]])
    assert (moved.moved_learned, moved.object_learned) == (1, 1)
    assert moved.stats.moveable_samples == 3
    with pytest.raises(relmap.RelmapError) as raised:  # in both lists: refused, nothing learned
        client.post_outcome(session, maps.frame_id, usable[6], moved=True,
                            moved_with_target=[usable[7]], same_object=[usable[7]])
    assert raised.value.code == grpc.StatusCode.INVALID_ARGUMENT
    assert client.get_session(session).stats.moveable_samples == 3


def test_the_after_cloud_of_an_unchanged_scene_says_not_moved(client, mug_path, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False)
    answer = client.post_outcome(session, maps.frame_id, maps.target, after_cloud=mug_path)
    assert answer.label == relmap.pb.LABEL_NOT_MOVEABLE
    assert not answer.evidence.moved and answer.evidence.target_points > 0


def test_an_outcome_of_an_evicted_frame_is_frame_gone(client, mug_points):
    session = client.create_session(seed=1)
    first = client.compute_maps(session, mug_points, point_labels=False)
    for _ in range(2):  # the test server keeps two frames per session
        client.compute_maps(session, mug_points, point_labels=False)
    with pytest.raises(relmap.RelmapError) as raised:
        client.post_outcome(session, first.frame_id, first.target, moved=True)
    assert raised.value.is_frame_gone and raised.value.reason == relmap.FRAME_GONE
    assert raised.value.metadata["frameId"] == str(first.frame_id)
    assert client.get_session(session).stats.moveable_samples == 0


def test_an_outcome_needs_exactly_one_of_label_and_after_cloud(client):
    session = client.create_session()
    with pytest.raises(ValueError):
        client.post_outcome(session, 1, 0)
