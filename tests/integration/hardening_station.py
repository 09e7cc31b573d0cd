"""The station the hardening tests (hardening_*_test.py) run: examples/sim.toml with free ports and
private pseudo-terminals, a password and an API token, the daemon started and stopped, the
processes a test starts (killed at exit whatever happens), the configuration command line, and
the figures each test prints at its end (docs/reliability.md "Hardening")."""
import atexit
import collections
import fcntl
import http.client
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

from daemon_harness import Checks, tle_with_epoch_now, wait_until
from hardening_clients import ROT_PORT, WEB_PORT, request, state

BIN = os.path.realpath(sys.argv[1])
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
TMP = tempfile.mkdtemp(prefix="azt-hardening-")
CONFIG = os.path.join(TMP, "azeltrack.toml")
LOCK = CONFIG + ".lock"
PTY_DIR = os.path.join(TMP, "pty")
GS232B = os.path.join(PTY_DIR, "gs232b")
PASSWORD = "a-long-password"
NORAD = "25544"
check = Checks()
figures = collections.OrderedDict()  # row -> what was measured, printed at the end


def figure(row, text):
    figures.setdefault(row, []).append(text)
    print(f"measure: row {row}: {text}")


def wait_for(what, probe, seconds=10.0):
    return check(wait_until(probe, seconds, every=0.05),
                 f"timed out after {seconds} s waiting for {what}")


def config_get(key):
    r = subprocess.run([BIN, "config", "get", "--config", CONFIG, key], capture_output=True,
                       timeout=20)
    return r.stdout.decode().strip() if r.returncode == 0 else f"rc={r.returncode} {r.stderr!r}"


def config_set(key, value):
    return subprocess.run([BIN, "config", "set", "--config", CONFIG, key, value],
                          capture_output=True, timeout=20)


def as_float(text):
    try:
        return float(text)
    except ValueError:
        return None


# ---- Processes this test starts (killed at exit whatever happens) ------------------------------

started = []  # (Popen, new process group?)


def cleanup():
    for p, group in started:
        if p.poll() is None:
            try:
                if group:
                    os.killpg(p.pid, signal.SIGKILL)
                else:
                    p.kill()
            except ProcessLookupError:
                pass
            p.wait()
    shutil.rmtree(TMP, ignore_errors=True)


atexit.register(cleanup)
daemon = None
daemon_log = None


def start_daemon(name):
    global daemon, daemon_log
    daemon_log = os.path.join(TMP, f"{name}.log")
    with open(daemon_log, "wb") as log:
        daemon = subprocess.Popen([BIN, "serve", "--config", CONFIG], stdout=log, stderr=log)
    started.append((daemon, False))
    return wait_for(f"the daemon ({name}) to answer with a known position",
                    lambda: state()["antenna"]["known"], 15)


def stop_daemon():
    daemon.terminate()
    return daemon.wait(10)


def alive(row):
    """The daemon process is running and /api/state answers 200 with JSON."""
    r = request("GET", "/api/state")
    return check(daemon.poll() is None and r.status == 200 and isinstance(r.body, dict),
                 f"row {row}: the daemon is alive and answers /api/state: exit "
                 f"{daemon.poll()}, {r.status} {r.raw[:200]!r}")


def hold_lock(seconds):
    """`flock CONFIG.lock sleep S` in its own process group; returns it and when it was started
    (the lock is released no sooner than S seconds after that) once the lock is held."""
    t0 = time.monotonic()
    p = subprocess.Popen(["flock", LOCK, "sleep", str(seconds)], start_new_session=True)
    started.append((p, True))

    def held():
        fd = os.open(LOCK, os.O_RDWR)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            fcntl.flock(fd, fcntl.LOCK_UN)  # not held yet: give it back at once
            return False
        except BlockingIOError:
            return True
        finally:
            os.close(fd)

    wait_for("flock to hold the config lock", held, 5)
    return p, t0


def in_thread(fn):
    """Runs fn in a thread; returns (thread, result list: [value or exception, end time])."""
    out = []

    def run():
        try:
            out.append(fn())
        except Exception as e:  # noqa: BLE001 - reported by the check that reads it
            out.append(e)
        out.append(time.monotonic())

    t = threading.Thread(target=run, daemon=True)
    t.start()
    return t, out


