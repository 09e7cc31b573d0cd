#!/usr/bin/env python3
"""clang-tidy on many translation units, each run only once per content (docs/building.md, "The
caches").

A unit's result is reused when nothing that determines it changed: the unit's compile command,
clang-tidy's arguments, its binary and version, every .clang-tidy above the unit, and the
contents of every file the unit includes (its full include closure as clang's preprocessor finds
it, system headers too; clang, not the build's gcc, because clang-tidy parses as clang). Paths
under the source and build trees are written relative to them, so clones at other paths share
results. Only clean results are kept; a unit with findings runs every time and its findings print.

The cache is a folder of small JSON entries, one per unit and key (default
~/.cache/azeltrack/clang-tidy, or $AZT_TIDY_CACHE). An entry is trusted only if its own checksum,
its key and every recorded file's content hash match: a corrupt, truncated or foreign entry is a
miss, never a pass. Writes are atomic (a temporary file renamed), so parallel runs cannot tear one.

Known limit, as for ccache's direct mode: a new header that would shadow an included one of the
same name earlier on the include path is not seen until a file of the closure changes.

Usage: tidy_cache.py --source DIR --build DIR [--jobs N] [--clang-tidy BIN] FILE... -- TIDY_ARGS...
Prints each unit's findings, then "tidy_cache: N units: C from the cache, R run, F with findings";
exits 1 if any unit has findings or could not run."""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

FORMAT = 1
# Options of the build's command that name its output or depfile: dropped for the -M run.
OUTPUT_OPTIONS = {"-o", "-MF", "-MT", "-MQ"}
OUTPUT_FLAGS = {"-c", "-MD", "-MMD"}


def sha256_bytes(data):
    return hashlib.sha256(data).hexdigest()


class Paths:
    """Absolute paths under the source or build tree <-> clone-independent names. A root is
    replaced wherever it appears, also without a slash after it, as in the package flags'
    -ffile-prefix-map=/path/to/clone=."""

    def __init__(self, source, build):
        # The build tree first: it usually lies inside the source tree.
        self.roots = [(os.path.realpath(build), "@BUILD@"),
                      (os.path.realpath(source), "@SRC@")]

    def portable(self, text):
        for root, name in self.roots:
            text = text.replace(root, name)
        return text

    def local(self, name):
        for root, tag in self.roots:
            if name.startswith(tag):
                return root + name[len(tag):]
        return name


class Cache:
    def __init__(self, folder):
        self.folder = folder
        self.hashes = {}  # path -> content hash, shared by every unit of this run

    def file_hash(self, path, fresh=False):
        if fresh or path not in self.hashes:
            try:
                with open(path, "rb") as f:
                    self.hashes[path] = sha256_bytes(f.read())
            except OSError:
                self.hashes[path] = None
        return self.hashes[path]

    def _entry_path(self, key):
        return os.path.join(self.folder, key[:2], key + ".json")

    def is_clean(self, key, paths):
        """True only for an intact entry of this key whose every file is unchanged."""
        try:
            with open(self._entry_path(key), encoding="utf-8") as f:
                entry = json.load(f)
            body = entry["body"]
            if entry["check"] != sha256_bytes(json.dumps(body, sort_keys=True).encode()):
                return False
            if body["format"] != FORMAT or body["key"] != key or body["result"] != "clean":
                return False
            deps = body["deps"]
            return bool(deps) and all(
                self.file_hash(paths.local(name)) == digest for name, digest in deps)
        except (OSError, ValueError, KeyError, TypeError):
            return False

    def store_clean(self, key, deps):
        body = {"format": FORMAT, "key": key, "result": "clean", "deps": deps}
        entry = {"body": body, "check": sha256_bytes(json.dumps(body, sort_keys=True).encode())}
        path = self._entry_path(key)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".tmp-")
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            json.dump(entry, f)
        os.replace(tmp, path)


def clang_for(tidy):
    """The clang++ of clang-tidy's own version (its preprocessor is the one clang-tidy runs)."""
    out = subprocess.run([tidy, "--version"], capture_output=True, text=True).stdout
    major = re.search(r"version (\d+)", out)
    names = ([f"clang++-{major.group(1)}"] if major else []) + ["clang++"]
    return next(filter(None, map(shutil.which, names)), None), out


def depfile_paths(text, directory):
    """The prerequisites of a make rule as clang -M writes it, as absolute real paths."""
    body = text.replace("\\\n", " ").split(":", 1)[1]
    names = re.findall(r"(?:\\ |[^\s])+", body)
    return [os.path.realpath(os.path.join(directory, n.replace("\\ ", " "))) for n in names]


