"""Headless Chromium driven over the DevTools protocol: load a page, read it, screenshot it.

Used to check the viewer in a real browser (tests) and to take its pictures (docs).
WebGL runs on SwiftShader, so no GPU or X server is needed. Every wait is bounded.
"""

from __future__ import annotations

import base64
import json
import shutil
import subprocess
import tempfile
import time
import urllib.request
from pathlib import Path
from typing import Any

from websockets.sync.client import connect

from robocram.viewer.errors import ViewerError

CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--no-first-run",
    "--hide-scrollbars",
    "--remote-debugging-port=0",
)


def find_chromium() -> str:
    """The Chromium binary; ViewerError saying how to install it if there is none."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    raise ViewerError("no Chromium found; install it with tools/setup_chromium.sh (apt-get)")


class HeadlessChromium:
    """One headless Chromium with one page; ``close()`` it (or use ``with``)."""

    def __init__(self, width: int = 1024, height: int = 640, timeout: float = 120.0) -> None:
        self.timeout = timeout  # [s] for start-up and each wait
        self._profile = Path(tempfile.mkdtemp(prefix="robocram-chromium-"))
        command = [find_chromium(), *CHROMIUM_FLAGS, f"--window-size={width},{height}"]
        command += [f"--user-data-dir={self._profile}", "about:blank"]
        self._process = subprocess.Popen(
            command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
        )
        self._next_id = 0
        try:
            self._socket = connect(self._page_socket(), max_size=None, open_timeout=timeout)
            self.call(
                "Emulation.setDeviceMetricsOverride",
                width=width,
                height=height,
                deviceScaleFactor=1,
                mobile=False,
            )
        except BaseException:
            self._stop_process()
            raise

    def _page_socket(self) -> str:
        port_file = self._profile / "DevToolsActivePort"
        deadline = time.monotonic() + self.timeout
        while not port_file.exists() or not port_file.read_text().strip():
            if self._process.poll() is not None or time.monotonic() > deadline:
                raise ViewerError(f"Chromium did not start (exit code {self._process.poll()})")
            time.sleep(0.05)
        port = int(port_file.read_text().split()[0])
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=10) as answer:
            targets = json.load(answer)
        return str(next(t for t in targets if t["type"] == "page")["webSocketDebuggerUrl"])

    def call(self, method: str, **params: Any) -> dict[str, Any]:
        """Send one DevTools command and return its result (events in between are dropped)."""
        self._next_id += 1
        self._socket.send(json.dumps({"id": self._next_id, "method": method, "params": params}))
        deadline = time.monotonic() + self.timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise ViewerError(f"Chromium did not answer {method} within {self.timeout} s")
            message = json.loads(self._socket.recv(timeout=remaining))
            if message.get("id") == self._next_id:
                if "error" in message:
                    raise ViewerError(f"Chromium refused {method}: {message['error']}")
                return dict(message.get("result", {}))

    def open(self, url: str) -> None:
        """Load ``url`` in the page."""
        self.call("Page.navigate", url=url)

    def evaluate(self, expression: str) -> Any:
        """The value of a JavaScript expression in the page."""
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        return result.get("result", {}).get("value")

    def wait_for_text(self, *texts: str) -> str:
        """Wait until the page's text shows every one of ``texts``; return the text."""
        deadline = time.monotonic() + self.timeout
        while True:
            shown = self.evaluate("document.body ? document.body.innerText : ''") or ""
            if all(text in shown for text in texts):
                return str(shown)
            if time.monotonic() > deadline:
                missing = [t for t in texts if t not in shown]
                raise ViewerError(f"the page did not show {missing} within {self.timeout} s")
            time.sleep(0.2)

    def screenshot(self, path: str | Path | None = None) -> bytes:
        """A PNG of the page as it is; also written to ``path`` if given."""
        png = base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])
        if path is not None:
            Path(path).parent.mkdir(parents=True, exist_ok=True)
            Path(path).write_bytes(png)
        return png

    def _stop_process(self) -> None:
        self._process.terminate()
        try:
            self._process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self._process.kill()
            self._process.wait(timeout=10)
        shutil.rmtree(self._profile, ignore_errors=True)

    def close(self) -> None:
        """Close the page connection and stop Chromium."""
        self._socket.close()
        self._stop_process()

    def __enter__(self) -> HeadlessChromium:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
