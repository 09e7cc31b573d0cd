#!/usr/bin/env python3
"""The account from the console against a real `azeltrack serve` (docs/web-api.md "The account"):
API tokens made (shown once, kept as a digest), listed by label, used and revoked at once; the
password changed only with the current one, the other sessions ended; the settings file exported
and imported whole (the password and the tokens kept); and the console's Restart, which outside
systemd re-executes the daemon: the same process id, the motors stopped first, back on the saved
settings. Usage: account_api_test.py AZELTRACK"""
import http.client
import json
import os
import shutil
import subprocess
import sys
import tempfile

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-account-")
CONFIG = os.path.join(TMP, "azeltrack.toml")
PORT = free_port()
BASE = f"http://127.0.0.1:{PORT}"
check = Checks()


def request(method, route, body=None, token=None):
    return http_json(BASE, method, route, body, token)


def raw(method, route, data=b"", token=None, content_type="text/plain"):
    """(status, body bytes) of a request whose body is `data` as given."""
    c = http.client.HTTPConnection("127.0.0.1", PORT, timeout=5)
    headers = {"Content-Type": content_type}
    if token:
        headers["Authorization"] = f"Bearer {token}"
    c.request(method, route, body=data, headers=headers)
    r = c.getresponse()
    return r.status, r.read()


def login(password):
    """(status, session cookie, csrf) of a password login."""
    c = http.client.HTTPConnection("127.0.0.1", PORT, timeout=10)
    c.request("POST", "/api/login", body=json.dumps({"password": password}),
              headers={"Content-Type": "application/json"})
    r = c.getresponse()
    body = json.loads(r.read() or b"null")
    cookie = (r.getheader("Set-Cookie") or "").split(";")[0]
    return r.status, cookie, (body or {}).get("csrf")


with open(CONFIG, "w", encoding="utf-8") as f:
    f.write("# kept by every save\n" + station_toml(PORT))
subprocess.run([BIN, "web", "password", "--config", CONFIG], input=b"first-password\n",
               check=True, capture_output=True)
ADMIN = subprocess.run([BIN, "web", "token", "--config", CONFIG], check=True,
                       capture_output=True).stdout.decode().strip()
