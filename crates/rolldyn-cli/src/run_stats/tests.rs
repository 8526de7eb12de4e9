use super::*;

fn template() -> TimeSeries {
    let mut ts = TimeSeries::default();
    for name in [
        "time_s",
        "cage_speed_rpm",
        "ball0_load_inner_n",
        "ball0_slide_to_roll_inner",
        "ball1_load_inner_n",
        "ball1_slide_to_roll_inner",
    ] {
        ts.channel(name, "1");
    }
    ts
}

/// The window's numbers equal those computed from the whole series
/// over its second half, the way they were computed before.
#[test]
fn window_statistics_equal_those_of_the_stored_series() {
    let (duration, rate) = (0.064, 1000.0);
    let mut stats = RunStatistics::new(&template(), duration, rate, 0.0);
    let mut rows = Vec::new();
    for k in 0..=64 {
        let t = k as f64 / rate;
        let load0 = (t * 300.0).sin().max(0.0) * 100.0;
        let load1 = (t * 300.0).cos().max(0.0) * 50.0;
        let row = vec![t, 4000.0 + k as f64, load0, 0.01 * k as f64, load1, -0.02];
        stats.push(&row);
        rows.push(row);
    }
    let w = stats.window();
    let window: Vec<&Vec<f64>> = rows.iter().filter(|r| r[0] >= 0.032 - 1e-12).collect();
    assert_eq!(w.span(), [0.032, 0.064]);
    let n = window.len() as f64;
    let mean_cage = window.iter().map(|r| r[1]).sum::<f64>() / n;
    assert!((w.mean("cage_speed_rpm") - mean_cage).abs() < 1e-9);
    let max_load = window.iter().map(|r| r[2].max(r[4])).fold(0.0, f64::max);
    assert_eq!(w.pooled_max("load_inner_n"), max_load);
    let pooled = window.iter().map(|r| r[2] + r[4]).sum::<f64>() / (2.0 * n);
    assert!((w.pooled_mean("load_inner_n") - pooled).abs() < 1e-9);
    let (mut s, mut c) = (0.0, 0.0);
    for r in &window {
        for (load, value) in [(r[2], r[3]), (r[4], r[5])] {
            if load > 0.0 {
                s += value;
                c += 1.0;
            }
        }
    }
    assert!((w.loaded_mean("slide_to_roll_inner") - s / c).abs() < 1e-12);
    assert_eq!(w.pooled_max_abs("slide_to_roll_inner"), 0.64);
    assert_eq!(stats.first("cage_speed_rpm"), 4000.0);
    assert_eq!(stats.last("cage_speed_rpm"), 4064.0);
    assert_eq!(w.signal().len(), window.len());
    assert_eq!(stats.samples(), 65);
}

/// An interrupted run's window is the second half of what it simulated.
#[test]
fn a_partial_run_averages_over_its_own_second_half() {
    let mut stats = RunStatistics::new(&template(), 1.0, 100.0, 0.0);
    for k in 0..=40 {
        stats.push(&[k as f64 / 100.0, k as f64, 0.0, 0.0, 0.0, 0.0]);
    }
    let w = stats.window();
    // Half of 0.4 s lies in block 12 (0.1875 … 0.203 s): from 0.19 s.
    assert_eq!(w.span(), [0.19, 0.4]);
    assert_eq!(
        w.mean("cage_speed_rpm"),
        (19..=40).sum::<i32>() as f64 / 22.0
    );
    // No contact is loaded: loaded means are 0, not NaN.
    assert_eq!(w.loaded_mean("slide_to_roll_inner"), 0.0);
}

