//! Fuzz target: the scene parser + validator + builder, as a deterministic, seeded, bounded
//! loop under plain `cargo test` (no nightly toolchain). The corpus is the shipped scenes
//! (`scenes/*.toml`); each case mutates one scene's TOML tree (hostile numbers 0, -0, 1e39,
//! 1e-50, nan, inf, NaN-like strings, huge arrays, dropped keys, duplicated tables, wrong
//! types) or its text (byte flips, truncation), parses it, and, if it is accepted, builds it
//! and runs a few steps: no panic, every pose finite, every fingertip force finite.
//!
//! The classes of issue 26 too: names replaced by the reserved `world`, 4-component vectors,
//! mesh and curve paths pointing at a FIFO, a directory, a device or files with a byte-order
//! mark, and the scene text itself with a byte-order mark (it must parse exactly as without).
//! Every error message must print its numbers in shortest form (no run of more than 24
//! digits: 1e300 was printed as 301), and no case may block (a watchdog aborts after 120 s:
//! a FIFO opened for reading blocked forever).
//!
//! `SOFTGRIP_FUZZ_ITERS=N` sets the number of cases (default [`DEFAULT_ITERS`], ~10 s in a
//! debug build); `SOFTGRIP_FUZZ_SEED=S` the seed. A failure prints the seed, the case and the
//! mutated scene text: paste it into a named regression test.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

use softgrip_scene::{PlainRun, Scene};
use toml::Value;

/// Cases per `cargo test` run.
const DEFAULT_ITERS: u64 = 800;

/// Non-regular files and files with a byte-order mark the mutations point meshes and curves
/// at (absolute paths, made by [`hostile_files`]).
const FIFO_OBJ: &str = "/tmp/softgrip-fuzz-scene-files/pipe.obj";
const FIFO_CSV: &str = "/tmp/softgrip-fuzz-scene-files/pipe.csv";
const DIR_OBJ: &str = "/tmp/softgrip-fuzz-scene-files/folder.obj";
const BOM_OBJ: &str = "/tmp/softgrip-fuzz-scene-files/bom.obj";
const BOM_CSV: &str = "/tmp/softgrip-fuzz-scene-files/bom.csv";

/// Makes the files of [`FIFO_OBJ`] and the others.
fn hostile_files() {
    let dir = Path::new(FIFO_OBJ).parent().unwrap();
    std::fs::create_dir_all(dir).unwrap();
    for fifo in [FIFO_OBJ, FIFO_CSV] {
        if !Path::new(fifo).exists() {
            let made = std::process::Command::new("mkfifo")
                .arg(fifo)
                .status()
                .unwrap();
            assert!(made.success());
        }
    }
    std::fs::create_dir_all(DIR_OBJ).unwrap();
    let tet = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    std::fs::write(BOM_OBJ, format!("\u{feff}{tet}")).unwrap();
    let curve = "delta_m,force_n\n0.0005,0.4\n0.001,1.2\n0.002,3.5\n0.003,6.8\n0.004,11.0\n";
    std::fs::write(BOM_CSV, format!("\u{feff}{curve}")).unwrap();
}

/// The longest run of ASCII digits in `s`.
fn digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}
/// Steps run of every accepted scene.
const STEPS: u64 = 12;

/// SplitMix64: a small deterministic generator (no dependency).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes")
}

/// The corpus: every shipped scene, as (name, text).
fn corpus() -> Vec<(String, String)> {
    let mut out: Vec<_> = std::fs::read_dir(scenes_dir())
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    out.sort();
    assert!(out.len() >= 5, "the shipped scenes");
    out
}

