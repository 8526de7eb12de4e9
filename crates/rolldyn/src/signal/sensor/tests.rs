use super::*;

fn spec(modes: Vec<HousingMode>) -> SensorSpec {
    SensorSpec {
        direction: 0.5 * PI,
        modes,
        noise_rms: 0.0,
        seed: 7,
        anti_alias_order: 4,
        anti_alias_cutoff: 20e3,
        full_scale: 1e6,
        adc_bits: 32,
        sample_rate: 50e3,
    }
}

const MODE: HousingMode = HousingMode {
    frequency: 3000.0,
    damping_ratio: 0.05,
    mass: 2.0,
};

/// The exact step against a fine fourth-order Runge–Kutta integration of
/// m(q̈ + 2ζωq̇ + ω²q) = f₀ + f₁s over three periods.
#[test]
fn the_exact_step_is_the_oscillators_solution() {
    let start = ModeState {
        q: [1e-6, -2e-6],
        v: [3e-3, 1e-3],
    };
    let (f0, f1) = ([40.0, -10.0], [2e5, 7e4]);
    let tau = 1e-3;
    let exact = MODE.advance(&start, tau, f0, f1);
    let w = MODE.omega();
    let n = 200_000;
    let h = tau / f64::from(n);
    for axis in 0..2 {
        let accel = |s: f64, q: f64, v: f64| {
            (f0[axis] + f1[axis] * s) / MODE.mass - 2.0 * MODE.damping_ratio * w * v - w * w * q
        };
        let (mut q, mut v) = (start.q[axis], start.v[axis]);
        for i in 0..n {
            let s = f64::from(i) * h;
            let (k1q, k1v) = (v, accel(s, q, v));
            let (k2q, k2v) = (
                v + 0.5 * h * k1v,
                accel(s + 0.5 * h, q + 0.5 * h * k1q, v + 0.5 * h * k1v),
            );
            let (k3q, k3v) = (
                v + 0.5 * h * k2v,
                accel(s + 0.5 * h, q + 0.5 * h * k2q, v + 0.5 * h * k2v),
            );
            let (k4q, k4v) = (v + h * k3v, accel(s + h, q + h * k3q, v + h * k3v));
            q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        }
        assert!(
            (exact.q[axis] - q).abs() <= 1e-9 * q.abs().max(1e-6),
            "{axis}: {} vs {q}",
            exact.q[axis]
        );
        assert!(
            (exact.v[axis] - v).abs() <= 1e-9 * v.abs().max(1e-3),
            "{axis}: {} vs {v}",
            exact.v[axis]
        );
    }
}

/// Steady-state amplitudes (√2 × RMS over 0.1 s, a whole number of
/// periods) of the chain driven by F cos(2πft) along the sensor's axis,
/// sampled as a run would (steps of 7 µs).
fn harmonic_response(spec: SensorSpec, frequency: f64, amplitude: f64) -> (f64, f64) {
    let mut chain = SensorChain::new(spec.clone(), 0.0, [0.0, amplitude]).unwrap();
    let force = |t: f64| [0.0, amplitude * (TAU * frequency * t).cos()];
    let (step, duration) = (7e-6, 0.2);
    let mut t: f64 = 0.0;
    let (mut acquired, mut housing, mut n) = (0.0f64, 0.0f64, 0.0);
    let mut next = 1u64;
    while t < duration {
        t = (t + step).min(duration);
        chain.advance(t, force(t));
        while let Some(s) = chain.sample(f64::from(next as u32) / spec.sample_rate) {
            if f64::from(next as u32) / spec.sample_rate > 0.1 + 1e-9 {
                acquired += s.acquired * s.acquired;
                housing += s.housing * s.housing;
                n += 1.0;
            }
            next += 1;
        }
    }
    ((2.0 * acquired / n).sqrt(), (2.0 * housing / n).sqrt())
}

/// The oscillator's receptance: the acceleration per force at `f`.
fn accelerance(mode: &HousingMode, f: f64) -> f64 {
    let (w, wf) = (mode.omega(), TAU * f);
    wf * wf
        / (mode.mass
            * ((w * w - wf * wf).powi(2) + (2.0 * mode.damping_ratio * w * wf).powi(2)).sqrt())
}

#[test]
fn a_harmonic_force_gives_the_modes_accelerance() {
    for f in [500.0, 2000.0, 3000.0, 5000.0] {
        let (acquired, housing) = harmonic_response(spec(vec![MODE]), f, 100.0);
        let expected = 100.0 * accelerance(&MODE, f);
        // The first-order hold over 7 µs steps and the sampled peak.
        assert!(
            (housing / expected - 1.0).abs() < 5e-3,
            "{f} Hz: {housing} vs {expected}"
        );
        // Far below the 20 kHz cutoff the filter passes the amplitude.
        assert!(
            (acquired / expected - 1.0).abs() < 5e-3,
            "{f} Hz: {acquired} vs {expected}"
        );
    }
}

#[test]
fn two_modes_add_and_the_axis_projects() {
    let second = HousingMode {
        frequency: 8000.0,
        damping_ratio: 0.03,
        mass: 0.5,
    };
    let mut s = spec(vec![MODE, second]);
    s.direction = PI / 3.0; // 60° from y: sees sin 60° of a z force
    let (_, housing) = harmonic_response(s, 2000.0, 100.0);
    // Both modes below resonance move in phase with the force.
    let expected =
        100.0 * (accelerance(&MODE, 2000.0) + accelerance(&second, 2000.0)) * (PI / 3.0).sin();
    assert!(
        (housing / expected - 1.0).abs() < 5e-3,
        "{housing} vs {expected}"
    );
}

