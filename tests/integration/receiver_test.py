#!/usr/bin/env python3
"""The receiver of pointing scans ([receiver], docs/calibration.md) on a real `azeltrack serve`: dB
lines over UDP, and rtl_power's CSV lines through a FIFO, reach /api/state `receiver`; malformed
lines are counted with their reason and change nothing else; a silence is counted once as missing;
the daemon answers throughout. Usage: receiver_test.py AZELTRACK"""
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-receiver-")
check = Checks()


def start(name, receiver_toml):
    web = free_port()
    config = os.path.join(TMP, name + ".toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web))
        f.write(receiver_toml)
    log = open(os.path.join(TMP, name + ".log"), "w", encoding="utf-8")
    p = subprocess.Popen([BIN, "serve", "--config", config], stdout=log, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{web}"
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start: " + open(log.name, encoding="utf-8").read())
    return p, base


def receiver(base):
    return http_json(base, "GET", "/api/state")[1]["receiver"]


try:
    # Refused at start, naming the key: nothing runs.
    for bad, key in (('source = "sdr"', "source"), ('source = "udp"', "port"),
                     ('source = "rtl_power"\npath = "power.csv"', "path"),
                     ('source = "udp"\nport = 70000', "port"), ('stale_s = 0', "stale_s")):
        config = os.path.join(TMP, "bad.toml")
        with open(config, "w", encoding="utf-8") as f:
            f.write(station_toml(web_port=free_port()) + "[receiver]\n" + bad + "\n")
        r = subprocess.run([BIN, "serve", "--config", config, "--run-for", "1"], capture_output=True,
                           text=True, timeout=20)
        check(r.returncode == 2 and f"[receiver].{key}" in r.stderr, f"{bad!r} refused: {r.stderr}")

    # No [receiver]: off.
    daemon, base = start("none", "")
    check(receiver(base) == {"source": "none", "state": "off"}, f"off by default: {receiver(base)}")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)

    # UDP: one reading per line; garbage counted, never taken for a reading.
    port = free_port()
    daemon, base = start("udp", f'[receiver]\nsource = "udp"\nport = {port}\nstale_s = 1.0\n')
    udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    udp.sendto(b"-42.5 dB\n", ("127.0.0.1", port))
    check(wait_until(lambda: receiver(base).get("power_db") == -42.5, 5), f"a reading: {receiver(base)}")
    r = receiver(base)
    check(r["state"] == "receiving" and r["good"] == 1 and r["malformed"] == 0, f"counted: {r}")
    for junk in (b"nan\n", b"12 dBm\n", b"\x00\xff\xfe", b"1e400\n", b"x" * 1400):
        udp.sendto(junk, ("127.0.0.1", port))
    udp.sendto(b"-41.0\n-40.0\n", ("127.0.0.1", port))
    check(wait_until(lambda: receiver(base)["good"] == 3, 5), f"two readings in one datagram: {receiver(base)}")
    r = receiver(base)
    check(r["malformed"] == 5 and r["last_malformed"] != "" and r["power_db"] == -40.0,
          f"five malformed, the last reason kept, the reading unchanged: {r}")
    missing_before = r["missing"]  # the wait for the first reading was a silence too
    check(wait_until(lambda: receiver(base)["state"] == "silent", 5), "silent after stale_s")
    wait_until(lambda: False, 1.5)
    r = receiver(base)
    check(r["missing"] == missing_before + 1 and r["power_db"] is None,
          f"one silence, one missing, however often asked: {r}")
    check(daemon.poll() is None, "the daemon runs on")
    daemon.send_signal(signal.SIGTERM)
    check(daemon.wait(10) == 0, "exits cleanly")

    # rtl_power through a FIFO, as `rtl_power … - > FIFO` writes it.
    fifo = os.path.join(TMP, "power.fifo")
    os.mkfifo(fifo)
    daemon, base = start("rtl", f'[receiver]\nsource = "rtl_power"\npath = "{fifo}"\n')
    lines = ("2025-06-01, 12:00:00, 1296000000, 1296500000, 1953.12, 10, -20.0, -10.0\n"
             "2025-06-01, 12:00:01, 1296000000, 1296500000, 1953.12, 10, -20.0, nan\n"
             "not a sweep\n")

    def writer():
        with open(fifo, "w", encoding="ascii") as f:  # blocks until the daemon reads
            f.write(lines)

    t = threading.Thread(target=writer)
    t.start()
    check(wait_until(lambda: receiver(base)["good"] == 1 and receiver(base)["malformed"] == 2, 5),
          f"one sweep, two malformed: {receiver(base)}")
    t.join(5)
    r = receiver(base)
    # The total power of −20 and −10 dB bins, averaged in linear units: −12.596 dB.
    check(r["power_db"] is not None and abs(r["power_db"] + 12.5963731) < 1e-6, f"the linear mean: {r}")
    check(r["path"] == fifo and r["source"] == "rtl_power", f"named: {r}")
    daemon.send_signal(signal.SIGTERM)
    check(daemon.wait(10) == 0, "exits cleanly")
finally:
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("receiver"))