log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
env = {k: v for k, v in os.environ.items() if k != "INVOCATION_ID"}  # not under systemd
daemon = subprocess.Popen([BIN, "serve", "--config", CONFIG], stdout=log, stderr=log, env=env)
try:
    check(wait_until(lambda: request("GET", "/api/state")[0] == 200, 20), "the daemon started")

    # Tokens: reading the list needs a login; made, shown once; used; listed; revoked.
    check(request("GET", "/api/tokens")[0] == 401, "the token list needs a login")
    code, made = request("POST", "/api/tokens", {"label": "logger script"}, ADMIN)
    check(code == 200 and len(made.get("token", "")) == 64, f"made: {code} {made}")
    text = open(CONFIG, encoding="utf-8").read()
    check(made["token"] not in text and "logger script" in text and "# kept by every save" in text,
          "the file keeps the digest and the label, never the token, and its comments")
    code, session = request("GET", "/api/session", token=made["token"])
    check(code == 200 and session["logged_in"] and session["token"] == "logger script",
          f"the new token acts at once: {session}")
    code, listed = request("GET", "/api/tokens", token=ADMIN)
    labels = [t["label"] for t in listed["tokens"]]
    check(code == 200 and "logger script" in labels and all("sha256" not in t
                                                            for t in listed["tokens"]),
          f"listed by label, no digest: {listed}")
    check(request("POST", "/api/tokens", {"label": "logger script"}, ADMIN)[0] == 409,
          "a second token of the same label is refused")
    for bad in ("", "x" * 41, "semi;colon", None, 7):
        code, body = request("POST", "/api/tokens", {"label": bad}, ADMIN)
        check(code == 400 and body.get("field") == "label", f"label {bad!r}: {code} {body}")
    code, _ = raw("DELETE", "/api/tokens/logger%20script", token=ADMIN)
    check(code == 200, f"revoked: {code}")
    check(request("GET", "/api/session", token=made["token"])[1]["logged_in"] is False,
          "the revoked token acts no more")
    check("logger script" not in open(CONFIG, encoding="utf-8").read(), "and is gone from the file")
    check(raw("DELETE", "/api/tokens/nobody", token=ADMIN)[0] == 404, "an unknown label is 404")
    check(raw("DELETE", "/api/tokens/%zz", token=ADMIN)[0] == 400, "a malformed escape is 400")

    # The password: the current one is needed; the old sessions end, the changer's goes on.
    code, other, _ = login("first-password")
    check(code == 200 and other, "a second session")
    code, body = request("POST", "/api/password",
                         {"old_password": "wrong-one", "new_password": "second-password"}, ADMIN)
    check(code == 401 and body.get("field") == "old_password", f"wrong current: {code} {body}")
    code, body = request("POST", "/api/password",
                         {"old_password": "first-password", "new_password": "short"}, ADMIN)
    check(code == 400 and body.get("field") == "new_password", f"too short: {code} {body}")
    code, body = request("POST", "/api/password",
                         {"old_password": "first-password", "new_password": "second-password"},
                         ADMIN)
    check(code == 200, f"changed: {code} {body}")
    check(login("first-password")[0] == 401 and login("second-password")[0] == 200,
          "the new password logs in, the old one no more")
    code, session = http_json(BASE, "GET", "/api/session", headers={"Cookie": other})
    check(session["logged_in"] is False, "the other session ended with the old password")

    # The file: exported whole; an import keeps this station's password and tokens.
    code, exported = raw("GET", "/api/config/file", token=ADMIN)
    with open(CONFIG, "rb") as f:
        check(code == 200 and exported == f.read(), f"exported as the file is: {code}")
    check(raw("GET", "/api/config/file")[0] == 401, "the export needs a login")
    imported = exported.decode().replace("[control]", "[control]\nramp_s = 2.5", 1) \
        if "[control]" in exported.decode() else exported.decode() + "\n[control]\nramp_s = 2.5\n"
    imported = "\n".join(l for l in imported.splitlines() if not l.startswith("password_hash"))
    code, body = raw("PUT", "/api/config/file", imported.encode(), token=ADMIN)
    check(code == 200, f"imported: {code} {body[:300]}")
    text = open(CONFIG, encoding="utf-8").read()
    check("ramp_s = 2.5" in text and "password_hash" in text,
          "the import is saved, with this station's password kept")
    check(login("second-password")[0] == 200, "and the password still works")
    code, body = raw("PUT", "/api/config/file", b"[control\nbroken", token=ADMIN)
    check(code == 400, f"a file that is not TOML is refused: {code}")
    code, body = raw("PUT", "/api/config/file",
                     imported.replace("ramp_s = 2.5", "ramp_s = 2.5\nwindow_deg = 9").encode(),
                     token=ADMIN)
    check(code == 400 and b"window_deg" in body, f"an invalid file is refused naming the key: {body}")
    check("ramp_s = 2.5" in open(CONFIG, encoding="utf-8").read(), "nothing saved by a refusal")

    # Restart: not under systemd, the daemon executes itself again (same pid), on the file.
    check(request("POST", "/api/restart", token=ADMIN)[0] == 200, "restart asked")
    check(wait_until(lambda: "restarting: running the same command again" in
                     open(os.path.join(TMP, "daemon.log")).read(), 10), "it says so")
    check(wait_until(lambda: request("GET", "/api/state")[0] == 200, 20), "back after the restart")
    check(daemon.poll() is None, "the same process, executed again")
    code, cfg = request("GET", "/api/config", token=ADMIN)
    check(code == 200 and cfg["control"]["ramp_s"] == 2.5, f"running the saved settings: {cfg.get('control')}")
    check("motors stopped" in open(os.path.join(TMP, "daemon.log")).read(), "the motors stopped first")
finally:
    daemon.terminate()
    try:
        daemon.wait(timeout=10)
    except subprocess.TimeoutExpired:
        daemon.kill()
    log.close()

failed = check.summary("account_api_test")
if not failed:
    shutil.rmtree(TMP, ignore_errors=True)
else:
    print(f"left {TMP} for inspection")
sys.exit(1 if failed else 0)
