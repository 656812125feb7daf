//! Cost of recording one simulation step (two fingertips, two contacts, one box): encoding
//! alone, and the whole `Recorder::write_step` (encode + chunking + zstd + file) at the default
//! options, to hold against the simulation's step time ("< 10 % of a step").
#![allow(missing_docs)]

#[path = "../tests/common/mod.rs"]
mod common;

use criterion::{Criterion, criterion_group, criterion_main};
use softgrip_record::msgs::softgrip_msgs::SoftContactArrayMsg;
use softgrip_record::{Recorder, RecorderOptions, RecordingInfo, RosMessage, cdr::CdrWriter};

fn bench(c: &mut Criterion) {
    let steps: Vec<_> = (0..1000).map(|k| common::step(k, 1_000_000)).collect();

    c.bench_function("encode SoftContactArrayMsg (2 contacts)", |b| {
        let mut w = CdrWriter::new();
        let msg = SoftContactArrayMsg {
            header: steps[0].header(),
            contacts: steps[0].contacts.clone(),
        };
        b.iter(|| {
            msg.encode_into(&mut w);
            std::hint::black_box(w.as_bytes().len())
        })
    });

    c.bench_function("markers of a step", |b| {
        b.iter(|| std::hint::black_box(softgrip_record::visuals::markers(&steps[3])))
    });

    let dir = tempfile::tempdir().expect("temp dir");
    for (name, options) in [
        (
            "write_step (zstd on 1 worker, 512 KiB chunks)",
            RecorderOptions::default(),
        ),
        (
            "write_step (zstd on caller thread)",
            RecorderOptions {
                compression_threads: 0,
                ..Default::default()
            },
        ),
        (
            "write_step (uncompressed)",
            RecorderOptions {
                compress: false,
                ..Default::default()
            },
        ),
    ] {
        let path = dir.path().join("bench.mcap");
        let mut rec =
            Recorder::with_options(&path, &RecordingInfo::default(), &options).expect("recorder");
        let mut steps = steps.clone();
        let mut k = 0usize;
        let mut t = 0u64;
        c.bench_function(name, |b| {
            b.iter(|| {
                let s = &mut steps[k % 1000];
                t += 1_000_000;
                s.time_ns = t;
                rec.write_step(s).expect("write");
                k += 1;
            })
        });
        rec.finish().expect("finish");
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
