#!/usr/bin/env bash
# Every test of the project, on a fresh machine: installs what it needs, then runs the suites.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo test --workspace
