//! Fuzz target of the MCAP reader (what `softgrip inspect`, `export` and `plot` open) and of
//! `recover`: a deterministic, seeded, bounded loop under plain `cargo test`. Corpus: the
//! shipped recordings (`recordings/*.mcap`) and the foreign writers' files
//! (`tests/data/foreign/`: lz4 chunks, no summary, no statistics, extension records).
//! Mutations: bit flips, truncation, splicing two inputs, corrupted record length fields
//! (random, 2^64 - 1, off by a few), extension records (opcode >= 0x80) inserted between
//! records, zero-filled tails. Every input goes through `Recording::from_bytes` and, when it
//! reads, the typed metadata and per-topic walks; none may panic. Asserted besides: an
//! extension record inserted into a file changes nothing that is read (softgrip's recover
//! stopped at one), and a zero tail appended to a cut file changes no message; one input in
//! eight also goes through `recover`, which keeps the messages the reader reads. `SOFTGRIP_FUZZ_ITERS` (default 1000: ~10 s in a debug build; 300 took 3.2 s) raises the budget,
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
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in [
        here.join("../../recordings"),
        here.join("tests/data/foreign"),
    ] {
        let mut found: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "mcap"))
            .collect();
        found.sort();
        assert!(!found.is_empty(), "no recordings in {}", dir.display());
        files.extend(found);
    }
    files.iter().map(|p| std::fs::read(p).unwrap()).collect()
}

/// An extension record (an opcode no reader knows) of `len` bytes.
fn extension(rng: &mut Rng, len: usize) -> Vec<u8> {
    let opcode = [0x80u8, 0xff, 0x42, 0x11, 0xa5][rng.below(5)];
    let mut r = vec![opcode];
    r.extend_from_slice(&(len as u64).to_le_bytes());
    r.extend((0..len).map(|_| rng.next() as u8));
    r
}

