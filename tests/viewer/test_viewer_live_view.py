"""``robocram view`` watched live in headless Chromium: it waits for the browser, then the
page sees the world change state by state while the plan runs.

The claims are which states reach the page and in what order, not how long each stays:
the runs here pace states briefly (``--dwell``, ``--push-rate``) and play each motion in a
few frames (``--play-period``: each frame is one more the page's software WebGL draws),
lit without the environment map (``--no-environment-map``: software WebGL builds it for
seconds); the feed still waits for the page to draw each state."""

from __future__ import annotations

import re
import socket
import threading
import time
from typing import cast

import pytest

from robocram.cli import EXIT_INPUT, EXIT_OK, main
from robocram.viewer import LiveFeed, Viewer
from robocram.viewer.errors import ViewerArgumentError
from robocram.viewer.headless_browser import HeadlessChromium
from robocram.world import World

SPEED = 128.0  # motions play at 128x their pace (fewer frames); each state is still paced
STATES_SEEN = 5  # at least this many different world states reach the page
SERVE_AFTER = 1.0  # [s] the page is served after the run (its last updates arrive)
PACING = ["--dwell", "0.05", "--push-rate", "50", "--play-period", "1.0"]  # [s], [Hz], [s]
PAGE = (400, 250)  # [px] a small page: SwiftShader draws each frame in a quarter the time
SERVER_POLLS, POLL = 1200, 0.1  # looks for the server to wait [s apart]: a hang guard

# Installed before the page's own scripts: records every "state N:" the caption shows, from
# the browser's side (a DOM observer), however briefly it is shown.
WATCHER = r"""
window.__states = [];
window.__waited = false;
new MutationObserver(() => {
  const text = document.body ? document.body.innerText : '';
  if (text.includes('waiting for a run')) window.__waited = true;
  for (const match of text.matchAll(/\bstate (\d+):/g)) {
    const n = Number(match[1]);
    if (!window.__states.includes(n)) window.__states.push(n);
  }
}).observe(document, {subtree: true, childList: true, characterData: true});
"""


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def _run_view(argv: list[str], codes: list[int]) -> threading.Thread:
    thread = threading.Thread(target=lambda: codes.append(main(argv)), daemon=True)
    thread.start()
    return thread


def test_view_waits_for_the_browser_then_the_page_sees_the_run(
    capsys: pytest.CaptureFixture[str],
) -> None:
    port = _free_port()
    codes: list[int] = []
    argv = ["view", "--port", str(port), "--speed", str(SPEED), "--seconds", str(SERVE_AFTER)]
    argv += [*PACING, "--no-environment-map"]
    thread = _run_view(argv, codes)
    with HeadlessChromium(*PAGE) as browser:  # starts while the view builds its scene
        browser.call("Page.enable")
        browser.call("Page.addScriptToEvaluateOnNewDocument", source=WATCHER)
        said = ""
        for _ in range(SERVER_POLLS):  # the server listens, then says it waits
            said += capsys.readouterr().out
            if "waiting for a browser" in said or not thread.is_alive():
                break
            time.sleep(POLL)
        assert "waiting for a browser" in said
        browser.open(f"http://127.0.0.1:{port}")
        thread.join(timeout=600)  # the run, then SERVE_AFTER of serving
        text = browser.wait_for_text("pick-mug succeeded", "perform going succeeded")
        seen = browser.evaluate("window.__states")
        waited = browser.evaluate("window.__waited")
    assert codes == [EXIT_OK]
    assert waited  # the page showed the viewer before any state: the plan waited for it
    assert len(seen) >= STATES_SEEN, seen
    assert seen == sorted(seen)  # in the order the plan reached them
    assert "pick-mug succeeded" in text and "perform going succeeded" in text
    last = re.search(r"state (\d+):", text)
    assert last is not None and int(last.group(1)) == max(seen) == 12  # the start, 12 motions


def test_view_no_wait_runs_without_a_browser(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["view", "--no-wait", "--port", str(_free_port()), "--speed", "50", "--seconds", "0"]
    argv += PACING
    assert main(argv) == EXIT_OK
    out = capsys.readouterr()
    assert "waiting for a browser" not in out.out and "the plan failed" not in out.err


def test_view_refuses_a_speed_that_is_not_positive(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["view", "--no-wait", "--speed", "0", "--port", str(_free_port())]) == EXIT_INPUT
    assert "--speed 0.0 must be positive" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("flag", "value", "says"),
    [
        ("--dwell", "-0.1", "--dwell -0.1 must be 0 or more"),
        ("--push-rate", "0", "--push-rate 0.0"),
        ("--play-period", "0", "--play-period 0.0 must be positive"),
    ],
)
def test_view_refuses_pacing_out_of_range(
    flag: str, value: str, says: str, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = ["view", "--no-wait", flag, value, "--port", str(_free_port())]
    assert main(argv) == EXIT_INPUT
    assert says in capsys.readouterr().err


@pytest.mark.parametrize(
    ("pacing", "says"),
    [
        ({"dwell": -0.1}, "dwell must be 0 or more"),
        ({"push_rate": 0.0}, "push rate must be"),
        ({"play_period": 0.0}, "play period must be positive"),
    ],
)
def test_a_live_feed_refuses_pacing_out_of_range(pacing: dict[str, float], says: str) -> None:
    nothing_drawn = cast(Viewer, None)  # the pacing is checked before the viewer is used
    with pytest.raises(ViewerArgumentError, match=says):
        LiveFeed(nothing_drawn, cast(World, None), 1.0, **pacing)