/// A hostile replacement value.
fn hostile(rng: &mut Rng, old: &Value) -> Value {
    let numbers = [
        0.0,
        -0.0,
        1e39,
        -1e39,
        1e-50,
        1e308,
        -1.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        3.4e38,
        1e-300,
        1e7,
    ];
    match rng.below(11) {
        0 | 1 => Value::Float(numbers[rng.below(numbers.len())]),
        // Plausible values: a number scaled by 10^k (below) or by a factor in [1/4, 4].
        8 | 9 => match old {
            Value::Float(x) => Value::Float(x * 4f64.powi(rng.below(3) as i32 - 1) * 1.5),
            Value::Integer(i) => Value::Integer(i.saturating_mul(rng.below(4) as i64)),
            _ => Value::Float(1.0),
        },
        2 | 7 => match old {
            // A number scaled by 10^k, k in [-12, 12].
            Value::Float(x) => Value::Float(x * 10f64.powi(rng.below(25) as i32 - 12)),
            Value::Integer(i) => Value::Integer(i.wrapping_mul(1 << rng.below(40))),
            _ => Value::Integer(i64::MAX),
        },
        3 => Value::String(
            [
                "NaN",
                "inf",
                "1e39",
                "",
                "auto",
                "world",
                FIFO_OBJ,
                FIFO_CSV,
                DIR_OBJ,
                "/dev/zero",
                BOM_OBJ,
                BOM_CSV,
            ][rng.below(12)]
            .to_string(),
        ),
        4 => Value::Boolean(true),
        5 => Value::Array(
            (0..[0, 1, 2, 4, 1000][rng.below(5)])
                .map(|_| Value::Float(1e39))
                .collect(),
        ),
        // A plausible direction with a fourth component (tactile `direction` dropped it).
        10 => Value::Array([1.0, 0.0, 0.0, 5.0].map(Value::Float).to_vec()),
        6 => Value::Integer([0, -1, i64::MAX, i64::MIN, 1 << 40][rng.below(5)]),
        _ => Value::Table(toml::Table::new()),
    }
}

/// A step into a TOML tree: a table key or an array index.
#[derive(Clone)]
enum Seg {
    Key(String),
    Index(usize),
}

/// Every node's path below `v` (depth first), containers and leaves alike.
fn paths(v: &Value, prefix: &mut Vec<Seg>, out: &mut Vec<Vec<Seg>>) {
    let children: Vec<(Seg, &Value)> = match v {
        Value::Table(t) => t.iter().map(|(k, c)| (Seg::Key(k.clone()), c)).collect(),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .map(|(i, c)| (Seg::Index(i), c))
            .collect(),
        _ => return,
    };
    for (seg, child) in children {
        prefix.push(seg);
        out.push(prefix.clone());
        paths(child, prefix, out);
        prefix.pop();
    }
}

fn node<'a>(v: &'a mut Value, path: &[Seg]) -> &'a mut Value {
    path.iter().fold(v, |v, seg| match (v, seg) {
        (Value::Table(t), Seg::Key(k)) => t.get_mut(k).unwrap(),
        (Value::Array(a), Seg::Index(i)) => &mut a[*i],
        _ => unreachable!("paths() only lists existing nodes"),
    })
}

/// One structured mutation of a node picked uniformly among all nodes of the tree: replace
/// it with a hostile or plausible value, drop it, duplicate it (a duplicated `[[body]]`,
/// `[[fingertip]]` or array component), or add an unknown key beside it.
fn mutate(rng: &mut Rng, tree: &mut Value) {
    let mut all = Vec::new();
    paths(tree, &mut Vec::new(), &mut all);
    if all.is_empty() {
        return;
    }
    let path = &all[rng.below(all.len())];
    let (last, parent_path) = path.split_last().unwrap();
    let parent = node(tree, parent_path);
    match (rng.below(8), parent, last) {
        (0, Value::Table(t), Seg::Key(k)) => {
            t.remove(k);
        }
        (0, Value::Array(a), Seg::Index(i)) => {
            a.remove(*i);
        }
        (1, Value::Array(a), Seg::Index(i)) => {
            let dup = a[*i].clone();
            a.push(dup);
        }
        (1, Value::Table(t), Seg::Key(k)) => {
            t.insert(format!("{k}_x"), Value::Float(1.0));
        }
        (_, parent, last) => {
            let child = node(parent, std::slice::from_ref(last));
            *child = hostile(rng, child);
        }
    }
}

/// The mutated text of one case.
fn case(rng: &mut Rng, text: &str) -> String {
    if rng.below(8) == 0 {
        // Text-level: flip bytes or truncate (the TOML parser's side).
        let mut bytes = text.as_bytes().to_vec();
        if rng.below(2) == 0 {
            bytes.truncate(rng.below(bytes.len()));
        } else {
            for _ in 0..1 + rng.below(4) {
                let i = rng.below(bytes.len());
                bytes[i] ^= 1 << rng.below(8);
            }
        }
        return String::from_utf8_lossy(&bytes).into_owned();
    }
    let mut tree: Value = toml::from_str(text).unwrap();
    for _ in 0..1 + rng.below(2) {
        mutate(rng, &mut tree);
    }
    toml::to_string(&tree).unwrap_or_default()
}

