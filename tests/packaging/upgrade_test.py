#!/usr/bin/env python3
"""The package's life in a throw-away Debian 12 root (docs/packaging.md): install version N, start
the daemon as its unit would, change settings through the daemon's API, upgrade to N+1 without a
terminal (`DEBIAN_FRONTEND=noninteractive apt-get install ./new.deb`), and find every setting
unchanged and the daemon running again; then remove (the settings stay) and purge (the user, the
unit and /var/lib/azeltrack go).

The root is made by debootstrap (minbase) and kept for later runs outside the clone, as
CACHE_DIR/bookworm-ARCH-minbase-KEY.tar (KEY: a hash of the release, variant, architecture, mirror
and package list, so a change to any of them makes a new root). The scratch root is bound onto
itself, so it is a mount point of its own even where the machine's "/" is not (a chroot or build
container, where unshare cannot change the propagation of "/"). Each step runs in it under chroot
in new mount and PID namespaces (unshare, the propagation left as it is and the scratch root's
mounts then made private): the mounts and every process it started vanish with it. The daemon
runs in a private network namespace too, with only a loopback, so its ports never meet the
machine's; this script's client joins it there.
No systemd runs in the root: the test plays systemd's part, running the unit's ExecStart as its
User with its RuntimeDirectory, and the package's own restart (deb-systemd-invoke) is skipped, as
it is in any chroot.

With one package of another architecture (the arm64 one, cross-built), the root is of that
architecture, run through qemu-user (binfmt_misc, registered here from qemu-user-static's own
entry when the machine has not): the package installs, the daemon starts, writes its settings
and answers, and purge leaves nothing.

Usage: upgrade_test.py DEB_N DEB_N_PLUS_1 [--cache-dir ~/.cache/azeltrack/debootstrap]
       upgrade_test.py DEB_OF_ANOTHER_ARCH [--cache-dir ~/.cache/azeltrack/debootstrap]
(as root: debootstrap, chroot, unshare and binfmt_misc need it)."""
import argparse
import hashlib
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "integration"))
from daemon_harness import Checks, http_json, wait_until  # noqa: E402
from console_update_steps import console_refusals, console_update, update_from_console  # noqa: E402,I100

MIRROR = "http://deb.debian.org/debian"
RELEASE = "bookworm"
VARIANT = "minbase"
INCLUDE = []  # debootstrap --include: none; the packages' own Depends come from apt at install
CONFIG = "/var/lib/azeltrack/azeltrack.toml"
BASE = "http://127.0.0.1:8080"
# The settings changed through the daemon, and how /api/config shows them.
CHANGES = [
    ("PUT", "/api/config/station", {"grid": "JO65MR"}),
    ("PUT", "/api/config/band", {"band": "1296"}),
    ("PUT", "/api/config/offsets", {"az_offset_deg": 0.37, "el_offset_deg": -0.21}),
    ("PUT", "/api/config/park", {"slot": 2, "name": "Service", "az_deg": 123.0, "el_deg": 45.0}),
]


def log(text):
    print(f"upgrade_test: {text}", flush=True)


