"""The retry policy, the C++ client's (client/retry.cpp): which failures are repeated,
the pushback trailer and the backoff, with hand-computed waits."""

from __future__ import annotations

from typing import List

import grpc
import pytest

import relmap
from relmap import retry
from relmap._rpc import error_details_pb2, status_pb2
from relmap.v1 import error_reason_pb2

CODE = grpc.StatusCode


def test_busy_and_owned_elsewhere_are_retried_whatever_the_call():
    for reason in (error_reason_pb2.BUSY, error_reason_pb2.SESSION_OWNED_ELSEWHERE):
        assert retry.is_retryable(CODE.RESOURCE_EXHAUSTED, "", reason, idempotent=False)


def test_a_broken_connection_is_retried_for_idempotent_calls_only():
    unspecified = error_reason_pb2.ERROR_REASON_UNSPECIFIED
    assert retry.is_retryable(CODE.UNAVAILABLE, "", unspecified, idempotent=True)
    assert not retry.is_retryable(CODE.UNAVAILABLE, "", unspecified, idempotent=False)
    assert retry.is_retryable(CODE.UNAVAILABLE, "", unspecified, idempotent=False, pushback=True)


def test_the_servers_answers_are_final():
    unspecified = error_reason_pb2.ERROR_REASON_UNSPECIFIED
    for code in (CODE.INVALID_ARGUMENT, CODE.PERMISSION_DENIED, CODE.NOT_FOUND,
                 CODE.FAILED_PRECONDITION, CODE.DEADLINE_EXCEEDED):
        assert not retry.is_retryable(code, "", unspecified, idempotent=True)
    # relmap's own RESOURCE_EXHAUSTED (an oversized cloud) is final; gRPC's full pool is not.
    assert not retry.is_retryable(CODE.RESOURCE_EXHAUSTED, "too many points", unspecified, True)
    assert retry.is_retryable(CODE.RESOURCE_EXHAUSTED, "Server Threadpool Exhausted", unspecified, False)


def test_pushback_trailer_in_seconds_and_nonsense_ignored():
    assert retry.pushback_of([("grpc-retry-pushback-ms", "250")]) == 0.25
    assert retry.pushback_of([("grpc-retry-pushback-ms", b"1500")]) == 1.5
    assert retry.pushback_of([("grpc-retry-pushback-ms", "")]) == 0.0  # as client/retry.cpp
    assert retry.pushback_of([("grpc-retry-pushback-ms", "-1")]) is None
    assert retry.pushback_of([("grpc-retry-pushback-ms", "\u0665")]) is None  # Arabic-Indic 5
    assert retry.pushback_of([("grpc-retry-pushback-ms", "99999999")]) is None  # > an hour
    assert retry.pushback_of([("other", "5")]) is None


def test_backoff_doubles_from_50_ms_to_the_2_s_cap_with_jitter():
    policy = relmap.RetryPolicy()
    # attempt 2: 0.05 s × (0.5 + 0) ; attempt 4: 0.05 × 2² × (0.5 + 0.5) = 0.2 s
    assert retry.backoff_before(2, policy, 0.0) == pytest.approx(0.025)
    assert retry.backoff_before(4, policy, 0.5) == pytest.approx(0.2)
    # attempt 8: 0.05 × 2⁶ = 3.2 s, capped at 2 s, × 1.5 (the top of the jitter)
    assert retry.backoff_before(8, policy, 1.0) == pytest.approx(3.0)


class FakeRpcError(grpc.RpcError):
    def __init__(self, code: grpc.StatusCode, trailers=()):
        self._code, self._trailers = code, tuple(trailers)

    def code(self):
        return self._code

    def details(self):
        return "fake"

    def trailing_metadata(self):
        return self._trailers


def busy_trailers(pushback_ms: str):
    info = error_details_pb2.ErrorInfo(domain="relmap.v1", reason="BUSY",
                                       metadata={"retryAfterMs": pushback_ms})
    status = status_pb2.Status(code=8)
    status.details.add().Pack(info)
    return [("grpc-status-details-bin", status.SerializeToString()),
            ("grpc-retry-pushback-ms", pushback_ms)]


def test_attempts_stop_at_max_attempts_and_pushbacks_do_not_count():
    failures: List[FakeRpcError] = [FakeRpcError(CODE.RESOURCE_EXHAUSTED, busy_trailers("1"))] * 6
    failures += [FakeRpcError(CODE.UNAVAILABLE)] * 10
    calls = []

    def attempt(timeout):
        calls.append(timeout)
        raise failures[len(calls) - 1]

    policy = relmap.RetryPolicy(max_attempts=3, initial_backoff=0.001, max_backoff=0.002)
    with pytest.raises(relmap.RelmapError) as raised:
        retry.call_with_retries(attempt, name="Test", idempotent=True, deadline=10, policy=policy)
    assert len(calls) == 6 + 3  # six pushbacks, then three counted attempts
    assert raised.value.code == CODE.UNAVAILABLE
    assert all(0 < timeout <= 10 for timeout in calls)


def test_the_reason_reaches_the_exception():
    def attempt(timeout):
        raise FakeRpcError(CODE.RESOURCE_EXHAUSTED, busy_trailers("5000"))

    with pytest.raises(relmap.RelmapError) as raised:  # the 5 s pushback passes the 1 s deadline
        retry.call_with_retries(attempt, name="Test", idempotent=False, deadline=1.0,
                                policy=relmap.RetryPolicy())
    assert raised.value.reason == relmap.BUSY
    assert raised.value.reason_name == "BUSY"
    assert raised.value.metadata == {"retryAfterMs": "5000"}


def test_an_unknown_reason_is_treated_like_none():
    info = error_details_pb2.ErrorInfo(domain="relmap.v1", reason="SOMETHING_NEW")
    status = status_pb2.Status()
    status.details.add().Pack(info)
    error = relmap.RelmapError.from_rpc_error(
        FakeRpcError(CODE.INTERNAL, [("grpc-status-details-bin", status.SerializeToString())]))
    assert error.reason == relmap.ERROR_REASON_UNSPECIFIED
    assert error.error_info.reason == "SOMETHING_NEW"
