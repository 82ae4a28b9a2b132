"""AddSamples and ClassifyFeatures from numpy, against a real relmap-server."""

from __future__ import annotations

import grpc
import numpy as np
import pytest

import relmap


def two_blobs(seed: int, count: int):
    """Moveable samples around (0.2, 0.8), the others around (0.8, 0.2): separable."""
    rng = np.random.default_rng(seed)
    moveable = rng.random(count) < 0.5
    centres = np.where(moveable[:, None], [0.2, 0.8], [0.8, 0.2])
    return centres + rng.normal(0.0, 0.05, (count, 2)), moveable


def test_a_session_that_learned_two_blobs_tells_them_apart(client):
    session = client.create_session(seed=1, feature_dimension=2)
    features, moveable = two_blobs(1, 200)
    stats = client.add_samples(session, features, moveable)
    assert stats.moveable_samples == moveable.sum()
    assert stats.non_moveable_samples == (~moveable).sum()
    test_features, test_moveable = two_blobs(2, 100)
    result = client.classify_features(session, test_features)
    assert result.relevance.shape == (100,)
    assert np.mean((result.relevance > 0.5) == test_moveable) > 0.95
    assert result.choice.sum() == pytest.approx(1.0)


def test_add_samples_with_the_same_request_id_learns_once(client):
    session = client.create_session(feature_dimension=2)
    features, moveable = two_blobs(3, 10)
    client.add_samples(session, features, moveable, request_id="batch-1")
    stats = client.add_samples(session, features, moveable, request_id="batch-1")
    assert stats.moveable_samples + stats.non_moveable_samples == 10


def test_wrong_dimension_and_non_finite_values_are_invalid_arguments(client):
    session = client.create_session(feature_dimension=2)
    for features in (np.zeros((1, 3)), np.array([[np.nan, 0.5]])):
        with pytest.raises(relmap.RelmapError) as raised:
            client.classify_features(session, features)
        assert raised.value.code == grpc.StatusCode.INVALID_ARGUMENT


def test_labels_must_match_the_vectors(client):
    session = client.create_session(feature_dimension=2)
    with pytest.raises(ValueError):
        client.add_samples(session, np.zeros((2, 2)), [True])
    with pytest.raises(ValueError):
        client.add_samples(session, np.zeros((1, 2)), [2])
