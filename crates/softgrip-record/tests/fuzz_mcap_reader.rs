//! Fuzz target of the MCAP reader (what `softgrip inspect`, `export` and `plot` open): a
//! deterministic, seeded, bounded loop under plain `cargo test`. Corpus: the shipped
//! recordings (`recordings/*.mcap`). Mutations: bit flips, truncation, splicing two inputs,
//! corrupted record length fields (random, 2^64 - 1, off by a few). Every input goes through
//! `Recording::from_bytes` and, when it reads, the typed metadata and per-topic walks; none may
//! panic. `SOFTGRIP_FUZZ_ITERS` (default 1000: ~10 s in a debug build; 300 took 3.2 s) raises the budget,
//! `SOFTGRIP_FUZZ_SEED` changes the seed. A crash prints the seed and iteration; it then
//! becomes a named regression test below.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::Path;

use softgrip_record::{Recording, topics};

/// xorshift64*: a small deterministic generator (no dependency).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn corpus() -> Vec<Vec<u8>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../recordings");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "mcap"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no recordings in {}", dir.display());
    files.iter().map(|p| std::fs::read(p).unwrap()).collect()
}

/// Offsets of the top-level record heads (opcode, u64 length) of a file.
fn record_heads(b: &[u8]) -> Vec<usize> {
    let mut heads = Vec::new();
    let mut at = 8;
    while at + 9 <= b.len() {
        heads.push(at);
        let len = u64::from_le_bytes(b[at + 1..at + 9].try_into().unwrap());
        match usize::try_from(len)
            .ok()
            .and_then(|l| (at + 9).checked_add(l))
        {
            Some(next) if next <= b.len() => at = next,
            _ => break,
        }
    }
    heads
}

/// One mutation of `input` (another corpus file `other` for splicing).
fn mutate(rng: &mut Rng, input: &[u8], other: &[u8]) -> Vec<u8> {
    let mut b = input.to_vec();
    match rng.below(5) {
        0 => {
            for _ in 0..=rng.below(8) {
                let i = rng.below(b.len());
                b[i] ^= 1 << rng.below(8);
            }
        }
        1 => b.truncate(rng.below(b.len())),
        2 => {
            let cut = rng.below(b.len());
            let from = rng.below(other.len());
            b.truncate(cut);
            b.extend_from_slice(&other[from..]);
        }
        3 => {
            let heads = record_heads(&b);
            if !heads.is_empty() {
                let h = heads[rng.below(heads.len())];
                let old = u64::from_le_bytes(b[h + 1..h + 9].try_into().unwrap());
                let new = match rng.below(4) {
                    0 => u64::MAX,
                    1 => rng.next(),
                    2 => old.wrapping_add(rng.below(16) as u64).wrapping_sub(8),
                    _ => 0,
                };
                b[h + 1..h + 9].copy_from_slice(&new.to_le_bytes());
            }
        }
        _ => {
            // A byte flipped inside a chunk's compressed data, or a record's opcode changed.
            let heads = record_heads(&b);
            if !heads.is_empty() {
                let h = heads[rng.below(heads.len())];
                b[h] = rng.next() as u8;
            }
        }
    }
    b
}

/// What inspect/export/plot do with a recording that opened.
fn exercise(bytes: &[u8]) {
    if let Ok(rec) = Recording::from_bytes(bytes) {
        let _ = rec.info();
        let _ = rec.run_summary();
        let n = rec.on_topic(topics::CONTACTS).count() + rec.on_topic(topics::CLOCK).count();
        assert!(n <= rec.messages.len());
    }
}

#[test]
fn fuzz_mcap_reader_never_panics() {
    let iters: usize = std::env::var("SOFTGRIP_FUZZ_ITERS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000);
    let seed: u64 = std::env::var("SOFTGRIP_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x5EED_1111);
    let corpus = corpus();
    let mut rng = Rng(seed | 1);
    let start = std::time::Instant::now();
    for i in 0..iters {
        let a = &corpus[rng.below(corpus.len())];
        let b = &corpus[rng.below(corpus.len())];
        let input = mutate(&mut rng, a, b);
        let r = std::panic::catch_unwind(|| exercise(&input));
        assert!(
            r.is_ok(),
            "the reader panicked at iteration {i} (seed {seed}); input of {} bytes",
            input.len()
        );
    }
    println!(
        "fuzz_mcap_reader: {iters} inputs (seed {seed}) in {:.1} s",
        start.elapsed().as_secs_f64()
    );
}

/// Regression: a killed writer's open chunk (length 2^64 - 1) at the end of a file is
/// recovered up to it, not refused.
#[test]
fn open_chunk_length_u64_max_is_recovered_up_to_it() {
    let file = &corpus()[0];
    let heads = record_heads(file);
    let chunk = *heads.iter().rev().find(|&&h| file[h] == 0x06).unwrap();
    let mut b = file[..chunk + 9 + 100].to_vec();
    b[chunk + 1..chunk + 9].copy_from_slice(&u64::MAX.to_le_bytes());
    let rec = Recording::from_bytes(&b).unwrap();
    assert_eq!(rec.recovery.unwrap().bytes_kept, chunk as u64);
}
