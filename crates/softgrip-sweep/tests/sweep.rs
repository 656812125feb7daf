//! Sweep tests (issue 13, "How it is checked"): shards concatenate to the whole run exactly; a
//! trial re-run by index reproduces its row; a bad trial is an error row naming the field;
//! results read back from CSV and Parquet equal the table the sweep produced; a trial's row
//! equals a direct run of the same scene edited by hand; `held` is true for the held box and
//! false for the dropped one.

use std::path::{Path, PathBuf};

use softgrip_sweep::{
    Outcome, ResultsTable, RunOptions, Shard, Sweep, SweepError, TrialRow, Value, run_scene,
    uniform,
};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn sweep() -> Sweep {
    Sweep::from_path(&data("grasp_sweep.toml")).expect("the test sweep loads")
}

fn run(sweep: &Sweep, threads: usize, shard: Shard) -> ResultsTable {
    sweep
        .run(&RunOptions { threads, shard }, &|_, _| {})
        .expect("the sweep runs")
}

/// The rows without their wall time (the one figure that differs between runs).
fn timeless(rows: &[TrialRow]) -> Vec<TrialRow> {
    rows.iter()
        .map(|r| TrialRow {
            wall_time: 0.0,
            ..r.clone()
        })
        .collect()
}

#[test]
fn trials_are_the_grid_product_with_seeded_random_values() {
    let s = sweep();
    assert_eq!(s.trials(), 8);
    assert_eq!(
        s.fields(),
        [
            "fingertip[0].material.youngs_modulus",
            "body[1].shape[0].density",
            "gripper.squeeze.depth"
        ]
    );
    // The random axis: low + (high - low) * u_j, u_j = SplitMix64 from the seed.
    let depth = |j| 0.0015 + 0.001 * uniform(7, j);
    assert_eq!(
        s.values(5).expect("in range"),
        [
            Value::Float(-1.0),
            Value::Float(500.0),
            Value::Float(depth(1))
        ]
    );
    assert_eq!(s.values(2).expect("in range")[2], Value::Float(depth(0)));
    assert!(matches!(s.values(8), Err(SweepError::Invalid { .. })));
}

#[test]
fn shards_concatenate_to_the_whole_and_rerun_reproduces_rows() {
    let s = sweep();
    let whole = run(&s, 2, Shard::WHOLE);
    assert_eq!(whole.rows.len(), 8);
    assert_eq!(
        whole.rows.iter().map(|r| r.trial).collect::<Vec<_>>(),
        (0..8).collect::<Vec<_>>()
    );
    let mut joined = s.table();
    for i in 0..3 {
        let part = run(&s, 1, Shard::new(i, 3).expect("valid shard"));
        joined.append(part).expect("same columns");
    }
    assert_eq!(timeless(&joined.rows), timeless(&whole.rows));
    for i in [0, 3, 5] {
        let again = s.run_trial(i).expect("in range");
        assert_eq!(
            timeless(&[again]),
            timeless(&whole.rows[i as usize..=i as usize])
        );
    }
}

#[test]
fn bad_trials_are_error_rows_naming_the_field_and_held_is_decided() {
    let s = sweep();
    let table = run(&s, 2, Shard::WHOLE);
    for r in &table.rows {
        let bad_modulus = r.values[0] == Value::Float(-1.0);
        match (&r.outcome, bad_modulus) {
            (Err(e), true) => {
                assert!(
                    e.contains("(trial ") && e.contains("`fingertip[0].material.youngs_modulus`"),
                    "{e}"
                );
                assert!(e.contains("-1"), "{e}");
            }
            (Ok(o), false) => {
                let heavy = r.values[1] == Value::Float(50000.0);
                assert_eq!(o.held, !heavy, "trial {}: {o:?}", r.trial);
                if heavy {
                    // Left on the table: the jaws rose 2 cm, the box did not.
                    assert!((o.slip_distance - 0.02).abs() < 2e-3, "{o:?}");
                } else {
                    // Carried: it slid less than 0.5 mm in the grip.
                    assert!(o.slip_distance.abs() < 5e-4, "{o:?}");
                }
            }
            other => panic!("trial {}: {other:?}", r.trial),
        }
    }
    assert_eq!(table.error_count(), 4);
    assert_eq!(table.held_count(), 2);
}

