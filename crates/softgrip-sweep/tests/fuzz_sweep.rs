//! Fuzz target of the sweep parser (CONVENTIONS: every parser of outside input has one): a
//! seeded, bounded loop of mutations of the test sweep's text (byte flips, truncations,
//! splices of other lines and of hostile axes: non-finite values, random ranges up to
//! ±1e308 and down to subnormals, a byte-order mark) through `Sweep::parse`, asserting no
//! panic, and for every accepted sweep that its trial count is the product of its axes, its
//! first trial's scene text parses as TOML, every number of every axis is finite, a random
//! axis spans its range (not one value repeated: -1e308 to 1e308 drew one value), and every
//! error prints its numbers in shortest form. `SOFTGRIP_FUZZ_ITERS` and `SOFTGRIP_FUZZ_SEED`
//! as in the scene's target.

use std::path::Path;

use softgrip_sweep::{Sweep, Value};

/// Hostile axes spliced into the sweep text.
const HOSTILE: [&str; 10] = [
    "[[vary]]\nfield = \"gripper.hold\"\nvalues = [nan, inf]\n",
    "[[vary]]\nfield = \"gripper.hold\"\nvalues = [0.1, -inf, 1e308]\n",
    "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = -1e308, high = 1e308, n = 64 }\n",
    "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = -1.7976931348623157e308, high = 1.7976931348623157e308, n = 64 }\n",
    "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = 5e-324, high = 1e-323, n = 16 }\n",
    "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = 1e300, high = inf, n = 4 }\n",
    "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = nan, high = 1.0, n = 4 }\n",
    "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = 0.0, high = 1e300, n = 1000000000000 }\n",
    "[[vary]]\nfield = \"gripper.hold\"\nvalues = [1e300, 1e-300]\n",
    "\u{feff}",
];

/// The longest run of ASCII digits in `s` (an `f64` in shortest form has at most 17
/// significant digits and 4 leading zeros).
fn digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

/// The checks of an accepted sweep's axes: finite numbers; a random axis over a range wide
/// enough for distinct doubles is not one value repeated.
fn check_axes(sweep: &Sweep, text: &str) {
    for a in sweep.axes() {
        let floats: Vec<f64> = (a.values.iter())
            .filter_map(|v| match v {
                Value::Float(x) => Some(*x),
                _ => None,
            })
            .collect();
        assert!(floats.iter().all(|x| x.is_finite()), "{text}");
        let (lo, hi) = floats
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), x| (l.min(*x), h.max(*x)));
        if floats.len() >= 16 && hi.abs().max(lo.abs()) > 1e-300 {
            assert!(lo < hi, "{} values all {lo:e}: {text}", floats.len());
        }
    }
}

fn next(state: &mut u64) -> u64 {
    // SplitMix64 (the same generator as the random axes).
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[test]
fn mutated_sweep_files_never_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let seed_text = std::fs::read_to_string(dir.join("grasp_sweep.toml")).expect("readable");
    let iters: u64 = std::env::var("SOFTGRIP_FUZZ_ITERS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(300);
    let mut state: u64 = std::env::var("SOFTGRIP_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(13);
    let lines: Vec<&str> = seed_text.lines().collect();
    let alphabet = b"[]{}=.,\"-0123456789eE_ abcxyz\n";
    let mut accepted = 0;
    for _ in 0..iters {
        let mut bytes = seed_text.clone().into_bytes();
        for _ in 0..1 + next(&mut state) % 4 {
            let n = bytes.len().max(1) as u64;
            let at = (next(&mut state) % n) as usize;
            match next(&mut state) % 4 {
                0 if at < bytes.len() => {
                    bytes[at] = alphabet[(next(&mut state) % alphabet.len() as u64) as usize]
                }
                1 => bytes.truncate(at),
                2 => {
                    let line = lines[(next(&mut state) % lines.len() as u64) as usize];
                    let at = at.min(bytes.len());
                    bytes.splice(at..at, format!("\n{line}\n").into_bytes());
                }
                3 if next(&mut state).is_multiple_of(2) => {
                    let axis = HOSTILE[(next(&mut state) % HOSTILE.len() as u64) as usize];
                    if axis.starts_with('\u{feff}') {
                        bytes.splice(0..0, axis.bytes());
                    } else {
                        bytes.extend_from_slice(format!("\n{axis}").as_bytes());
                    }
                }
                _ if at < bytes.len() => {
                    bytes.remove(at);
                }
                _ => {}
            }
        }
        let text = String::from_utf8_lossy(&bytes);
        match Sweep::parse(&text, "fuzz.toml", &dir) {
            Ok(sweep) => {
                accepted += 1;
                let product: u64 = sweep.axes().iter().map(|a| a.values.len() as u64).product();
                assert_eq!(sweep.trials(), product, "{text}");
                let scene = sweep.scene_text(0).expect("trial 0 exists");
                assert!(toml::from_str::<toml::Table>(&scene).is_ok(), "{scene}");
                check_axes(&sweep, &text);
            }
            Err(e) => {
                let m = e.to_string();
                assert!(digit_run(&m) <= 24, "not in shortest form: {m}\n{text}");
            }
        }
    }
    // The mutations are small: some must leave a valid sweep, or the target tests nothing.
    assert!(accepted > 0, "no mutation of {iters} was accepted");
}