def poll_state_while(busy, at_least=20):
    """GET /api/state on fresh connections until busy() is false and at least `at_least` were
    made; returns the worst time, the count and the non-200 answers."""
    worst, n, bad = 0.0, 0, []
    while busy() or n < at_least:
        try:
            r = request("GET", "/api/state", timeout=2)
            worst = max(worst, r.seconds)
            if r.status != 200:
                bad.append(r.status)
        except (OSError, http.client.HTTPException) as e:
            worst = max(worst, 2.0)
            bad.append(repr(e))
        n += 1
        time.sleep(0.02)
    return worst, n, bad


# ---- The configuration: examples/sim.toml with free ports and private pseudo-terminals ---------


def substitute(text, pattern, replacement):
    new, n = re.subn(pattern, replacement, text, count=1, flags=re.S)
    if n != 1:
        raise SystemExit(f"examples/sim.toml changed: {pattern!r} not found")
    return new


def config_checks(candidate):
    path = os.path.join(TMP, "candidate.toml")
    with open(path, "w") as f:
        f.write(candidate)
    r = subprocess.run([BIN, "config", "check", "--config", path], capture_output=True)
    os.unlink(path)
    return r


def prepare():
    """Writes the configuration (with row 2's catalogue) and the password; returns row 5's rotctld
    idle timeout (None when this build has no such key) and an API token."""
    # Row 2's catalogue: the name line is Latin-1 (0xE9 alone is not UTF-8).
    with open(os.path.join(TMP, "sats.tle"), "wb") as f:
        f.write(tle_with_epoch_now(b"ISS Z\xe9RYA"))
    text = open(os.path.join(ROOT, "examples/sim.toml")).read()
    text = substitute(text, r'(\[target\]\s*\nname = )"moon"', r'\1"stop"')
    text = substitute(text, r'(\[rotctld\][^\[]*?\nport = )\d+', rf'\g<1>{ROT_PORT}')
    text = substitute(text, r'(\[pstrotator\][^\[]*?\nport = )\d+', r'\g<1>0')
    text = substitute(text, r'(\[web\][^\[]*?\nport = )\d+', rf'\g<1>{WEB_PORT}')
    for name in ["gs232b", "easycomm2", "spid"]:  # not /run/azeltrack: another daemon may use it
        text = substitute(text, rf'device = "pty:{name}"', f'device = "pty:{PTY_DIR}/{name}"')
    text = re.sub(r'\nidle_timeout_s = [^\n]*', "", text)  # set below when this build has it
    text += '\n[satellites]\nfile = "sats.tle"\n'
    # Row 5's rotctld idle timeout: tested at 10 s (the least allowed) if this build has the key.
    idle_s = 10
    with_idle = substitute(text, r'(\[rotctld\][^\[]*?\nport = \d+)',
                           rf'\g<1>\nidle_timeout_s = {idle_s}')
    if config_checks(with_idle).returncode == 0:
        text = with_idle
    else:
        idle_s = None
        r = config_checks(text)
        if r.returncode != 0:
            raise SystemExit(f"the test's configuration does not pass `config check`: {r.stderr!r}")
    with open(CONFIG, "w") as f:
        f.write(text)
    r = subprocess.run([BIN, "web", "password", "--config", CONFIG],
                       input=(PASSWORD + "\n").encode(), capture_output=True)
    if r.returncode != 0:
        raise SystemExit(f"azeltrack web password: rc {r.returncode} {r.stderr!r}")
    token = subprocess.run([BIN, "web", "token", "--config", CONFIG], check=True,
                           capture_output=True).stdout.decode().strip()

    return idle_s, token

def stop_all():
    """What a test's `finally` does: the daemon's log if a check failed, then every process the
    test started stopped and its directory removed."""
    if check.failed and daemon_log and os.path.exists(daemon_log):
        print(open(daemon_log, "rb").read()[-3000:].decode("utf-8", "replace"), file=sys.stderr)
    cleanup()


def report(t_start):
    """Prints the figures and the count of checks; exits 1 if one failed."""
    print(f"figures ({time.monotonic() - t_start:.1f} s):")
    for row in sorted(figures):
        for text in figures[row]:
            print(f"  row {row}: {text}")
    print(f"{check.passed} passed, {check.failed} failed")
    sys.exit(1 if check.failed else 0)
