"""What the daemon's integration tests share: pass/fail counting, free ports, the console's HTTP
API with a bearer token, waiting for a condition, and a rotctld conversation."""
import http.client
import json
import socket
import sys
import time
import urllib.error
import urllib.request


class Checks:
    """Counts checks; a failed one is printed with what it checked."""

    def __init__(self):
        self.passed = 0
        self.failed = 0

    def __call__(self, condition, what):
        if condition:
            self.passed += 1
        else:
            self.failed += 1
            print(f"FAIL: {what}", file=sys.stderr)
        return condition

    def summary(self, name):
        print(f"{name}: {self.passed} passed, {self.failed} failed")
        return 1 if self.failed else 0


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def http_json(base, method, route, body=None, token=None, headers=None, timeout=5):
    """(status, parsed JSON body) of one request to the console."""
    h = {"Content-Type": "application/json"}
    if token:
        h["Authorization"] = f"Bearer {token}"
    h.update(headers or {})
    data = json.dumps(body).encode() if body is not None else None
    req = urllib.request.Request(base + route, data=data, method=method, headers=h)
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            return r.status, json.loads(r.read() or b"null")
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"null")


def wait_until(probe, seconds=10.0, every=0.1):
    """True once probe() is true, asked every `every` seconds (errors while the daemon starts
    or restarts count as not yet); False when `seconds` pass first."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            if probe():
                return True
        except (OSError, ValueError, KeyError, TypeError, http.client.HTTPException):
            pass
        time.sleep(every)
    return False


def rotctld(port, lines, timeout=3.0):
    """Sends rotctld command lines on one connection; returns each line's reply lines."""
    replies = []
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        f = s.makefile("rwb")
        for line in lines:
            f.write(line.encode() + b"\n")
            f.flush()
            reply = f.readline().decode().strip()
            # `p` answers two lines; the others one (RPRT n).
            if line.strip() == "p" and not reply.startswith("RPRT"):
                reply += " " + f.readline().decode().strip()
            replies.append(reply)
    return replies
