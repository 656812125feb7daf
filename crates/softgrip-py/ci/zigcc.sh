#!/bin/sh
# The linker of the manylinux wheel (crates/softgrip-py/ci/build-wheel.sh passes it to rustc for
# the extension alone: `cargo rustc ... -- -C linker=zigcc.sh`, so every other crate stays the
# workspace's target/debug build). zig's cc from PyPI's `ziglang`, run through maturin's own
# argument filter (`maturin zig cc`, what `maturin build --zig` generates), links against the
# symbol versions of glibc 2.17 (manylinux2014): the system's newer glibc would tie the wheel
# to glibc >= 2.34. Needs the venv's `maturin` and `python` on PATH.
PY=$(command -v python)
export CARGO_ZIGBUILD_ZIG_COMMAND="$PY"
export CARGO_ZIGBUILD_ZIG_COMMAND_ARGS='-m ziglang'
exec maturin zig cc -- -g -fno-sanitize=all -target x86_64-linux-gnu.2.17 "$@"
