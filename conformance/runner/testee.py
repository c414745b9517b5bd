"""A testee process that cannot take the runner down with it.

- Each request carries an ``id``. A testee may echo it in its answer; an answer with another id
  is a stray and fails the request it was read for. After each case the runner sends
  ``{"op": "sync", "id": N}`` (an op no testee has: it answers ``{"skipped": true}``) and reads
  up to that answer: any line before it is a surplus answer of that case, which fails it, and the
  testee is restarted so that no later case reads a shifted answer.
- Each testee has its own queue, fed only by its own reader thread: a killed testee's thread
  cannot put its end-of-output into its successor's queue.
- A testee runs in its own process group (its own session); on a timeout, on a surplus answer
  and when the runner exits, the whole group is killed: a wrapper script's children go too.
- An answer line holds at most ``MAX_ANSWER`` bytes before its newline (64 MiB; the canonical
  JSON of the largest golden case is about 11 MiB): a longer one fails the request, unread
  beyond the limit, and the testee is killed.
"""

from __future__ import annotations

import atexit
import json
import os
import queue
import signal
import subprocess
import sys
import threading
import time
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

MAX_ANSWER = 64 * 1024 * 1024  # bytes of one answer line (PROTOCOL.md, "Answers")
_EOF, _OVERSIZE = b"", b"\0oversize"
_LIVE: weakref.WeakSet[Testee] = weakref.WeakSet()
CAPABILITIES = ("decode", "validate", "encode")  # the protocol's operations, in the order a case runs them


class TesteeError(RuntimeError):
    """A request the testee did not answer properly: the case fails with this message."""


class TesteeTimeout(TesteeError):
    pass


@dataclass
class Binding:
    name: str
    command: list[str]
    env: dict[str, str] = field(default_factory=dict)
    requires: list[str] = field(default_factory=list)
    cwd: Path = Path.cwd()
    # the protocol operations the testee offers (decode, validate, encode): only these are asked, and
    # each must be answered (PROTOCOL.md, "Capabilities")
    capabilities: tuple[str, ...] = CAPABILITIES

    def missing(self) -> list[str]:
        return [r for r in self.requires if not (self.cwd / r).exists()]


def _pump(out: IO[bytes], lines: queue.Queue[bytes], limit: int, stop: threading.Event) -> None:
    """Read answer lines into this testee's own queue; at most ``limit`` bytes a line are held."""

    def put(item: bytes) -> bool:
        while not stop.is_set():
            try:
                lines.put(item, timeout=0.2)
                return True
            except queue.Full:
                continue
        return False

    try:
        while True:
            line = out.readline(limit + 1)
            if len(line) > limit and not line.endswith(b"\n"):
                put(_OVERSIZE)
                return
            if not put(line) or not line:
                return
    except (OSError, ValueError):
        put(_EOF)


