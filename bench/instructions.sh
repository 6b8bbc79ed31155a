#!/usr/bin/env bash
# Counts the instructions of the `cargo bench -p lugre` workloads (bench/workloads.rs: loops,
# cycles, simulate, dynamics, fit) at two or more commits, with valgrind's cachegrind: a count
# the load of a shared machine does not change, where timed runs vary by tens of percent.
#
#   bench/instructions.sh 04f2623 HEAD           # prints one row per case: the counts, the change
#
# Each commit is checked out into a temporary worktree, bench/workloads.rs (of the working
# tree) is built there as an example of the lugre crate (release profile, its own target
# directory under ${CARGO_TARGET_DIR:-target}/instructions/), and each case is counted as
# (instructions of K iterations - instructions of 0 iterations) / K: the inputs' setup is
# subtracted. Needs valgrind and about 15 minutes per commit on one core.
set -euo pipefail
root=$(git rev-parse --show-toplevel)
work=$(cat "$root/bench/workloads.rs")
target=${CARGO_TARGET_DIR:-$root/target}/instructions
tmp=$(mktemp -d)
trap 'for d in "$tmp"/wt-*; do git -C "$root" worktree remove --force "$d" 2>/dev/null || true; done; rm -rf "$tmp"' EXIT

# The instructions one run of `$@` executes (cachegrind's "I refs").
count() {
    valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "$@" 2>&1 >/dev/null |
        sed -n 's/.*I *refs: *//p' | tr -d ','
}

bins=()
for commit in "$@"; do
    wt="$tmp/wt-$commit"
    git -C "$root" worktree add --quiet --detach "$wt" "$commit"
    src="$work"
    # Before 603662e the counter with energies was its own type.
    if grep -q "pub struct EnergyCycleCounter" "$wt/crates/lugre/src/cycles/mod.rs"; then
        src=$(sed 's/CycleCounter::new(0.0).and_then(|c| c.with_energy($m, 0.0))/lugre::EnergyCycleCounter::new(0.0, $m, 0.0)/' <<<"$src")
    fi
    printf '%s\n' "$src" >"$wt/crates/lugre/examples/workloads.rs"
    (cd "$wt" && CARGO_TARGET_DIR="$target/$commit" cargo build --quiet --release -p lugre --example workloads)
    cp "$target/$commit/release/examples/workloads" "$tmp/workloads-$commit"
    bins+=("$tmp/workloads-$commit")
done

printf '%-30s' case; printf ' %16s' "$@"; printf ' %8s\n' change
for case in $("${bins[0]}" list); do
    k=1
    case $case in dynamics/*) k=10 ;; fit/slow) k=5 ;; esac
    per=()
    for bin in "${bins[@]}"; do
        per+=($((($(count "$bin" "$case" "$k") - $(count "$bin" "$case" 0)) / k)))
    done
    printf '%-30s' "$case"; printf ' %16s' "${per[@]}"
    awk -v a="${per[0]}" -v b="${per[${#per[@]}-1]}" 'BEGIN { printf " %+7.2f%%\n", 100 * (b - a) / a }'
done