/// `b` with an extension record inserted at a record boundary of its data section (before
/// the data-end record, where the spec lets any record be), if it has one.
fn with_extension(rng: &mut Rng, b: &[u8]) -> Option<Vec<u8>> {
    let heads = record_heads(b);
    let data_end = heads.iter().position(|&h| b[h] == 0x0f)?;
    let at = heads[1 + rng.below(data_end)];
    let len = rng.below(64);
    Some([&b[..at], &extension(rng, len), &b[at..]].concat())
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

/// The invariances of the foreign-writer classes on an intact corpus file `b`: an extension
/// record inserted changes nothing read, a zero tail after a cut changes no message.
fn invariances(rng: &mut Rng, b: &[u8]) -> Result<(), String> {
    let Ok(original) = Recording::from_bytes(b) else {
        return Ok(());
    };
    // Files without a data-section CRC (Python's, softgrip's recover output does have one):
    // an inserted record leaves them valid.
    let data_crc = record_heads(b)
        .iter()
        .find(|&&h| b[h] == 0x0f)
        .map(|&h| u32::from_le_bytes(b[h + 9..h + 13].try_into().unwrap()));
    if data_crc == Some(0)
        && let Some(ext) = with_extension(rng, b)
    {
        match Recording::from_bytes(&ext) {
            Ok(r) if r.messages == original.messages && r.metadata == original.metadata => {}
            Ok(_) => return Err("an extension record changed what was read".into()),
            Err(e) => return Err(format!("an extension record made the file unreadable: {e}")),
        }
    }
    let heads = record_heads(b);
    if heads.len() > 2 {
        let cut = heads[1 + rng.below(heads.len() - 1)];
        let plain = Recording::from_bytes(&b[..cut]);
        let mut zeros = b[..cut].to_vec();
        zeros.resize(cut + 1 + rng.below(1 << 16), 0);
        let tailed = Recording::from_bytes(&zeros);
        match (plain, tailed) {
            (Ok(p), Ok(t)) if p.messages == t.messages => {}
            (Err(_), Err(_)) => {}
            _ => return Err(format!("a zero tail after byte {cut} changed the messages")),
        }
    }
    Ok(())
}

/// `recover` of `bytes` (through a temporary file): no panic; what it keeps includes every
/// message the reader reads of an unfinished file (their count, at least).
fn recover_case(bytes: &[u8], dir: &Path, i: usize) -> Result<(), String> {
    let input = dir.join(format!("in-{i}.mcap"));
    let output = dir.join(format!("out-{i}.mcap"));
    std::fs::write(&input, bytes).unwrap();
    let read = Recording::from_bytes(bytes).ok().filter(|r| r.recovered());
    let result = softgrip_record::recover(&input, &output);
    std::fs::remove_file(&output).ok();
    let kept = std::env::temp_dir().join(format!("softgrip-fuzz-recover-{i}.mcap"));
    let verdict = match (result, read) {
        (Ok(r), Some(rec)) if (r.messages as usize) < rec.messages.len() => Err(format!(
            "recover kept {} messages, the reader reads {}",
            r.messages,
            rec.messages.len()
        )),
        (Err(softgrip_record::Error::NothingRecovered { .. }), Some(rec))
            if !rec.messages.is_empty() =>
        {
            Err(format!(
                "recover kept nothing, the reader reads {}",
                rec.messages.len()
            ))
        }
        _ => Ok(()),
    };
    // A failing input is kept for its regression test.
    match verdict {
        Ok(()) => std::fs::remove_file(&input).ok(),
        Err(_) => std::fs::rename(&input, &kept).ok(),
    };
    verdict.map_err(|e| format!("{e} (input kept in {})", kept.display()))
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
    let dir = std::env::temp_dir().join(format!("softgrip-fuzz-mcap-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for i in 0..iters {
        let a = &corpus[rng.below(corpus.len())];
        let b = &corpus[rng.below(corpus.len())];
        let mut input = mutate(&mut rng, a, b);
        match rng.below(8) {
            0 => input = with_extension(&mut rng, &input).unwrap_or(input),
            1 => input.resize(input.len() + rng.below(1 << 16), 0),
            _ => {}
        }
        let r = std::panic::catch_unwind(|| exercise(&input));
        assert!(
            r.is_ok(),
            "the reader panicked at iteration {i} (seed {seed}); input of {} bytes",
            input.len()
        );
        if i % 8 == 0 {
            let r = std::panic::catch_unwind(|| recover_case(&input, &dir, i));
            match r {
                Ok(Ok(())) => {}
                Ok(Err(e)) => panic!("iteration {i} (seed {seed}): {e}"),
                Err(_) => panic!("recover panicked at iteration {i} (seed {seed})"),
            }
        }
        if i % 16 == 0 {
            let r = std::panic::catch_unwind(|| {
                let mut r2 = Rng(rng.0);
                invariances(&mut r2, a)
            });
            match r {
                Ok(Ok(())) => {}
                Ok(Err(e)) => panic!("iteration {i} (seed {seed}): {e}"),
                Err(_) => panic!("the reader panicked on an invariance case at {i} (seed {seed})"),
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
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

/// Regression (the fuzz loop, seed 0x5EED_1111, iteration 432, once the gripper recordings
/// joined the corpus): a cut file whose `/softgrip/contacts` channel names a schema the file no
/// longer holds. The reader read its 6 messages as a schemaless channel; `recover` dropped the
/// channel and kept 33 of the 39. It now keeps it without a schema and says so.
#[test]
fn a_channel_whose_schema_is_lost_is_recovered_without_one() {
    let input =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/fuzz_recover_lost_schema.mcap");
    let bytes = std::fs::read(&input).unwrap();
    let read = Recording::from_bytes(&bytes).unwrap();
    assert_eq!(read.messages.len(), 39);
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.mcap");
    let report = softgrip_record::recover(&input, &out).unwrap();
    assert_eq!(report.messages, 39, "{report:?}");
    assert!(
        report.skipped.iter().any(|s| s.contains(
            "channel 4 (/softgrip/contacts) names schema 3, which the file does not hold"
        )),
        "{report:?}"
    );
    let back = Recording::from_bytes(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(back.messages.len(), 39);
    assert!(!back.recovered());
}
