"""The update from the console in the upgrade test's root (docs/packaging.md): the
signed packages, the ones the root helper must refuse, and the client phases that upload them
through the daemon's API and run the helper as azeltrack-update.path would. Used by
upgrade_test.py, on the host (the packages, the steps) and as its client in the daemon's network
namespace (the uploads)."""
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "integration"))
from daemon_harness import http_json, http_upload, wait_until  # noqa: E402

CONFIG = "/var/lib/azeltrack/azeltrack.toml"
BASE = "http://127.0.0.1:8080"
RELEASE_KEY = "5A33A3747E83ECC0CD2795FE2124FFC9F62C5588"  # packaging/keys/azeltrack-release.asc


def log(text):
    print(f"upgrade_test: {text}", flush=True)


def run_helper():
    """Plays azeltrack-update.path: runs the root helper in the root, as systemd would."""
    root = os.environ["AZT_ROOT"]
    return subprocess.run(["chroot", root, "/usr/libexec/azeltrack/azeltrack-update"],
                          stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          env=dict(os.environ, PATH="/usr/sbin:/usr/bin:/sbin:/bin"))


def upload_and_help(token, deb_in_root):
    """Uploads a package through the console, runs the helper, and waits until the daemon shows
    the helper done with it. (upload status, upload reply, /api/software at the end)."""
    with open(os.environ["AZT_ROOT"] + deb_in_root, "rb") as f:
        data = f.read()
    status, reply = http_upload(BASE, "/api/software/update", data, token=token)
    if status != 200:
        return status, reply, None
    helper = run_helper()
    software = {}

    def done():
        nonlocal software
        software = http_json(BASE, "GET", "/api/software")[1]
        h = software.get("helper") or {}
        return h.get("sha256") == reply.get("sha256") and h.get("phase") in (
            "refused", "installed", "failed")
    wait_until(done, seconds=30)
    software["helper_run"] = helper.returncode
    software["helper_stderr"] = helper.stderr[-500:]
    return status, reply, software


def console_update(token, checks):
    debs = json.loads(os.environ["AZT_UPDATE_DEBS"])
    _, before = http_json(BASE, "GET", "/api/software")
    checks(before.get("updates") is True, f"the packaged daemon takes updates: {before}")
    status, reply, software = upload_and_help(token, debs["next"])
    checks(status == 200 and len(reply.get("sha256", "")) == 64, f"upload: {status} {reply}")
    inbox = os.environ["AZT_ROOT"] + "/var/lib/azeltrack/update/request.deb"
    checks(not os.path.exists(inbox), "the helper took the request from the inbox")
    h = (software or {}).get("helper") or {}
    checks(h.get("phase") == "installed" and h.get("percent") == 100,
           f"the helper installed it: {software}")
    checks(h.get("from") == before.get("version") and h.get("to") == debs["next_version"],
           f"from {before.get('version')} to {debs['next_version']}: {h}")
    checks(TEST_KEY in h.get("signer", "") and "azeltrack test signing key" in h.get("signer", ""),
           f"the page shows who signed it: {h.get('signer')}")


def console_refusals(token, checks):
    """Each package the helper must refuse, and what the daemon refuses itself: nothing changes."""
    debs = json.loads(os.environ["AZT_UPDATE_DEBS"])
    status, reply = http_upload(BASE, "/api/software/update", b"not a package", token=token)
    checks(status == 400 and "not a Debian package" in reply.get("error", ""),
           f"garbage refused by the daemon: {status} {reply}")
    with open(os.environ["AZT_ROOT"] + debs["next"], "rb") as f:
        good = f.read()
    status, reply = http_upload(BASE, "/api/software/update", good)
    checks(status == 401, f"an upload without a login: {status} {reply}")
    cases = [("older", "is older than the installed"), ("other_name", "not azeltrack"),
             ("other_arch", "this machine is"), ("corrupt", "not a valid Debian package"),
             ("unsigned", "not signed"),
             ("other_key", f"{debs['other_key_fpr']}, which this station does not trust")]
    for name, reason in cases:
        status, reply, software = upload_and_help(token, debs[name])
        h = (software or {}).get("helper") or {}
        checks(status == 200 and h.get("phase") == "refused" and reason in h.get("message", ""),
               f"{name}: refused with '{reason}': {status} {reply} {software}")


def refused_packages(root, deb_n1):
    """The packages the helper must refuse, made in the root's /tmp: another package's name (the
    test data's azeltrack-test), another architecture, and N+1 with its data member damaged."""
    here = os.path.dirname(os.path.abspath(__file__))
    shutil.copy(os.path.join(here, "..", "data", "software", "azeltrack-test_0.1_all.deb"),
                root.path + "/tmp/other_name.deb")
    host = subprocess.run(["dpkg", "--print-architecture"], capture_output=True,
                          text=True).stdout.strip()
    other = "arm64" if host != "arm64" else "amd64"
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(tmp + "/pkg/DEBIAN")
        with open(tmp + "/pkg/DEBIAN/control", "w", encoding="utf-8") as f:
            f.write(f"Package: azeltrack\nVersion: 99.0\nArchitecture: {other}\n"
                    "Maintainer: test <test@example.org>\nDescription: another architecture\n")
        subprocess.run(["dpkg-deb", "--root-owner-group", "--build", tmp + "/pkg",
                        root.path + "/tmp/other_arch.deb"], check=True, capture_output=True)
    with open(root.path + deb_n1, "rb") as f:
        data = bytearray(f.read())
    # The data member is last and largest: damage it inside, the ar headers stay whole, so the
    # daemon's check passes and dpkg-deb's finds the bad compressed stream.
    middle = len(data) - len(data) // 4
    data[middle:middle + 64] = bytes(b ^ 0x5A for b in data[middle:middle + 64])
    with open(root.path + "/tmp/corrupt.deb", "wb") as f:
        f.write(data)
    return {"other_name": "/tmp/other_name.deb", "other_arch": "/tmp/other_arch.deb",
            "corrupt": "/tmp/corrupt.deb"}