class Testee:
    """A testee process, started once (and again after it dies or misbehaves), one JSON line per request."""

    def __init__(self, binding: Binding, timeout: float, max_answer: int = MAX_ANSWER,
                 expand: Callable[[str], str] = lambda s: s) -> None:
        self.binding = binding
        self.timeout = timeout
        self.max_answer = max_answer
        self.expand = expand
        self.deadline: float | None = None  # monotonic time after which no request waits
        self.proc: subprocess.Popen[bytes] | None = None
        self.lines: queue.Queue[bytes] = queue.Queue(maxsize=2)
        self._stop = threading.Event()
        self.next_id = 0
        self.consecutive_timeouts = 0
        _LIVE.add(self)

    def start(self) -> None:
        env = dict(os.environ)
        env.update({k: self.expand(v) for k, v in self.binding.env.items()})
        cmd = [self.expand(c) for c in self.binding.command]
        self.proc = subprocess.Popen(cmd, cwd=self.binding.cwd, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=sys.stderr, start_new_session=True)
        self.lines, self._stop = queue.Queue(maxsize=2), threading.Event()
        assert self.proc.stdout is not None
        threading.Thread(target=_pump, args=(self.proc.stdout, self.lines, self.max_answer, self._stop),
                         daemon=True).start()

    def _send(self, request: dict[str, Any]) -> int:
        if self.proc is None or self.proc.poll() is not None:
            self.kill()
            self.start()
        assert self.proc is not None and self.proc.stdin is not None
        self.next_id += 1
        try:
            self.proc.stdin.write((json.dumps({**request, "id": self.next_id}) + "\n").encode())
            self.proc.stdin.flush()
        except (BrokenPipeError, OSError) as exc:
            self.kill()
            raise TesteeError(f"testee died ({type(exc).__name__})") from None
        return self.next_id

    def _wait(self) -> float:
        left = self.timeout if self.deadline is None else min(self.timeout, self.deadline - time.monotonic())
        return max(left, 0.0)

    def _read(self) -> bytes:
        wait = self._wait()
        try:
            line = self.lines.get(timeout=wait)
        except queue.Empty:
            self.kill()  # it did not answer this request: it will not answer quit either
            self.consecutive_timeouts += 1
            raise TesteeTimeout(f"testee gave no answer within {wait:g} s") from None
        self.consecutive_timeouts = 0
        if line is _OVERSIZE:
            self.kill()
            raise TesteeError(f"testee wrote an answer line longer than {self.max_answer} bytes")
        if not line:
            self.kill()
            raise TesteeError("testee exited")
        return line

    @staticmethod
    def _parse(line: bytes) -> dict[str, Any]:
        try:
            answer = json.loads(line)
        except (json.JSONDecodeError, UnicodeDecodeError):
            raise TesteeError(f"testee wrote a line that is not JSON: {line[:80]!r}") from None
        if not isinstance(answer, dict):
            raise TesteeError("testee answered with something other than an object")
        return answer

    def ask(self, request: dict[str, Any]) -> dict[str, Any]:
        rid = self._send(request)
        answer = self._parse(self._read())
        got = answer.pop("id", rid)
        if got != rid:
            self.kill()  # its answers are out of step: start afresh for the next case
            raise TesteeError(f"answer to request {got!r} read for request {rid} (a stray or surplus answer)")
        return answer

    def many(self, requests: list[dict[str, Any]]) -> list[dict[str, Any]]:
        """Answers to a batch of requests sent at once (the reliability campaign): a thread writes
        them while this one reads, so neither pipe can fill up and stall the other."""
        if self.proc is None or self.proc.poll() is not None:
            self.kill()
            self.start()
        assert self.proc is not None and self.proc.stdin is not None
        first = self.next_id + 1
        self.next_id += len(requests)
        data = "".join(json.dumps({**r, "id": first + k}) + "\n" for k, r in enumerate(requests)).encode()
        stdin = self.proc.stdin

        def write() -> None:
            try:
                stdin.write(data)
                stdin.flush()
            except OSError:
                pass  # it died: the reads below say so

        writer = threading.Thread(target=write, daemon=True)
        writer.start()
        out = []
        for k in range(len(requests)):
            answer = self._parse(self._read())
            if answer.pop("id", first + k) != first + k:
                self.kill()
                raise TesteeError(f"{self.binding.name}: answers out of step at request {first + k}")
            out.append(answer)
        writer.join()
        return out

    def drain(self) -> str | None:
        """After a case: None when the testee answered nothing beyond its requests; else why the
        case fails (a surplus answer), the testee then killed so the next case starts clean."""
        if self.proc is None or self.proc.poll() is not None:
            surplus = self._leftover()
            self.kill()
            return surplus
        try:
            rid = self._send({"op": "sync"})
            line = self._read()
        except TesteeError:
            return None  # it died or hung after its last answer: the next case restarts it
        try:
            answer = self._parse(line)
        except TesteeError:
            answer = {"line": line.decode("utf-8", "replace")}
        if answer.get("id", rid) == rid and {k: v for k, v in answer.items() if k != "id"} == {"skipped": True}:
            return None
        self.kill()
        return f"surplus answer after the case's last request: {line[:80]!r}"

    def _leftover(self) -> str | None:
        try:
            line = self.lines.get_nowait()
        except queue.Empty:
            return None
        return f"surplus answer after the case's last request: {line[:80]!r}" if line not in (_EOF, _OVERSIZE) \
            else None

    def kill(self) -> None:
        """Kill the testee's whole process group, at once."""
        self._stop.set()
        proc, self.proc = self.proc, None
        if proc is None:
            return
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        try:
            proc.kill()
        except OSError:
            pass
        proc.wait()
        for pipe in (proc.stdin, proc.stdout):
            try:
                if pipe is not None:
                    pipe.close()
            except OSError:
                pass

    def stop(self, ask_first: bool = True) -> None:
        """Ask the testee to quit (5 s), then kill its process group (what it left running too)."""
        proc = self.proc
        if proc is not None and ask_first and proc.poll() is None and proc.stdin is not None:
            try:
                proc.stdin.write(b'{"op": "quit"}\n')
                proc.stdin.flush()
                proc.wait(timeout=5)
            except (OSError, subprocess.TimeoutExpired):
                pass
        self.kill()


def kill_all() -> None:
    """Kill every testee still running (at exit, on SIGTERM / SIGHUP)."""
    for t in list(_LIVE):
        t.kill()


def install_handlers() -> None:
    """Testees die with the runner: at exit, and on SIGTERM / SIGHUP (then the runner exits 143 / 129)."""
    atexit.register(kill_all)

    def on_signal(signum: int, _frame: Any) -> None:
        kill_all()
        os._exit(128 + signum)

    for sig in (signal.SIGTERM, signal.SIGHUP):
        try:
            signal.signal(sig, on_signal)
        except (ValueError, OSError):  # not the main thread: atexit still applies
            pass
