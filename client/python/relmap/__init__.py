"""relmap: the Python client of relmap-server (proto/relmap/v1/relevance_service.proto).

Example::

    import relmap
    client = relmap.Client("127.0.0.1:50051")
    session = client.create_session(seed=1)
    maps = client.compute_maps(session, relmap.read_pcd("scene.pcd"))
    client.post_outcome(session, maps.frame_id, maps.target, moved=True)

See client/python/README.md for the whole API.
"""

from relmap.client import Client, random_request_id
from relmap.cloud import POINT_DTYPE, CloudLike, as_points, packed_cloud, pcd_cloud, to_cloud
from relmap.errors import RelmapError
from relmap.local_server import LocalServer
from relmap.pcd import format_pcd, parse_pcd, read_pcd, write_pcd
from relmap.results import Classification, Maps, Session
from relmap.retry import RetryPolicy
from relmap.v1 import relevance_service_pb2 as pb
from relmap.v1.error_reason_pb2 import (BUSY, ERROR_REASON_UNSPECIFIED, FRAME_GONE,
                                        SESSION_OWNED_ELSEWHERE)

__all__ = [
    "BUSY", "Classification", "Client", "CloudLike", "ERROR_REASON_UNSPECIFIED", "FRAME_GONE",
    "LocalServer", "Maps", "POINT_DTYPE", "RelmapError", "RetryPolicy", "SESSION_OWNED_ELSEWHERE", "Session",
    "as_points", "format_pcd", "packed_cloud", "parse_pcd", "pb", "pcd_cloud", "random_request_id",
    "read_pcd", "to_cloud", "write_pcd",
]
