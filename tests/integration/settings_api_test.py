#!/usr/bin/env python3
"""The console's settings from the configuration schema against a real `azeltrack serve`:
GET /api/config/schema (every section, the file's values, no secret), PUT /api/config/SECTION[/N]
saved in the file (its comments kept) and applied at once or listed in `restart_needed`, and the
refusals (unknown key, wrong type, out of range, secret, hostile bodies) that save nothing.
Usage: settings_api_test.py AZELTRACK"""
import http.client
import os
import shutil
import subprocess
import sys
import tempfile

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-settings-")
CONFIG = os.path.join(TMP, "azeltrack.toml")
PORT = free_port()
BASE = f"http://127.0.0.1:{PORT}"
check = Checks()


def request(method, route, body=None, token=None):
    return http_json(BASE, method, route, body, token)


def raw_put(route, data, token):
    """(status, body) of a PUT whose body is `data` as given: not necessarily JSON."""
    c = http.client.HTTPConnection("127.0.0.1", PORT, timeout=5)
    c.request("PUT", route, body=data, headers={"Authorization": f"Bearer {token}",
                                                "Content-Type": "application/json"})
    r = c.getresponse()
    return r.status, r.read()


def schema_key(schema, section, key):
    s = next(s for s in schema["sections"] if s["name"] == section)
    return next(k for k in s["keys"] if k["key"] == key)


with open(CONFIG, "w", encoding="utf-8") as f:
    f.write("# my station's notes: every save keeps them\n" + station_toml(PORT))
subprocess.run([BIN, "web", "password", "--config", CONFIG], input=b"a-long-password\n",
               check=True, capture_output=True)
TOKEN = subprocess.run([BIN, "web", "token", "--config", CONFIG], check=True,
                       capture_output=True).stdout.decode().strip()
