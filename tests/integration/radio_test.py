#!/usr/bin/env python3
"""The radio of docs/radio.md against a real `azeltrack serve` and Hamlib's own rigctld with its
dummy rig (`rigctld -m 1`), and WSJT-X datagrams built here as QDataStream writes them
(WSJTX/wsjtx Network/NetworkMessage.hpp, big-endian).

 1  EME, own echo at 1296 MHz: the rig's RX read back with `rigctl -m 2 … f` is the state's
    rx_hz, which is the dial plus the Moon's echo Doppler of the state within 1 Hz
 2  rigctld killed and restarted on its port: the link goes down and is up again within 5 s, with
    one log line each way
 3  a WSJT-X Status with a DX grid, schema 2 (WSJT-X 1.7's short form) and schema 3 (every field
    WSJT-X 2.6 sends): the running DX follows (not saved to the file)
 4  Status transmitting, schema 2 and 3: the antenna is held within 100 ms of the datagram's
    receipt (the daemon's own instants: `wsjtx.transmitting_since_unix_s`, the receipt, and
    `station_io.held_since_unix_s`, the first control tick that held the antenna), a rotctld `P`
    does not progress; not transmitting: the hold lifts and the antenna moves
 5  garbage, truncated (schema 2 and 3), unknown-schema and oversized datagrams while WSJT-X
    transmits: counted as malformed and nothing else changes (the DX, the hold and its start,
    the counts of decoded messages), the daemon runs on

Usage: radio_test.py AZELTRACK"""
import os
import socket
import struct
import subprocess
import sys
import tempfile
import time

from daemon_harness import (Checks, free_port, http_json, rotctld, station_toml, stop_at_exit,
                            wait_until)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-radio-")
check = Checks()
procs = []
DIAL_MHZ = 1296.1  # [sky] band "1296" is 1296.100 MHz: the state's moon figures are at the dial


stop_at_exit(procs, TMP)


