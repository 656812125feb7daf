//! `softgrip sweep` (issue 13 item 2): the shards' CSV files concatenate to the whole sweep's
//! (every column but `wall_time`), the Parquet file reads back as the printed CSV, `--trial`
//! prints that trial's row, and bad arguments are one-line errors with a non-zero exit.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use softgrip_sweep::ResultsTable;

fn sweep_file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../softgrip-sweep/tests/data/grasp_sweep.toml")
}

fn softgrip(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(args)
        .output()
        .expect("softgrip runs")
}

fn stdout_table(out: &Output) -> ResultsTable {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    ResultsTable::from_csv(&String::from_utf8_lossy(&out.stdout)).expect("CSV results")
}

/// The table without wall times (the one column that differs between runs).
fn timeless(mut t: ResultsTable) -> ResultsTable {
    for r in &mut t.rows {
        r.wall_time = 0.0;
    }
    t
}

#[test]
fn shards_concatenate_to_the_whole_and_files_read_back() {
    let sweep = sweep_file();
    let sweep = sweep.to_str().expect("UTF-8 path");
    let whole = stdout_table(&softgrip(&["sweep", sweep, "--threads", "2"]));
    assert_eq!(whole.rows.len(), 8);
    assert_eq!(whole.held_count(), 2);
    assert_eq!(whole.error_count(), 4);
    let mut joined: Option<ResultsTable> = None;
    for i in 0..3 {
        let shard = format!("{i}/3");
        let part = stdout_table(&softgrip(&["sweep", sweep, "--shard", &shard]));
        match &mut joined {
            None => joined = Some(part),
            Some(j) => j.append(part).expect("same columns"),
        }
    }
    assert_eq!(
        timeless(joined.expect("three shards")),
        timeless(whole.clone())
    );

    let dir = tempfile::tempdir().expect("temp dir");
    let pq = dir.path().join("r.parquet");
    let pq_arg = pq.to_str().expect("UTF-8 path");
    let out = softgrip(&["sweep", sweep, "--out", pq_arg]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("8 of 8 trials, 2 held, 4 errors"),
        "{stderr}"
    );
    let back = ResultsTable::read_parquet(&pq).expect("reads back");
    assert_eq!(timeless(back), timeless(whole.clone()));
    // Not over an existing file without --force.
    let again = softgrip(&["sweep", sweep, "--out", pq_arg]);
    assert!(!again.status.success());

    let one = stdout_table(&softgrip(&["sweep", sweep, "--trial", "5"]));
    assert_eq!(timeless(one).rows, timeless(whole).rows[5..6]);
}

#[test]
fn bad_arguments_are_clear_errors() {
    let sweep = sweep_file();
    let sweep = sweep.to_str().expect("UTF-8 path");
    for (args, message) in [
        (
            vec!["--shard", "3/3"],
            "the index i of `i/n` must be in 0..n",
        ),
        (vec!["--shard", "a"], "must be `i/n`"),
        (vec!["--trial", "8"], "`trial` must be in 0..8"),
        (vec!["--out", "r.json"], "must end in .parquet or .csv"),
    ] {
        let mut all = vec!["sweep", sweep];
        all.extend(args.iter());
        let out = softgrip(&all);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?}");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
        assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
    }
}
