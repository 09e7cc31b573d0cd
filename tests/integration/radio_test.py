#!/usr/bin/env python3
"""The radio of docs/radio.md against a real `azeltrack serve` and Hamlib's own rigctld with its
dummy rig (`rigctld -m 1`), and WSJT-X datagrams built here as QDataStream writes them
(WSJTX/wsjtx Network/NetworkMessage.hpp, big-endian).

 1  EME, own echo at 1296 MHz: the rig's RX read back with `rigctl -m 2 … f` is the state's
    rx_hz, which is the dial plus the Moon's echo Doppler of the state within 1 Hz
 2  rigctld killed and restarted on its port: the link goes down and is up again within 5 s, with
    one log line each way
 3  a WSJT-X Status with a DX grid: the running DX follows (not saved to the file)
 4  Status transmitting: the antenna holds (a rotctld `P` does not progress); not transmitting:
    it moves
 5  garbage, truncated and oversized datagrams: counted as malformed, the daemon runs on

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

# 3: the DX grid follows WSJT-X, live, not saved.
udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
udp.sendto(status(dx_grid="JO65MR", dx_call="OZ1ABC"), ("127.0.0.1", UDP))
check(wait_until(lambda: state(base)["wsjtx"]["dx_grid"] == "JO65MR", 2),
      f"3: wsjtx dx_grid: {state(base)['wsjtx']}")
check(wait_until(lambda: http_json(base, "GET", "/api/config")[1]["dx_grid"] == "JO65MR", 2),
      "3: the running DX is WSJT-X's")
check(wait_until(lambda: state(base)["moon"]["dx_echo_doppler_hz"] is not None, 3),
      "3: the Moon's DX echo Doppler is computed for it")
check("JO65MR" not in open(config, encoding="utf-8").read(), "3: not saved to the file")

# 4: transmitting holds the antenna.
udp.sendto(status(dx_grid="JO65MR", transmitting=True), ("127.0.0.1", UDP))
check(wait_until(lambda: state(base)["wsjtx"]["transmitting"], 1, 0.02), "4: transmitting")
start = state(base)["antenna"]
rotctld(ROT, [f"P {start['az_deg'] + 40:.1f} 30"])
time.sleep(1.5)
held = state(base)["antenna"]
check(abs(held["az_deg"] - start["az_deg"]) < 0.5,
      f"4: held while transmitting: {start['az_deg']:.2f} -> {held['az_deg']:.2f}")
udp.sendto(status(dx_grid="JO65MR", transmitting=False), ("127.0.0.1", UDP))
check(wait_until(lambda: abs(state(base)["antenna"]["az_deg"] - start["az_deg"]) > 2, 3),
      "4: moves once WSJT-X receives")

# 5: garbage, truncated and oversized datagrams.
malformed = state(base)["wsjtx"]["malformed"]
udp.sendto(b"not wsjt-x at all", ("127.0.0.1", UDP))
udp.sendto(status(dx_grid="JO65MR")[:-3], ("127.0.0.1", UDP))
udp.sendto(b"\xad\xbc\xcb\xda" + b"\0" * 9000, ("127.0.0.1", UDP))
check(wait_until(lambda: state(base)["wsjtx"]["malformed"] == malformed + 3, 2),
      f"5: three counted malformed: {state(base)['wsjtx']}")
check(state(base)["wsjtx"]["dx_grid"] == "JO65MR", "5: nothing changed by them")
check(daemon.poll() is None, "5: the daemon runs on")
sys.exit(check.summary("radio"))
