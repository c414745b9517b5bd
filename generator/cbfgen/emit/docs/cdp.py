"""A minimal Chrome DevTools Protocol client over Chromium's --remote-debugging-pipe.

Chromium reads NUL-terminated JSON commands from file descriptor 3 and
writes replies and events to descriptor 4; no network port, no WebSocket
library. Used by `make docs-check` (layout, images, console) and `make
docs-pdf` (Page.printToPDF). Every event is kept, so a caller can read the
console messages a page sent.
"""

from __future__ import annotations

import base64
import json
import os
import select
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--hide-scrollbars", "--remote-debugging-pipe", "--font-render-hinting=none")
TIMEOUT = 60.0
MARGIN_TOP = 0.75  # inches of a printed page above its body (the header's band)
MARGIN_BOTTOM = 0.85  # inches below its body (the footer's band)


class CdpError(RuntimeError):
    pass


class Browser:
    """One headless Chromium and one page (a flattened target session)."""

    def __init__(self, chromium: str) -> None:
        self._profile = tempfile.TemporaryDirectory(prefix="cbf-chromium-")
        to_child_r, self._to_child = os.pipe()
        self._from_child, from_child_w = os.pipe()

        def wire() -> None:  # in the child: the pipe ends become descriptors 3 and 4, kept across exec
            high_r, high_w = os.dup(to_child_r), os.dup(from_child_w)  # the pipes may already be 3 or 4
            os.dup2(high_r, 3)
            os.dup2(high_w, 4)
            os.set_inheritable(3, True)
            os.set_inheritable(4, True)

        self._proc = subprocess.Popen(
            [chromium, *FLAGS, f"--user-data-dir={self._profile.name}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            preexec_fn=wire, close_fds=False)
        os.close(to_child_r)
        os.close(from_child_w)
        self._buf = b""
        self._next = 0
        self.events: list[dict[str, Any]] = []
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self._session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.call(f"{domain}.enable", session=True)

    # -- the wire ------------------------------------------------------------
    def _read(self, deadline: float) -> dict[str, Any]:
        while b"\0" not in self._buf:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._from_child], [], [], left)[0]:
                raise CdpError("Chromium did not answer in time")
            chunk = os.read(self._from_child, 1 << 20)
            if not chunk:
                raise CdpError("Chromium closed the debugging pipe")
            self._buf += chunk
        msg, _, self._buf = self._buf.partition(b"\0")
        data: dict[str, Any] = json.loads(msg)
        return data

    def call(self, method: str, params: dict[str, Any] | None = None, *, session: bool = False) -> dict[str, Any]:
        self._next += 1
        msg: dict[str, Any] = {"id": self._next, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = self._session
        os.write(self._to_child, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + TIMEOUT
        while True:
            reply = self._read(deadline)
            if reply.get("id") == self._next:
                if "error" in reply:
                    raise CdpError(f"{method}: {reply['error'].get('message')}")
                result: dict[str, Any] = reply.get("result", {})
                return result
            if "method" in reply:
                self.events.append(reply)

    def page(self, method: str, params: dict[str, Any] | None = None) -> dict[str, Any]:
        return self.call(method, params, session=True)

    def wait_event(self, name: str, since: int) -> None:
        deadline = time.monotonic() + TIMEOUT
        while not any(e.get("method") == name for e in self.events[since:]):
            reply = self._read(deadline)
            if "method" in reply:
                self.events.append(reply)

    # -- what the checks use ---------------------------------------------------
    def open(self, url: str, width: int, height: int) -> None:
        """Load url at a viewport of width x height CSS pixels and wait for its load event."""
        self.page("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
        since = len(self.events)
        self.page("Page.navigate", {"url": url})
        self.wait_event("Page.loadEventFired", since)

    def evaluate(self, expression: str) -> Any:
        res = self.page("Runtime.evaluate", {"expression": expression, "returnByValue": True})
        if "exceptionDetails" in res:
            raise CdpError(f"evaluate: {res['exceptionDetails'].get('text')}")
        return res["result"].get("value")

    def screenshot(self, path: Path) -> None:
        data = self.page("Page.captureScreenshot", {"format": "png"})["data"]
        path.write_bytes(base64.b64decode(data))

    def pdf(self, path: Path, footer: str, header: str = "<span></span>") -> None:
        data = self.page("Page.printToPDF", {
            "printBackground": True, "displayHeaderFooter": True, "generateDocumentOutline": True,
            "headerTemplate": header,
            "footerTemplate": footer, "paperWidth": 8.27, "paperHeight": 11.69,
            "marginTop": MARGIN_TOP, "marginBottom": MARGIN_BOTTOM, "marginLeft": 0.6, "marginRight": 0.6})["data"]
        path.write_bytes(base64.b64decode(data))

    def console(self, since: int = 0) -> list[str]:
        """Every console message, uncaught exception and browser log entry since event number since."""
        out = []
        for e in self.events[since:]:
            p = e.get("params", {})
            if e.get("method") == "Runtime.consoleAPICalled":
                out.append(f"console.{p.get('type')}: " + " ".join(str(a.get("value", a.get("description", "")))
                                                                   for a in p.get("args", [])))
            elif e.get("method") == "Runtime.exceptionThrown":
                out.append(f"exception: {p.get('exceptionDetails', {}).get('text')}")
            elif e.get("method") == "Log.entryAdded":
                entry = p.get("entry", {})
                out.append(f"log.{entry.get('level')}: {entry.get('text')} {entry.get('url', '')}".strip())
        return out

    def close(self) -> None:
        try:
            self.call("Browser.close")
        except (CdpError, OSError):
            pass
        try:
            self._proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self._proc.kill()
            self._proc.wait()
        for fd in (self._to_child, self._from_child):
            try:
                os.close(fd)
            except OSError:
                pass
        self._profile.cleanup()

    def __enter__(self) -> Browser:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
