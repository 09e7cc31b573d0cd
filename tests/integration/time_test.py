#!/usr/bin/env python3
"""The clock of docs/time.md on loopback, no clock changed: a GPS replayed by gpsfake at the current
time, gpsd writing its NTP shared memory, chronyd -x (no clock control) serving NTP from it on a
free port, an NTP query, and the daemon's `time` state beside chronyc's own report.

 1  no chronyd: the state says not synchronised and why, and the daemon tracks on
 2  gpsfake -> gpsd -> SHM 0 -> chronyd: an NTP query answers stratum 1, refid GPS
 3  the daemon's `time` matches `chronyc -c tracking` (stratum, refid, offset, dispersion), its
    sources list the GPS refclock selected, `synced` is chrony's verdict and the kernel's
    (read here through adjtimex), `rtc` is whether /dev/rtc0 exists
 4  [time] manage_chrony: the console sets the NTP servers, the sources file is written and
    chronyd reloads it (chronyc lists the new server); a name carrying a directive is refused
 5  chronyd stopped: not synchronised again, and the Moon is still tracked

Usage: time_test.py AZELTRACK (as root: gpsd writes SHM 0 and chronyd's socket is root's)"""
import atexit
import ctypes
import os
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time

from daemon_harness import (Checks, free_port, http_json, remove_gpsd_shm, station_toml,
                            wait_until)

BIN = os.path.realpath(sys.argv[1])
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "data", "gps"))
import make_nmea  # noqa: E402  (the GPS logs' writer, tests/data/gps)

if os.geteuid() != 0:
    print("time: skipped: gpsd writes NTP shared memory 0 and chronyd runs only as root")
    sys.exit(77)

TMP = tempfile.mkdtemp(prefix="azt-time-")
RUN = os.path.join(TMP, "run")  # chronyd's command socket: its directory must be 0700
SOURCES_D = os.path.join(TMP, "sources.d")
SOCK = os.path.join(RUN, "chronyd.sock")
os.mkdir(RUN, 0o700)
os.mkdir(SOURCES_D)
check = Checks()
procs = []
GPSD = free_port()


def cleanup():
    for p in procs:
        try:
            os.killpg(p.pid, signal.SIGKILL)  # gpsfake waits on its gpsd; chronyd is its own group
        except ProcessLookupError:
            pass
        p.wait(10)
    remove_gpsd_shm(GPSD)
    shutil.rmtree(TMP, ignore_errors=True)


atexit.register(cleanup)


def spawn(argv, log_name, **kw):
    log = open(os.path.join(TMP, log_name), "w", encoding="utf-8")
    p = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, start_new_session=True, **kw)
    procs.append(p)
    return p


def chronyc(*args):
    r = subprocess.run(["chronyc", "-h", SOCK, *args], capture_output=True, text=True, timeout=10)
    return r.returncode, r.stdout, r.stderr


def kernel_synced():
    """adjtimex(2) asked to change nothing: TIME_ERROR (5) or STA_UNSYNC (0x40) is unsynced.
    struct timex: int modes (padded to a long), long offset, freq, maxerror, esterror, int status."""
    buf = ctypes.create_string_buffer(512)  # struct timex, modes = 0 (the first field)
    state = ctypes.CDLL(None, use_errno=True).adjtimex(buf)
    status = int.from_bytes(buf.raw[ctypes.sizeof(ctypes.c_long) * 5:][:4], "little")
    return state != 5 and not status & 0x40


