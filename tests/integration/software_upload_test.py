#!/usr/bin/env python3
"""The console's package upload (docs/packaging.md) against a real `azeltrack serve` started as the
package's unit starts it (--update-inbox, --update-status): what crosses the HTTP transport.
- curl's upload (`Expect: 100-continue`, then the body) of a real package built by dpkg-deb is
  left in the inbox byte for byte, its SHA-256 in the answer and in GET /api/software;
- an upload from a client without a login is refused (401) from its head, and one that sends
  its body anyway still reads that answer; a logged-in one announcing more than 64 MiB is
  refused (413) from its head; nothing reaches the inbox;
- one upload at a time, decided from the head: a second one while the first is still arriving
  is refused (409) before its body is read;
- while a 48 MiB package is received, hashed and written (fsynced) the event loop keeps
  answering: the slowest GET /api/state during the upload is measured and must stay under 250 ms;
- the helper's report (written here as the helper writes it) is shown, and a bad report is an
  error on the page, not a crash.
Usage: software_upload_test.py AZELTRACK"""
import hashlib
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

from daemon_harness import (Checks, free_port, http_json, http_upload, station_toml,
                            upload_test_deb, wait_until)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-software-")
CONFIG = os.path.join(TMP, "azeltrack.toml")
INBOX = os.path.join(TMP, "update")
STATUS = os.path.join(TMP, "status")
PORT = free_port()
BASE = f"http://127.0.0.1:{PORT}"
check = Checks()


def build_deb(filler_bytes):
    """The upload test's package and its bytes."""
    path = upload_test_deb(TMP, filler_bytes)
    with open(path, "rb") as f:
        return path, f.read()


def curl_upload(path):
    """curl's upload of a file, as a script would send it: `Expect: 100-continue` first."""
    return subprocess.run(["curl", "-sS", "-H", f"Authorization: Bearer {TOKEN}",
                           "-H", "Content-Type: application/vnd.debian.binary-package",
                           "-H", "Expect: 100-continue", "--data-binary", f"@{path}",
                           f"{BASE}/api/software/update"], capture_output=True, text=True,
                          timeout=120)


def raw_head(headers):
    """Sends a request head alone and returns the status line of the answer."""
    with socket.create_connection(("127.0.0.1", PORT), timeout=5) as s:
        s.sendall(headers.encode())
        return s.recv(4096).split(b"\r\n", 1)[0].decode(errors="replace")


def slowest_state_during(work):
    """Runs `work` in a thread and asks GET /api/state meanwhile: the slowest answer, seconds."""
    thread = threading.Thread(target=work)
    slowest = 0.0
    thread.start()
    while thread.is_alive():
        t0 = time.monotonic()
        status, _ = http_json(BASE, "GET", "/api/state")
        slowest = max(slowest, time.monotonic() - t0)
        check(status == 200, f"GET /api/state during the upload: {status}")
        time.sleep(0.01)
    thread.join()
    return slowest


with open(CONFIG, "w", encoding="utf-8") as f:
    f.write(station_toml(PORT))
subprocess.run([BIN, "web", "password", "--config", CONFIG], input=b"a-long-password\n",
               check=True, capture_output=True)
TOKEN = subprocess.run([BIN, "web", "token", "--config", CONFIG], check=True,
                       capture_output=True).stdout.decode().strip()
log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", CONFIG, "--update-inbox", INBOX,
                           "--update-status", STATUS], stdout=log, stderr=log)
