#!/bin/bash
# Each integration test's own CPU time (user + system, seconds), run alone with
# `--exact` under /usr/bin/time, heaviest first: where the suite's time goes.
# Usage: scripts/test-costs.sh [FILTER] > costs.txt   (after `cargo test --no-run`)
# Columns: CPU s, wall s, exit status, test name. Sum the first column for the whole.
set -u
cd "$(dirname "$0")/.."
bin=$(ls -t target/debug/deps/it-* | grep -v '\.d$' | head -1)
timing=$(mktemp)
trap 'rm -f "$timing"' EXIT
"$bin" --list 2>/dev/null | sed -n 's/: test$//p' | grep -- "${1:-}" |
    while read -r name; do
        INSTA_UPDATE=no /usr/bin/time -f '%U %S %e' -o "$timing" \
            "$bin" --exact "$name" --test-threads 1 </dev/null >/dev/null 2>&1
        status=$?
        read -r user sys wall < <(tail -n 1 "$timing")
        awk -v u="$user" -v s="$sys" -v w="$wall" -v c="$status" -v n="$name" \
            'BEGIN { printf "%.2f %s %s %s\n", u + s, w, c, n }'
    done | sort -rn
