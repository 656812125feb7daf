//! Fuzz target of the sweep parser (CONVENTIONS: every parser of outside input has one): a
//! seeded, bounded loop of mutations of the test sweep's text (byte flips, truncations,
//! splices of other lines) through `Sweep::parse`, asserting no panic, and for every accepted
//! sweep that its trial count is the product of its axes and its first trial's scene text
//! parses as TOML. `SOFTGRIP_FUZZ_ITERS` and `SOFTGRIP_FUZZ_SEED` as in the scene's target.

use std::path::Path;

use softgrip_sweep::Sweep;

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
        .unwrap_or(150);
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
                _ if at < bytes.len() => {
                    bytes.remove(at);
                }
                _ => {}
            }
        }
        let text = String::from_utf8_lossy(&bytes);
        if let Ok(sweep) = Sweep::parse(&text, "fuzz.toml", &dir) {
            accepted += 1;
            let product: u64 = sweep.axes().iter().map(|a| a.values.len() as u64).product();
            assert_eq!(sweep.trials(), product, "{text}");
            let scene = sweep.scene_text(0).expect("trial 0 exists");
            assert!(toml::from_str::<toml::Table>(&scene).is_ok(), "{scene}");
        }
    }
    // The mutations are small: some must leave a valid sweep, or the target tests nothing.
    assert!(accepted > 0, "no mutation of {iters} was accepted");
}
