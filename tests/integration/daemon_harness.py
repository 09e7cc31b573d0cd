"""What the daemon's integration tests share: pass/fail counting, free ports, the console's HTTP
API with a bearer token, waiting for a condition, and a rotctld conversation."""
import atexit
import http.client
import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request

# The instant at which the daemons of the tests that scan the sky start (`serve --utc-start`), so
# that what they find up is the same at any hour the tests run (a test that scanned
# "the first source up" passed or failed with the time of day). At FN06HE, 23:00 local time on the
# day of a new Moon, inside tzdata's leap-second table: the Sun (−61°) and the Moon (−66°) are
# down, Cassiopeia A, the catalogue's first source, stands at 58.5° (azimuth 312°).
FIXED_UTC = "2025-11-20T04:00:00Z"
# The simulated antenna's start near Cassiopeia A at FIXED_UTC, for the scan tests: without it the
# first slew, from az 0° the long way round at a test's 4°/s, takes 80 s of the test. Only time
# depends on it: a scan of another source still works, after a longer slew.
START_NEAR_SCAN_SOURCE = "[sim.az]\nstart_deg = 306.0\n[sim.el]\nstart_deg = 57.0\n"


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



def stop_at_exit(procs, tmp):
    """At exit: each process still running is terminated (killed after 5 s), then `tmp` removed."""
    def cleanup():
        for p in procs:
            if p.poll() is None:
                p.terminate()
                try:
                    p.wait(5)
                except subprocess.TimeoutExpired:
                    p.kill()
        shutil.rmtree(tmp, ignore_errors=True)
    atexit.register(cleanup)


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


def http_upload(base, route, data, token=None, content_type="application/vnd.debian.binary-package",
                timeout=30):
    """(status, parsed JSON body) of a POST whose body is `data` (bytes), as a file upload."""
    h = {"Content-Type": content_type}
    if token:
        h["Authorization"] = f"Bearer {token}"
    req = urllib.request.Request(base + route, data=data, method="POST", headers=h)
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            return r.status, json.loads(r.read() or b"null")
    except urllib.error.HTTPError as e:
        try:
            return e.code, json.loads(e.read() or b"null")
        except ValueError:
            return e.code, None


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


def cross_scan_of_a_source(base, beam_deg):
    """POST /api/scan's body for a short cross scan (5 points a line, 1.5 beams each side) of the
    first radio source (a point, not the Sun's or the Moon's disc) between 20° and 70° of
    elevation, where a scan has room on every side, and that source's elevation. The daemon runs
    at FIXED_UTC, so this is the same source every time; none up is a failure."""
    targets = http_json(base, "GET", "/api/targets")[1]["targets"]
    up = [t for t in targets if t.get("kind") == "source" and 20.0 <= t["el_deg"] <= 70.0]
    if not up:
        sys.exit(f"no radio source between 20° and 70° at {FIXED_UTC}: {targets}")
    return {"source": up[0]["name"], "kind": "cross", "beamwidth_deg": beam_deg,
            "points_per_line": 5, "half_span_beams": 1.5, "settle_s": 0.5,
            "dwell_s": 0.8}, up[0]["el_deg"]


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


def station_toml(web_port=0, rotctld_port=0, mount_rate_deg_s=None):
    """The start of the integration tests' configurations: a schema-2 station at FN06HE that
    tracks nothing at start, with its servers on the given ports (0: off); a mount rate makes
    moves take seconds instead of minutes. Tests append their own tables."""
    text = ('schema_version = 2\n[station]\ngrid = "FN06HE"\n[target]\nname = "stop"\n'
            f'[rotctld]\nport = {rotctld_port}\n[pstrotator]\nport = 0\n[web]\nport = {web_port}\n')
    if mount_rate_deg_s is not None:
        text += (f"[mount.az]\nmax_rate_deg_s = {mount_rate_deg_s}\n"
                 f"[mount.el]\nmax_rate_deg_s = {mount_rate_deg_s}\n")
    return text


def tle_with_epoch_now(name_line=b"ISS (ZARYA)"):
    """An ISS element set whose epoch is now (its passes are the next hours'), as bytes
    under `name_line` (which may be any bytes: a test of a name that is not UTF-8)."""
    import datetime

    def checksum(line):
        s = sum(int(c) if c.isdigit() else (1 if c == "-" else 0) for c in line[:68])
        return line[:68] + str(s % 10)
    now = datetime.datetime.now(datetime.timezone.utc)
    day = (now - datetime.datetime(now.year, 1, 1, tzinfo=datetime.timezone.utc)).total_seconds()
    epoch = "%02d%012.8f" % (now.year % 100, day / 86400 + 1)
    l1 = "1 25544U 98067A   %s  .00016717  00000-0  30119-3 0  999" % epoch
    l2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.49815488441110"
    return name_line + b"\n" + checksum(l1).encode() + b"\n" + checksum(l2).encode() + b"\n"


def remove_gpsd_shm(port):
    """gpsd started by gpsfake on `port` leaves its shared-memory export behind when killed (key
    0x4770 followed by the port in hex, gpsd's GPSD_SHM_KEY scheme for test instances)."""
    import subprocess  # pylint: disable=import-outside-toplevel
    subprocess.run(["ipcrm", "-M", f"0x4770{port:04x}"], capture_output=True, check=False)


def upload_test_deb(folder, filler_bytes):
    """A real package named azeltrack (dpkg-deb, uncompressed) holding `filler_bytes` of random
    data, built in a new folder under `folder`, for the Software page's upload tests and
    benchmark; its path."""
    root = os.path.join(folder, f"pkg-{filler_bytes}")
    os.makedirs(f"{root}/DEBIAN")
    os.makedirs(f"{root}/usr/share/azeltrack-test")
    with open(f"{root}/DEBIAN/control", "w", encoding="utf-8") as f:
        f.write("Package: azeltrack\nVersion: 0.1.0+9\nArchitecture: all\n"
                "Maintainer: test <test@example.org>\nDescription: upload test\n")
    with open(f"{root}/usr/share/azeltrack-test/filler", "wb") as f:
        f.write(os.urandom(filler_bytes))
    subprocess.run(["dpkg-deb", "-Znone", "--root-owner-group", "--build", root, f"{root}.deb"],
                   check=True, capture_output=True)
    return f"{root}.deb"