try:
    check(wait_until(lambda: http_json(BASE, "GET", "/api/state")[0] == 200, 20), "daemon up")
    status, page = http_json(BASE, "GET", "/api/software")
    check(status == 200 and page["updates"] is True and page["pending"] is False,
          f"the software page: {status} {page}")

    small, small_bytes = build_deb(200 * 1024)
    curl = curl_upload(small)
    check('"sha256"' in curl.stdout, f"curl's upload with Expect: 100-continue: {curl.stdout} {curl.stderr}")
    sha = hashlib.sha256(small_bytes).hexdigest()
    with open(os.path.join(INBOX, "request.deb"), "rb") as f:
        check(f.read() == small_bytes, "the inbox holds the package byte for byte")
    _, page = http_json(BASE, "GET", "/api/software")
    check(page["pending"] is True and page["upload"]["sha256"] == sha, f"shown as pending: {page}")
    os.remove(os.path.join(INBOX, "request.deb"))  # as the helper takes it

    head = (f"POST /api/software/update HTTP/1.1\r\nHost: 127.0.0.1\r\n"
            f"Content-Type: application/vnd.debian.binary-package\r\n")
    check(" 401 " in raw_head(head + "Content-Length: 1000000\r\n\r\n"),
          "a megabyte without a login: 401 from the head, the body never taken in")
    status, reply = http_upload(BASE, "/api/software/update", small_bytes)
    check(status == 401 and "login" in reply["error"],
          f"a client that sends the body anyway reads the 401: {status} {reply}")
    check(" 413 " in raw_head(head + f"Authorization: Bearer {TOKEN}\r\n"
                                     "Content-Length: 70000000\r\n\r\n"),
          "over 64 MiB with a login: 413 from the head")
    # docs/reliability.md "Hardening, round three" row 10: one upload at a time, decided from the
    # head. While one connection is still sending a large body, a second upload is answered 409
    # before its body is read; once the first connection is gone, the slot is free again.
    first = socket.create_connection(("127.0.0.1", PORT), timeout=5)
    first.sendall((head + f"Authorization: Bearer {TOKEN}\r\nContent-Length: 50000000\r\n\r\n"
                   ).encode() + b"!<arch>\n" + b"x" * 65536)
    check(wait_until(lambda: " 409 " in raw_head(head + f"Authorization: Bearer {TOKEN}\r\n"
                                                 "Content-Length: 50000000\r\n\r\n"), 5),
          "a second upload while the first is being received: 409 from its head")
    first.close()
    check(wait_until(lambda: " 400 " in raw_head(head + f"Authorization: Bearer {TOKEN}\r\n"
                                                 "Content-Length: 10\r\n\r\n!<arch>\nxx"), 5),
          "the slot is free once the first connection has gone (a small upload is read: 400)")
    status, reply = http_upload(BASE, "/api/software/update", b"!<arch>\n" + b"x" * 100,
                                token=TOKEN)
    check(status == 400 and "not a Debian package" in reply["error"], f"a broken archive: {reply}")
    check(not os.path.exists(os.path.join(INBOX, "request.deb")), "nothing refused reached the inbox")

    big, big_bytes = build_deb(48 * 1024 * 1024)
    answer = {}
    # curl sends it (another process: this one's threads would share Python's lock and time it).
    slowest = slowest_state_during(lambda: answer.update(out=curl_upload(big).stdout))
    print(f"software_upload: {len(big_bytes) / 2**20:.1f} MiB package; slowest GET /api/state "
          f"during its upload {slowest * 1000:.1f} ms")
    check(hashlib.sha256(big_bytes).hexdigest() in answer.get("out", ""),
          f"the 48 MiB package: {answer}")
    check(slowest < 0.25, f"the loop answered within 250 ms during the upload ({slowest:.3f} s)")
    check(os.path.getsize(os.path.join(INBOX, "request.deb")) == len(big_bytes), "the big package stored")
    status, reply = http_upload(BASE, "/api/software/update", small_bytes, token=TOKEN)
    check(status == 409 and "waiting for the update helper" in reply["error"],
          f"a second package while one waits: {status} {reply}")

    with open(STATUS, "w", encoding="utf-8") as f:
        f.write(f"phase=installed\npercent=100\nmessage=installed\nfrom=0.1.0\nto=0.1.0+9\n"
                f"sha256={sha}\nat={int(time.time())}\n")
    _, page = http_json(BASE, "GET", "/api/software")
    check(page["helper"]["phase"] == "installed" and page["helper"]["to"] == "0.1.0+9",
          f"the helper's report: {page}")
    with open(STATUS, "wb") as f:
        f.write(b"phase=\xff\x00garbage\n")
    status, page = http_json(BASE, "GET", "/api/software")
    check(status == 200 and page["helper"] is None and "phase" in page.get("helper_error", ""),
          f"a bad report is an error on the page: {page}")
    check(daemon.poll() is None, "the daemon still runs")
finally:
    daemon.terminate()
    daemon.wait(timeout=10)
    log.close()
    if check.failed:
        with open(os.path.join(TMP, "daemon.log"), encoding="utf-8", errors="replace") as f:
            print(f.read()[-3000:], file=sys.stderr)
    shutil.rmtree(TMP, ignore_errors=True)
sys.exit(check.summary("software_upload"))
