"""LZF decompression (liblzf's format), for PCD files saved as binary_compressed."""

from __future__ import annotations


def decompress(data: bytes, size: int) -> bytes:
    """The ``size`` bytes that ``data`` expands to; ValueError if it does not.

    Each control byte is either a literal run (below 32: that many + 1 bytes follow)
    or a back-reference (length in its top 3 bits, 7 meaning "plus the next byte",
    + 2; distance in its low 5 bits and the next byte, + 1). A reference may overlap
    the bytes it produces: it then repeats the last ``distance`` bytes periodically.
    """
    out = bytearray(size)
    ip = op = 0
    n = len(data)
    while ip < n:
        control = data[ip]
        ip += 1
        if control < 32:
            length = control + 1
            if ip + length > n or op + length > size:
                raise ValueError("LZF: literal run past the end")
            out[op:op + length] = data[ip:ip + length]
            ip += length
            op += length
            continue
        length = control >> 5
        if length == 7:
            if ip >= n:
                raise ValueError("LZF: truncated reference")
            length += data[ip]
            ip += 1
        if ip >= n:
            raise ValueError("LZF: truncated reference")
        ref = op - ((control & 0x1F) << 8) - data[ip] - 1
        ip += 1
        length += 2
        if ref < 0 or op + length > size:
            raise ValueError("LZF: reference out of range")
        distance = op - ref
        if distance >= length:
            out[op:op + length] = out[ref:ref + length]
        else:
            period = bytes(out[ref:op])
            out[op:op + length] = (period * (length // distance + 1))[:length]
        op += length
    if op != size:
        raise ValueError(f"LZF: {op} bytes decompressed, the header says {size}")
    return bytes(out)