/// A checkpoint's statistics restore to the same numbers.
#[test]
fn statistics_survive_a_checkpoint() {
    let mut stats = RunStatistics::new(&template(), 0.064, 1000.0, 0.0);
    for k in 0..40 {
        let t = k as f64 * 1e-3;
        stats.push(&[t, k as f64, (t * 300.0).sin(), 0.1, 0.0, -0.2]);
    }
    let mut w = StateWriter::new();
    stats.save(&mut w);
    let bytes = w.into_bytes();
    let mut back = RunStatistics::new(&template(), 0.064, 1000.0, 0.0);
    let mut r = StateReader::new(&bytes);
    back.restore(&mut r).unwrap();
    assert!(r.is_done());
    for s in [&mut stats, &mut back] {
        for k in 40..65 {
            let t = k as f64 * 1e-3;
            s.push(&[t, k as f64, (t * 300.0).sin(), 0.1, 0.0, -0.2]);
        }
    }
    let (a, b) = (stats.window(), back.window());
    assert_eq!(a.mean("cage_speed_rpm"), b.mean("cage_speed_rpm"));
    assert_eq!(
        a.loaded_mean("slide_to_roll_inner"),
        b.loaded_mean("slide_to_roll_inner")
    );
    assert_eq!(a.signal(), b.signal());
    assert_eq!(stats.samples(), back.samples());
    // Another run's statistics are refused.
    let mut other = TimeSeries::default();
    other.channel("time_s", "s");
    let mut r = StateReader::new(&bytes);
    assert!(
        RunStatistics::new(&other, 1.0, 1.0, 0.0)
            .restore(&mut r)
            .is_err()
    );
}

/// A run extended far beyond its duration keeps at most MAX_BLOCKS
/// blocks, and its window is still the second half of the run.
#[test]
fn an_extended_run_merges_blocks_and_keeps_its_window() {
    let mut stats = RunStatistics::new(&template(), 0.064, 1000.0, 0.0);
    for k in 0..=1000 {
        stats.push(&[k as f64 / 1000.0, k as f64, 0.0, 0.0, 0.0, 0.0]);
    }
    assert!(stats.blocks.len() <= MAX_BLOCKS);
    let w = stats.window();
    let [from, to] = w.span();
    assert_eq!(to, 1.0);
    // The window starts at the block boundary at or before 0.5 s.
    assert!(from <= 0.5 && from > 0.5 - stats.block_length, "{from}");
    let first = (from * 1000.0).round() as i32;
    let mean = (first..=1000).sum::<i32>() as f64 / (1001 - first) as f64;
    assert!((w.mean("cage_speed_rpm") - mean).abs() < 1e-9);
}

/// The kept signal is bounded.
#[test]
fn the_signal_buffer_is_bounded() {
    let stats = RunStatistics::new(&template(), 3600.0, 1e5, 0.0);
    assert_eq!(stats.signal_capacity, SIGNAL_SAMPLES);
}