def start_rigctld(port):
    p = subprocess.Popen(["rigctld", "-m", "1", "-T", "127.0.0.1", "-t", str(port)],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    procs.append(p)
    wait_until(lambda: can_connect(port), 5, 0.05)
    return p


def can_connect(port):
    try:
        socket.create_connection(("127.0.0.1", port), timeout=0.5).close()
        return True
    except OSError:
        return False


def rig_frequency(port):
    out = subprocess.run(["rigctl", "-m", "2", "-r", f"127.0.0.1:{port}", "f"],
                         capture_output=True, text=True, timeout=5, check=True)
    return float(out.stdout.split()[0])


def utf8(text):
    data = text.encode()
    return struct.pack(">I", len(data)) + data


def status(dx_grid="", dx_call="", transmitting=False):
    """A schema-2 Status ending after its DX grid (WSJT-X 1.7's form)."""
    body = struct.pack(">III", 0xADBCCBDA, 2, 1) + utf8("WSJT-X")
    body += struct.pack(">Q", 1296100000) + utf8("Q65") + utf8(dx_call) + utf8("-20") + utf8("Q65")
    body += struct.pack(">???", True, transmitting, False) + struct.pack(">II", 1500, 1500)
    body += utf8("W1AW") + utf8("FN31") + utf8(dx_grid)
    return body


def status3(dx_grid="", dx_call="", transmitting=False):
    """A schema-3 Status with every field (WSJT-X 2.6's form, NetworkMessage.hpp's order): id,
    dial, mode, DX call, report, Tx mode, Tx enabled, Transmitting, Decoding, Rx DF, Tx DF, DE call,
    DE grid, DX grid, Tx watchdog, sub-mode, fast mode, special operation mode, frequency
    tolerance, T/R period, configuration name, Tx message."""
    body = struct.pack(">III", 0xADBCCBDA, 3, 1) + utf8("WSJT-X")
    body += struct.pack(">Q", 1296100000) + utf8("Q65") + utf8(dx_call) + utf8("-20") + utf8("Q65")
    body += struct.pack(">???", True, transmitting, False) + struct.pack(">II", 1500, 1500)
    body += utf8("W1AW") + utf8("FN31") + utf8(dx_grid) + struct.pack(">?", False) + utf8("A")
    body += struct.pack(">?B", False, 0) + struct.pack(">II", 100, 60) + utf8("EME 23cm")
    body += utf8(f"{dx_call} W1AW FN31" if dx_call else "")
    return body


STATUS = {2: status, 3: status3}


def state(base):
    return http_json(base, "GET", "/api/state")[1]


RIG = free_port()
WEB = free_port()
ROT = free_port()
UDP = free_port()
start_rigctld(RIG)
config = os.path.join(TMP, "radio.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=WEB, rotctld_port=ROT, mount_rate_deg_s=10))
    f.write('[sky]\nband = "1296"\n')
    f.write(f'[radio]\nrigctld = "127.0.0.1:{RIG}"\ndoppler = "eme"\neme_mode = "self"\n'
            f"dial_mhz = {DIAL_MHZ}\n")
    f.write(f'[wsjtx]\nlisten = "127.0.0.1:{UDP}"\n')
log_path = os.path.join(TMP, "daemon.log")
log = open(log_path, "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", config], stdout=log, stderr=subprocess.STDOUT)
procs.append(daemon)
base = f"http://127.0.0.1:{WEB}"
if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
    print(open(log_path, encoding="utf-8").read())
    sys.exit("the daemon did not start")


def log_text():
    log.flush()
    return open(log_path, encoding="utf-8").read()


# 1: the rig on the Moon's own echo.
check(wait_until(lambda: state(base)["radio"]["rx_hz"] is not None, 5),
      f"1: the RX written: {state(base)['radio']}")
before = state(base)
rig_hz = rig_frequency(RIG)
after = state(base)
radio = before["radio"] if abs(before["radio"]["rx_hz"] - rig_hz) < 1 else after["radio"]
print(f"1: rig {rig_hz:.0f} Hz, state rx_hz {radio['rx_hz']:.0f} at {radio['at']}, "
      f"correction {radio['rx_correction_hz']:.2f} Hz, moon echo "
      f"{after['moon']['echo_doppler_hz']:.2f} Hz")
check(abs(radio["rx_hz"] - rig_hz) < 1, f"1: the rig reads back the state's rx_hz: {rig_hz}")
check(radio["link"] == "up" and radio["doppler"] == "eme", f"1: link and source: {radio}")
expected = DIAL_MHZ * 1e6 + after["moon"]["echo_doppler_hz"]
check(abs(rig_hz - expected) <= 1.0, f"1: dial + echo Doppler {expected:.1f} vs rig {rig_hz}")
check(abs(radio["rx_correction_hz"] - after["moon"]["echo_doppler_hz"]) < 0.5,
      "1: the correction is the state's echo Doppler")

# 2: rigctld killed and restarted.
rig = procs[0]
rig.terminate()
rig.wait(5)
check(wait_until(lambda: state(base)["radio"]["link"].startswith("down"), 5),
      f"2: link down: {state(base)['radio']['link']}")
time.sleep(1.0)  # a few retries while nothing listens: none of them logged
restarted = time.monotonic()
start_rigctld(RIG)
check(wait_until(lambda: state(base)["radio"]["link"] == "up", 5),
      f"2: link up again within 5 s: {state(base)['radio']['link']}")
print(f"2: link up {time.monotonic() - restarted:.2f} s after rigctld restarted")
text = log_text()
check(text.count(": link down:") == 1 and text.count(": link up") == 2,
      "2: one log line each way (and the first link up): "
      f"{[line for line in text.splitlines() if 'link' in line]}")
check(daemon.poll() is None, "2: the daemon runs on")

# 3: the DX grid follows WSJT-X, live, not saved: schema 2, then schema 3.
udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
for schema, grid, call in [(2, "JO65MR", "OZ1ABC"), (3, "KP20LE", "OH2XYZ")]:
    udp.sendto(STATUS[schema](dx_grid=grid, dx_call=call), ("127.0.0.1", UDP))
    check(wait_until(lambda: state(base)["wsjtx"]["dx_grid"] == grid, 2),
          f"3: schema {schema}: wsjtx dx_grid: {state(base)['wsjtx']}")
    check(wait_until(lambda: http_json(base, "GET", "/api/config")[1]["dx_grid"] == grid, 2),
          f"3: schema {schema}: the running DX is WSJT-X's")
    check(wait_until(lambda: state(base)["moon"]["dx_echo_doppler_hz"] is not None, 3),
          f"3: schema {schema}: the Moon's DX echo Doppler is computed for it")
    check(grid not in open(config, encoding="utf-8").read(), f"3: {grid} not saved to the file")
GRID = "KP20LE"


def hold_after(schema, transmitting):
    """Sends a Status; returns the state once the antenna's hold says the same (None: never)."""
    udp.sendto(STATUS[schema](dx_grid=GRID, transmitting=transmitting), ("127.0.0.1", UDP))
    seen = {}

    def probe():
        seen["state"] = state(base)
        return (seen["state"]["station_io"]["held_since_unix_s"] is not None) == transmitting
    return seen["state"] if wait_until(probe, 2, 0.005) else None


# 4: transmitting holds the antenna within 100 ms, schema 2 and 3; not transmitting releases it.
for schema in (2, 3):
    sent = time.monotonic()
    held = hold_after(schema, True)
    seen_s = time.monotonic() - sent
    check(held is not None and held["wsjtx"]["transmitting"], f"4: schema {schema}: held")
    if held is not None:
        latency_ms = 1000 * (held["station_io"]["held_since_unix_s"]
                             - held["wsjtx"]["transmitting_since_unix_s"])
        print(f"4: schema {schema}: antenna held {latency_ms:.2f} ms after the Status's receipt "
              f"(seen in /api/state {1000 * seen_s:.0f} ms after sending)")
        check(-1 < latency_ms < 100, f"4: schema {schema}: held within 100 ms: {latency_ms:.1f} ms")
    if schema == 2:  # a move asked for while held does not start
        start = state(base)["antenna"]
        rotctld(ROT, [f"P {start['az_deg'] + 40:.1f} 30"])
        time.sleep(1.5)
        now = state(base)["antenna"]
        check(abs(now["az_deg"] - start["az_deg"]) < 0.5,
              f"4: held while transmitting: {start['az_deg']:.2f} -> {now['az_deg']:.2f}")
    released = hold_after(schema, False)
    check(released is not None and released["wsjtx"]["transmitting_since_unix_s"] is None
          and not released["wsjtx"]["hold"], f"4: schema {schema}: released: {released}")
check(wait_until(lambda: abs(state(base)["antenna"]["az_deg"] - start["az_deg"]) > 2, 3),
      "4: moves once WSJT-X receives")

# 5: garbage, truncated, unknown-schema and oversized datagrams while WSJT-X transmits.
hold_after(3, True)
before = state(base)
udp.sendto(b"not wsjt-x at all", ("127.0.0.1", UDP))
udp.sendto(status(dx_grid="JO65MR")[:-3], ("127.0.0.1", UDP))
udp.sendto(status3(dx_grid="JO65MR")[:-9], ("127.0.0.1", UDP))
udp.sendto(struct.pack(">III", 0xADBCCBDA, 4, 1) + status3()[12:], ("127.0.0.1", UDP))
udp.sendto(b"\xad\xbc\xcb\xda" + b"\0" * 9000, ("127.0.0.1", UDP))
check(wait_until(lambda: state(base)["wsjtx"]["malformed"] == before["wsjtx"]["malformed"] + 5, 2),
      f"5: five counted malformed: {state(base)['wsjtx']}")
after = state(base)
for key in ["dx_grid", "dx_call", "transmitting", "transmitting_since_unix_s", "hold", "received",
            "tr_period_s", "last_heard"]:
    check(after["wsjtx"][key] == before["wsjtx"][key],
          f"5: wsjtx {key} unchanged: {before['wsjtx'][key]} -> {after['wsjtx'][key]}")
# The same start, to the microseconds of converting the tick's steady clock to UTC per request.
check(abs(after["station_io"]["held_since_unix_s"] - before["station_io"]["held_since_unix_s"])
      < 1e-3, "5: the antenna's hold goes on from the same instant")
check(http_json(base, "GET", "/api/config")[1]["dx_grid"] == GRID, "5: the running DX unchanged")
check(hold_after(3, False) is not None, "5: a good Status still releases it")
check(daemon.poll() is None, "5: the daemon runs on")
sys.exit(check.summary("radio"))
