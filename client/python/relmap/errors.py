"""relmap's errors as Python exceptions: the gRPC code and the server's reason.

relmap-server puts the machine-readable reason of an error a client acts on in the
status details (the ``grpc-status-details-bin`` trailer: a google.rpc.Status holding
a google.rpc.ErrorInfo of domain "relmap.v1"; proto/relmap/v1/error_reason.proto).
Decide by :attr:`RelmapError.reason`, never by the message.
"""

from __future__ import annotations

from typing import Mapping, Optional, Sequence, Tuple, Union

import grpc

from relmap._rpc import error_details_pb2, status_pb2
from relmap.v1 import error_reason_pb2

DOMAIN = "relmap.v1"
DETAILS_KEY = "grpc-status-details-bin"

Metadata = Sequence[Tuple[str, Union[str, bytes]]]


def error_info_of(trailing_metadata: Optional[Metadata]) -> Optional[error_details_pb2.ErrorInfo]:
    """The ErrorInfo of domain "relmap.v1" in a failed call's trailers, if any."""
    for key, value in trailing_metadata or ():
        if key != DETAILS_KEY or not isinstance(value, bytes):
            continue
        details = status_pb2.Status()
        try:
            details.ParseFromString(value)
        except Exception:  # noqa: BLE001 - a trailer that does not parse carries no reason
            return None
        for detail in details.details:
            info = error_details_pb2.ErrorInfo()
            if detail.Unpack(info) and info.domain == DOMAIN:
                return info
    return None


def reason_of(info: Optional[error_details_pb2.ErrorInfo]) -> int:
    """The ErrorReason value of ``info``: ERROR_REASON_UNSPECIFIED without one, and for
    a reason this package does not know (a newer server's), as the C++ client does."""
    if info is None:
        return error_reason_pb2.ERROR_REASON_UNSPECIFIED
    try:
        return error_reason_pb2.ErrorReason.Value(info.reason)
    except ValueError:
        return error_reason_pb2.ERROR_REASON_UNSPECIFIED


class RelmapError(Exception):
    """A failed call: its gRPC code, the server's message and the reason, if any.

    Example::

        try:
            client.post_outcome(session, frame_id=1, supervoxel_id=3, moved=True)
        except relmap.RelmapError as error:
            if error.reason == relmap.FRAME_GONE:
                ...  # nothing was learned: go on from new maps
            else:
                raise
    """

    def __init__(self, code: grpc.StatusCode, message: str,
                 error_info: Optional[error_details_pb2.ErrorInfo] = None, call: str = "") -> None:
        self.code = code
        self.message = message
        self.error_info = error_info
        self.reason = reason_of(error_info)
        self.call = call
        super().__init__(str(self))

    @classmethod
    def from_rpc_error(cls, error: grpc.RpcError, call: str = "") -> "RelmapError":
        """The exception for a grpc.RpcError raised by a stub (a grpc.Call)."""
        trailers = error.trailing_metadata() if hasattr(error, "trailing_metadata") else None
        code = error.code() if hasattr(error, "code") else grpc.StatusCode.UNKNOWN
        message = error.details() if hasattr(error, "details") else str(error)
        return cls(code, message or "", error_info_of(trailers), call)

    @property
    def reason_name(self) -> str:
        """The reason as the proto names it ("FRAME_GONE"), "" without one."""
        if self.reason == error_reason_pb2.ERROR_REASON_UNSPECIFIED:
            return ""
        return error_reason_pb2.ErrorReason.Name(self.reason)

    @property
    def metadata(self) -> Mapping[str, str]:
        """The reason's metadata (e.g. "sessionId", "frameId" of FRAME_GONE)."""
        return dict(self.error_info.metadata) if self.error_info is not None else {}

    @property
    def is_frame_gone(self) -> bool:
        """PostOutcome named a frame the session no longer has: nothing was learned."""
        return self.reason == error_reason_pb2.FRAME_GONE

    def __str__(self) -> str:
        where = f"{self.call}: " if self.call else ""
        reason = f", reason {self.reason_name}" if self.reason_name else ""
        return f"{where}{self.message} (code {self.code.name}{reason})"
