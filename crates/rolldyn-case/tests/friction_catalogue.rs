//! Friction torque of Harris's local method with the EHL rolling
//! resistance (docs/power.md, docs/lubrication.md) against SKF's
//! frictional-moment model (SKF, *Rolling bearings*, catalogue 10000 EN,
//! 2013, "Friction"; docs/validation.md, "Friction torque against the
//! catalogue model"), written out here as an independent reference.
//!
//! Grid: catalogue bearings 6205, 6210, 6305 (radial load) and 7205B,
//! 7310B (axial load), 100–20 000 r/min, loads 1, 5 and 20 % of the
//! estimated C_r, operating viscosities 5–200 mm²/s; oil-jet lubrication
//! on both sides (SKF's kinematic starvation φ_rs with K_rs = 3e-8),
//! churning left out of both (rolldyn's churning and SKF's M_drag), both
//! sliding terms at SKF's full-film μ_EHL = 0.05 of a mineral oil. Compared only where the
//! catalogue model's full-film conditions hold: viscosity ratio
//! κ = ν/ν₁ ≥ 1 (ISO 281's rated viscosity ν₁), the catalogue model's own
//! weight of boundary friction φ_bl ≤ 0.1, and n d_m ≤ 5e5 mm·r/min (an
//! assumption: the range of open oil-lubricated bearings). Printed as
//! ratios; `ROLLDYN_FRICTION_CSV=path` also writes them for
//! docs/figures/friction_skf.png (scripts/plot_friction_skf.py).
//!
//! Palmgren's M₀ + M₁ at oil mist and oil bath are printed beside it (not
//! asserted: its f₀ table not re-checked). Both rolling-force fits are run (Houpert's, the default, and Biboulet
//! & Houpert's fully flooded one). Asserted for the default: within the
//! conditions the median ratio within ±10 %, at least 3/4 of the points
//! within ±25 % (the rest are the lightest loads, docs/validation.md), and
//! between neighbouring speeds the torque rises or falls as SKF's does but
//! at two points at most.

#![allow(clippy::unwrap_used)]

use rolldyn_case::catalogue::CatalogueBearing;
use rolldyn_case::{Override, load_case, simulation};

/// SKF's constants of one series: R1, R2, R3, S1, S2, S3 and K_z
/// (catalogue 10000 EN, tables of geometry constants; R3 = S3 = 0 for
/// deep-groove bearings).
struct Series {
    r: [f64; 3],
    s: [f64; 3],
    kz: f64,
    angular: bool,
}

fn series(designation: &str) -> Series {
    match &designation[..2] {
        "62" => Series {
            r: [3.9e-7, 1.7, 0.0],
            s: [3.23e-3, 36.5, 0.0],
            kz: 3.1,
            angular: false,
        },
        "63" => Series {
            r: [3.7e-7, 1.7, 0.0],
            s: [2.84e-3, 92.8, 0.0],
            kz: 3.1,
            angular: false,
        },
        "72" => Series {
            r: [4.33e-7, 2.02, 2.44e-12],
            s: [1.82e-2, 0.71, 2.44e-12],
            kz: 4.4,
            angular: true,
        },
        _ => Series {
            r: [4.54e-7, 2.02, 1.84e-12],
            s: [1.64e-2, 0.71, 1.84e-12],
            kz: 4.4,
            angular: true,
        },
    }
}

/// SKF's M_rr + M_sl \[N·mm\] of a bearing of bore d and outside diameter
/// D \[mm\] at n \[r/min\], ν \[mm²/s\], radial and axial loads \[N\].
fn skf(s: &Series, d: f64, big_d: f64, n: f64, nu: f64, fr: f64, fa: f64) -> f64 {
    let dm = 0.5 * (d + big_d);
    let (g_rr, g_sl) = if s.angular {
        let fg_r = s.r[2] * dm.powi(4) * n * n;
        let fg_s = s.s[2] * dm.powi(4) * n * n;
        (
            s.r[0] * dm.powf(1.97) * (fr + fg_r + s.r[1] * fa).powf(0.54),
            s.s[0] * dm.powf(0.26) * ((fr + fg_s).powf(4.0 / 3.0) + s.s[1] * fa.powf(4.0 / 3.0)),
        )
    } else {
        assert_eq!(fa, 0.0, "the grid loads deep-groove bearings radially");
        (
            s.r[0] * dm.powf(1.96) * fr.powf(0.54),
            s.s[0] * dm.powf(-0.26) * fr.powf(5.0 / 3.0),
        )
    };
    let phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm).powf(1.28) * nu.powf(0.64));
    let phi_rs = (-3e-8 * nu * n * (d + big_d) * (s.kz / (2.0 * (big_d - d))).sqrt()).exp();
    let phi_bl = (-2.6e-8 * (n * nu).powf(1.4) * dm).exp();
    let mu_sl = phi_bl * 0.15 + (1.0 - phi_bl) * 0.05;
    phi_ish * phi_rs * g_rr * (nu * n).powf(0.6) + g_sl * mu_sl
}

