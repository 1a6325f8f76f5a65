"""A headless Chromium driven through its DevTools protocol over a pipe, standard library only.

With --remote-debugging-pipe Chromium reads protocol commands from its file descriptor 3 and
writes replies and events to its file descriptor 4: JSON messages, each ended by a NUL byte.
Browser(...) starts Chromium (under `timeout -k`, in its own process group, with a throwaway
profile) with two pipes at those descriptors; send() writes a command and returns its reply,
waiting at most a deadline; wait_for() polls a JavaScript expression in a page until it is
true. Every wait is bounded, and close() (also on an exception, as a context manager) ends
Chromium and every process it started, then removes the profile and Chromium's messages.

Chromium gets no network but the loopback interface: every host name resolves to nothing
(--host-resolver-rules) and its background services (updates, sync, metrics, default apps) are
off, so it reaches only the server the test started on 127.0.0.1.
"""

import fcntl
import json
import os
import select
import shutil
import signal
import subprocess
import tempfile
import time


MAX_MESSAGE_BYTES = 64 << 20  # the longest message read (a page's evaluated value); raise at will


def _pipe():
    """A pipe whose two descriptors are 10 or above, clear of 3 and 4, which the shell that
    starts Chromium sets (a pipe end at 3 or 4 would be closed by its own redirection)."""
    ends = []
    for fd in os.pipe():
        ends.append(fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10))
        os.close(fd)
    return ends


class DevToolsError(Exception):
    """A protocol error, a reply that did not come in time, or a Chromium that ended early."""


class Browser:
    """A headless Chromium and its DevTools pipe. `seconds` bounds the whole browser run."""

    def __init__(self, browser, seconds, extra=()):
        self.folder = tempfile.mkdtemp(prefix="fosssim-chromium-")  # profile/ and stderr.log
        self.process = None
        self.next_id = 0
        self.buffer = b""
        self.commands = self.replies = None
        commands_read, self.commands = _pipe()  # we write commands, Chromium reads fd 3
        self.replies, replies_write = _pipe()   # Chromium writes fd 4, we read
        try:
            # subprocess passes descriptors under their own numbers; the shell puts them at 3
            # and 4 for Chromium (exec: Chromium replaces the shell, in timeout's group).
            placed = (f'exec "$@" 3<&{commands_read} 4>&{replies_write} '
                      f'{commands_read}<&- {replies_write}>&-')
            command = ["timeout", "-k", "10", str(seconds), "bash", "-c", placed, "bash", browser,
                       "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                       "--remote-debugging-pipe",
                       f"--user-data-dir={os.path.join(self.folder, 'profile')}",
                       "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1",
                       "--disable-background-networking", "--disable-component-update",
                       "--disable-sync", "--disable-default-apps", "--no-default-browser-check",
                       "--metrics-recording-only", *extra,
                       "about:blank"]
            # A process group of its own (timeout makes one too): close() ends all of it. Its
            # messages go to a file, which never fills up as an unread pipe would.
            with open(os.path.join(self.folder, "stderr.log"), "wb") as log:
                self.process = subprocess.Popen(
                    command, pass_fds=(commands_read, replies_write), stdin=subprocess.DEVNULL,
                    stdout=subprocess.DEVNULL, stderr=log, start_new_session=True)
        except BaseException:
            self.close()
            raise
        finally:
            os.close(commands_read)
            os.close(replies_write)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        """Asks Chromium to close, then ends its process group; removes its folder."""
        if self.process is not None and self.process.poll() is None:
            try:
                self.send("Browser.close", timeout=10)
            except (DevToolsError, OSError):
                pass
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                pass
            for sig in (signal.SIGTERM, signal.SIGKILL):
                try:
                    os.killpg(self.process.pid, sig)
                except ProcessLookupError:
                    break
                try:
                    self.process.wait(5)
                    break
                except subprocess.TimeoutExpired:
                    continue
        if self.process is not None:
            try:
                os.killpg(self.process.pid, signal.SIGKILL)  # renderers left behind, if any
            except ProcessLookupError:
                pass
            self.process.wait()
        for fd in (self.commands, self.replies):
            if fd is not None:
                try:
                    os.close(fd)
                except OSError:
                    pass
        self.commands = self.replies = None
        shutil.rmtree(self.folder, ignore_errors=True)

    def _ended(self, what):
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            pass
        with open(os.path.join(self.folder, "stderr.log"), "rb") as log:
            stderr = log.read().decode(errors="replace")
        return DevToolsError(f"Chromium ended (exit {self.process.returncode}) {what}:\n"
                             f"{stderr[-2000:]}")

    def _read_message(self, deadline):
        """The next message from Chromium, or None when the deadline passes first."""
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            ready, _, _ = select.select([self.replies], [], [], left)
            if not ready:
                return None
            chunk = os.read(self.replies, 1 << 16)
            if not chunk:
                raise self._ended("while a reply was awaited")
            self.buffer += chunk
            if len(self.buffer) > MAX_MESSAGE_BYTES:
                raise DevToolsError(f"a DevTools message longer than {MAX_MESSAGE_BYTES} bytes")
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method, params=None, session=None, timeout=30):
        """The result of one protocol command (on a target's session when given)."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        try:
            os.write(self.commands, json.dumps(message).encode() + b"\0")
        except BrokenPipeError:
            raise self._ended(f"before {method}") from None
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply is None:
                raise DevToolsError(f"no reply to {method} within {timeout} s")
            # Events, and late replies to commands that timed out, are passed over.
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise DevToolsError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})

    def attach(self, target_id):
        """A flat session on a target (a page, a service worker)."""
        return self.send("Target.attachToTarget",
                         {"targetId": target_id, "flatten": True})["sessionId"]

    def new_page(self):
        """(target id, session) of a new blank page, its Page and Runtime domains enabled."""
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.attach(target)
        self.send("Page.enable", session=session)
        self.send("Runtime.enable", session=session)
        return target, session

    def evaluate(self, session, expression, timeout=30):
        """The value of a JavaScript expression in the page (a promise is awaited)."""
        result = self.send("Runtime.evaluate",
                           {"expression": expression, "awaitPromise": True,
                            "returnByValue": True}, session=session, timeout=timeout)
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise DevToolsError(f"{expression!r} threw: {text}")
        return result["result"].get("value")

    def wait_for(self, session, expression, seconds, what):
        """Polls `expression` in the page until it is truthy, and returns its value; raises
        DevToolsError naming `what` when `seconds` pass first."""
        deadline = time.monotonic() + seconds
        while True:
            try:
                value = self.evaluate(session, expression,
                                      timeout=max(1.0, deadline - time.monotonic()))
            except DevToolsError as problem:
                # A page being replaced by a navigation answers with an error: try again.
                if time.monotonic() > deadline:
                    raise DevToolsError(f"{what}: not within {seconds} s ({problem})") from None
                value = None
            if value:
                return value
            if time.monotonic() > deadline:
                raise DevToolsError(f"{what}: not within {seconds} s")
            time.sleep(0.2)

    def navigate(self, session, url, timeout=60):
        """Opens `url` in the page; raises DevToolsError when the navigation fails (its
        network error, e.g. net::ERR_CONNECTION_REFUSED)."""
        result = self.send("Page.navigate", {"url": url}, session=session, timeout=timeout)
        if result.get("errorText"):
            raise DevToolsError(f"{url}: {result['errorText']}")
        return result

    def targets(self, kind):
        """The target ids of every target of a kind ("page", "service_worker")."""
        infos = self.send("Target.getTargets")["targetInfos"]
        return [info["targetId"] for info in infos if info["type"] == kind]