/// The target: parse, validate and build `text`; if accepted, run a few steps. `Ok` says
/// whether the scene was accepted, `Err` what broke (a panic is caught by the caller).
pub fn scene_target(text: &str, base: &Path) -> Result<bool, String> {
    let parsed = Scene::parse(text, "fuzz.toml", base);
    // A byte-order mark before the text changes nothing.
    let with_mark = Scene::parse(&format!("\u{feff}{text}"), "fuzz.toml", base);
    match (&parsed, &with_mark) {
        (Ok(a), Ok(b)) if a.file() == b.file() => {}
        (Err(a), Err(b)) if a.to_string() == b.to_string() => {}
        _ => return Err("a byte-order mark changed the scene".into()),
    }
    let scene = match parsed {
        Ok(scene) => scene,
        Err(e) => {
            // Rejected with a typed error: fine, if its numbers are in shortest form.
            let m = e.to_string();
            if digit_run(&m) > 24 {
                return Err(format!("a number not in shortest form: {m}"));
            }
            return Ok(false);
        }
    };
    if let Some(b) = scene.file().bodies.iter().find(|b| b.name == "world") {
        return Err(format!("a body named `{}` was accepted", b.name));
    }
    let mut run = PlainRun::new(&scene);
    for step in 0..scene.steps().min(STEPS) {
        run.step();
        for (name, h) in &run.handles.bodies {
            let rb = &run.world.physics.bodies[*h];
            if !(rb.translation().is_finite() && rb.rotation().is_finite()) {
                return Err(format!("step {step}: body `{name}` has a non-finite pose"));
            }
        }
        for c in run.world.soft.contacts() {
            let (f, t) = c.wrench_about([0.0; 3]);
            if !(c.normal_force.is_finite() && f.iter().chain(&t).all(|x| x.is_finite())) {
                return Err(format!(
                    "step {step}: a fingertip force is not finite: {c:?}"
                ));
            }
        }
    }
    Ok(true)
}

#[test]
fn fuzz_scene_parser_validator_builder() {
    let iters = env("SOFTGRIP_FUZZ_ITERS", DEFAULT_ITERS);
    let seed = env("SOFTGRIP_FUZZ_SEED", 0x5EED_0011);
    let corpus = corpus();
    let base = scenes_dir();
    hostile_files();
    let mut rng = Rng(seed);
    // A case that blocks (a FIFO opened for reading) never returns: the watchdog ends the
    // process with the case's number after 120 s without progress.
    let progress = std::sync::Arc::new(std::sync::atomic::AtomicU64::new(0));
    {
        let progress = progress.clone();
        std::thread::spawn(move || {
            let mut last = u64::MAX;
            loop {
                std::thread::sleep(std::time::Duration::from_secs(120));
                let now = progress.load(std::sync::atomic::Ordering::SeqCst);
                if now == last {
                    eprintln!("fuzz_scene: case {now} blocked for 120 s (seed {seed:#x})");
                    std::process::abort();
                }
                last = now;
            }
        });
    }
    let (mut accepted, start) = (0u64, std::time::Instant::now());
    // Quiet the default hook while panics are caught (they are reported below).
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut failure = None;
    for i in 0..iters {
        progress.store(i, std::sync::atomic::Ordering::SeqCst);
        let (name, text) = &corpus[rng.below(corpus.len())];
        let mutated = case(&mut rng, text);
        match catch_unwind(AssertUnwindSafe(|| scene_target(&mutated, &base))) {
            Ok(Ok(ran)) => accepted += ran as u64,
            Ok(Err(e)) => failure = Some(format!("case {i} (from {name}): {e}")),
            Err(p) => {
                let msg = p
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                failure = Some(format!("case {i} (from {name}): panic: {msg}"));
            }
        }
        if let Some(f) = &failure {
            std::panic::set_hook(hook);
            let secs = start.elapsed().as_secs_f64();
            panic!("seed {seed:#x}, {f} (after {secs:.1} s)\n--- scene ---\n{mutated}");
        }
    }
    std::panic::set_hook(hook);
    println!(
        "fuzz_scene: {iters} cases, {accepted} accepted and run {STEPS} steps, {:.1} s (seed {seed:#x})",
        start.elapsed().as_secs_f64()
    );
    assert!(
        accepted > iters / 20,
        "the mutations must leave some scenes valid"
    );
}