log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", CONFIG], stdout=log, stderr=log)
try:
    check(wait_until(lambda: request("GET", "/api/state")[0] == 200, 20), "the daemon started")

    # The schema: open to read like /api/config, with the file's values and never a secret.
    code, schema = request("GET", "/api/config/schema")
    check(code == 200 and len(schema["sections"]) > 30, f"schema: {code}")
    window = schema_key(schema, "control", "window_deg")
    check(window["range"]["max"] == 2.0 and window["applies"] == "restart", f"window: {window}")
    check(schema_key(schema, "web", "port")["value"] == PORT, "the file's value is shown")
    check(schema_key(schema, "web", "password_hash")["value"] is None, "the hash is not shown")
    check("argon2id" not in open(os.path.join(TMP, "daemon.log")).read() and
          "$argon2id$" not in str(schema), "no secret in the schema")
    check(schema["restart_needed"] == [], f"nothing to restart yet: {schema['restart_needed']}")

    # A restart key: saved, listed until the next start; a live key: applied at once.
    before = open(CONFIG, encoding="utf-8").read()
    code, r = request("PUT", "/api/config/mount.az", {"max_rate_deg_s": 2.5, "encoder_bits": 14},
                      TOKEN)
    check(code == 200 and r["restart"] == ["mount.az.encoder_bits", "mount.az.max_rate_deg_s"]
          and r["applied"] == [], f"mount: {code} {r}")
    check(set(r["restart_needed"]) == {"mount.az.encoder_bits", "mount.az.max_rate_deg_s"},
          f"restart_needed: {r}")
    saved = open(CONFIG, encoding="utf-8").read()
    check("encoder_bits = 14" in saved and "# my station's notes" in saved, f"saved: {saved}")
    check(request("GET", "/api/config")[1]["restart_needed"] == r["restart_needed"],
          "/api/config lists the same")
    code, r = request("PUT", "/api/config/station", {"grid": "JO22"}, TOKEN)
    check(code == 200 and r["applied"] == ["station.grid"], f"grid: {code} {r}")
    check(request("GET", "/api/state")[1]["station"]["grid"] == "JO22", "the grid applied at once")
    code, r = request("PUT", "/api/config/park/2", {"name": "dish down", "el_deg": 5.0}, TOKEN)
    check(code == 200 and r["applied"] == ["park.2.el_deg", "park.2.name"], f"park: {code} {r}")
    check(request("GET", "/api/config")[1]["park"][1]["name"] == "dish down", "park slot applied")
    # An item of an array of tables inside a table: saved as [[satellites.transmitter]] and
    # read back by the schema (the items were once written and listed under the wrong name).
    code, r = request("PUT", "/api/config/satellites.transmitter/1",
                      {"norad": "43017", "downlink_mhz": 145.96, "uplink_mhz": 435.65,
                       "mode": "linear_inverting"}, TOKEN)
    check(code == 200 and "satellites.transmitter.1.norad" in r["restart"], f"sat: {code} {r}")
    saved = open(CONFIG, encoding="utf-8").read()
    check("[[satellites.transmitter]]" in saved and '"satellites.transmitter"' not in saved,
          f"saved as an array of tables in [satellites]: {saved}")
    items = next(s for s in request("GET", "/api/config/schema")[1]["sections"]
                 if s["name"] == "satellites.transmitter")["items"]
    check(len(items) == 1 and items[0].get("norad") == "43017"
          and items[0].get("mode") == "linear_inverting", f"the schema's items: {items}")
    # Back to the value it started with: no longer waiting for a restart.
    code, r = request("PUT", "/api/config/mount.az", {"encoder_bits": None}, TOKEN)
    check(code == 200 and "mount.az.encoder_bits" not in r["restart_needed"]
          and "mount.az.max_rate_deg_s" in r["restart_needed"], f"undone: {r}")

    # Refusals name the key and save nothing.
    before = open(CONFIG, encoding="utf-8").read()
    for route, body, field in [
            ("/api/config/control", {"window_deg": 3.0}, "window_deg"),
            ("/api/config/control", {"windw_deg": 0.1}, "windw_deg"),
            ("/api/config/control", {"lead": "yes"}, "lead"),
            ("/api/config/mount.el", {"encoder_bits": 12.5}, "encoder_bits"),
            ("/api/config/web", {"password_hash": "$argon2id$v=19$x"}, "password_hash"),
            ("/api/config/station", {"lat_deg": 50.0}, "lat_deg"),  # without lon_deg: the file's
            ("/api/config/serial/3", {"baud": 1200}, None)]:
        code, r = request("PUT", route, body, TOKEN)
        check(code == 400 and (field is None or r.get("field") == field),
              f"{route} {body}: {code} {r}")
    for route in ["/api/config/nosuch", "/api/config/park/0", "/api/config/control/1"]:
        code, r = request("PUT", route, {"name": "x"}, TOKEN)
        check(code == 404, f"{route}: {code} {r}")
    for data in [b"[1,2]", b"\"text\"", b"{", b"{}", b"{\"window_deg\": " + b"[" * 5000 + b"]" * 5000
                 + b"}", b"{\"window_deg\": 1e999}", b"x" * 70000]:
        code, _ = raw_put("/api/config/control", data, TOKEN)
        check(400 <= code < 500, f"hostile body {data[:30]!r}…: {code}")
    code, _ = request("PUT", "/api/config/control", {"window_deg": 0.2})
    check(code == 401, f"without the login: {code}")
    check(open(CONFIG, encoding="utf-8").read() == before, "a refused change saved nothing")
    check(request("GET", "/api/state")[0] == 200, "the daemon answers after all that")
    check(subprocess.run([BIN, "config", "check", "--config", CONFIG],
                         capture_output=True).returncode == 0, "the saved file is valid")
finally:
    daemon.terminate()
    daemon.wait(10)
    shutil.rmtree(TMP, ignore_errors=True)
sys.exit(check.summary("settings_api"))