def ntp_packet(port, payload, timeout=1.0):
    """One UDP exchange with chronyd; None when it does not answer."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.settimeout(timeout)
        s.sendto(payload, ("127.0.0.1", port))
        try:
            return s.recv(1024)
        except socket.timeout:
            return None


def ntp_query(port):
    """(stratum, refid, root dispersion in s) from a plain mode-3 client request (RFC 5905)."""
    reply = ntp_packet(port, b"\x23" + bytes(47))  # LI 0, VN 4, mode 3
    if reply is None or len(reply) < 48:
        return None
    dispersion = struct.unpack("!I", reply[8:12])[0] / 65536.0
    return reply[1], reply[12:16].rstrip(b"\0").decode(errors="replace"), dispersion


def time_state(base):
    return http_json(base, "GET", "/api/state")[1]["time"]


# 1: the daemon first, tracking the Moon; no chronyd yet.
WEB = free_port()
NTP = free_port()
config = os.path.join(TMP, "station.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=WEB).replace('name = "stop"', 'name = "moon"'))
    f.write(f'[time]\nchrony_socket = "{SOCK}"\npoll_s = 1\nmanage_chrony = true\n'
            f'sources_file = "{SOURCES_D}/azeltrack.sources"\n'
            f'[gps]\nenabled = true\ngpsd = "127.0.0.1:{GPSD}"\n')
token = subprocess.run([BIN, "web", "token", "--config", config], check=True, capture_output=True,
                       text=True).stdout.strip()
daemon = spawn([BIN, "serve", "--config", config], "daemon.log")
base = f"http://127.0.0.1:{WEB}"
check(wait_until(lambda: time_state(base)["checked_s_ago"] is not None, 20), "1: the daemon runs")
t = time_state(base)
check(t["synced"] is False and t["reason"] and t["chrony_error"],
      f"1: no chronyd: not synchronised, with the reason: {t}")
check(t["rtc"] == os.path.exists("/dev/rtc0"), f"1: rtc is whether /dev/rtc0 exists: {t['rtc']}")

# 2: the chain. The log starts on a whole second; gpsfake takes ~0.5 s to send its first line.
start = int(time.time()) + 3
log = os.path.join(TMP, "live.nmea")
make_nmea.write_live(log, start, 600)
with open(os.path.join(TMP, "chrony.conf"), "w", encoding="utf-8") as f:
    f.write("refclock SHM 0 refid GPS poll 0 dpoll 0 filter 1\n"  # gpsd's unit 0, every second
            f"port {NTP}\nbindaddress 127.0.0.1\nallow 127.0.0.1\ncmdport 0\n"
            f"bindcmdaddress {SOCK}\npidfile {RUN}/chronyd.pid\nsourcedir {SOURCES_D}\n")
time.sleep(max(0.0, start - 0.5 - time.time()))
# -t: a TCP source (gpsd writes no SHM for gpsfake's default pty); -n: gpsd polls without a client.
fake = spawn(["gpsfake", "-t", "-n", "-q", "-1", "-W", "5", "-P", str(GPSD),
              "-c", f"{1 / make_nmea.SENTENCES_PER_FIX:.4f}", log], "gpsfake.log",
             env={**os.environ, "TMPDIR": TMP})
chronyd = spawn(["chronyd", "-x", "-d", "-u", "root", "-f", os.path.join(TMP, "chrony.conf")],
                "chronyd.log")
t0 = time.monotonic()
answer = subprocess.run(
    ["/usr/bin/python3", "-c", f"""
import ntplib, sys, time
end = time.monotonic() + 60
while time.monotonic() < end:
    try:
        r = ntplib.NTPClient().request('127.0.0.1', port={NTP}, version=4, timeout=1)
        if r.stratum == 1:
            print(r.stratum, r.ref_id.to_bytes(4, 'big').rstrip(b'\\0').decode(), r.leap)
            sys.exit(0)
    except ntplib.NTPException:
        pass
    time.sleep(0.5)
