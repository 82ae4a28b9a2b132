"""The Python client of relmap-server: one object per server connection, safe to share
between threads. The C++ client's behaviour (client/relevance_client.h): session calls
carry the session's bearer token and id, every call has a deadline that covers its
retries, calls the server provably did not run (and idempotent calls that met a broken
connection) are retried with backoff (relmap.retry), and failures raise RelmapError
with the gRPC code and the server's reason (relmap.errors)."""

from __future__ import annotations

import secrets
import threading
from typing import Any, Callable, List, Optional, Sequence, Tuple

import grpc
import numpy as np

from relmap._rpc import health_pb2
from relmap.cloud import CloudLike, to_cloud
from relmap.results import Classification, Maps, Session
from relmap.retry import RetryPolicy, call_with_retries
from relmap.v1 import relevance_service_pb2 as pb
from relmap.v1 import relevance_service_pb2_grpc as pb_grpc

_HEALTH_CHECK = "/grpc.health.v1.Health/Check"
Metadata = List[Tuple[str, str]]


def random_request_id() -> str:
    """128 random bits as 32 hex digits: a request id no other client will pick."""
    return secrets.token_hex(16)


class Client:
    """A connection to relmap-server.

    ``deadline`` (seconds) bounds a whole call, retries and backoffs included: 30 s,
    the C++ client's default (a 640×480 ComputeMaps takes ~0.15 s on the server).

    Example::

        import relmap
        with relmap.Client("127.0.0.1:50051") as client:
            session = client.create_session(seed=1)
            maps = client.compute_maps(session, "scene.pcd")
            client.post_outcome(session, maps.frame_id, maps.target, moved=True)
            print(client.get_session(session).stats.moveable_samples)   # 1
    """

    def __init__(self, address: str = "127.0.0.1:50051", *, deadline: float = 30.0,
                 retry: RetryPolicy = RetryPolicy(), max_message_bytes: int = 64 << 20,
                 tls_root_certificates: Optional[bytes] = None,
                 admin_key: Optional[str] = None) -> None:
        options = [("grpc.max_send_message_length", max_message_bytes),
                   ("grpc.max_receive_message_length", max_message_bytes)]
        if tls_root_certificates is None:
            self._channel = grpc.insecure_channel(address, options=options)
        else:
            credentials = grpc.ssl_channel_credentials(root_certificates=tls_root_certificates)
            self._channel = grpc.secure_channel(address, credentials, options=options)
        self._stub = pb_grpc.RelevanceServiceStub(self._channel)
        self._health = self._channel.unary_unary(
            _HEALTH_CHECK, request_serializer=health_pb2.HealthCheckRequest.SerializeToString,
            response_deserializer=health_pb2.HealthCheckResponse.FromString)
        self.address = address
        self.deadline = deadline
        self.retry = retry
        self.admin_key = admin_key
        self._retries = 0
        self._lock = threading.Lock()

    def close(self) -> None:
        """Closes the channel; the client cannot be used after."""
        self._channel.close()

    def __enter__(self) -> "Client":
        return self

    def __exit__(self, *exc_info: Any) -> None:
        self.close()

    @property
    def retries(self) -> int:
        """Attempts beyond the first, over the client's life."""
        with self._lock:
            return self._retries

    # --- Sessions ---------------------------------------------------------------------

    def create_session(self, config: Optional[pb.SessionConfig] = None, *,
                       seed: Optional[int] = None,
                       feature_dimension: Optional[int] = None) -> Session:
        """A new session; ``seed`` and ``feature_dimension`` override ``config``'s.

        Example::

            session = client.create_session(seed=1)                       # clouds
            features = client.create_session(feature_dimension=2)          # features only
            paper = client.create_session(relmap.pb.SessionConfig(
                classifier=relmap.pb.ClassifierConfig(variant=relmap.pb.CLASSIFIER_VARIANT_PAPER2018)))
        """
        request_config = pb.SessionConfig()
        if config is not None:
            request_config.CopyFrom(config)
        if seed is not None:
            request_config.seed = seed
        if feature_dimension is not None:
            request_config.feature_dimension = feature_dimension
        response = self._invoke("CreateSession", self._stub.CreateSession,
                                pb.CreateSessionRequest(config=request_config),
                                idempotent=False, metadata=self._admin_metadata())
        return Session(response.session_id, response.session_token, response.config)

    def get_session(self, session: Session) -> pb.GetSessionResponse:
        """The session's configuration and statistics (``.stats.moveable_samples``, ...)."""
        return self._invoke("GetSession", self._stub.GetSession,
                            pb.GetSessionRequest(session_id=session.id),
                            idempotent=True, metadata=_session_metadata(session))

    def list_sessions(self) -> List[pb.GetSessionResponse]:
        """Every session of the server, following the pages."""
        sessions: List[pb.GetSessionResponse] = []
        token = ""
        while True:
            page = self.list_sessions_page(page_token=token)
            sessions.extend(page.sessions)
            token = page.next_page_token
            if not token:
                return sessions

    def list_sessions_page(self, page_size: int = 0, page_token: str = "") -> pb.ListSessionsResponse:
        """One page of the sessions, ordered by id (page_size 0 means 100)."""
        return self._invoke("ListSessions", self._stub.ListSessions,
                            pb.ListSessionsRequest(page_size=page_size, page_token=page_token),
                            idempotent=True, metadata=self._admin_metadata())

    def delete_session(self, session: Session) -> None:
        """Deletes the session and everything it learned (with the admin key, on a server
        started with one). Not retried after a broken connection: a repeat after a lost
        answer would say NOT_FOUND."""
        self._invoke("DeleteSession", self._stub.DeleteSession,
                     pb.DeleteSessionRequest(session_id=session.id), idempotent=False,
                     metadata=_session_metadata(session) + self._admin_metadata())

    def export_session(self, session: Session) -> pb.ExportSessionResponse:
        """The whole state of the session (``.state``: config, samples, RNG) and its stats."""
        return self._invoke("ExportSession", self._stub.ExportSession,
                            pb.ExportSessionRequest(session_id=session.id),
                            idempotent=True, metadata=_session_metadata(session))

    def import_session(self, state: pb.SessionState) -> Session:
        """A new session (new id and token) that relearns an exported state.

        Example::

            state = client.export_session(session).state
            copy = client.import_session(state)
        """
        response = self._invoke("ImportSession", self._stub.ImportSession,
                                pb.ImportSessionRequest(state=state), idempotent=False,
                                metadata=self._admin_metadata())
        return Session(response.session_id, response.session_token, state.config)

    # --- Clouds -----------------------------------------------------------------------

    def compute_maps(self, session: Session, cloud: CloudLike, *, point_labels: bool = True,
                     features: bool = False, repeat_after_broken_connection: bool = False) -> Maps:
        """Segments ``cloud`` (numpy points, a PCD path or bytes, or a Cloud; see
        relmap.cloud) into supervoxels and returns their relevance and choice maps and
        the next push target. ``point_labels=False`` leaves out each point's supervoxel
        id (most of the answer's bytes); ``features=True`` adds the 48 features.

        Not repeated after a broken connection unless asked: a repeat of a frame that
        was computed draws another target, so a seeded run would no longer replay.

        Example::

            points = np.zeros((480, 640), dtype=relmap.POINT_DTYPE)   # or N×6 x,y,z,r,g,b
            maps = client.compute_maps(session, points, point_labels=False)
            maps.target, maps.relevance[maps.target]                  # (17, 0.5)
        """
        request = pb.ComputeMapsRequest(session_id=session.id, cloud=to_cloud(cloud),
                                        omit_point_labels=not point_labels,
                                        include_features=features)
        response = self._invoke("ComputeMaps", self._stub.ComputeMaps, request,
                                idempotent=repeat_after_broken_connection,
                                metadata=_session_metadata(session))
        return Maps.from_response(response, point_labels, features)

    def post_outcome(self, session: Session, frame_id: int, supervoxel_id: int, *,
                     moved: Optional[bool] = None, after_cloud: Optional[CloudLike] = None,
                     moved_with_target: Sequence[int] = (), same_object: Sequence[int] = (),
                     request_id: Optional[str] = None) -> pb.PostOutcomeResponse:
        """Teaches the session what pushing ``supervoxel_id`` of frame ``frame_id`` did:
        either the client's own label (``moved``) or the cloud after the push, which the
        server's change detector labels (``.evidence`` says what it saw).
        ``moved_with_target`` names other supervoxels of the frame the push moved with
        the target (the rest of the pushed object): each is learned as moveable after it
        (``.moved_learned`` counts the usable ones). ``same_object`` names the other
        supervoxels of the target's rigid object, moved or not: each is learned with the
        target's label (``.object_learned``); a supervoxel in both lists, or the target in
        either, is refused. The server deduplicates on
        ``request_id`` (a random one by default), so the call is retried safely. A frame
        the session no longer has raises RelmapError with reason FRAME_GONE
        (``error.is_frame_gone``): nothing was learned.

        Example::

            answer = client.post_outcome(session, maps.frame_id, maps.target, moved=False)
            answer.stats.non_moveable_samples                         # 1
            answer = client.post_outcome(session, maps.frame_id, 4, moved=True,
                                         moved_with_target=[5, 9])
            answer.stats.moveable_samples, answer.moved_learned       # (3, 2)
            answer = client.post_outcome(session, maps.frame_id, 7, moved=False,
                                         same_object=[8])
            answer.stats.non_moveable_samples, answer.object_learned  # (3, 1)
        """
        if (moved is None) == (after_cloud is None):
            raise ValueError("post_outcome needs exactly one of moved and after_cloud")
        request = pb.PostOutcomeRequest(session_id=session.id, frame_id=frame_id,
                                        supervoxel_id=supervoxel_id,
                                        moved_supervoxels=list(moved_with_target),
                                        object_supervoxels=list(same_object),
                                        request_id=request_id or random_request_id())
        if after_cloud is not None:
            request.after_cloud.CopyFrom(to_cloud(after_cloud))
        else:
            request.label = _label(bool(moved))
        return self._invoke("PostOutcome", self._stub.PostOutcome, request, idempotent=True,
                            metadata=_session_metadata(session))

    # --- Features ---------------------------------------------------------------------

    def classify_features(self, session: Session, features: np.ndarray) -> Classification:
        """Relevance and choice of feature vectors (N×D, D the session's dimension).

        Example::

            result = client.classify_features(session, np.array([[0.1, 0.9], [0.8, 0.2]]))
            result.relevance, result.choice
        """
        request = pb.ClassifyFeaturesRequest(session_id=session.id,
                                             features=_feature_vectors(features))
        response = self._invoke("ClassifyFeatures", self._stub.ClassifyFeatures, request,
                                idempotent=True, metadata=_session_metadata(session))
        return Classification(np.array(response.relevance, dtype=np.float64),
                              np.array(response.choice, dtype=np.float64))

    def add_samples(self, session: Session, features: np.ndarray, moveable: Sequence[bool],
                    *, request_id: Optional[str] = None) -> pb.SessionStats:
        """Learns labelled feature vectors in order (N×D, and N labels: true = moveable).
        Deduplicated on ``request_id`` (a random one by default), so retried safely.

        Example::

            stats = client.add_samples(session, np.array([[0.1, 0.9], [0.8, 0.2]]), [True, False])
            stats.moveable_samples, stats.non_moveable_samples        # (1, 1)
        """
        vectors = _feature_vectors(features)
        labels = np.asarray(moveable)
        if labels.ndim != 1 or labels.shape[0] != len(vectors):
            raise ValueError(f"{len(vectors)} feature vectors need as many labels, got shape {labels.shape}")
        if labels.dtype != np.bool_ and not np.all(np.isin(labels, (0, 1))):
            raise ValueError("labels must be booleans or 0/1")
        samples = [pb.LabelledFeature(feature=vector, label=_label(bool(label)))
                   for vector, label in zip(vectors, labels)]
        request = pb.AddSamplesRequest(session_id=session.id, samples=samples,
                                       request_id=request_id or random_request_id())
        response = self._invoke("AddSamples", self._stub.AddSamples, request, idempotent=True,
                                metadata=_session_metadata(session))
        return response.stats

    # --- Health -----------------------------------------------------------------------

    def check_health(self, service: str = "") -> str:
        """grpc.health.v1.Health/Check: "SERVING", or "NOT_SERVING" from a server that
        drains before it stops. ``service`` "" is the whole server, as is
        "relmap.v1.RelevanceService"; other names raise RelmapError NOT_FOUND."""
        response = self._invoke("Health/Check", self._health,
                                health_pb2.HealthCheckRequest(service=service),
                                idempotent=True, metadata=[])
        return health_pb2.HealthCheckResponse.ServingStatus.Name(response.status)

    # --- Plumbing ---------------------------------------------------------------------

    def _invoke(self, name: str, method: Callable[..., Any], request: Any, *, idempotent: bool,
                metadata: Metadata) -> Any:
        """One logical call of ``method`` through the retry loop, which owns the deadline."""
        return call_with_retries(
            lambda timeout: method(request, timeout=timeout, metadata=metadata),
            name=name, idempotent=idempotent, deadline=self.deadline, policy=self.retry,
            on_retry=self._count_retry)

    def _count_retry(self) -> None:
        with self._lock:
            self._retries += 1

    def _admin_metadata(self) -> Metadata:
        return [("x-relmap-admin-key", self.admin_key)] if self.admin_key else []


def _session_metadata(session: Session) -> Metadata:
    """The bearer token, and the id as x-relmap-session for load balancers that route
    by session."""
    return [("authorization", f"Bearer {session.token}"), ("x-relmap-session", session.id)]


def _label(moved: bool) -> int:
    return pb.LABEL_MOVEABLE if moved else pb.LABEL_NOT_MOVEABLE


def _feature_vectors(features: np.ndarray) -> List[pb.FeatureVector]:
    array = np.asarray(features, dtype=np.float64)
    if array.ndim != 2:
        raise ValueError(f"features must be N×D, got shape {array.shape}")
    return [pb.FeatureVector(values=row) for row in array.tolist()]
