#!/usr/bin/env bash
# Fails, naming file:line, where a tracked file cites what a maintainer cannot open: a bare
# "issue N" (this repository carries no issue tracker) or a design note it does not hold.
# Cite the page of docs/ that explains the matter, or give the reason in the comment itself.
# Another project's tracker is cited by its name and number ("Hamlib #282", "Gpredict #127"),
# which this check leaves alone. Only the files git tracks are read, so build directories are
# never searched; the fuzzers' generated corpora and binary files are skipped. Runs in well under
# a second; lint.sh runs it first.
# Usage: check_citations.sh SOURCE_DIR
set -euo pipefail
src=${1:?usage: check_citations.sh SOURCE_DIR}
if ! git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "citations: $src is not a git work tree, so its tracked files are unknown: not checked" >&2
  exit 0
fi
# The word issue or issues followed by a number, in any case; and the design note's file name,
# spelled so that this line does not match itself.
pattern='\bissues? [0-9]+|DESIGN[.]md'
cd "$src"
# grep's status is not used: xargs may split the list, and a batch without a hit would hide a
# batch with one. What it prints decides.
hits=$(git ls-files -z -- . ':(exclude)fuzz/corpus' | xargs -0 grep -nIiE -s -- "$pattern") || true
if [ -n "$hits" ]; then
  printf '%s\n' "$hits"
  echo "citations: cite a page of docs/ (or give the reason) instead of the above" >&2
  exit 1
fi
echo "citations: $(git ls-files -- . ':(exclude)fuzz/corpus' | wc -l) tracked files cite no issue number"