class Unit:
    def __init__(self, path, command):
        self.path = path
        self.directory = command["directory"]
        self.args = command.get("arguments") or shlex.split(command["command"])

    def include_closure(self, clang):
        """Every file the unit reads (itself included), or None if clang cannot tell."""
        args, skip = [clang], False
        for arg in self.args[1:]:
            if skip:
                skip = False
            elif arg in OUTPUT_OPTIONS:
                skip = True
            elif arg not in OUTPUT_FLAGS:
                args.append(arg)
        args += ["-M", "-w", "-Wno-unknown-warning-option", "-D__clang_analyzer__=1"]
        p = subprocess.run(args, cwd=self.directory, capture_output=True, text=True)
        return depfile_paths(p.stdout, self.directory) if p.returncode == 0 else None


class Linter:
    def __init__(self, options, tidy_args):
        self.paths = Paths(options.source, options.build)
        self.cache = Cache(options.cache)
        self.tidy = shutil.which(options.clang_tidy)
        if not self.tidy:
            raise SystemExit(f"tidy_cache: {options.clang_tidy} not found")
        self.clang, version = clang_for(self.tidy)
        with open(os.path.realpath(self.tidy), "rb") as f:
            self.tool = version + sha256_bytes(f.read())
        self.build = options.build
        self.tidy_args = tidy_args
        self.source = os.path.realpath(options.source)

    def configs(self, path):
        """The text of every .clang-tidy from the unit's folder up to the source root."""
        texts, folder = [], os.path.dirname(path)
        while folder.startswith(self.source):
            candidate = os.path.join(folder, ".clang-tidy")
            if os.path.exists(candidate):
                with open(candidate, encoding="utf-8") as f:
                    texts.append(self.paths.portable(candidate) + "\n" + f.read())
            folder = os.path.dirname(folder)
        return texts

    def key(self, unit):
        parts = [f"format {FORMAT}", self.tool, *self.configs(unit.path), *self.tidy_args,
                 self.paths.portable(unit.directory), *map(self.paths.portable, unit.args)]
        return sha256_bytes("\0".join(parts).encode())

    def deps(self, unit):
        closure = unit.include_closure(self.clang) if self.clang else None
        if not closure:
            return None
        hashed = [(self.paths.portable(p), self.cache.file_hash(p)) for p in closure]
        return None if any(h is None for _, h in hashed) else hashed

    def unchanged(self, deps):
        """Every file of a closure still as hashed (read again, not from this run's memo)."""
        return all(self.cache.file_hash(self.paths.local(name), fresh=True) == digest
                   for name, digest in deps)

    def run(self, unit):
        """("cached" | "clean" | "findings", output) for one unit."""
        key = self.key(unit)
        if self.cache.is_clean(key, self.paths):
            return "cached", ""
        before = self.deps(unit)
        p = subprocess.run([self.tidy, "-p", self.build, *self.tidy_args, unit.path],
                           capture_output=True, text=True)
        if p.returncode != 0:
            return "findings", p.stdout + p.stderr
        # Kept only if no file of the closure changed while clang-tidy read it.
        if before is not None and self.unchanged(before):
            self.cache.store_clean(key, before)
        return "clean", ""


def main():
    argv = sys.argv[1:]
    tidy_args = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[:argv.index("--")] if "--" in argv else argv
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--clang-tidy", default="clang-tidy")
    parser.add_argument("--cache", default=os.environ.get("AZT_TIDY_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"),
        "azeltrack", "clang-tidy"))
    parser.add_argument("files", nargs="+")
    options = parser.parse_args(argv)
    with open(os.path.join(options.build, "compile_commands.json"), encoding="utf-8") as f:
        commands = {os.path.realpath(os.path.join(c["directory"], c["file"])): c
                    for c in json.load(f)}
    linter = Linter(options, tidy_args)
    units = []
    for name in options.files:
        path = os.path.realpath(name)
        if path not in commands:
            raise SystemExit(f"tidy_cache: {name} is not in compile_commands.json")
        units.append(Unit(path, commands[path]))
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, options.jobs)) as pool:
        results = list(pool.map(linter.run, units))
    counts = {k: sum(1 for r, _ in results if r == k) for k in ("cached", "clean", "findings")}
    for result, output in results:
        if result == "findings":
            print(output, end="")
    print(f"tidy_cache: {len(units)} units: {counts['cached']} from the cache, "
          f"{counts['clean'] + counts['findings']} run, {counts['findings']} with findings")
    return 1 if counts["findings"] else 0


if __name__ == "__main__":
    sys.exit(main())
