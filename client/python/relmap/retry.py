"""When a failed call may be sent again, and how long to wait: the C++ client's policy
(client/retry.h, client/client_options.h), the same codes, reasons and backoff."""

from __future__ import annotations

import dataclasses
import random
import time
from typing import Callable, Optional, TypeVar

import grpc

from relmap.errors import Metadata, RelmapError
from relmap.v1 import error_reason_pb2

T = TypeVar("T")

PUSHBACK_KEY = "grpc-retry-pushback-ms"
# gRPC's own text for a sync server with no worker thread left: no handler ran, so the
# server could give no reason (src/cpp/server/server_cc.cc).
THREADPOOL_EXHAUSTED = "Server Threadpool Exhausted"
_NOT_NOW = (grpc.StatusCode.RESOURCE_EXHAUSTED, grpc.StatusCode.UNAVAILABLE)


@dataclasses.dataclass(frozen=True)
class RetryPolicy:
    """Attempts per call, the first included (1 = never retry), and the backoff before
    the second attempt, doubled each time up to ``max_backoff``, times a jitter factor
    in [0.5, 1.5). A busy server's answers with a pushback do not count as attempts:
    those are repeated until the deadline. The C++ client's defaults."""

    max_attempts: int = 5
    initial_backoff: float = 0.05  # seconds
    max_backoff: float = 2.0  # seconds


def is_retryable(code: grpc.StatusCode, message: str, reason: int, idempotent: bool,
                 pushback: bool = False) -> bool:
    """Whether a failed call may be repeated: the server provably did not run it (its
    reason BUSY or SESSION_OWNED_ELSEWHERE; a pushback trailer on RESOURCE_EXHAUSTED or
    UNAVAILABLE; gRPC's "Server Threadpool Exhausted"), or, for idempotent calls only,
    the connection failed (UNAVAILABLE) and the call may or may not have run."""
    if reason in (error_reason_pb2.BUSY, error_reason_pb2.SESSION_OWNED_ELSEWHERE):
        return True
    if pushback and code in _NOT_NOW:
        return True
    if code == grpc.StatusCode.RESOURCE_EXHAUSTED and message == THREADPOOL_EXHAUSTED:
        return True
    return code == grpc.StatusCode.UNAVAILABLE and idempotent


def pushback_of(trailing_metadata: Optional[Metadata]) -> Optional[float]:
    """The server's grpc-retry-pushback-ms trailer in seconds, if the call ended with one
    (ASCII digits only, at most about an hour; anything else is not a pushback). Parsed
    digit by digit as client/retry.cpp does, so that both clients read a trailer alike."""
    for key, value in trailing_metadata or ():
        if key != PUSHBACK_KEY:
            continue
        text = value.decode("ascii", "replace") if isinstance(value, bytes) else value
        milliseconds = 0
        for digit in text:
            if digit not in "0123456789" or milliseconds > 3_600_000:
                return None
            milliseconds = milliseconds * 10 + int(digit)
        return milliseconds / 1000.0
    return None


def backoff_before(attempt: int, policy: RetryPolicy, unit_random: float) -> float:
    """The wait before attempt ``attempt`` (2, 3, ...), in seconds:
    initial_backoff · 2^(attempt−2), capped at max_backoff, times (0.5 + unit_random)."""
    doublings = min(max(attempt - 2, 0), 30)
    base = min(policy.initial_backoff * float(1 << doublings), policy.max_backoff)
    return base * (0.5 + unit_random)


def call_with_retries(attempt: Callable[[float], T], *, name: str, idempotent: bool,
                      deadline: float, policy: RetryPolicy,
                      on_retry: Callable[[], None] = lambda: None) -> T:
    """One logical call: ``attempt(timeout)`` (one RPC, given the seconds left of the
    call's ``deadline`` in seconds) until it succeeds, fails for good, runs out of
    attempts or its next wait would pass the deadline. Raises RelmapError."""
    end = time.monotonic() + deadline
    attempts = 0  # pushbacks excepted: those are repeated until the deadline
    call = 1
    while True:
        try:
            return attempt(max(end - time.monotonic(), 0.0))
        except grpc.RpcError as rpc_error:
            error = RelmapError.from_rpc_error(rpc_error, name)
            trailers = rpc_error.trailing_metadata() if hasattr(rpc_error, "trailing_metadata") else None
        pushback = pushback_of(trailers)
        if not is_retryable(error.code, error.message, error.reason, idempotent,
                            pushback is not None):
            raise error
        if pushback is None:
            attempts += 1
            if attempts >= policy.max_attempts:
                raise error
        call += 1
        wait = max(pushback or 0.0, backoff_before(call, policy, random.random()))
        if time.monotonic() + wait >= end:
            raise error
        time.sleep(wait)
        on_retry()