/// Palmgren's M₀ + M₁ \[N·mm\] (Palmgren 1959 as reproduced in Harris &
/// Kotzalas 2006, ch. 6; the f₀ and f₁ values not re-checked against the
/// printed tables): M₀ = 1e-7 f₀ (ν n)^⅔ d_m³ (ν n ≥ 2000, else
/// 160e-7 f₀ d_m³), M₁ = f₁ P₁ d_m with f₁ = 0.0007 (P₀/C₀)^0.5, P₁ = F_r
/// (deep-groove, radial load) or f₁ = 0.001 (P₀/C₀)^0.33, P₁ = F_a,
/// P₀ = 0.26 F_a (40° angular-contact, axial load); f₀ for oil mist and
/// oil bath: 1 and 2 (deep-groove), 1.7 and 3.3 (angular-contact).
fn palmgren(angular: bool, dm: f64, n: f64, nu: f64, load: f64, c0: f64) -> [f64; 2] {
    let (f0, f1, p1) = if angular {
        ([1.7, 3.3], 0.001 * (0.26 * load / c0).powf(0.33), load)
    } else {
        ([1.0, 2.0], 0.0007 * (load / c0).sqrt(), load)
    };
    let m0 = |f: f64| {
        if nu * n >= 2000.0 {
            1e-7 * f * (nu * n).powf(2.0 / 3.0) * dm.powi(3)
        } else {
            160e-7 * f * dm.powi(3)
        }
    };
    f0.map(|f| m0(f) + f1 * p1 * dm)
}

/// ISO 281's rated viscosity ν₁ \[mm²/s\] at n \[r/min\], d_m \[mm\].
fn rated_viscosity(n: f64, dm: f64) -> f64 {
    if n < 1000.0 {
        45_000.0 * n.powf(-0.83) / dm.sqrt()
    } else {
        4500.0 / (n.sqrt() * dm.sqrt())
    }
}

