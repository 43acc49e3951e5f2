"""The gallery's thumbnails: the site's own viewer page (viewer.html?m=ID, from file://, as a
reader opens it) in headless Chromium, the picture read off its canvas as the viewer's snapshot
draws it, scaled down to a JPEG in the page.

Chromium is driven through the DevTools protocol on a pipe (``--remote-debugging-pipe``: JSON
messages ending in a NUL byte on the child's fds 3 and 4), so nothing beyond the standard library
is needed. WebGL runs on SwiftShader (no GPU needed). Where Chromium is not found (hbc.locate:
$HBC_CHROMIUM, else chromium on PATH) the rows keep a placeholder and the summary says so.
"""

from __future__ import annotations

import base64
import concurrent.futures
import json
import os
import subprocess
import threading

from . import locate
from .progress import Progress

WIDTH, HEIGHT = 240, 180  # the thumbnail, in pixels
LOAD_TIMEOUT = 300.0  # seconds for one mesh to be read, analysed and drawn by the page

# Run in the page: waits for the viewer to settle, draws its canvas scaled into a JPEG data URL.
_SNAPSHOT_JS = """
new Promise((ok) => {
  const t0 = Date.now();
  (function poll() {
    const v = window.hbcViewer, s = document.body && document.body.dataset.state;
    if (v && s === 'ready') {
      requestAnimationFrame(() => {
        v.viewer.renderNow();
        const src = v.viewer.renderer.domElement, c = document.createElement('canvas');
        c.width = %(w)d; c.height = %(h)d;
        const g = c.getContext('2d'), k = Math.max(c.width / src.width, c.height / src.height);
        g.fillStyle = '#fff'; g.fillRect(0, 0, c.width, c.height);
        const w = src.width * k, h = src.height * k;
        g.drawImage(src, (c.width - w) / 2, (c.height - h) / 2, w, h);
        ok({ok: true, url: c.toDataURL('image/jpeg', 0.82)});
      });
    } else if (s === 'error') ok({ok: false, error: document.getElementById('hbc-error')?.textContent || 'error'});
    else if (Date.now() - t0 > %(t)d) ok({ok: false, error: 'the page took longer than %(s)d s (state ' + s + ')'});
    else setTimeout(poll, 100);
  })();
})
""" % {"w": WIDTH, "h": HEIGHT, "t": int(LOAD_TIMEOUT * 1000), "s": int(LOAD_TIMEOUT)}


class ChromiumError(RuntimeError):
    pass


class Chromium:
    """One headless Chromium; ``call`` sends a DevTools command and waits for its answer (from any
    thread: a reader thread hands each answer to its caller)."""

    def __init__(self, executable: str):
        to_child_r, self._w = os.pipe()
        self._r, from_child_w = os.pipe()
        # The child's ends moved above 4, so that the redirections below never close one another.
        to_child_r, from_child_w = (_above_four(fd) for fd in (to_child_r, from_child_w))
        args = [executable, "--headless=new", "--remote-debugging-pipe", "--no-sandbox", "--no-first-run",
                "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist",
                "--disable-background-timer-throttling", "--disable-renderer-backgrounding",
                f"--window-size={WIDTH * 3},{HEIGHT * 3}", "about:blank"]

        # The pipe's ends become the child's fds 3 (commands in) and 4 (answers out) by the shell's
        # redirections (bash: dash takes one-digit fds only), which exec keeps.
        shell = f'exec "$0" "$@" 3<&{to_child_r} 4>&{from_child_w} {to_child_r}<&- {from_child_w}>&-'
        self._proc = subprocess.Popen(["/bin/bash", "-c", shell, *args], pass_fds=(to_child_r, from_child_w),
                                      stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL)
        os.close(to_child_r)
        os.close(from_child_w)
        self._next, self._lock, self._waiting = 1, threading.Lock(), {}
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        buf = b""
        while True:
            chunk = os.read(self._r, 1 << 16)
            if not chunk:
                break
            buf += chunk
            *messages, buf = buf.split(b"\0")
            for m in messages:
                msg = json.loads(m)
                slot = self._waiting.get(msg.get("id"))
                if slot:
                    slot[1] = msg
                    slot[0].set()
        for slot in list(self._waiting.values()):
            slot[0].set()

    def call(self, method: str, params: dict | None = None, session: str | None = None, timeout=LOAD_TIMEOUT + 30):
        with self._lock:
            i = self._next
            self._next += 1
            slot = self._waiting[i] = [threading.Event(), None]
            msg = {"id": i, "method": method, "params": params or {}}
            if session:
                msg["sessionId"] = session
            os.write(self._w, json.dumps(msg).encode() + b"\0")
        if not slot[0].wait(timeout) or slot[1] is None:
            raise ChromiumError(f"Chromium did not answer {method}")
        del self._waiting[i]
        if "error" in slot[1]:
            raise ChromiumError(f"{method}: {slot[1]['error'].get('message')}")
        return slot[1].get("result", {})

    def close(self):
        try:
            self.call("Browser.close", timeout=10)
        except (ChromiumError, OSError):
            pass
        try:
            self._proc.wait(10)
        except subprocess.TimeoutExpired:
            self._proc.kill()
        os.close(self._w)


