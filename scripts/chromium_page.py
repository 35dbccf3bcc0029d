#!/usr/bin/env python3
"""Drive one page in headless Chromium over the DevTools protocol (stdlib only).

Used by tests/viz/viewer_browser_check.py, and to take README pictures:
    python3 scripts/chromium_page.py PAGE.html --frame last --out shot.png [--size 1200x800]

The browser is $AMP_CHROMIUM or `chromium` on PATH. CDP goes over
--remote-debugging-pipe (JSON messages ended by NUL; fd 3 to the browser, fd 4
from it), so no port is opened. Every wait has a timeout, and the browser's
whole process group is killed at the end whatever happens.
"""
import argparse
import base64
import contextlib
import fcntl
import json
import os
import queue
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from urllib.parse import unquote

# SwiftShader gives WebGL without a GPU. Chromium 156 accepts it only through
# ANGLE: --use-gl=swiftshader is refused ("Requested GL implementation
# (gl=none,angle=none) not found"), the GPU process exits and restarts, and
# now and then the page's WebGL context is lost. Software WebGL also needs
# --enable-unsafe-swiftshader. --no-sandbox because we may run as root.
FLAGS = ["--headless=new", "--use-gl=angle", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--no-sandbox", "--disable-gpu-sandbox",
         "--no-first-run", "--no-default-browser-check", "--disable-dev-shm-usage",
         "--disable-background-networking", "--disable-extensions",
         "--hide-scrollbars", "--mute-audio", "--remote-debugging-pipe"]


class PageError(Exception):
    """A one-line failure: timeout, browser gone, or a JS evaluation error."""


class PageTimeout(PageError):
    """A wait ran out of time."""


def find_chromium():
    """The browser executable, or None when it is not installed."""
    exe = os.environ.get("AMP_CHROMIUM") or "chromium"
    return shutil.which(exe)


def _exception_text(details):
    """First line of a CDP ExceptionDetails' message."""
    text = details.get("exception", {}).get("description") or details.get("text") or "?"
    return text.splitlines()[0]