#[test]
fn a_row_equals_a_direct_run_of_the_hand_edited_scene() {
    let s = sweep();
    // Trial 0: modulus 0.59e6 and density 500 (as in the file), depth = the random axis's
    // first value.
    let row = s.run_trial(0).expect("in range");
    let depth = 0.0015 + 0.001 * uniform(7, 0);
    let text = std::fs::read_to_string(data("grasp.toml"))
        .expect("readable")
        .replace("depth = 0.002,", &format!("depth = {depth:?},"));
    let scene = softgrip_ecs::Scene::parse(&text, "hand-edited", &data(""))
        .expect("the edited scene is valid");
    let direct: Outcome = run_scene(&scene, &text, "box", None).expect("runs");
    assert_eq!(row.outcome, Ok(direct));
    assert!(direct.held);
    // The squeeze reached its depth: the peak compression is at least the commanded x.
    assert!(
        direct.peak_x >= depth / 0.01 * 0.99,
        "{direct:?} vs {depth}"
    );
}

#[test]
fn results_read_back_from_csv_and_parquet_equal_the_table() {
    let s = sweep();
    let table = run(&s, 2, Shard::new(0, 2).expect("valid"));
    assert_eq!(table.rows.len(), 4);
    let dir = tempfile::tempdir().expect("temp dir");
    let csv = dir.path().join("r.csv");
    let pq = dir.path().join("r.parquet");
    table.write_csv(&csv).expect("writes");
    table.write_parquet(&pq).expect("writes");
    assert_eq!(ResultsTable::read_csv(&csv).expect("reads"), table);
    assert_eq!(ResultsTable::read_parquet(&pq).expect("reads"), table);
    let header = std::fs::read_to_string(&csv).expect("readable");
    assert!(header.starts_with(
        "trial,fingertip[0].material.youngs_modulus,body[1].shape[0].density,\
         gripper.squeeze.depth,held,slips,slip_distance,peak_force,peak_x,\
         validity_excursions,hold_force,wall_time,error\n"
    ));
}

/// A results CSV written before `hold_force` existed (the same columns without it) reads
/// back, every outcome equal and `hold_force` NaN: `--resume` and `read_results` keep working
/// on old tables.
#[test]
fn results_without_hold_force_still_read_back() {
    let s = sweep();
    let table = run(&s, 2, Shard::new(0, 2).expect("valid"));
    let dir = tempfile::tempdir().expect("temp dir");
    let csv_path = dir.path().join("r.csv");
    table.write_csv(&csv_path).expect("writes");
    let mut reader = csv::Reader::from_path(&csv_path).expect("readable");
    let header = reader.headers().expect("header").clone();
    let drop = header
        .iter()
        .position(|c| c == "hold_force")
        .expect("a hold_force column");
    let keep = |rec: &csv::StringRecord| {
        rec.iter()
            .enumerate()
            .filter(|(k, _)| *k != drop)
            .map(|(_, c)| c.to_string())
            .collect::<Vec<_>>()
    };
    let mut writer = csv::Writer::from_writer(Vec::new());
    writer.write_record(keep(&header)).expect("writes");
    for rec in reader.records() {
        writer
            .write_record(keep(&rec.expect("a row")))
            .expect("writes");
    }
    let legacy = String::from_utf8(writer.into_inner().expect("flushed")).expect("utf-8");
    let old = ResultsTable::from_csv(&legacy).expect("a legacy table reads");
    assert_eq!(old.fields, table.fields);
    assert_eq!(old.rows.len(), table.rows.len());
    for (o, n) in old.rows.iter().zip(&table.rows) {
        assert_eq!(
            (o.trial, &o.values, o.wall_time),
            (n.trial, &n.values, n.wall_time)
        );
        match (&o.outcome, &n.outcome) {
            (Ok(a), Ok(b)) => {
                assert!(a.hold_force.is_nan(), "{a:?}");
                assert_eq!(
                    Outcome {
                        hold_force: b.hold_force,
                        ..*a
                    },
                    *b
                );
            }
            (a, b) => assert_eq!(a, b),
        }
    }
    let neither = legacy.replacen("validity_excursions", "excursions", 1);
    let e = ResultsTable::from_csv(&neither).expect_err("not a results table");
    assert!(
        e.contains("hold_force") && e.contains("validity_excursions"),
        "{e}"
    );
}