class Root:
    """A Debian 12 root in a folder, and commands run in it."""

    def __init__(self, path):
        self.path = path
        self.bound = False
        self.archives = ""  # a folder kept between runs for apt's downloaded packages

    def prepare(self, cache_dir, arch):
        """Binds the folder onto itself, then fills it from the cached root of this release,
        variant, architecture, mirror and package list, or from debootstrap (then cached)."""
        recipe = json.dumps([RELEASE, VARIANT, arch, MIRROR, sorted(INCLUDE)])
        key = hashlib.sha256(recipe.encode()).hexdigest()[:16]
        cache = os.path.join(cache_dir, f"{RELEASE}-{arch}-{VARIANT}-{key}.tar") if cache_dir else ""
        subprocess.run(["mount", "--bind", self.path, self.path], check=True)
        self.bound = True
        if cache_dir:
            # The packages apt fetches for the install (the program's dependencies) are kept
            # for the next run; apt checks each against the archive's signed index before use.
            self.archives = os.path.join(cache_dir, f"{RELEASE}-{arch}-apt-archives")
            os.makedirs(os.path.join(self.archives, "partial"), exist_ok=True)
        if cache and os.path.exists(cache):
            log(f"unpacking the root from {cache}")
            subprocess.run(["tar", "-xf", cache, "-C", self.path], check=True)
            return
        log(f"debootstrap {RELEASE} ({VARIANT}, {arch}) into a scratch folder")
        include = f"--include={','.join(INCLUDE)}" if INCLUDE else ""
        # In a namespace of its own: what debootstrap mounts in the root (/proc, /sys) and
        # leaves mounted when it runs in a chroot goes with the namespace.
        root = shlex.quote(self.path)
        subprocess.run(["unshare", "--mount", "--propagation", "unchanged", "sh", "-ec",
                        f"mount --make-rprivate {root}; debootstrap --variant={VARIANT} "
                        f"--arch={arch} {include} {RELEASE} {root} {MIRROR}"],
                       check=True, stdout=subprocess.DEVNULL)
        if cache:
            os.makedirs(cache_dir, exist_ok=True)
            subprocess.run(["tar", "--one-file-system", "-cf", cache + ".part", "-C", self.path,
                            "."], check=True)
            os.replace(cache + ".part", cache)

    def release(self):
        """Unbinds the root; False if it stays mounted (then it must not be deleted: a leftover
        bind of /dev below it would be deleted with it)."""
        if not self.bound:
            return True
        return subprocess.run(["umount", "--recursive", self.path]).returncode == 0

    def _script(self, inner, private_net):
        root = shlex.quote(self.path)
        return "\n".join([
            "set -e",
            # The root's own mount, private in this namespace: nothing below propagates out.
            f"mount --make-rprivate {root}",
            f"mount -t proc proc {root}/proc",
            f"mount --rbind /dev {root}/dev",
            f"mount --make-rslave {root}/dev",
            (f"mount --bind {shlex.quote(self.archives)} {root}/var/cache/apt/archives"
             if self.archives else ":"),
            f"mount -t tmpfs tmpfs {root}/run",
            f"cp /etc/resolv.conf {root}/etc/resolv.conf",
            "ip link set lo up" if private_net else ":",
            inner,
        ])

    def run(self, command, private_net=False):
        """`command` (sh) in the root; (exit status, output)."""
        inner = f"exec chroot {shlex.quote(self.path)} /bin/sh -c {shlex.quote(command)}"
        return self._unshare(inner, private_net)

    def _unshare(self, inner, private_net):
        args = ["unshare", "--mount", "--propagation", "unchanged", "--pid", "--fork"]
        args += ["--net"] if private_net else []
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive", LC_ALL="C.UTF-8")
        p = subprocess.run(args + ["bash", "-c", self._script(inner, private_net)], env=env,
                           stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        return p.returncode, p.stdout

    def with_daemon(self, client_args, client_env=None):
        """Starts the unit's ExecStart as its User in a private network, runs this script as a
        client there (`--client …`), then stops the daemon with SIGTERM as systemd would.
        (client's exit status, daemon's exit status, the daemon's log)."""
        unit = self.read("/lib/systemd/system/azeltrack.service")
        exec_start = next(l.split("=", 1)[1] for l in unit.splitlines()
                          if l.startswith("ExecStart="))
        user = next(l.split("=", 1)[1] for l in unit.splitlines() if l.startswith("User="))
        root = shlex.quote(self.path)
        env = {"AZT_ROOT": self.path, **(client_env or {})}
        client = " ".join([f"{k}={shlex.quote(v)}" for k, v in env.items()] +
                          [shlex.quote(a) for a in
                           [sys.executable, os.path.abspath(__file__), "--client"] + client_args])
        inner = "\n".join([
            # RuntimeDirectory=azeltrack, as systemd makes it.
            f"chroot {root} install -d -o {user} -g {user} -m 755 /run/azeltrack",
            f"chroot {root} setpriv --reuid={user} --regid={user} --init-groups "
            f"{exec_start} >{root}/tmp/daemon.log 2>&1 &",
            "daemon=$!",
            "set +e",
            client,
            "client=$?",
            "kill -TERM $daemon",
            "wait $daemon",
            "echo \"client=$client daemon=$?\"",
        ])
        _, out = self._unshare(inner, private_net=True)
        statuses = dict(kv.split("=") for kv in out.strip().splitlines()[-1].split())
        return int(statuses["client"]), int(statuses["daemon"]), self.read("/tmp/daemon.log"), out

    def read(self, path):
        with open(self.path + path, encoding="utf-8", errors="replace") as f:
            return f.read()

    def json(self, path):
        """The JSON a client phase saved; None when it saved nothing."""
        try:
            with open(self.path + path, encoding="utf-8") as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def exists(self, path):
        return os.path.lexists(self.path + path)

    def sha256(self, path):
        """The file's SHA-256; None when it is missing."""
        try:
            with open(self.path + path, "rb") as f:
                return hashlib.sha256(f.read()).hexdigest()
        except OSError:
            return None


def client(phase, token_file, out_file):
    """Runs inside the daemon's network namespace: waits for the console, then one phase. The
    phases of an update from the console find the root in AZT_ROOT and the packages in
    AZT_UPDATE_DEBS (a JSON object of name -> path in the root)."""
    checks = Checks()
    up = wait_until(lambda: http_json(BASE, "GET", "/api/state")[0] == 200, seconds=30)
    checks(up, "the daemon's console answers")
    token = ""
    if token_file != "-":
        with open(token_file, encoding="utf-8") as f:
            token = f.read().strip()
    if up and phase == "change":
        for method, route, body in CHANGES:
            status, reply = http_json(BASE, method, route, body, token=token)
            checks(status == 200, f"{method} {route} {body}: {status} {reply}")
    if up and phase == "console-update":
        console_update(token, checks)
    if up and phase == "console-refusals":
        console_refusals(token, checks)
    if up:
        status, config = http_json(BASE, "GET", "/api/config")
        checks(status == 200, f"GET /api/config: {status}")
        _, software = http_json(BASE, "GET", "/api/software")
        with open(out_file, "w", encoding="utf-8") as f:
            json.dump({"config": config, "software": software}, f, sort_keys=True)
    return checks.summary(f"client {phase}")


def changed_settings_shown(config):
    """Whether /api/config shows every change in CHANGES."""
    text = json.dumps(config)
    return all(s in text for s in ('"JO65MR"', '"1296"', "0.37", "-0.21", '"Service"', "123"))


def apt_install(root, deb):
    status, out = root.run(f"apt-get install -y -q {shlex.quote(deb)}")
    return status, out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("debs", nargs="*")
    ap.add_argument("--cache-dir", default="")
    ap.add_argument("--client", nargs=3, metavar=("PHASE", "TOKEN_FILE", "OUT_FILE"))
    args = ap.parse_args()
    if args.client:
        return client(*args.client)
    if os.geteuid() != 0:
        print("upgrade_test: skipped: debootstrap, chroot and unshare need root")
        return 77
    debs = [os.path.abspath(d) for d in args.debs]
    arch = subprocess.run(["dpkg-deb", "-f", debs[0], "Architecture"], check=True,
                          capture_output=True, text=True).stdout.strip()
    if arch != subprocess.run(["dpkg", "--print-architecture"], capture_output=True,
                              text=True).stdout.strip():
        register_qemu(arch)
    checks = Checks()
    scratch = tempfile.mkdtemp(prefix="azt-root-", dir=os.environ.get("AZT_ROOT_DIR"))
    root = Root(scratch)
    try:
        root.prepare(args.cache_dir, arch)
        os.chmod(scratch, 0o755)  # the root's "/" (mkdtemp's 0700): the daemon's user gets through
        for deb in debs:
            shutil.copy(deb, root.path + "/tmp/")
        in_root = ["/tmp/" + os.path.basename(d) for d in debs]
        install_and_first_start(root, in_root[0], checks)
        if len(in_root) > 1:
            settings = change_and_upgrade(root, in_root[1], checks)
            update_from_console(root, in_root, settings, checks)
        remove_and_purge(root, checks)
    finally:
        if root.release():
            shutil.rmtree(scratch, ignore_errors=True)
        else:
            log(f"{scratch} is still mounted: left in place")
    return checks.summary(f"upgrade_test ({arch})")


def register_qemu(arch):
    """Lets the kernel run ARCH's programs through qemu-user-static, as systemd-binfmt does at
    boot on a machine with that package: its own binfmt.d entry, written to binfmt_misc."""
    cpu = {"arm64": "aarch64", "armhf": "arm"}.get(arch, arch)
    misc = "/proc/sys/fs/binfmt_misc"
    if not os.path.exists(f"{misc}/register"):
        subprocess.run(["mount", "-t", "binfmt_misc", "binfmt_misc", misc], check=True)
    if os.path.exists(f"{misc}/qemu-{cpu}"):
        return
    with open(f"/usr/lib/binfmt.d/qemu-{cpu}.conf", encoding="utf-8") as f:
        entry = f.read().strip()
    log(f"registering qemu-{cpu} with binfmt_misc")
    with open(f"{misc}/register", "w", encoding="utf-8") as f:
        f.write(entry)


def install_and_first_start(root, deb, checks):
    log(f"installing {os.path.basename(deb)} and its dependencies")
    root.run("apt-get update -q")
    status, out = apt_install(root, deb)
    checks(status == 0, f"apt-get install N: {status}\n{out[-3000:]}")
    check_installed(root, checks)

    log("first start: the daemon writes the default settings")
    c, d, daemon_log, out = root.with_daemon(["first", "-", root.path + "/tmp/first.json"])
    checks(c == 0 and d == 0, f"first start: client {c}, daemon {d}\n{out}\n{daemon_log}")
    checks(root.exists(CONFIG), "the first start wrote the settings")
    mode = os.stat(root.path + CONFIG).st_mode & 0o777 if root.exists(CONFIG) else 0
    checks(mode == 0o640, f"the settings are 0640, not {oct(mode)}")


def change_and_upgrade(root, deb_n1, checks):
    status, token = root.run(f"setpriv --reuid=azeltrack --regid=azeltrack --init-groups "
                             f"azeltrack web token --config {CONFIG}")
    checks(status == 0, f"azeltrack web token: {status} {token}")
    with open(root.path + "/tmp/token", "w", encoding="utf-8") as f:
        f.write(token.strip().splitlines()[0] if token.strip() else "")

    log("changing settings through the daemon")
    c, d, daemon_log, out = root.with_daemon(["change", root.path + "/tmp/token",
                                              root.path + "/tmp/before.json"])
    checks(c == 0, f"settings changed through the daemon\n{out}")
    checks(d == 0 and "motors stopped" in daemon_log,
           f"SIGTERM stopped the motors and exited 0 (status {d})\n{daemon_log[-2000:]}")
    before = (root.json("/tmp/before.json") or {}).get("config")
    checks(before and changed_settings_shown(before), f"/api/config shows the changes: {before}")
    sha_before = root.sha256(CONFIG)

    log(f"upgrading to {os.path.basename(deb_n1)} without a terminal")
    status, out = apt_install(root, deb_n1)
    checks(status == 0, f"apt-get install N+1: {status}\n{out[-3000:]}")
    checks("Configuration file" not in out and "conffile" not in out.lower(),
           f"no conffile question\n{out}")
    _, version = root.run("dpkg-query -W -f='${Version}' azeltrack")
    _, expected = root.run(f"dpkg-deb -f {deb_n1} Version")
    checks(version.strip() == expected.strip(), f"installed {version} after the upgrade")
    checks(sha_before and root.sha256(CONFIG) == sha_before,
           "the settings file is byte for byte the same")
    _, leftovers = root.run("find /var/lib/azeltrack /etc/chrony -name '*.dpkg-*' "
                            "-o -name '*.ucf-*'")
    checks(leftovers.strip() == "", f"no dpkg leftovers: {leftovers}")

    log("starting the upgraded daemon")
    c, d, daemon_log, out = root.with_daemon(["after", "-", root.path + "/tmp/after.json"])
    checks(c == 0 and d == 0, f"the daemon runs after the upgrade\n{out}\n{daemon_log}")
    after = (root.json("/tmp/after.json") or {}).get("config")
    checks(after is not None and after == before, f"every setting unchanged:\n{before}\n{after}")
    return before


def remove_and_purge(root, checks):
    sha_before = root.sha256(CONFIG)
    log("remove: the settings stay")
    status, out = root.run("apt-get remove -y -q azeltrack")
    checks(status == 0, f"apt-get remove: {status}\n{out[-2000:]}")
    checks(not root.exists("/usr/bin/azeltrack"), "the program is gone")
    checks(sha_before and root.sha256(CONFIG) == sha_before, "the settings stay")
    checks(root.run("getent passwd azeltrack")[0] == 0, "the user stays")

    log("purge: the user, the unit and the settings go")
    status, out = root.run("apt-get purge -y -q azeltrack")
    checks(status == 0, f"apt-get purge: {status}\n{out[-2000:]}")
    checks(not root.exists("/var/lib/azeltrack"), "/var/lib/azeltrack is gone")
    checks(root.run("getent passwd azeltrack")[0] != 0, "the user is gone")
    checks(root.run("getent group azeltrack")[0] != 0, "the group is gone")
    checks(not root.exists("/var/lib/azeltrack-update"), "/var/lib/azeltrack-update is gone")
    for gone in ("/lib/systemd/system/azeltrack.service",
                 "/etc/systemd/system/multi-user.target.wants/azeltrack.service",
                 "/etc/chrony/conf.d/azeltrack.conf", "/etc/chrony/sources.d/azeltrack.sources",
                 "/etc/azeltrack"):
        checks(not root.exists(gone), f"{gone} is gone")


def check_installed(root, checks):
    """What the installed package set up: the user, the folder, the links, the unit enabled."""
    status, passwd = root.run("getent passwd azeltrack")
    checks(status == 0 and ":/var/lib/azeltrack:" in passwd, f"the system user: {passwd}")
    _, groups = root.run("id -nG azeltrack")
    checks("dialout" in groups.split(), f"azeltrack is in dialout: {groups}")
    st = os.stat(root.path + "/var/lib/azeltrack")
    checks(st.st_mode & 0o777 == 0o711, f"/var/lib/azeltrack is 0711: {oct(st.st_mode)}")
    _, owner = root.run("stat -c %U /var/lib/azeltrack")
    checks(owner.strip() == "azeltrack", f"/var/lib/azeltrack belongs to azeltrack: {owner}")
    checks(os.readlink(root.path + "/etc/chrony/sources.d/azeltrack.sources")
           == "/var/lib/azeltrack/chrony/azeltrack.sources", "chrony's sources link")
    checks(root.exists("/var/lib/azeltrack/chrony/azeltrack.sources"), "the sources file exists")
    checks(root.exists("/etc/systemd/system/multi-user.target.wants/azeltrack.service"),
           "the unit is enabled")


if __name__ == "__main__":
    sys.exit(main())
