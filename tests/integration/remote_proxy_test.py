#!/usr/bin/env python3
"""docs/remote.md's recipe, run as it is: Debian's nginx terminates TLS (a
throw-away certificate) in front of a real `azeltrack serve` on the loopback. Over HTTPS: a STOP
without a login is refused (before the fix, any request through a local proxy counted as "this
machine" and stopped the antenna without one); the login (cookie and CSRF token), the live view's
WebSocket and an action work through the proxy; a STOP with the login is accepted; and a STOP
straight to the daemon from the loopback still needs none (the touch panel's).
Usage: remote_proxy_test.py AZELTRACK   (skipped, 77, without nginx)"""
import base64
import json
import os
import re
import shutil
import socket
import ssl
import subprocess
import sys
import tempfile
import urllib.request

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

NGINX = shutil.which("nginx") or "/usr/sbin/nginx"
if not os.path.exists(NGINX):
    print("remote_proxy: nginx is not installed (scripts/install-deps --test)")
    sys.exit(77)
BIN = os.path.realpath(sys.argv[1])
DOCS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "remote.md")
TMP = tempfile.mkdtemp(prefix="azt-remote-")
WEB, TLS = free_port(), free_port()
DIRECT = f"http://127.0.0.1:{WEB}"
PROXY = f"https://127.0.0.1:{TLS}"
check = Checks()


def recipe():
    """docs/remote.md's nginx block, with this run's certificate, ports and name."""
    text = open(DOCS, encoding="utf-8").read()
    block = re.search(r"<!-- nginx-recipe.*?```nginx\n(.*?)```", text, re.S).group(1)
    block = block.replace("listen 443 ssl;", f"listen 127.0.0.1:{TLS} ssl;")
    block = block.replace("/etc/ssl/azeltrack/fullchain.pem", f"{TMP}/cert.pem")
    block = block.replace("/etc/ssl/azeltrack/privkey.pem", f"{TMP}/key.pem")
    block = block.replace("http://127.0.0.1:8080", DIRECT)
    user = "user root root;\n" if os.geteuid() == 0 else ""
    temps = "".join(f"{name}_temp_path {TMP}/{name};\n" for name in
                    ("client_body", "proxy", "fastcgi", "uwsgi", "scgi"))
    return (f"{user}worker_processes 1;\npid {TMP}/nginx.pid;\nerror_log {TMP}/error.log;\n"
            f"events {{ worker_connections 64; }}\nhttp {{\naccess_log off;\n{temps}{block}}}\n")


def https(method, route, body=None, headers=None):
    context = ssl.create_default_context(cafile=f"{TMP}/cert.pem")
    data = json.dumps(body).encode() if body is not None else None
    req = urllib.request.Request(PROXY + route, data=data, method=method,
                                 headers={"Content-Type": "application/json", **(headers or {})})
    try:
        with urllib.request.urlopen(req, timeout=10, context=context) as r:
            return r.status, json.loads(r.read() or b"null"), r.headers
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"null"), e.headers


def websocket_state(cookie):
    """The live view through the proxy: the handshake's status line and the first text frame."""
    context = ssl.create_default_context(cafile=f"{TMP}/cert.pem")
    raw = socket.create_connection(("127.0.0.1", TLS), timeout=10)
    s = context.wrap_socket(raw, server_hostname="127.0.0.1")
    key = base64.b64encode(os.urandom(16)).decode()
    s.sendall((f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{TLS}\r\nUpgrade: websocket\r\n"
               f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
               f"Origin: {PROXY}\r\nCookie: {cookie}\r\n\r\n").encode())
    data = b""
    while b"\r\n\r\n" not in data:
        data += s.recv(4096)
    head, rest = data.split(b"\r\n\r\n", 1)
    while len(rest) < 2:
        rest += s.recv(4096)
    s.close()
    return head.split(b"\r\n")[0].decode(), rest[:1]


subprocess.run(["openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt",
                "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", f"{TMP}/key.pem", "-out",
                f"{TMP}/cert.pem", "-days", "1", "-subj", "/CN=127.0.0.1", "-addext",
                "subjectAltName=IP:127.0.0.1"], check=True, capture_output=True)
config = os.path.join(TMP, "azeltrack.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(WEB))
subprocess.run([BIN, "web", "password", "--config", config], input=b"a-long-password\n",
               check=True, capture_output=True)
with open(f"{TMP}/nginx.conf", "w", encoding="utf-8") as f:
    f.write(recipe())
log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", config], stdout=log, stderr=log)
nginx = subprocess.Popen([NGINX, "-p", TMP, "-c", f"{TMP}/nginx.conf", "-g", "daemon off;"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
try:
    check(wait_until(lambda: http_json(DIRECT, "GET", "/api/state")[0] == 200, 20), "daemon up")
    check(wait_until(lambda: https("GET", "/api/state")[0] == 200, 10),
          f"the console through nginx over HTTPS: {open(TMP + '/error.log').read()[-500:]}")
    status, body, _ = https("POST", "/api/stop", {}, {"Origin": PROXY})
    check(status == 401, f"a STOP through the proxy without a login: {status} {body}")
    status, body, headers = https("POST", "/api/login", {"password": "a-long-password"},
                                  {"Origin": PROXY})
    cookie = (headers.get("Set-Cookie") or "").split(";")[0]
    csrf = (body or {}).get("csrf", "")
    check(status == 200 and cookie.startswith("azt_session=") and csrf,
          f"the login through the proxy: {status} {body}")
    session = {"Origin": PROXY, "Cookie": cookie, "X-CSRF-Token": csrf}
    line, opcode = websocket_state(cookie)
    check(" 101 " in line and opcode in (b"\x81", b"\x01"),
          f"the live view's WebSocket through the proxy: {line} {opcode}")
    status, body, _ = https("POST", "/api/target", {"name": "sun"}, session)
    check(status == 200 and body.get("mode") == "TRACK", f"an action through the proxy: {status} {body}")
    status, body, _ = https("POST", "/api/stop", {}, session)
    check(status == 200, f"a STOP through the proxy with the login: {status} {body}")
    status, body = http_json(DIRECT, "POST", "/api/stop", {})
    check(status == 200, f"a STOP straight from the loopback needs no login: {status} {body}")
    check(daemon.poll() is None and nginx.poll() is None, "the daemon and nginx still run")
finally:
    nginx.terminate()
    nginx.wait(10)
    daemon.terminate()
    daemon.wait(10)
    log.close()
    if check.failed:
        print(open(os.path.join(TMP, "daemon.log"), encoding="utf-8", errors="replace").read()[-2000:],
              file=sys.stderr)
    shutil.rmtree(TMP, ignore_errors=True)
sys.exit(check.summary("remote_proxy"))
