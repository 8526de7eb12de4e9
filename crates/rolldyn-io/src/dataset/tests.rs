use super::*;

fn series(rows: std::ops::Range<usize>) -> TimeSeries {
    let mut ts = TimeSeries::default();
    ts.channel("time_s", "s");
    ts.channel("x_m", "m");
    for i in rows {
        ts.push(&[i as f64 * 1e-3, (i as f64).sin()]);
    }
    ts
}

fn temp(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-ds-{tag}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    dir
}

#[test]
fn parts_hold_fixed_row_ranges_and_read_back_as_one_series() {
    let dir = temp("parts");
    let template = series(0..0);
    let n = part_rows(2);
    let total = 2 * n + 17;
    let mut w = SeriesWriter::create(&dir, &template, &[("case", "t".into())], false).unwrap();
    let whole = series(0..total);
    for i in 0..total {
        w.push(&[
            whole.column("time_s").unwrap()[i],
            whole.column("x_m").unwrap()[i],
        ])
        .unwrap();
        if i % 1000 == 7 {
            w.sync().unwrap();
        }
    }
    w.sync().unwrap();
    assert_eq!(w.rows(), total as u64);
    // The written parts' room is kept for the next (memory: two parts).
    assert!(w.in_flight.is_none());
    assert!(w.spare.as_ref().is_some_and(|s| s.is_empty()));
    let parts = part_files(&dir).unwrap();
    assert_eq!(parts.len(), 3);
    assert_eq!(read_parquet(&parts[0]).unwrap().len(), n);
    let back = read_parquet(&dir).unwrap();
    assert_eq!(back, whole);
    assert_eq!(back.unit("x_m"), Some("m"));
    // Projection: one column, same values.
    let x = read_columns(&dir, Some(&["x_m"])).unwrap();
    assert_eq!(x.names(), ["x_m"]);
    assert_eq!(x.column("x_m"), whole.column("x_m"));
    // Asked in another order than the file's (and twice): each name keeps
    // its own values.
    let both = read_columns(&dir, Some(&["x_m", "time_s", "x_m"])).unwrap();
    assert_eq!(both.names(), ["time_s", "x_m"]);
    assert_eq!(both.column("x_m"), whole.column("x_m"));
    assert_eq!(both.column("time_s"), whole.column("time_s"));
    // A missing part is a gap in time: refused, naming it.
    std::fs::rename(&parts[1], dir.join("moved")).unwrap();
    let e = read_parquet(&dir).unwrap_err().to_string();
    assert!(e.contains("part-000001.parquet is missing"), "{e}");
    std::fs::rename(dir.join("moved"), &parts[1]).unwrap();
    // Row streaming stops where asked.
    let mut count = 0;
    for_each_row(&dir, Some(5), |r| {
        assert_eq!(r.len(), 2);
        count += 1;
    })
    .unwrap();
    assert_eq!(count, 5);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn float32_parts_read_back_as_float64_rounded_to_float32() {
    let dir = temp("f32");
    let whole = series(0..100);
    let mut w = SeriesWriter::create(&dir, &whole, &[], true).unwrap();
    for i in 0..100 {
        w.push(&[
            whole.column("time_s").unwrap()[i],
            whole.column("x_m").unwrap()[i],
        ])
        .unwrap();
    }
    w.sync().unwrap();
    let back = read_parquet(&dir).unwrap();
    assert_eq!(back.unit("x_m"), Some("m"));
    for (a, b) in back
        .column("x_m")
        .unwrap()
        .iter()
        .zip(whole.column("x_m").unwrap())
    {
        assert_eq!(*a, f64::from(*b as f32));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn resume_keeps_the_checkpointed_rows_and_gives_the_same_parts() {
    let n = part_rows(2);
    let total = 3 * n + 5;
    let whole = series(0..total);
    let row = |i: usize| {
        [
            whole.column("time_s").unwrap()[i],
            whole.column("x_m").unwrap()[i],
        ]
    };
    // Uninterrupted.
    let straight = temp("straight");
    let mut w = SeriesWriter::create(&straight, &whole, &[], false).unwrap();
    for i in 0..total {
        w.push(&row(i)).unwrap();
    }
    w.sync().unwrap();
    // Checkpointed at n + 3 rows, then written on to 2n + 9 and killed.
    let killed = temp("killed");
    let mut w = SeriesWriter::create(&killed, &whole, &[], false).unwrap();
    let checkpoint = n + 3;
    for i in 0..2 * n + 9 {
        w.push(&row(i)).unwrap();
        if i + 1 == checkpoint {
            w.sync().unwrap();
        }
    }
    drop(w);
    let mut w = SeriesWriter::resume(&killed, &whole, &[], checkpoint as u64, false).unwrap();
    assert_eq!(w.rows(), checkpoint as u64);
    for i in checkpoint..total {
        w.push(&row(i)).unwrap();
    }
    w.sync().unwrap();
    let (a, b) = (part_files(&straight).unwrap(), part_files(&killed).unwrap());
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(std::fs::read(x).unwrap(), std::fs::read(y).unwrap());
    }
    // More rows than on disk: refused with the missing part named.
    let e = SeriesWriter::resume(&killed, &whole, &[], 10 * n as u64, false).unwrap_err();
    assert!(e.to_string().contains("missing"), "{e}");
    std::fs::remove_dir_all(&straight).ok();
    std::fs::remove_dir_all(&killed).ok();
}

#[test]
fn a_full_part_failing_in_the_background_is_reported_by_the_next_sync() {
    let dir = temp("lost");
    let n = part_rows(2);
    let whole = series(0..n + 1);
    let mut w = SeriesWriter::create(&dir, &whole, &[], false).unwrap();
    // The directory goes away under the run: the full part cannot be
    // written, and the error names it.
    std::fs::remove_dir_all(&dir).unwrap();
    for i in 0..n + 1 {
        w.push(&[
            whole.column("time_s").unwrap()[i],
            whole.column("x_m").unwrap()[i],
        ])
        .unwrap();
    }
    let e = w.sync().unwrap_err().to_string();
    assert!(e.contains("part-000000.parquet"), "{e}");
}