TEST_KEY = "FC4892F01AAC91A16E33CF6BD790D49363F83F75"  # tests/data/software/signing


def signed_packages(root, deb_n1):
    """N+1 signed with the tests' key (which the test trusts in the root as an operator trusts
    their own), and N+1 signed with a key nobody trusts, made in the root's /tmp."""
    signing = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "software",
                           "signing")
    shutil.copy(os.path.join(signing, "test-key.asc"), root.path + "/tmp/test-key.asc")
    with tempfile.TemporaryDirectory() as home:
        env = dict(os.environ, GNUPGHOME=home)
        quiet = {"env": env, "check": True, "capture_output": True}
        subprocess.run(["gpg", "--batch", "--import", os.path.join(signing, "test-key.secret.asc")],
                       **quiet)
        subprocess.run(["gpg", "--batch", "--passphrase", "", "--quick-gen-key",
                        "nobody trusts me <other@example.invalid>", "ed25519", "sign", "never"],
                       **quiet)
        other = subprocess.run(["gpg", "--batch", "--with-colons", "--list-secret-keys",
                                "other@example.invalid"], **quiet, text=True).stdout
        other = next(line.split(":")[9] for line in other.splitlines() if line.startswith("fpr"))
        made = {}
        for name, key in (("next_signed", TEST_KEY), ("other_key", other)):
            made[name] = f"/tmp/{name}.deb"
            shutil.copy(root.path + deb_n1, root.path + made[name])
            subprocess.run(["debsigs", "--sign=origin", f"--default-key={key}",
                            root.path + made[name]], **quiet)
    made["other_key_fpr"] = other
    return made


def update_from_console(root, debs, settings, checks):
    """The seed's update page (docs/packaging.md): back on N (a downgrade by apt, settings kept),
    the operator uploads N+1 on the console; the root helper (run here as azeltrack-update.path
    would start it) checks and installs it; the daemon restarted (as the postinst would, with
    systemd) runs N+1 and shows the helper's result; every setting is unchanged. Then the packages
    the helper must refuse change nothing."""
    log("downgrading to N, to update it from the console")
    status, out = root.run(f"apt-get install -y -q --allow-downgrades {shlex.quote(debs[0])}")
    checks(status == 0, f"apt-get install N again: {status}\n{out[-2000:]}")
    sha_before = root.sha256(CONFIG)
    _, next_version = root.run(f"dpkg-deb -f {debs[1]} Version")
    status, keys = root.run("azeltrack-update-keys list")
    checks(status == 0 and f"{RELEASE_KEY} azeltrack release" in keys,
           f"the package trusts the project's release key: {status} {keys}")
    signed = signed_packages(root, debs[1])
    status, out = root.run("azeltrack-update-keys add /tmp/test-key.asc")
    checks(status == 0 and TEST_KEY in out, f"the operator trusts their own key, as root: {out}")
    env = {"AZT_UPDATE_DEBS": json.dumps({"next": signed["next_signed"],
                                          "next_version": next_version.strip(),
                                          "unsigned": debs[1], **signed,
                                          "older": debs[0], **refused_packages(root, debs[1])})}

    log("updating N to N+1 from the console (upload, the root helper, apt)")
    c, d, daemon_log, out = root.with_daemon(["console-update", root.path + "/tmp/token",
                                              root.path + "/tmp/update.json"], env)
    checks(c == 0, f"the update from the console\n{out}\n{daemon_log[-2000:]}")
    _, version = root.run("dpkg-query -W -f='${Version}' azeltrack")
    checks(version.strip() == next_version.strip(), f"installed {version} after the console's update")
    checks(root.sha256(CONFIG) == sha_before, "the settings file is byte for byte the same")

    log("the restarted daemon shows the update's result")
    c, d, daemon_log, out = root.with_daemon(["console-refusals", root.path + "/tmp/token",
                                              root.path + "/tmp/refusals.json"], env)
    checks(c == 0 and d == 0, f"packages refused, daemon running\n{out}\n{daemon_log[-2000:]}")
    shown = root.json("/tmp/refusals.json") or {}
    software = shown.get("software") or {}
    checks(software.get("version") == next_version.strip(),
           f"the daemon after the restart runs {next_version.strip()}: {software}")
    checks(shown.get("config") == settings, f"every setting unchanged:\n{settings}\n{shown.get('config')}")
    _, version = root.run("dpkg-query -W -f='${Version}' azeltrack")
    checks(version.strip() == next_version.strip(), f"still {next_version.strip()} after the refusals")
    checks(root.sha256(CONFIG) == sha_before, "the settings file is still the same")
