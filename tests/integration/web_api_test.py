#!/usr/bin/env python3
"""Every endpoint of the console API (docs/web-api.md) against a real `azeltrack serve` on the
simulated antenna, with a bearer token from `azeltrack web token`: what each action does to the
daemon's state and to the saved file, and that bad values are 400s naming the field that change
nothing. Also a forged Origin, a raw WebSocket handshake, and 20 WebSocket clients.
Usage: web_api_test.py AZELTRACK"""
import base64
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request

from daemon_harness import Checks, free_port, http_json, station_toml, tle_with_epoch_now, wait_until

BIN = os.path.realpath(sys.argv[1])
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
TMP = tempfile.mkdtemp(prefix="azt-web-api-")
CONFIG = os.path.join(TMP, "azeltrack.toml")
check = Checks()


PORT = free_port()
BASE = f"http://127.0.0.1:{PORT}"


def request(method, route, body=None, token=None, headers=None):
    return http_json(BASE, method, route, body, token, headers)


def state():
    return request("GET", "/api/state")[1]


def wait_for(what, probe, seconds=10.0):
    return check(wait_until(probe, seconds), f"timed out waiting for {what}")


with open(os.path.join(TMP, "sats.tle"), "wb") as f:
    f.write(tle_with_epoch_now())

with open(CONFIG, "w") as f:
    f.write("# a comment that every save must keep\n" + station_toml(PORT, mount_rate_deg_s=10.0) + f"""[satellites]
file = "sats.tle"
beamwidth_deg = 30.0
[[spacecraft]]
name = "Moon table"
file = "{os.path.join(ROOT, "tests/data/horizons/moon_vectors_csv_kms.txt")}"
description = "a Horizons vector table (March 2025: outside its span now)"
frequency_mhz = 8420.0
""")
subprocess.run([BIN, "web", "password", "--config", CONFIG], input=b"a-long-password\n",
               check=True, capture_output=True)
TOKEN = subprocess.run([BIN, "web", "token", "--config", CONFIG], check=True,
                       capture_output=True).stdout.decode().strip()
# A LAN bind address without a password: refused at start, naming [web].
lan = os.path.join(TMP, "lan.toml")
lan_port = free_port()
with open(lan, "w") as f:
    f.write('[station]\ngrid = "FN06HE"\n[rotctld]\nport = 0\n[pstrotator]\nport = 0\n'
            f'[web]\nbind = "0.0.0.0"\nport = {lan_port}\n')
r = subprocess.run([BIN, "serve", "--config", lan, "--run-for", "1"], capture_output=True)
check(r.returncode == 2 and b"[web]" in r.stderr and b"password" in r.stderr,
      f"LAN bind without a password: rc={r.returncode} {r.stderr[-200:]}")
check("password_hash" not in open(lan).read(), "nothing generated for a LAN bind")