class ChromiumPage:
    """One headless browser with one page attached (flat session)."""

    def __init__(self, size=(1200, 800), timeout=60.0, exe=None):
        self.size, self.timeout = size, timeout
        self.exe = exe or find_chromium()
        if not self.exe:
            raise PageError("chromium not found (install it or set AMP_CHROMIUM)")
        self.errors, self.warnings = [], []
        self._events, self._replies = queue.Queue(), {}
        self._cond = threading.Condition()
        self._next_id, self._session, self._proc, self._fds = 0, None, None, []
        self._profile = tempfile.mkdtemp(prefix="amp-chromium-")
        self._log = open(os.path.join(self._profile, "chromium.log"), "wb")

    def __enter__(self):
        try:
            self._launch()
            self._attach()
        except BaseException:  # also Ctrl-C: never leave a browser behind
            self.close()
            raise
        return self

    def __exit__(self, *exc):
        self.close()

    def _launch(self):
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()
        self._fds = [self._to_browser, self._from_browser, to_browser_r, from_browser_w]

        def child_fds():
            # Move the pipe ends above 10 first so that dup2 onto 3 and 4
            # cannot clobber one another, then clear close-on-exec via dup2.
            hi_r = fcntl.fcntl(to_browser_r, fcntl.F_DUPFD, 10)
            hi_w = fcntl.fcntl(from_browser_w, fcntl.F_DUPFD, 10)
            os.dup2(hi_r, 3)
            os.dup2(hi_w, 4)

        w, h = self.size
        args = [self.exe, *FLAGS, f"--window-size={w},{h}",
                f"--user-data-dir={self._profile}", "about:blank"]
        # A new session makes the browser a process-group leader, so close()
        # can kill the zygote, GPU and renderer children along with it.
        self._proc = subprocess.Popen(
            args, stdin=subprocess.DEVNULL, stdout=self._log, stderr=self._log,
            pass_fds=(3, 4), preexec_fn=child_fds, start_new_session=True)
        for fd in (to_browser_r, from_browser_w):  # the browser's ends now
            os.close(fd)
            self._fds.remove(fd)
        threading.Thread(target=self._reader, daemon=True).start()

    def _reader(self):
        """Split the browser's byte stream at NULs; route replies and events."""
        buf = b""
        try:
            while chunk := self._read_chunk():
                *messages, buf = (buf + chunk).split(b"\0")
                for raw in messages:
                    self._dispatch(json.loads(raw))
        finally:  # wake every waiter: the browser is gone (or spoke garbage)
            with self._cond:
                self._replies[None] = {}
                self._cond.notify_all()
            self._events.put(None)

    def _read_chunk(self):
        try:
            return os.read(self._from_browser, 1 << 16)
        except OSError:  # closed under us by close()
            return b""

    def _dispatch(self, msg):
        if "id" in msg:
            with self._cond:
                self._replies[msg["id"]] = msg
                self._cond.notify_all()
            return
        self._note_problem(msg.get("method"), msg.get("params", {}))
        self._events.put(msg)

    def _note_problem(self, method, p):
        """Keep console errors/warnings, uncaught exceptions and log errors."""
        level, text = None, ""
        if method == "Runtime.consoleAPICalled":
            level = p.get("type")
            text = "console: " + " ".join(
                str(a.get("value", a.get("description", ""))) for a in p.get("args", []))
        elif method == "Runtime.exceptionThrown":
            level, text = "error", "uncaught: " + _exception_text(p.get("exceptionDetails", {}))
        elif method == "Log.entryAdded":
            e = p.get("entry", {})
            level, text = e.get("level"), f"log ({e.get('source')}): {e.get('text', '')}"
        if level in ("error", "warning"):
            (self.errors if level == "error" else self.warnings).append(text)

    def close(self):
        """Ask the browser to quit, then kill its process group; drop the profile."""
        if self._proc and self._proc.poll() is None:
            try:
                self._send("Browser.close", session=False, wait=False)
                self._proc.wait(timeout=5)
            except (OSError, subprocess.TimeoutExpired, PageError):
                pass
        if self._proc:
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(self._proc.pid, signal.SIGKILL)
            self._proc.wait()
            self._proc = None
        for fd in self._fds:
            with contextlib.suppress(OSError):
                os.close(fd)
        self._fds = []
        self._log.close()
        shutil.rmtree(self._profile, ignore_errors=True)

    def _send(self, method, params=None, session=True, wait=True, timeout=None, what=None):
        """Send one command; return its result, or raise PageError.

        `what` names the wait in the timeout message (default: the method)."""
        with self._cond:
            self._next_id += 1
            mid = self._next_id
        msg = {"id": mid, "method": method, "params": params or {}}
        if session and self._session:
            msg["sessionId"] = self._session
        try:
            os.write(self._to_browser, json.dumps(msg).encode() + b"\0")
        except OSError:  # EPIPE: nobody reads fd 3 any more
            raise self._gone(what or method) from None
        if not wait:
            return None
        deadline = time.monotonic() + (timeout or self.timeout)
        with self._cond:
            while mid not in self._replies:
                left = deadline - time.monotonic()
                if None in self._replies:
                    raise self._gone(what or method)
                if left <= 0:
                    raise PageTimeout(f"timed out after {timeout or self.timeout:.0f} s "
                                    f"waiting for {what or method}")
                self._cond.wait(left)
            reply = self._replies.pop(mid)
        if "error" in reply:
            raise PageError(f"{method} failed: {reply['error'].get('message')}")
        return reply.get("result", {})

    def _wait_event(self, method, deadline, what):
        """Params of the next `method` event before `deadline` (monotonic)."""
        while True:
            left = deadline - time.monotonic()
            try:
                msg = self._events.get(timeout=max(left, 0.001))
            except queue.Empty:
                raise PageTimeout(f"timed out after {self.timeout:.0f} s waiting for {what}") from None
            if msg is None:  # the reader's sentinel
                raise self._gone(what)
            if msg.get("method") == method:
                return msg.get("params", {})

    def _gone(self, what):
        """The error for a browser that died: with its last logged error."""
        with contextlib.suppress(OSError):
            self._log.flush()
            lines = Path(self._profile, "chromium.log").read_text(errors="replace").splitlines()
            last = [ln for ln in lines if ("ERROR" in ln or "FATAL" in ln) and "dbus" not in ln]
            if last:
                return PageError(f"browser exited while waiting for {what}; it said: {last[-1][-160:]}")
        return PageError(f"browser exited while waiting for {what}")

    def _attach(self):
        # The pipe talks to the browser target; open our own tab and attach
        # to it with a flat session so page commands carry its sessionId.
        target = self._send("Target.createTarget", {"url": "about:blank"}, session=False)
        res = self._send("Target.attachToTarget",
                         {"targetId": target["targetId"], "flatten": True}, session=False)
        self._session = res["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self._send(f"{domain}.enable")
        w, h = self.size  # exact viewport, whatever the window decorations
        self._send("Emulation.setDeviceMetricsOverride",
                   {"width": w, "height": h, "deviceScaleFactor": 1, "mobile": False})

    # ---- page API ------------------------------------------------------
    def open(self, path):
        """Navigate to a local file and wait for its load event."""
        url = Path(path).resolve().as_uri()
        res = self._send("Page.navigate", {"url": url})
        if res.get("errorText"):
            raise PageError(f"cannot open {url}: {res['errorText']}")
        # A late load event of the initial about:blank may come first, so
        # wait until the loaded document is really ours.
        deadline = time.monotonic() + self.timeout
        while True:
            self._wait_event("Page.loadEventFired", deadline, f"{url} to load")
            if unquote(self.evaluate("location.href") or "") == unquote(url):
                return

    def evaluate(self, expression, timeout=None, what=None):
        """Value of a JS expression; promises are awaited."""
        res = self._send("Runtime.evaluate",
                         {"expression": expression, "awaitPromise": True,
                          "returnByValue": True}, timeout=timeout,
                         what=what or f"JS `{expression[:40]}`")
        if "exceptionDetails" in res:
            raise PageError("JS error: " + _exception_text(res["exceptionDetails"]))
        return res.get("result", {}).get("value")

    def wait_ready(self, timeout=None, stop_on_error=False):
        """Poll until document.body.dataset.ampReady is "1" (or, if asked,
        until the page reports an error: a viewer that failed to build its
        scene will never be ready, no need to sit out the timeout)."""
        timeout = timeout or self.timeout
        deadline = time.monotonic() + timeout
        late = PageTimeout(f"timed out after {timeout:.0f} s waiting for document.body.dataset.ampReady")
        while (left := deadline - time.monotonic()) > 0:
            if stop_on_error and self.errors:
                raise PageError(f"page error: {self.errors[0]}")
            try:  # a busy page may not answer at all: same timeout
                if self.evaluate("document.body && document.body.dataset.ampReady === '1'",
                                 timeout=left):
                    return
            except PageTimeout:
                raise late from None
            time.sleep(0.25)
        raise late

    def set_frame(self, frame):
        """Move the slider as a user would (value + 'input'), then wait 2 rAFs.

        Returns ampViewer.frame afterwards, so callers can check the slider
        really drives the viewer."""
        js = """(async () => {
          const s = document.getElementById('amp-frame');
          if (!s) throw new Error('no #amp-frame slider');
          s.value = String(%d);
          s.dispatchEvent(new Event('input', {bubbles: true}));
          for (let k = 0; k < 2; ++k) await new Promise(r => requestAnimationFrame(r));
          return window.ampViewer ? window.ampViewer.frame : null;
        })()""" % int(frame)
        return self.evaluate(js, what=f"the page to render frame {int(frame)}")

    def frame_count(self):
        return self.evaluate("window.ampViewer ? window.ampViewer.frameCount : null")

    def screenshot(self):
        """PNG bytes of the viewport."""
        res = self._send("Page.captureScreenshot", {"format": "png"}, what="a screenshot")
        return base64.b64decode(res["data"])


def resolve_frame(spec, count):
    """'last', a fraction with a '.' (0.5 = middle) or an index -> index."""
    if spec == "last":
        return count - 1
    return round(float(spec) * (count - 1)) if "." in spec else int(spec)


def parse_size(text):
    w, _, h = text.lower().partition("x")
    return int(w), int(h)


def main():
    ap = argparse.ArgumentParser(description="Screenshot an `amp view` page at one frame.")
    ap.add_argument("page")
    ap.add_argument("--frame", default="0", help="index, 'last' or a fraction like 0.5")
    ap.add_argument("--out", required=True, help="PNG file to write")
    ap.add_argument("--size", default="1200x800", type=parse_size, help="viewport WxH")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per wait")
    args = ap.parse_args()
    try:
        with ChromiumPage(args.size, args.timeout) as page:
            page.open(args.page)
            page.wait_ready()
            count = page.frame_count()
            if not isinstance(count, int) or count < 1:
                raise PageError("window.ampViewer.frameCount missing")
            frame = resolve_frame(args.frame, count)
            if not 0 <= frame < count:
                raise PageError(f"frame {frame} out of range 0..{count - 1}")
            page.set_frame(frame)
            Path(args.out).write_bytes(page.screenshot())
            problems = page.errors
    except (PageError, ValueError, OSError) as exc:
        print(f"chromium_page: {exc}", file=sys.stderr)
        return 1
    note = f"; page errors: {problems[0]}" if problems else ""
    print(f"wrote {args.out} ({args.size[0]}x{args.size[1]}, frame {frame} of {count}){note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