/// The balls' passage jitter over the window is that of the intervals
/// between successive passages ending in it, and survives a checkpoint.
#[test]
fn passage_jitter_counts_the_windows_intervals_and_survives_a_checkpoint() {
    let mut balls = TimeSeries::default();
    for name in [
        "time_s",
        "ball0_azimuth_rad",
        "ball1_azimuth_rad",
        "ball2_azimuth_rad",
    ] {
        balls.channel(name, "1");
    }
    let (duration, rate, at) = (0.512, 1000.0, -std::f64::consts::FRAC_PI_2);
    let pitch = std::f64::consts::TAU / 3.0;
    // Ball 1 is 4 % of the pitch ahead, and all wobble a little.
    let row = |k: usize| -> Vec<f64> {
        let t = k as f64 / rate;
        let mut row = vec![t];
        for j in 0..3 {
            let ahead = if j == 1 { 0.04 * pitch } else { 0.0 };
            let wobble = 0.01 * (37.0 * t + j as f64).sin();
            let a = j as f64 * pitch + ahead + wobble + 60.0 * t;
            row.push(a.rem_euclid(std::f64::consts::TAU));
        }
        row
    };
    let mut stats = RunStatistics::new(&balls, duration, rate, at);
    let mut resumed = RunStatistics::new(&balls, duration, rate, at);
    for k in 0..=512 {
        stats.push(&row(k));
        if k == 300 {
            let mut w = StateWriter::new();
            stats.save(&mut w);
            let bytes = w.into_bytes();
            let mut r = StateReader::new(&bytes);
            resumed.restore(&mut r).unwrap();
            assert!(r.is_done());
        }
        if k > 300 {
            resumed.push(&row(k));
        }
    }
    let jitter = stats.window().passage_jitter().unwrap();
    assert_eq!(Some(jitter), resumed.window().passage_jitter());
    // The same from all passages at once: those ending in the window
    // (from 0.256 s, a sample on a block boundary).
    let mut detector = rolldyn::signal::passage::PassageDetector::new(at);
    let mut passages = Vec::new();
    for k in 0..=512 {
        let r = row(k);
        detector.push(r[0], r[1..].iter().copied(), &mut |p| passages.push(p));
    }
    passages.sort_by(f64::total_cmp);
    let intervals: Vec<f64> = passages
        .windows(2)
        .filter(|w| w[1] >= 0.256)
        .map(|w| w[1] - w[0])
        .collect();
    let n = intervals.len() as f64;
    let mean = intervals.iter().sum::<f64>() / n;
    let sd = (intervals.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / n).sqrt();
    assert_eq!(jitter.intervals, intervals.len());
    assert!((jitter.mean_interval - mean).abs() < 1e-12);
    assert!((jitter.jitter - sd / mean).abs() < 1e-9);
    // Ball 1 ahead by 4 % of the pitch: intervals p(1 ± 0.04) and p.
    assert!(jitter.jitter > 0.02 && jitter.jitter < 0.05, "{jitter:?}");
    // Without ball channels there is none.
    assert_eq!(
        RunStatistics::new(&template(), 0.064, 1000.0, 0.0)
            .window()
            .passage_jitter(),
        None
    );
}

/// The window's halves split its blocks in the middle: each has the
/// means of its own samples, the first ends where the second starts, and
/// their means bracket the window's.
#[test]
fn the_window_halves_split_it_in_the_middle() {
    let (duration, rate) = (0.064, 1000.0);
    let mut stats = RunStatistics::new(&template(), duration, rate, 0.0);
    for k in 0..=64 {
        let t = k as f64 / rate;
        stats.push(&[t, 4000.0 + k as f64, 1.0, 0.0, 1.0, 0.0]);
    }
    let [first, second] = stats.window_halves().unwrap();
    assert_eq!(first.span(), [0.032, 0.048]);
    assert_eq!(second.span(), [0.048, 0.064]);
    assert_eq!(first.last("cage_speed_rpm"), 4048.0);
    assert_eq!(second.last("cage_speed_rpm"), 4064.0);
    // Samples 32..=47 and 48..=64.
    assert!((first.mean("cage_speed_rpm") - 4039.5).abs() < 1e-9);
    assert!((second.mean("cage_speed_rpm") - 4056.0).abs() < 1e-9);
    assert_eq!(first.signal().len(), 17);
    assert_eq!(second.signal().len(), 17);
    // A window longer than the kept signal has no halves (the first would
    // have no vibration record).
    let mut long = RunStatistics::new(&template(), 4.0, 10_000.0, 0.0);
    for k in 0..=40_000 {
        let t = k as f64 / 10_000.0;
        long.push(&[t, 4000.0, 1.0, 0.0, 1.0, 0.0]);
    }
    assert!(long.window().signal().len() < 20_000);
    assert!(long.window_halves().is_none());
    // Too short a window has no halves.
    let mut short = RunStatistics::new(&template(), duration, rate, 0.0);
    short.push(&[0.0, 1.0, 1.0, 0.0, 1.0, 0.0]);
    assert!(short.window_halves().is_none());
}