#[test]
fn sweep_file_errors_name_the_field() {
    let dir = data("");
    let err = |text: &str| {
        Sweep::from_str(&format!("scene = \"grasp.toml\"\n{text}"), &dir)
            .expect_err("an invalid sweep")
            .to_string()
    };
    let typo = err("[[vary]]\nfield = \"fingertip[0].material.youngs_modulu\"\nvalues = [1.0]");
    assert!(
        typo.contains("`vary[0].field`") && typo.contains("unknown field `youngs_modulu`"),
        "{typo}"
    );
    let wrong_type = err("[[vary]]\nfield = \"gripper.hold\"\nvalues = [\"long\"]");
    assert!(wrong_type.contains("`vary[0].field`"), "{wrong_type}");
    let missing = err("[[vary]]\nfield = \"fingertip[2].radius\"\nvalues = [0.01]");
    assert!(
        missing.contains("past the end of `fingertip`, which has 2"),
        "{missing}"
    );
    let both = err(
        "[[vary]]\nfield = \"gripper.hold\"\nvalues = [1.0]\nrandom = { low = 0.0, high = 1.0, n = 2 }",
    );
    assert!(both.contains("`vary[0].values`"), "{both}");
    let n = err("[[vary]]\nfield = \"gripper.hold\"\nrandom = { low = 0.0, high = 1.0, n = 0 }");
    assert!(n.contains("`vary[0].random.n` must be in 1..="), "{n}");
    let twice = err(
        "[[vary]]\nfield = \"gripper.hold\"\nvalues = [1.0]\n[[vary]]\nfield = \"gripper.hold\"\nvalues = [2.0]",
    );
    assert!(twice.contains("`vary[1].field`"), "{twice}");
    let object = err("object = \"table\"");
    assert!(object.contains("not a dynamic body"), "{object}");
    let e = Sweep::from_str("scene = \"nope.toml\"", &dir).expect_err("no scene");
    assert!(matches!(e, SweepError::Scene { .. }), "{e}");
}

#[test]
fn per_trial_recordings_are_written() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = data("grasp.toml");
    let text = format!(
        "scene = {:?}\nmcap_dir = \"runs\"\n[[vary]]\nfield = \"gripper.hold\"\nvalues = [0.1]\n",
        scene.display().to_string()
    );
    let s = Sweep::from_str(&text, dir.path()).expect("valid");
    let row = s.run_trial(0).expect("in range");
    assert!(row.outcome.is_ok(), "{row:?}");
    let mcap = dir.path().join("runs/trial-000000.mcap");
    let bytes = std::fs::read(&mcap).expect("the recording exists");
    assert!(bytes.starts_with(b"\x89MCAP0\r\n"), "{}", mcap.display());
}

#[test]
fn a_hold_that_does_not_end_is_an_error_row() {
    // 0.5 s: the grasp is still lifting (the hold ends at about 0.75 s).
    let text = "scene = \"grasp.toml\"\n[[vary]]\nfield = \"duration\"\nvalues = [0.5, 1.2]\n";
    let s = Sweep::from_str(text, &data("")).expect("valid");
    let short = s.run_trial(0).expect("in range");
    let e = short.outcome.expect_err("no end of the hold");
    assert!(
        e.contains("the hold did not end within the scene's duration (0.5"),
        "{e}"
    );
    assert!(s.run_trial(1).expect("in range").outcome.is_ok());
}