log = open(os.path.join(TMP, "daemon.log"), "w")
daemon = subprocess.Popen([BIN, "serve", "--config", CONFIG], stdout=log, stderr=log)
try:
    wait_for("the daemon", lambda: state()["antenna"]["known"], 30.0)

    # Reading is open; the page and its files are served.
    for route in ["/", "/js/main.js", "/js/bands.js", "/app.css", "/css/sky.css", "/pages/radio.html",
                  "/css/radio.css", "/api/state", "/api/config", "/api/targets", "/api/sky?hours=2",
                  "/api/session", "/api/locator?grid=FN06HE"]:
        with urllib.request.urlopen(BASE + route, timeout=5) as r:
            check(r.status == 200, f"GET {route} answered {r.status}")
    s = state()
    for key in ["mode", "utc", "antenna", "target", "faults", "moon", "sun", "corrections"]:
        check(key in s, f"state lacks {key}")
    # The console's modules must come as JavaScript, its style sheets as CSS, or the browser refuses
    # them (nosniff); the pages loaded when first opened as HTML.
    for route, kind in [("/js/main.js", "text/javascript"), ("/css/radio.css", "text/css"),
                        ("/pages/radio.html", "text/html")]:
        with urllib.request.urlopen(BASE + route, timeout=5) as r:
            check(r.headers["Content-Type"].startswith(kind),
                  f"{route} served as {r.headers['Content-Type']}")
    bands = {b["band"]: b for b in request("GET", "/api/targets")[1]["bands"]}
    check(bands.get("144", {}).get("wavelength") == "2 m", f"band 144: {bands.get('144')}")
    check(abs(bands.get("1296", {}).get("freq_mhz", 0) - 1296.1) < 1e-9, "band 1296's frequency")
    code, square = request("GET", "/api/locator?grid=FN06HE")
    check(code == 200 and abs(square["lat_deg"] - 46.1875) < 1e-9, f"locator FN06HE: {square}")
    code, refused = request("GET", "/api/locator?grid=ZZ99")
    check(code == 400 and refused.get("field") == "grid", f"locator ZZ99: {code} {refused}")
    sky = request("GET", "/api/sky?hours=2")[1]
    check(len(sky["moon_path"]) == 13, f"2 h of Moon path every 10 min: {len(sky['moon_path'])}")

    # Without credentials every action is 401 and moves nothing, except STOP from this machine
    # (loopback): a stop never waits for a password.
    for method, route in [("POST", "/api/target"), ("PUT", "/api/config/band"),
                          ("POST", "/api/faults/clear")]:
        code, _ = request(method, route, {"name": "moon"})
        check(code == 401, f"{method} {route} without login: {code}")
    check(state()["mode"] == "STOP", "a refused action changed the mode")
    code, _ = request("POST", "/api/stop")
    check(code == 200, f"POST /api/stop from loopback without login: {code}")
    code, _ = request("POST", "/api/target", {"name": "moon"}, TOKEN,
                      {"Origin": "http://evil.example"})
    check(code == 403, f"forged Origin with a valid token: {code}")

    # Targets.
    code, r = request("POST", "/api/target", {"name": "casa"}, TOKEN)
    check(code == 200 and state()["target"]["name"] == "Cassiopeia A", f"track casa: {code} {r}")
    code, r = request("POST", "/api/target", {"ra_deg": 83.633, "dec_deg": 22.0145}, TOKEN)
    check(code == 200 and state()["mode"] == "TRACK", f"track RA/Dec: {code} {r}")
    code, r = request("POST", "/api/target", {"park": 2}, TOKEN)
    check(code == 200 and state()["mode"] == "PARK", f"park 2: {code} {r}")
    code, r = request("POST", "/api/target", {"az_deg": 123.0, "el_deg": 33.0}, TOKEN)
    check(code == 200 and state()["mode"] == "MAN", f"manual: {code} {r}")
    wait_for("the antenna at 123/33",
             lambda: abs(state()["antenna"]["az_deg"] - 123) < 0.2 and
             abs(state()["antenna"]["el_deg"] - 33) < 0.2, 30)
    for body, field in [({"name": "vega"}, "name"), ({"park": 5}, "park"),
                        ({"az_deg": 500, "el_deg": 10}, "az_deg"),
                        ({"az_deg": 10, "el_deg": 95}, "el_deg"),
                        ({"ra_deg": "x", "dec_deg": 1}, "ra_deg"), ({}, "name")]:
        code, r = request("POST", "/api/target", body, TOKEN)
        check(code == 400 and r.get("field") == field, f"target {body}: {code} {r}")
    check(state()["mode"] == "MAN", "a refused target changed the mode")

    # A spacecraft from a Horizons table (docs/satellites.md): listed with its description and
    # frequency; outside its table's span it has no position, and the daemon carries on.
    crafts = [t for t in request("GET", "/api/targets")[1]["targets"] if t["kind"] == "spacecraft"]
    check(len(crafts) == 1 and crafts[0]["frequency_mhz"] == 8420.0 and "Horizons" in
          crafts[0]["description"] and crafts[0]["az_deg"] is None and "error" in crafts[0],
          f"spacecraft listed: {crafts}")

    # A satellite (docs/satellites.md): listed with its next pass, tracked as a target,
    # pre-positioned to where its planned pass starts.
    sats = request("GET", "/api/targets")[1]["satellites"]
    check(len(sats) == 1 and sats[0]["name"] == "ISS (ZARYA)" and "next_pass" in sats[0],
          f"satellites listed: {sats}")
    code, r = request("POST", "/api/target", {"name": "sat:iss"}, TOKEN)
    t = state()["target"]
    check(code == 200 and t["name"] == "sat:ISS (ZARYA)" and t["satellite"]["phase"] in
          ("waiting for AOS", "tracking") and t["satellite"]["aos"] < t["satellite"]["los"],
          f"track sat:iss: {code} {r} {t}")
    loss = t["satellite"].get("planned_loss", {})
    check(loss.get("beyond_deg") == 15.0 and loss.get("seconds", -1) >= 0.0 and
          (loss["seconds"] == 0.0) == (loss.get("from") is None),
          f"the planned loss, half of [satellites] beamwidth_deg, before AOS: {loss}")
    path = request("GET", "/api/sky?hours=1")[1]["pass_path"]
    # Every 10 s and the pass's end: a grazing pass of a few seconds still has AOS and LOS.
    check(len(path) >= 2 and path[0]["utc"] < path[-1]["utc"],
          f"the planned pass on the sky plot: {len(path)} points {t}")
    if t["satellite"]["phase"] == "waiting for AOS" and path:
        start = path[0]
        wait_for("the antenna pre-positioned at AOS",
                 lambda: abs(((state()["antenna"]["az_deg"] - start["az_deg"]) + 180) % 360 - 180)
                 < 1.0 and abs(state()["antenna"]["el_deg"] - max(start["el_deg"], 0)) < 1.0, 60)
    code, r = request("POST", "/api/target", {"name": "sat:hubble"}, TOKEN)
    check(code == 400 and r.get("field") == "name" and "hubble" in r.get("error", "") + str(r),
          f"unknown satellite: {code} {r}")
    code, _ = request("POST", "/api/stop", None, TOKEN)
    check(code == 200 and state()["mode"] == "STOP", "stop")

    # Corrections: saved and live.
    for _ in range(3):
        request("POST", "/api/correction", {"axis": "az", "steps": 1}, TOKEN)
    code, r = request("POST", "/api/correction", {"axis": "el", "steps": -2}, TOKEN)
    check(code == 200 and abs(r["el_user_deg"] + 0.02) < 1e-9, f"el correction: {r}")
    c = state()["corrections"]
    check(abs(c["az_user_deg"] - 0.03) < 1e-9, f"az total {c['az_user_deg']}")
    text = open(CONFIG).read()
    check("az_user_deg = 0.03" in text and "# a comment that every save must keep" in text,
          "the saved file holds the total and keeps its comment")
    code, r = request("POST", "/api/correction", {"axis": "up", "steps": 1}, TOKEN)
    check(code == 400 and r.get("field") == "axis", f"bad axis: {r}")
    code, r = request("POST", "/api/correction", {"reset": True}, TOKEN)
    check(code == 200 and state()["corrections"]["az_user_deg"] == 0, "reset")

    # Settings.
    code, _ = request("PUT", "/api/config/band", {"band": "1296"}, TOKEN)
    check(code == 200 and state()["moon"]["band"] == "1296", "band applied")
    code, r = request("PUT", "/api/config/band", {"band": "99"}, TOKEN)
    check(code == 400 and r.get("field") == "band", f"bad band: {r}")
    code, _ = request("PUT", "/api/config/dx", {"dx_grid": "JO65"}, TOKEN)
    check(code == 200 and state()["moon"]["dx_echo_doppler_hz"] is not None, "DX Doppler shown")
    code, r = request("PUT", "/api/config/dx", {"dx_grid": "XX"}, TOKEN)
    check(code == 400 and r.get("field") == "dx_grid", f"bad DX locator: {r}")
    code, _ = request("PUT", "/api/config/dx", {"dx_grid": ""}, TOKEN)
    check(code == 200 and state()["moon"]["dx_echo_doppler_hz"] is None, "DX cleared")
    code, _ = request("PUT", "/api/config/station", {"grid": "JO65"}, TOKEN)
    check(code == 200 and state()["station"]["grid"] == "JO65", "grid applied")
    code, _ = request("PUT", "/api/config/station",
                      {"lat_deg": 52.1, "lon_deg": 5.2, "alt_m": 10.0}, TOKEN)
    check(code == 200 and abs(state()["station"]["lat_deg"] - 52.1) < 1e-9, "lat/lon applied")
    code, r = request("PUT", "/api/config/station", {"lat_deg": 95.0, "lon_deg": 5.0}, TOKEN)
    check(code == 400 and r.get("field") == "lat_deg", f"bad latitude: {r}")
    code, _ = request("PUT", "/api/config/offsets", {"az_offset_deg": 1.5}, TOKEN)
    check(code == 200 and state()["corrections"]["az_offset_deg"] == 1.5, "offset applied")
    code, r = request("PUT", "/api/config/offsets", {"el_offset_deg": 500}, TOKEN)
    check(code == 400, f"bad offset: {r}")
    code, _ = request("PUT", "/api/config/tilt", {"tilt_el_deg": [0.1] * 60}, TOKEN)
    check(code == 200, "whole tilt table")
    code, _ = request("PUT", "/api/config/tilt", {"index": 59, "value": -0.3}, TOKEN)
    tilt = request("GET", "/api/config")[1]["corrections"]["tilt_el_deg"]
    check(code == 200 and tilt[59] == -0.3 and tilt[0] == 0.1, "tilt entry")
    for body in [{"index": 60, "value": 0}, {"index": 1, "value": 9.0}, {"tilt_el_deg": [1, 2]}]:
        code, r = request("PUT", "/api/config/tilt", body, TOKEN)
        check(code == 400, f"bad tilt {body}: {code}")
    code, _ = request("PUT", "/api/config/park",
                      {"slot": 3, "name": "dish down", "az_deg": 90, "el_deg": 5}, TOKEN)
    park = request("GET", "/api/config")[1]["park"]
    check(code == 200 and park[2]["name"] == "dish down" and park[2]["el_deg"] == 5, "park slot")
    code, r = request("PUT", "/api/config/park", {"slot": 1, "el_deg": 120}, TOKEN)
    check(code == 400, f"bad park elevation: {r}")
    code, r = request("PUT", "/api/config/control", {"window_deg": 0.3}, TOKEN)
    check(code == 200 and "control.window_deg" in r["restart_needed"], f"control: {r}")
    code, r = request("PUT", "/api/config/control", {"window_deg": 3.0}, TOKEN)
    check(code == 400, f"bad window: {r}")
    code, _ = request("POST", "/api/faults/clear", None, TOKEN)
    check(code == 200, "faults/clear")
    check(subprocess.run([BIN, "config", "check", "--config", CONFIG],
                         capture_output=True).returncode == 0, "the saved file is valid")

    # WebSocket: a same-origin handshake is accepted, a forged one refused; 20 clients get pushes.
    # Views without a login share 16 places (docs/reliability.md "Hardening" row 5); these 20 are a
    # logged-in station's.
    def ws_handshake(origin, token=None):
        s = socket.create_connection(("127.0.0.1", PORT), timeout=5)
        key = base64.b64encode(os.urandom(16)).decode()
        auth = f"Authorization: Bearer {token}\r\n" if token else ""
        s.sendall((f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{PORT}\r\nUpgrade: websocket\r\n"
                   f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n{auth}"
                   f"Sec-WebSocket-Version: 13\r\nOrigin: {origin}\r\n\r\n").encode())
        head = b""
        while b"\r\n\r\n" not in head:
            head += s.recv(1)
        return s, head.split(b"\r\n")[0].decode()

    s, status = ws_handshake("http://evil.example")
    check(" 403 " in status, f"forged WebSocket Origin: {status}")
    s.close()
    clients = []
    for _ in range(20):
        s, status = ws_handshake(f"http://127.0.0.1:{PORT}", TOKEN)
        check(" 101 " in status, f"WebSocket handshake: {status}")
        clients.append(s)
    start = time.time()
    frames = 0
    for s in clients:
        s.settimeout(2)
        data = s.recv(65536)
        # A text frame (opcode 1), whole (FIN) or the first fragment of a longer state: RFC 6455
        # lets the server fragment, and Beast does past its 4 KB write buffer.
        frames += 1 if data[:1] in (b"\x81", b"\x01") else 0
    check(frames == 20, f"{frames} of 20 clients got a text frame")
    rss_kb = int([l for l in open(f"/proc/{daemon.pid}/status") if l.startswith("VmRSS")][0].split()[1])
    cpu0 = sum(int(x) for x in open(f"/proc/{daemon.pid}/stat").read().split()[13:15])
    t0 = time.time()
    end = t0 + 5
    while time.time() < end:  # keep reading so nobody is a slow client
        for s in clients:
            try:
                s.setblocking(False)
                s.recv(65536)
            except BlockingIOError:
                pass
        time.sleep(0.05)
    cpu1 = sum(int(x) for x in open(f"/proc/{daemon.pid}/stat").read().split()[13:15])
    cpu_pct = 100.0 * (cpu1 - cpu0) / os.sysconf("SC_CLK_TCK") / (time.time() - t0)
    print(f"measure: 20 WebSocket consoles: daemon RSS {rss_kb} kB, CPU {cpu_pct:.1f} % of one core")
    for s in clients:
        s.close()
finally:
    daemon.terminate()
    daemon.wait(10)
    log.close()
    if check.failed:
        print(open(os.path.join(TMP, "daemon.log")).read()[-3000:], file=sys.stderr)
    shutil.rmtree(TMP, ignore_errors=True)
print(f"{check.passed} passed, {check.failed} failed")
sys.exit(1 if check.failed else 0)