def _above_four(fd: int) -> int:
    import fcntl

    high = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(fd)
    return high


def snapshot(browser: Chromium, url: str) -> bytes:
    """The JPEG of the viewer page at `url` once it has drawn its mesh; ChromiumError with the
    page's own words when it could not."""
    target = browser.call("Target.createTarget", {"url": "about:blank"})["targetId"]
    try:
        session = browser.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        browser.call("Page.navigate", {"url": url}, session)
        answer = browser.call("Runtime.evaluate", {"expression": _SNAPSHOT_JS, "awaitPromise": True,
                                                   "returnByValue": True}, session)
        value = answer.get("result", {}).get("value") or {}
        if not value.get("ok"):
            raise ChromiumError(value.get("error") or json.dumps(answer)[:300])
        return base64.b64decode(value["url"].split(",", 1)[1])
    finally:
        browser.call("Target.closeTarget", {"targetId": target}, timeout=30)


def make(out, meshes, *, jobs=2, json_progress=False, progress=True) -> str:
    """The missing thumbs/ID.jpg of the meshes the viewer can show; returns what was done in words
    (also why nothing was: no Chromium). A mesh the page cannot draw gets its words in
    thumbs/ID.error, and no second try until its cache entry changes."""
    todo = [m for m in meshes if m["result"].get("viewer") and not (out / "thumbs" / f"{m['id']}.jpg").exists()
            and not (out / "thumbs" / f"{m['id']}.error").exists()]
    have = sum(1 for m in meshes if (out / "thumbs" / f"{m['id']}.jpg").exists())
    if not todo:
        return f"{have} thumbnail(s), none missing"
    try:
        executable = locate.chromium()
    except locate.LocateError as e:
        return f"no thumbnails made: {e}"
    from . import _gallery_site

    _gallery_site.write_viewer(out)
    bar = Progress("thumbnails", len(todo), json_lines=json_progress, bar=progress)
    browser = Chromium(executable)
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            futures = {pool.submit(_one, browser, out, m): m for m in todo}
            for f in concurrent.futures.as_completed(futures):
                bar.step(futures[f]["rel"], f.result())
    finally:
        browser.close()
        bar.close()
    failed = sum(1 for m in todo if (out / "thumbs" / f"{m['id']}.error").exists())
    return f"{len(todo) - failed} thumbnail(s) made in Chromium" + (f", {failed} failed" if failed else "")


def _one(browser, out, m) -> str:
    url = (out / "viewer.html").resolve().as_uri() + f"?m={m['id']}"
    try:
        (out / "thumbs" / f"{m['id']}.jpg").write_bytes(snapshot(browser, url))
        return ""
    except ChromiumError as e:
        (out / "thumbs" / f"{m['id']}.error").write_text(str(e))
        return str(e)
