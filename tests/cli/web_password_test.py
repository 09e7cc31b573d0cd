#!/usr/bin/env python3
"""`azeltrack web password` as a new operator meets it (docs/command-line.md). On a terminal (a pty
here) it asks twice without echoing what is typed, and refuses a short or mistyped password saving
nothing; from a pipe it says what it reads; with nothing to read it says so. The daemon's first
start prints a generated password with a command to change it that works as printed, from
another directory. Usage: web_password_test.py AZELTRACK"""
import os
import pty
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-webpw-")
failures = []
passed = 0


def check(ok, what):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(what)
        print("FAIL:", what)


def read_until(fd, pattern, seconds=10.0):
    """Everything the pty printed until `pattern` (a regex) appears, or the time is up."""
    out, end = b"", time.monotonic() + seconds
    while time.monotonic() < end and not re.search(pattern, out.decode(errors="replace")):
        ready, _, _ = select.select([fd], [], [], 0.1)
        if ready:
            try:
                chunk = os.read(fd, 4096)
            except OSError:
                break
            if not chunk:
                break
            out += chunk
    return out.decode(errors="replace")


def on_terminal(config, answers):
    """Runs `web password` on a pty, answering each prompt in turn; returns (rc, screen)."""
    pid, fd = pty.fork()
    if pid == 0:
        os.execv(BIN, [BIN, "web", "password", "--config", config])
    screen = read_until(fd, r"password.*not shown\): ")
    for i, answer in enumerate(answers):
        os.write(fd, (answer + "\n").encode())
        if i + 1 < len(answers):
            screen += read_until(fd, r"The same again: ")
    # The rest, until it exits and the pty closes (a pattern never found): read all the while,
    # since a program restoring the terminal waits for its output to be read.
    screen += read_until(fd, r"(?!x)x", 30.0)
    _, status = os.waitpid(pid, 0)
    os.close(fd)
    return os.waitstatus_to_exitcode(status), screen


def saved_hash(config):
    return "password_hash" in open(config, encoding="utf-8").read()


def free_port():
    import socket
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def fresh(name, web_port=0):
    """A station that tracks nothing, its servers off but the console (when given a port)."""
    path = os.path.join(TMP, name)
    with open(path, "w", encoding="utf-8") as f:
        f.write('schema_version = 2\n[station]\ngrid = "FN06HE"\n[target]\nname = "stop"\n'
                f'[rotctld]\nport = 0\n[pstrotator]\nport = 0\n[web]\nport = {web_port}\n')
    return path


try:
    c = fresh("short.toml")
    rc, screen = on_terminal(c, ["short"])
    check(rc != 0 and "at least 8 characters" in screen and not saved_hash(c),
          f"a short password refused, nothing saved: rc {rc} {screen!r}")

    c = fresh("differ.toml")
    rc, screen = on_terminal(c, ["first-password", "second-password"])
    check(rc != 0 and "differ" in screen and not saved_hash(c),
          f"two different passwords refused, nothing saved: rc {rc} {screen!r}")

    c = fresh("good.toml")
    rc, screen = on_terminal(c, ["a-long-password", "a-long-password"])
    check(rc == 0 and saved_hash(c), f"typed twice: saved: rc {rc} {screen!r}")
    check("a-long-password" not in screen, f"the password never shows on the screen: {screen!r}")
    check("The same again" in screen, "asked a second time")

    c = fresh("pipe.toml")
    r = subprocess.run([BIN, "web", "password", "--config", c], input=b"piped-password\n",
                       capture_output=True)
    check(r.returncode == 0 and saved_hash(c) and b"reading the new password from standard input"
          in r.stderr, f"from a pipe it says what it reads: {r.returncode} {r.stderr!r}")

    c = fresh("empty.toml")
    r = subprocess.run([BIN, "web", "password", "--config", c], stdin=subprocess.DEVNULL,
                       capture_output=True)
    check(r.returncode != 0 and b"no password on standard input" in r.stderr and not saved_hash(c),
          f"nothing to read: said, nothing saved: {r.returncode} {r.stderr!r}")

    # The first start's hint, run as printed from another directory.
    c = fresh("serve.toml", free_port())
    log = open(os.path.join(TMP, "serve.log"), "w+", encoding="utf-8")
    daemon = subprocess.Popen([BIN, "serve", "--config", "serve.toml"], stdout=log,
                              stderr=subprocess.STDOUT, cwd=TMP)
    hint = None
    end = time.monotonic() + 20
    while time.monotonic() < end and hint is None:
        log.seek(0)
        m = re.search(r"change it with `([^`]+)`", log.read())
        hint = m.group(1) if m else None
        time.sleep(0.2)
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)
    check(hint is not None and hint.startswith(BIN + " web password --config /"),
          f"the first start names the command with absolute paths: {hint!r}")
    if hint:
        r = subprocess.run(hint.split(" "), input=b"changed-password\n", capture_output=True,
                           cwd="/")
        check(r.returncode == 0, f"the hint works as printed, from /: {r.returncode} {r.stderr!r}")
finally:
    shutil.rmtree(TMP, ignore_errors=True)

print(f"web_password: {passed} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