sys.exit(1)
"""], capture_output=True, text=True, timeout=90)
print(f"measure: NTP stratum 1 from the GPS {time.monotonic() - t0:.1f} s after chronyd started")
check(answer.stdout.split() == ["1", "GPS", "0"],
      f"2: NTP answers stratum 1, refid GPS, leap 0: {answer.stdout!r} {answer.stderr[-300:]!r}")

# 3: the daemon's view beside chronyc's.
check(wait_until(lambda: time_state(base)["chrony_synced"], 15), f"3: chrony_synced: {time_state(base)}")
# Right after selection the dispersion is seconds and falls fast: compare once chrony has settled
# (a minute at most: on a loaded machine gpsfake's sentences come late and chrony takes longer).
check(wait_until(lambda: time_state(base)["root_dispersion_s"] < 0.01, 60),
      f"3: settled: {time_state(base)['root_dispersion_s']}")
t = time_state(base)
rc, out, err = chronyc("-c", "-n", "tracking")
fields = out.strip().split(",")
check(rc == 0 and len(fields) == 14, f"3: chronyc tracking: {out!r} {err!r}")
check(t["stratum"] == int(fields[2]) == 1, f"3: stratum {t['stratum']} = chronyc's {fields[2]}")
check(t["ref"] == fields[1] == "GPS" and t["ref_id"] == fields[0],
      f"3: reference {t['ref']}/{t['ref_id']} = chronyc's {fields[1]}/{fields[0]}")
# A second apart at most: a settled clock's offset and dispersion move by far less than 5 ms a second.
check(abs(t["offset_s"] + float(fields[4])) < 0.005,
      f"3: offset {t['offset_s']} s (the opposite of chronyc's correction {fields[4]})")
check(abs(t["root_dispersion_s"] - float(fields[11])) < 0.005,
      f"3: root dispersion {t['root_dispersion_s']} s, chronyc's {fields[11]}")
check(t["leap"] == fields[13] == "Normal", f"3: leap {t['leap']}")
gps = [s for s in t["sources"] if s["name"] == "GPS"]
check(gps and gps[0]["mode"] == "refclock" and gps[0]["state"] == "selected",
      f"3: the GPS refclock is selected: {t['sources']}")
kernel = kernel_synced()
check(t["kernel_synced"] == kernel, f"3: kernel_synced {t['kernel_synced']} = adjtimex's {kernel}")
check(t["synced"] == kernel and (t["reason"] is None) == kernel,
      f"3: synced is chrony's verdict and the kernel's: {t['synced']} ({t['reason']})")
check(http_json(base, "GET", "/api/state")[1]["gps"]["state"] == "fix3d",
      "3: the same gpsd gives the daemon its fix")

# 4: the NTP servers from the console.
status, body = http_json(base, "POST", "/api/time/servers",
                         {"servers": ["127.0.0.2", "a.example\nallow all"]}, token)
check(status == 400 and "not a host name" in body.get("error", ""),
      f"4: a directive in a name is refused: {status} {body}")
check(not os.path.exists(os.path.join(SOURCES_D, "azeltrack.sources")), "4: nothing written")
status, body = http_json(base, "POST", "/api/time/servers", {"servers": ["127.0.0.2"]}, token)
check(status == 200 and body["time"]["servers"] == ["127.0.0.2"], f"4: servers set: {status} {body}")
written = open(os.path.join(SOURCES_D, "azeltrack.sources"), encoding="utf-8").read()
check("server 127.0.0.2 iburst\n" in written, f"4: the sources file: {written!r}")
rc, out, err = chronyc("-c", "-n", "sources")
check(",127.0.0.2," in out, f"4: chronyd reloaded its sources: {out!r}")
check(wait_until(lambda: any(s["name"] == "127.0.0.2" for s in time_state(base)["sources"]), 5),
      "4: the console lists the new source")
status, body = http_json(base, "POST", "/api/time/servers", {"servers": ["127.0.0.2"]})
check(status == 401, f"4: no login, no change: {status}")

# R21 (docs/reliability.md): malformed and non-client packets get no answer; a client still does.
for what, packet in [("10 bytes", bytes(10)), ("mode 0", b"\x20" + bytes(47)),
                     ("mode 6 (control)", b"\x26" + bytes(47)), ("version 7", b"\x3b" + bytes(47))]:
    check(ntp_packet(NTP, packet, 0.5) is None, f"R21: no answer to {what}")
check((ntp_query(NTP) or (0,))[0] == 1, "R21: a client is still answered, stratum 1")

# R20: the GPS unplugged (gpsfake and its gpsd killed): the served root dispersion grows instead of
# the server claiming the accuracy it had, and the daemon sees the GPS source fall silent.
os.killpg(fake.pid, signal.SIGKILL)
fake.wait(10)
held = ntp_query(NTP)
check(wait_until(lambda: ntp_query(NTP)[2] > held[2] + 0.001, 20),
      f"R20: root dispersion grows without the GPS: {held} -> {ntp_query(NTP)}")
check(wait_until(lambda: http_json(base, "GET", "/api/state")[1]["gps"]["state"] == "no_gpsd", 10),
      "R20: the daemon shows the GPS gone")
check(wait_until(lambda: [s for s in time_state(base)["sources"] if s["name"] == "GPS"][0]
                 ["last_rx_s"] > 3, 15), "R20: the GPS source's last sample ages")

# 5: chronyd gone: not synchronised, and the antenna still follows the Moon.
chronyd.send_signal(signal.SIGTERM)
chronyd.wait(10)
check(wait_until(lambda: time_state(base)["synced"] is False and
                 time_state(base)["chrony_error"] is not None, 10),
      f"5: chronyd stopped: not synchronised: {time_state(base)}")
state = http_json(base, "GET", "/api/state")[1]
check(state["mode"] == "TRACK" and state["target"]["name"].lower() == "moon",
      f"5: tracking carries on: {state['mode']} {state['target']}")
check(daemon.poll() is None, "5: the daemon runs on")
daemon.send_signal(signal.SIGTERM)
daemon.wait(10)

sys.exit(check.summary("time"))