#[test]
fn the_anti_alias_filter_is_3_db_down_at_its_cutoff() {
    let rate = 400e3;
    for order in 1..=8 {
        let mut filter = butterworth(order, 20e3, rate);
        let mut square = 0.0;
        for i in 0..40_000 {
            let mut x = (TAU * 20e3 * f64::from(i) / rate).sin();
            for s in &mut filter {
                x = s.filter(x);
            }
            if i >= 20_000 {
                square += x * x;
            }
        }
        // 1000 whole periods of 20 samples: amplitude √2 × RMS.
        let amplitude = (2.0 * square / 20_000.0).sqrt();
        assert!(
            (amplitude - 0.5f64.sqrt()).abs() < 1e-3,
            "order {order}: {amplitude}"
        );
    }
}

#[test]
fn noise_has_its_rms_through_the_filter() {
    let mut s = spec(vec![MODE]);
    s.noise_rms = 0.5;
    let mut chain = SensorChain::new(s.clone(), 0.0, [0.0; 2]).unwrap();
    let (mut sum, mut n) = (0.0, 0);
    let samples = 40_000u32;
    for i in 1..=samples {
        let t = f64::from(i) / s.sample_rate;
        chain.advance(t, [0.0; 2]);
        let x = chain.sample(t).unwrap().acquired;
        if i > 100 {
            sum += x * x;
            n += 1;
        }
    }
    let rms = (sum / f64::from(n)).sqrt();
    // White noise of RMS σ up to f_s/2 through a fourth-order Butterworth
    // (noise bandwidth 1.026 f_c for order 4).
    let expected = 0.5 * (1.026 * s.anti_alias_cutoff / (0.5 * s.sample_rate)).sqrt();
    assert!((rms / expected - 1.0).abs() < 0.03, "{rms} vs {expected}");
}

#[test]
fn the_adc_quantises_and_counts_clipped_samples() {
    let mut s = spec(vec![MODE]);
    s.adc_bits = 8;
    s.full_scale = 10.0;
    let mut chain = SensorChain::new(s, 0.0, [0.0; 2]).unwrap();
    let step = 20.0 / 256.0;
    assert_eq!(chain.quantise(0.3), 4.0 * step);
    assert_eq!(chain.clipped(), 0);
    assert_eq!(chain.quantise(25.0), 10.0 - step);
    assert_eq!(chain.quantise(-25.0), -10.0);
    assert_eq!(chain.clipped(), 2);
}

#[test]
fn a_checkpoint_continues_the_chain_bit_for_bit() {
    let mut s = spec(vec![MODE]);
    s.noise_rms = 0.1;
    let force = |t: f64| {
        [
            30.0 * (TAU * 170.0 * t).sin(),
            200.0 + 50.0 * (TAU * 900.0 * t).cos(),
        ]
    };
    let run = |chain: &mut SensorChain, from: u32, to: u32, out: &mut Vec<SensorSample>| {
        for i in from..to {
            let t = f64::from(i) * 13e-6;
            chain.advance(t, force(t));
            let k = (t * 50e3).floor();
            if let Some(x) = chain.sample(k / 50e3) {
                if out.last().is_none_or(|l| l.index != x.index) {
                    out.push(x);
                }
            }
        }
    };
    let mut whole = SensorChain::new(s.clone(), 0.0, force(0.0)).unwrap();
    let mut a = Vec::new();
    run(&mut whole, 1, 2000, &mut a);
    let mut first = SensorChain::new(s.clone(), 0.0, force(0.0)).unwrap();
    let mut b = Vec::new();
    run(&mut first, 1, 1000, &mut b);
    let mut out = StateWriter::new();
    first.save(&mut out);
    let bytes = out.into_bytes();
    let mut second = SensorChain::new(s, 0.0, force(0.0)).unwrap();
    second.restore(&mut StateReader::new(&bytes)).unwrap();
    run(&mut second, 1000, 2000, &mut b);
    assert_eq!(a, b);
    assert!(a.len() > 500);
}

#[test]
fn bad_values_are_refused_by_name() {
    type Change = Box<dyn Fn(&mut SensorSpec)>;
    let cases: Vec<(&str, Change)> = vec![
        ("sensor.modes", Box::new(|s| s.modes.clear())),
        (
            "sensor.modes.damping_ratio",
            Box::new(|s| s.modes[0].damping_ratio = 1.0),
        ),
        (
            "sensor.modes.frequency",
            Box::new(|s| s.modes[0].frequency = 0.0),
        ),
        ("sensor.noise", Box::new(|s| s.noise_rms = -1.0)),
        (
            "sensor.anti_alias_cutoff",
            Box::new(|s| s.anti_alias_cutoff = 25e3),
        ),
        (
            "sensor.anti_alias_order",
            Box::new(|s| s.anti_alias_order = 0),
        ),
        ("sensor.adc_bits", Box::new(|s| s.adc_bits = 40)),
    ];
    for (field, change) in cases {
        let mut s = spec(vec![MODE]);
        change(&mut s);
        assert_eq!(SensorChain::new(s, 0.0, [0.0; 2]).unwrap_err().field, field);
    }
}
