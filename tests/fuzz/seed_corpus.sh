#!/usr/bin/env bash
# Copies every case file of cases/ into DIR as the fuzzer's seed corpus.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
dir="${1:?usage: seed_corpus.sh DIR}"
mkdir -p "$dir"
find "$root/cases" -name '*.toml' | while read -r f; do
    cp "$f" "$dir/$(echo "${f#$root/cases/}" | tr '/' '_')"
done
