#!/usr/bin/env python3
"""The declared MSRV is honest: no crate the workspace builds with (normal and build
dependencies, transitively; dev-dependencies of the workspace excluded) declares a newer
`rust-version` than the workspace's. Clippy's `incompatible_msrv` lint (run with -D warnings in
scripts/test.sh) checks the workspace's own use of the standard library against the same value.

Usage: python3 scripts/check-msrv.py   (from the repository root; needs cargo)"""
import json
import subprocess
import sys


def version(v):
    parts = [int(x) for x in v.split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def main():
    meta = json.loads(subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--locked"],
        check=True, capture_output=True, text=True).stdout)
    packages = {p["id"]: p for p in meta["packages"]}
    nodes = {n["id"]: n for n in meta["resolve"]["nodes"]}
    problems = []
    for member in meta["workspace_members"]:
        declared = packages[member].get("rust_version")
        if not declared:
            problems.append(f"{packages[member]['name']} declares no rust-version")
            continue
        seen, stack = set(), [member]
        while stack:
            node = stack.pop()
            if node in seen:
                continue
            seen.add(node)
            for dep in nodes[node]["deps"]:
                if all(k["kind"] == "dev" for k in dep["dep_kinds"]):
                    continue
                stack.append(dep["pkg"])
        for node in seen:
            needed = packages[node].get("rust_version")
            if needed and version(needed) > version(declared):
                problems.append(f"{packages[member]['name']} declares rust-version {declared}, "
                                f"but its dependency {packages[node]['name']} "
                                f"{packages[node]['version']} needs {needed}")
    if problems:
        print("\n".join(sorted(set(problems))), file=sys.stderr)
        return 1
    print("MSRV ok: every workspace crate's dependencies build with its declared rust-version")
    return 0


if __name__ == "__main__":
    sys.exit(main())
