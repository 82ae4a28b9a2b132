"""Sessions, export and import, and health, against a real relmap-server."""

from __future__ import annotations

import re

import grpc
import numpy as np
import pytest

import relmap
from conftest import start_server


def test_every_rpc_of_the_service_has_a_client_method():
    service = relmap.pb.DESCRIPTOR.services_by_name["RelevanceService"]
    names = [re.sub(r"(?<!^)(?=[A-Z])", "_", method.name).lower() for method in service.methods]
    assert len(names) == 10 and "import_session" in names
    assert [name for name in names if not callable(getattr(relmap.Client, name, None))] == []


def test_create_returns_a_token_and_the_config_with_defaults(client):
    session = client.create_session(seed=7)
    assert len(session.id) > 0 and len(session.token) > 0
    assert session.config.seed == 7
    assert session.config.supervoxels.voxel_resolution == pytest.approx(0.008)  # the authors'


def test_get_shows_the_config_and_empty_stats(client):
    session = client.create_session(seed=3, feature_dimension=5)
    answer = client.get_session(session)
    assert answer.session_id == session.id
    assert answer.config.feature_dimension == 5
    assert answer.stats.moveable_samples == 0 and answer.stats.frames == 0


def test_list_follows_the_pages(client):
    created = {client.create_session(seed=i).id for i in range(3)}
    assert created <= {entry.session_id for entry in client.list_sessions()}
    first = client.list_sessions_page(page_size=1)
    assert len(first.sessions) == 1 and first.next_page_token


def test_delete_removes_the_session(client):
    session = client.create_session()
    client.delete_session(session)
    with pytest.raises(relmap.RelmapError) as raised:
        client.get_session(session)
    assert raised.value.code == grpc.StatusCode.NOT_FOUND


def test_export_then_import_relearns_the_same_samples(client):
    session = client.create_session(seed=2, feature_dimension=2)
    features = np.array([[0.1, 0.9], [0.15, 0.85], [0.9, 0.1], [0.85, 0.2]])
    client.add_samples(session, features, [True, True, False, False])
    exported = client.export_session(session)
    assert len(exported.state.samples) == 4
    copy = client.import_session(exported.state)
    assert copy.id != session.id
    stats = client.get_session(copy).stats
    assert (stats.moveable_samples, stats.non_moveable_samples) == (2, 2)
    np.testing.assert_array_equal(client.classify_features(copy, features).relevance,
                                  client.classify_features(session, features).relevance)


def test_health_of_the_server_and_of_the_service(client):
    assert client.check_health() == "SERVING"
    assert client.check_health("relmap.v1.RelevanceService") == "SERVING"
    with pytest.raises(relmap.RelmapError) as raised:
        client.check_health("no.such.Service")
    assert raised.value.code == grpc.StatusCode.NOT_FOUND


def test_admin_key_is_needed_where_the_server_asks_for_it(tmp_path):
    key_file = tmp_path / "admin.key"
    key_file.write_text("s3cret\n")
    server = start_server("--admin-key-file", str(key_file))
    try:
        with relmap.Client(server.address, admin_key="s3cret") as admin:
            session = admin.create_session(seed=1, feature_dimension=2)
            admin.add_samples(session, np.array([[0.1, 0.9]]), [True])
            state = admin.export_session(session).state
            for key, code in ((None, grpc.StatusCode.UNAUTHENTICATED),
                              ("guess", grpc.StatusCode.PERMISSION_DENIED)):
                with relmap.Client(server.address, admin_key=key) as other:
                    for call in (other.create_session, other.list_sessions,
                                 lambda: other.import_session(state),
                                 lambda: other.delete_session(session)):  # its token is not enough
                        with pytest.raises(relmap.RelmapError) as raised:
                            call()
                        assert raised.value.code == code
                    assert other.get_session(session).stats.moveable_samples == 1  # the token is
            copy = admin.import_session(state)
            assert {session.id, copy.id} <= {entry.session_id for entry in admin.list_sessions()}
            admin.delete_session(session)
            assert [entry.session_id for entry in admin.list_sessions()] == [copy.id]
    finally:
        server.stop()
