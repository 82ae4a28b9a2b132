"""A relmap-server child process for programs and tests that run their own, as the C++
client's LocalServer does (client/local_server.h): loopback, a port of the kernel's
choosing, a temporary directory for its data and port file (removed when it stops), its
output in a log file. Stopped with SIGTERM, so it drains its calls."""

from __future__ import annotations

import os
import pathlib
import shutil
import subprocess
import tempfile
import time
from typing import Any, Optional, Sequence

_START_SECONDS = 15.0  # to write its port file
_STOP_SECONDS = 15.0  # it drains calls for at most 10 s: past that it is hung


class LocalServer:
    """A running relmap-server on 127.0.0.1.

    Example::

        with relmap.LocalServer.start("build/server/relmap-server") as server:
            with relmap.Client(server.address) as client:
                session = client.create_session(seed=1)
    """

    def __init__(self, process: "subprocess.Popen[bytes]", directory: pathlib.Path,
                 log_path: pathlib.Path, port: int) -> None:
        self.process = process
        self.directory = directory
        self.log_path = log_path
        self.address = f"127.0.0.1:{port}"

    @classmethod
    def start(cls, binary: str, arguments: Sequence[str] = (), *, memory_only: bool = False,
              log_path: Optional[str] = None) -> "LocalServer":
        """Starts ``binary`` with ``arguments`` added to its flags; ``memory_only`` gives it
        no --data-dir. FileNotFoundError when it is not executable; RuntimeError, with its
        log, when it exits or has not written its port within 15 s."""
        if not os.access(binary, os.X_OK):
            raise FileNotFoundError(f"no executable relmap-server at {binary}")
        directory = pathlib.Path(tempfile.mkdtemp(prefix="relmap-server-"))
        port_file = directory / "port"
        log = pathlib.Path(log_path) if log_path else directory / "server.log"
        command = [binary, "--listen", "127.0.0.1:0", "--port-file", str(port_file)]
        if not memory_only:
            command += ["--data-dir", str(directory / "data")]
        with open(log, "wb") as output:
            process = subprocess.Popen(command + list(arguments), stdin=subprocess.DEVNULL,
                                       stdout=output, stderr=subprocess.STDOUT)
        end = time.monotonic() + _START_SECONDS
        while time.monotonic() < end:
            text = port_file.read_text().strip() if port_file.exists() else ""
            if text.isdigit() and int(text) > 0:
                return cls(process, directory, log, int(text))
            if process.poll() is not None:
                break
            time.sleep(0.02)
        exited = process.poll()
        why = (f"exited at start-up with status {exited}" if exited is not None
               else f"has not written its port within {_START_SECONDS:.0f} s")
        if exited is None:
            process.kill()
        process.wait()
        # Its first lines say why (a bad flag comes before the usage), its last ones what
        # it did last.
        text = log.read_bytes()
        if len(text) > 3000:
            text = text[:1000] + b"\n...\n" + text[-2000:]
        shutil.rmtree(directory, ignore_errors=True)
        raise RuntimeError(f"{binary} {why}; its log:\n{text.decode('utf-8', 'replace')}")

    @property
    def pid(self) -> int:
        """The server's process id."""
        return self.process.pid

    def kill(self) -> None:
        """SIGKILL, as a crash would end it; its directory stays until stop()."""
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()

    def stop(self) -> int:
        """SIGTERM and a wait, SIGKILL if it has not ended within 15 s; removes its
        directory. The exit status (negative: the signal that ended it)."""
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=_STOP_SECONDS)
            except subprocess.TimeoutExpired:
                self.kill()
        shutil.rmtree(self.directory, ignore_errors=True)
        return self.process.returncode

    def __enter__(self) -> "LocalServer":
        return self

    def __exit__(self, *exc_info: Any) -> None:
        self.stop()