/// The catalogue case with the operating viscosity ν (the Walther law's
/// second point removed: the oil at its operating temperature) and SKF's
/// μ_EHL for the sliding.
fn case_text(bearing: &CatalogueBearing, nu: f64, law: &str) -> String {
    let density = 870.0;
    bearing
        .case_text()
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with("second_"))
        .map(|l| {
            if l.starts_with("viscosity = ") {
                format!("viscosity = \"{} Pa.s\"", nu * 1e-6 * density)
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
        + &format!(
            "\n[power]\nsliding_friction = 0.05\n[lubrication]\nmethod = \"oil_jet\"\nrolling_resistance = \"{law}\"\n"
        )
}

/// The compared points' ratios (with their labels), the points where the
/// trend in speed differs from SKF's, and the CSV rows, of rolling-force
/// fit `law`.
type Grid = (Vec<(f64, String)>, Vec<String>, Vec<String>, Vec<[f64; 2]>);

fn grid(law: &str) -> Grid {
    let mut rows = Vec::new();
    let mut ratios = Vec::new();
    let mut trends: Vec<String> = Vec::new();
    let mut palmgren_ratios = Vec::new();
    for name in ["6205", "6210", "6305", "7205B", "7310B"] {
        let bearing = CatalogueBearing::lookup(name, None).unwrap();
        let s = series(name);
        let ratings = bearing.ratings().unwrap();
        let c_r = ratings.dynamic;
        let (d, big_d) = (bearing.bore * 1e3, bearing.outside_diameter * 1e3);
        let dm = 0.5 * (d + big_d);
        for nu in [5.0, 20.0, 70.0, 200.0] {
            let text = case_text(&bearing, nu, law);
            for fraction in [0.01, 0.05, 0.2] {
                let load = fraction * c_r;
                // The last compared point: rolldyn's torque and SKF's.
                let mut previous: Option<(f64, f64)> = None;
                for n in [100.0, 300.0, 1000.0, 3000.0, 10_000.0, 20_000.0] {
                    let (key, fr, fa) = if s.angular {
                        ("operating.force_x", 0.0, load)
                    } else {
                        ("operating.force_z", load, 0.0)
                    };
                    let overrides = [
                        Override::parse_set(&format!("operating.speed=\"{n} rpm\"")).unwrap(),
                        Override::parse_set(&format!("{key}=\"{load} N\"")).unwrap(),
                    ];
                    let case = load_case(name, &text, &overrides).unwrap();
                    let (eq, p) = simulation::power_loss(&case).unwrap();
                    let w = eq.inner_speed;
                    // SKF's M_drag is left out on both sides.
                    let torque = (p.total() - p.churning) / w * 1e3;
                    let rolling =
                        (p.inner.rolling_resistance + p.outer.rolling_resistance) / w * 1e3;
                    let reference = skf(&s, d, big_d, n, nu, fr, fa);
                    let kappa = nu / rated_viscosity(n, dm);
                    let boundary = (-2.6e-8 * (n * nu).powf(1.4) * dm).exp();
                    let compared = kappa >= 1.0 && boundary <= 0.1 && n * dm <= 5e5;
                    let ratio = torque / reference;
                    if compared {
                        if let Some((t0, r0)) = previous {
                            if (torque > t0) != (reference > r0) {
                                trends.push(format!("{name} {nu} mm²/s {fraction} at {n} r/min"));
                            }
                        }
                        previous = Some((torque, reference));
                        let [mist, bath] = palmgren(s.angular, dm, n, nu, load, ratings.r#static);
                        palmgren_ratios.push([torque / mist, torque / bath]);
                        ratios.push((ratio, format!("{name} {n} r/min {nu} mm²/s {fraction}")));
                    }
                    rows.push(format!(
                        "{law},{name},{n},{nu},{fraction},{kappa:.3},{:.0},{torque:.4},{rolling:.4},{reference:.4},{ratio:.4},{compared}",
                        n * dm
                    ));
                }
            }
        }
    }
    (ratios, trends, rows, palmgren_ratios)
}

/// Median, lowest and highest ratio, the counts within ±25 and ±35 %.
fn describe(law: &str, ratios: &mut [(f64, String)], trends: &[String]) -> (f64, usize) {
    ratios.sort_by(|a, b| a.0.total_cmp(&b.0));
    let median = ratios[ratios.len() / 2].0;
    let within = |band: f64| {
        ratios
            .iter()
            .filter(|(r, _)| (r - 1.0).abs() <= band)
            .count()
    };
    eprintln!(
        "{law}: rolldyn / SKF over {} points in the catalogue model's conditions: median {median:.3}, lowest {:.3} ({}), highest {:.3} ({}); within ±25 %: {}, ±35 %: {}; trend in speed differs at {trends:?}",
        ratios.len(),
        ratios[0].0,
        ratios[0].1,
        ratios[ratios.len() - 1].0,
        ratios[ratios.len() - 1].1,
        within(0.25),
        within(0.35)
    );
    (median, within(0.25))
}

#[test]
fn friction_torque_against_the_skf_model() {
    let mut rows = vec!["law,bearing,speed_rpm,viscosity_mm2_s,load_fraction,kappa,n_dm,rolldyn_n_mm,rolling_resistance_n_mm,skf_n_mm,ratio,compared".to_string()];
    let (mut ratios, trends, default_rows, palmgren_ratios) = grid("houpert");
    let (mut flooded, flooded_trends, flooded_rows, _) = grid("biboulet_houpert");
    let within = palmgren_ratios
        .iter()
        .filter(|[m, b]| *m >= 1.0 && *b <= 1.0)
        .count();
    let median = |k: usize| {
        let mut v: Vec<f64> = palmgren_ratios.iter().map(|r| r[k]).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    eprintln!(
        "houpert against Palmgren: median rolldyn / oil mist {:.2}, / oil bath {:.2}; between the two at {within} of {} points",
        median(0),
        median(1),
        palmgren_ratios.len()
    );
    rows.extend(default_rows);
    rows.extend(flooded_rows);
    if let Ok(path) = std::env::var("ROLLDYN_FRICTION_CSV") {
        std::fs::write(&path, rows.join("\n") + "\n").unwrap();
    }
    describe("biboulet_houpert", &mut flooded, &flooded_trends);
    let (median, within) = describe("houpert", &mut ratios, &trends);
    assert!(ratios.len() > 100, "{} points compared", ratios.len());
    assert!((median - 1.0).abs() < 0.10, "median ratio {median}");
    assert!(
        within as f64 >= 0.75 * ratios.len() as f64,
        "{within} of {} points within ±25 %",
        ratios.len()
    );
    assert!(trends.len() <= 2, "{trends:?}");
}
