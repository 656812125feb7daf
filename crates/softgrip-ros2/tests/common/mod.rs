//! Running DDS participants only inside a private network namespace: `unshare -n` (as root)
//! or `unshare -r -n` (a user namespace, for a non-root user where the kernel allows it), with
//! `lo` brought up first. No discovery packet can leave the machine: the namespace has no
//! interface but its own loopback.
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Output};

/// The `unshare` arguments that give this user a private network namespace in which `lo` can
/// be brought up; panics with what to do if there are none.
pub fn unshare_args() -> &'static [&'static str] {
    const CANDIDATES: [&[&str]; 2] = [&["-n"], &["-r", "-n"]];
    let mut tried = Vec::new();
    for args in CANDIDATES {
        let out = Command::new("unshare")
            .args(args)
            .args(["ip", "link", "set", "lo", "up"])
            .output();
        match out {
            Ok(o) if o.status.success() => return args,
            Ok(o) => tried.push(format!(
                "`unshare {} ip link set lo up`: {} {}",
                args.join(" "),
                o.status,
                String::from_utf8_lossy(&o.stderr).trim()
            )),
            Err(e) => tried.push(format!("`unshare {}`: {e}", args.join(" "))),
        }
    }
    panic!(
        "the DDS tests need a private network namespace (`unshare -n`, util-linux, and `ip`, \
         iproute2) so that no discovery traffic leaves the machine, and this user may not make \
         one. Run them as root, or allow unprivileged user namespaces \
         (sysctl kernel.unprivileged_userns_clone=1 / user.max_user_namespaces > 0). Tried:\n  {}",
        tried.join("\n  ")
    )
}

/// Runs `script` with bash inside a fresh private network namespace whose `lo` is up
/// (`$0`, `$1`, ... are `args`).
pub fn in_private_netns(script: &str, args: &[&str], envs: &[(&str, &str)]) -> Output {
    let full = format!("ip link set lo up || exit 90\n{script}");
    Command::new("unshare")
        .args(unshare_args())
        .args(["bash", "-c", &full])
        .args(args)
        .envs(envs.iter().copied())
        .output()
        .unwrap_or_else(|e| panic!("running unshare: {e}"))
}

/// Panics unless this process is in a network namespace whose only interface is `lo`: the
/// tests that create DDS participants check this first.
pub fn assert_isolated() {
    let dev = std::fs::read_to_string("/proc/self/net/dev").expect("reading /proc/self/net/dev");
    let ifaces: Vec<&str> = dev
        .lines()
        .skip(2)
        .filter_map(|l| l.split(':').next())
        .map(str::trim)
        .collect();
    assert_eq!(
        ifaces,
        ["lo"],
        "refusing to create a DDS participant outside a private network namespace (interfaces \
         here: {ifaces:?}); these tests are run by their `*_in_private_netns` parent test"
    );
}

/// Runs the `#[ignore]`d test `name` of the current test binary inside a private network
/// namespace and panics with its output if it fails.
pub fn run_ignored_test_in_netns(name: &str) {
    let exe = std::env::current_exe().expect("the test binary's path");
    let exe = exe.to_str().expect("a UTF-8 path");
    let out = in_private_netns(
        r#"exec "$0" --ignored --exact "$1" --nocapture --test-threads=1"#,
        &[exe, name],
        &[],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    eprintln!("--- {name} (in a private network namespace) ---\n{stdout}{stderr}");
    assert!(out.status.success(), "{name} failed: {}", out.status);
    assert!(
        stdout.contains("1 passed"),
        "{name} did not run (filtered out?): {stdout}"
    );
}

/// The Python with `cyclonedds` (SOFTGRIP_PY), or a panic saying how to make one.
pub fn python() -> String {
    let py = std::env::var("SOFTGRIP_PY").unwrap_or_else(|_| {
        panic!(
            "SOFTGRIP_PY is not set: it must name a Python with the PyPI package `cyclonedds` \
             (11.0.1). Create one with `bash .ci/python-venv.sh` (it prints the path) and run \
             `SOFTGRIP_PY=$PWD/target/pyvenv/bin/python cargo test -p softgrip-ros2`."
        )
    });
    assert!(Path::new(&py).exists(), "SOFTGRIP_PY={py} does not exist");
    let ok = Command::new(&py)
        .args(["-c", "import cyclonedds.domain, cyclonedds.idl"])
        .output()
        .unwrap_or_else(|e| panic!("running SOFTGRIP_PY={py}: {e}"));
    assert!(
        ok.status.success(),
        "SOFTGRIP_PY={py} cannot import cyclonedds ({}): run `bash .ci/python-venv.sh`, which \
         installs cyclonedds==11.0.1",
        String::from_utf8_lossy(&ok.stderr).trim()
    );
    py
}
