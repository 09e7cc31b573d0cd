"""The clients of the hardening tests (hardening_*_test.py): the console's HTTP API on fresh
connections, raw bytes as they are, WebSocket upgrades and frames, and a rotctld `p`, against the
daemon on WEB_PORT and ROT_PORT (free ports chosen when this module is first imported)."""
import base64
import collections
import http.client
import json
import os
import re
import socket
import time

from daemon_harness import free_port

WEB_PORT = free_port()
ROT_PORT = free_port()

Reply = collections.namedtuple("Reply", "status body seconds raw")


def request(method, route, body=None, token=None, headers=None, timeout=5.0, source=None):
    """One request on a fresh connection. body is the parsed JSON (strict UTF-8), or the
    exception text when the answer is not valid JSON; seconds is the whole exchange."""
    h = {"Content-Type": "application/json"}
    if token:
        h["Authorization"] = f"Bearer {token}"
    h.update(headers or {})
    data = json.dumps(body).encode() if body is not None else None
    conn = http.client.HTTPConnection("127.0.0.1", WEB_PORT, timeout=timeout,
                                      source_address=(source, 0) if source else None)
    t0 = time.monotonic()
    try:
        conn.request(method, route, body=data, headers=h)
        r = conn.getresponse()
        raw = r.read()
        status = r.status
    finally:
        conn.close()
    seconds = time.monotonic() - t0
    try:
        parsed = json.loads(raw.decode("utf-8")) if raw else None
    except ValueError as e:
        parsed = f"not valid JSON: {e}"
    return Reply(status, parsed, seconds, raw)


def state():
    return request("GET", "/api/state").body


def raw_http(data, timeout=5.0, port=None):
    """Sends `data` as it is on a raw socket and reads the answer until the server closes or the
    body is complete. Returns (status or None, head bytes, body bytes)."""
    s = socket.create_connection(("127.0.0.1", port or WEB_PORT), timeout=timeout)
    try:
        try:
            s.sendall(data)
        except (BrokenPipeError, ConnectionResetError):
            pass  # the server answered before reading it all (431): read what it said
        got = b""
        while True:
            try:
                chunk = s.recv(65536)
            except (ConnectionResetError, socket.timeout):
                break
            if not chunk:
                break
            got += chunk
            if b"\r\n\r\n" in got:
                head, body = got.split(b"\r\n\r\n", 1)
                m = re.search(rb"(?im)^content-length:\s*(\d+)", head)
                if m and len(body) >= int(m.group(1)):
                    break
    finally:
        s.close()
    head, _, body = got.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.[01] (\d{3})", head)
    return (int(m.group(1)) if m else None), head, body


def json_error_body(body):
    """The body as a JSON object with an "error" text, or None."""
    try:
        obj = json.loads(body.decode("utf-8"))
    except ValueError:
        return None
    return obj if isinstance(obj, dict) and isinstance(obj.get("error"), str) else None


def read_head(s):
    """An HTTP answer's head, read byte by byte so no WebSocket frame after it is consumed.
    Returns the status line, or "closed" / "reset" / "timeout"."""
    head = b""
    try:
        while b"\r\n\r\n" not in head:
            c = s.recv(1)
            if not c:
                return "closed" if not head else head.split(b"\r\n")[0].decode("latin-1")
            head += c
    except ConnectionResetError:
        return "reset"
    except socket.timeout:
        return "timeout"
    return head.split(b"\r\n")[0].decode("latin-1")


def ws_connect(origin=True, host=None):
    s = socket.create_connection(("127.0.0.1", WEB_PORT), timeout=3)
    key = base64.b64encode(os.urandom(16)).decode()
    host = host if host is not None else f"127.0.0.1:{WEB_PORT}".encode()
    req = (b"GET /ws HTTP/1.1\r\nHost: " + host + b"\r\nUpgrade: websocket\r\n"
           b"Connection: Upgrade\r\nSec-WebSocket-Key: " + key.encode() +
           b"\r\nSec-WebSocket-Version: 13\r\n" +
           (f"Origin: http://127.0.0.1:{WEB_PORT}\r\n".encode() if origin else b"") + b"\r\n")
    s.sendall(req)
    return s


def parse_frame(buf):
    """(opcode, payload, bytes used, fin) of the first whole server frame in buf, or None."""
    if len(buf) < 2:
        return None
    opcode, n, at = buf[0] & 0x0F, buf[1] & 0x7F, 2
    if n == 126:
        if len(buf) < 4:
            return None
        n, at = int.from_bytes(buf[2:4], "big"), 4
    elif n == 127:
        if len(buf) < 10:
            return None
        n, at = int.from_bytes(buf[2:10], "big"), 10
    if buf[1] & 0x80:
        at += 4  # servers do not mask; skip a key anyway
    if len(buf) < at + n:
        return None
    return opcode, buf[at:at + n], at + n, bool(buf[0] & 0x80)


def read_frames(s, seconds):
    """Every whole message received within `seconds`, as (opcode, payload): a message the server
    sent in fragments (RFC 6455 §5.4: FIN clear, then continuation frames of opcode 0; Beast
    fragments what exceeds its write buffer, 4 KiB) is joined as a browser joins it."""
    frames, buf, partial = [], b"", None
    end = time.monotonic() + seconds
    s.settimeout(0.1)
    while time.monotonic() < end:
        try:
            chunk = s.recv(65536)
        except socket.timeout:
            continue
        if not chunk:
            break
        buf += chunk
        while (f := parse_frame(buf)) is not None:
            opcode, payload, used, fin = f
            buf = buf[used:]
            if opcode == 0 and partial is not None:
                partial = (partial[0], partial[1] + payload)
            elif opcode >= 8:  # a control frame may come between fragments
                frames.append((opcode, payload))
                continue
            else:
                partial = (opcode, payload)
            if fin:
                frames.append(partial)
                partial = None
    return frames


def rotctld_p(source=None, timeout=1.0):
    """A `p` on a fresh rotctld connection: (az, el) and the seconds it took, or raises."""
    t0 = time.monotonic()
    s = socket.create_connection(("127.0.0.1", ROT_PORT), timeout=timeout,
                                 source_address=(source, 0) if source else None)
    try:
        s.sendall(b"p\n")
        got = b""
        while got.count(b"\n") < 2:
            chunk = s.recv(4096)
            if not chunk:
                raise ConnectionError(f"closed after {got!r}")
            got += chunk
    finally:
        s.close()
    az, el = (float(x) for x in got.split(b"\n")[:2])
    return (az, el), time.monotonic() - t0
