#!/usr/bin/env bash
# Builds the libFuzzer target (clang, ASan + UBSan) in build-fuzz/ and fuzzes the case reader
# and `check` for SECONDS (default 120) from the seed corpus of cases/. Exits non-zero on any
# finding (crash, sanitizer report, timeout, out-of-memory), leaving its input in build-fuzz/.
#   tests/fuzz/run.sh [SECONDS] [extra libFuzzer flags...]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-120}"
shift || true
cmake -S . -B build-fuzz -DDEBRISFLOW_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDEBRISFLOW_TESTS=OFF -DDEBRISFLOW_BENCH=OFF > /dev/null
cmake --build build-fuzz --target case_check_fuzz -j2
tests/fuzz/seed_corpus.sh build-fuzz/corpus
cd build-fuzz
./case_check_fuzz corpus -dict=../tests/fuzz/case.dict -max_total_time="$seconds" -timeout=120 \
    -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 "$@"
