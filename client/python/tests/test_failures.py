"""What goes wrong: a bad token, invalid clouds, a busy server and a server that went
away, each raising RelmapError with the right code (and reason) after the C++ client's
retries."""

from __future__ import annotations

import threading
import time

import grpc
import numpy as np
import pytest

import relmap
from conftest import start_server


def session_calls(client, session, frame_id):
    """Every RPC on a session, each as a thunk, named."""
    return {
        "GetSession": lambda: client.get_session(session),
        "ComputeMaps": lambda: client.compute_maps(session, np.zeros((1, 6))),
        "PostOutcome": lambda: client.post_outcome(session, frame_id, 0, moved=True),
        "ClassifyFeatures": lambda: client.classify_features(session, np.zeros((1, 48))),
        "AddSamples": lambda: client.add_samples(session, np.zeros((1, 48)), [True]),
        "ExportSession": lambda: client.export_session(session),
        "DeleteSession": lambda: client.delete_session(session),
    }


def test_a_wrong_token_is_permission_denied_on_every_session_call(client, mug_points):
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, mug_points, point_labels=False)
    forged = relmap.Session(session.id, "not-the-token")
    for name, call in session_calls(client, forged, maps.frame_id).items():
        with pytest.raises(relmap.RelmapError) as raised:
            call()
        assert (raised.value.call, raised.value.code) == (name, grpc.StatusCode.PERMISSION_DENIED)
        assert raised.value.reason == relmap.ERROR_REASON_UNSPECIFIED
    assert client.retries == 0  # a refusal is final
    stats = client.get_session(session).stats  # the real token still works; nothing learned
    assert (stats.frames, stats.moveable_samples) == (1, 0)


def test_a_missing_token_is_unauthenticated(client):
    session = client.create_session()
    for name, call in session_calls(client, relmap.Session(session.id, ""), 1).items():
        with pytest.raises(relmap.RelmapError) as raised:
            call()
        assert (raised.value.call, raised.value.code) == (name, grpc.StatusCode.UNAUTHENTICATED)


def nan_cloud():
    points = np.zeros((100, 6))
    points[:, :3] = np.nan
    return points


@pytest.mark.parametrize("cloud", [nan_cloud(), np.zeros((0, 6)), b"not a PCD file",
                                   np.array([[0.0, 0.0, np.inf, 1, 2, 3]])],
                         ids=["all-nan", "empty", "garbage-pcd", "infinite"])
def test_an_invalid_cloud_is_an_invalid_argument(client, cloud):
    session = client.create_session()
    with pytest.raises(relmap.RelmapError) as raised:
        client.compute_maps(session, cloud)
    assert raised.value.code == grpc.StatusCode.INVALID_ARGUMENT
    assert raised.value.call == "ComputeMaps"


def test_a_busy_server_is_waited_for(mug_points):
    # One cloud at a time and one waiting: of six maps sent at once, some are turned away
    # as BUSY with a pushback (tests/integration/busy_server_test.cpp sees it on the wire),
    # and the client repeats them until each is served.
    server = start_server("--max-concurrent-frames", "1", "--max-queued-frames", "1")
    cloud = relmap.packed_cloud(mug_points)
    try:
        with relmap.Client(server.address) as client:
            sessions = [client.create_session(seed=i) for i in range(6)]
            results, errors = [], []

            def run(session):
                try:
                    results.append(client.compute_maps(session, cloud, point_labels=False))
                except relmap.RelmapError as error:
                    errors.append(error)

            threads = [threading.Thread(target=run, args=(s,)) for s in sessions]
            for thread in threads:
                thread.start()
            for thread in threads:
                thread.join()
            assert errors == [] and len(results) == 6
            assert client.retries >= 1
    finally:
        server.stop()


def test_a_server_that_went_away_is_unavailable_after_the_retries():
    server = start_server()
    policy = relmap.RetryPolicy(max_attempts=5, initial_backoff=0.05, max_backoff=2.0)
    with relmap.Client(server.address, retry=policy) as client:
        session = client.create_session()
        server.kill()  # kill -9: a crash
        with pytest.raises(relmap.RelmapError) as raised:
            client.get_session(session)  # idempotent: five attempts
        assert raised.value.code == grpc.StatusCode.UNAVAILABLE
        assert client.retries == 4
        with pytest.raises(relmap.RelmapError) as raised:
            client.create_session()  # not idempotent: one attempt
        assert raised.value.code == grpc.StatusCode.UNAVAILABLE
        assert client.retries == 4
        with pytest.raises(relmap.RelmapError):
            client.compute_maps(session, np.zeros((1, 6)))  # not repeated unless asked
        assert client.retries == 4
        with pytest.raises(relmap.RelmapError):
            client.compute_maps(session, np.zeros((1, 6)), repeat_after_broken_connection=True)
        assert client.retries == 8
    server.stop()


def test_the_deadline_bounds_the_retries_of_a_call():
    # 100 attempts at 0.1-0.2 s each would take 10 s or more; the 0.5 s deadline ends the
    # call at the first backoff that would pass it (client/relevance_client.cpp does so).
    server = start_server()
    policy = relmap.RetryPolicy(max_attempts=100, initial_backoff=0.1, max_backoff=0.1)
    with relmap.Client(server.address, deadline=0.5, retry=policy) as client:
        session = client.create_session()
        server.kill()
        start = time.monotonic()
        with pytest.raises(relmap.RelmapError) as raised:
            client.get_session(session)
        elapsed = time.monotonic() - start
        assert raised.value.code == grpc.StatusCode.UNAVAILABLE
        assert 1 <= client.retries < 10
        assert elapsed < 0.5 + 0.3  # the deadline, and at most one attempt's slack
    server.stop()
