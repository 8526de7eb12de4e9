//! C8 (Lei et al. 2023 §5; docs/validation.md): the 30 × 62 × 16 angular-contact
//! bearing (Table 1: D 9.525 mm, Z 11, d_m 46 mm, α 30°; groove curvatures
//! 0.52 assumed), F_a 3000 N, F_r 780 N, 9000 … 17 000 rpm.
//!
//! Power by Harris's local method (f_s 0.08, α_h 0.007 as Lei et al. 2023 eq 21,
//! no cage land): Lei et al. 2023 §5.1 states that the loss rises with speed and
//! with axial load, that spin is the largest share (> 50 % under axial
//! load), and that radial load changes it little. Temperatures of the
//! coupled network: the outer ring warms with speed (Lei et al. 2023 Fig. 11,
//! Table 2); the numbers against Table 2 are in docs/validation.md.
//! And one cross-check: the quasi-static and dynamic hysteresis of the same
//! Jones–Harris state agree (the same law, Lei et al. 2023 eq 21 / Harris), 1 %.

use super::common::{bearing_30x62, bearing_7008c, dynamics_7008c, thermal_30x62};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::OdeSystem;
use rolldyn::material::Material;
use rolldyn::operating::Loads;
use rolldyn::power::{LocalMethodInputs, local_power_loss};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
use rolldyn::thermal::coupled::{CoupledOptions, CoupledProblem, Expansion, coupled_steady};

const RPM: f64 = std::f64::consts::TAU / 60.0;

fn inputs() -> LocalMethodInputs {
    LocalMethodInputs {
        sliding_friction: 0.08,
        hysteresis: 0.007,
        pocket_friction: 0.05,
        cage_weight: 0.0,
        pocket_radius: 23e-3,
        guide: None,
        drag: DragParameters::default(),
        seals: None,
        rolling_resistance: None,
        churning: None,
    }
}

fn conditions(rpm: f64, axial: f64, radial: f64) -> Conditions {
    Conditions {
        loads: Loads {
            force: [axial, 0.0, radial],
            moment: [0.0; 2],
        },
        inner_speed: rpm * RPM,
        control: RacewayControl::Outer,
    }
}

#[test]
fn c8_power_trends_of_seed004() {
    let g = bearing_30x62();
    let steel = Material::STEEL_52100;
    let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).unwrap();
    let power = |rpm, axial, radial| {
        let eq = qs
            .solve(&conditions(rpm, axial, radial), &SolverOptions::default())
            .unwrap();
        local_power_loss(&g, &eq, &inputs())
    };
    let series = |points: &[(f64, f64, f64)]| -> Vec<f64> {
        points
            .iter()
            .map(|&(n, a, r)| {
                let p = power(n, a, r);
                let spin = p.inner.spin + p.outer.spin;
                assert!(
                    spin > 0.5 * p.total(),
                    "spin {spin} of {} W at {n} rpm, {a} N, {r} N",
                    p.total()
                );
                p.total()
            })
            .collect()
    };
    let speed =
        series(&[9000.0, 11_000.0, 13_000.0, 15_000.0, 17_000.0].map(|n| (n, 3000.0, 780.0)));
    let axial = series(&[500.0, 2000.0, 5000.0, 9000.0].map(|a| (10_000.0, a, 780.0)));
    let radial = series(&[100.0, 1100.0, 2100.0, 3100.0].map(|r| (10_000.0, 3000.0, r)));
    eprintln!("C8 power: speed {speed:.1?} W, axial {axial:.1?} W, radial {radial:.1?} W");
    assert!(speed.windows(2).all(|w| w[1] > w[0]), "rises with speed");
    assert!(
        axial.windows(2).all(|w| w[1] > w[0]),
        "rises with axial load"
    );
    let rel = |v: &[f64]| (v[v.len() - 1] - v[0]) / v[0];
    assert!(
        rel(&radial).abs() < 0.25 * rel(&axial),
        "radial load matters little"
    );
}

#[test]
fn c8_hysteresis_same_in_quasistatic_and_dynamic() {
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    params.rolling_hysteresis = 0.007;
    let steel = Material::STEEL_52100;
    let g = bearing_7008c();
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let y = model.state_from_equilibrium(&eq);
    let mut dy = vec![0.0; model.dimension()];
    let dynamic = model.rhs_with_power(0.0, &y, &mut dy);
    let qs = local_power_loss(&g, &eq, &inputs());
    for (d, q) in [
        (dynamic.inner.hysteresis, qs.inner.hysteresis),
        (dynamic.outer.hysteresis, qs.outer.hysteresis),
    ] {
        assert!(
            q > 0.0 && (d / q - 1.0).abs() < 0.01,
            "dynamic {d} W, quasi-static {q} W"
        );
    }
}

#[test]
fn c8_outer_ring_warms_with_speed() {
    let g = bearing_30x62();
    let steel = Material::STEEL_52100;
    let (thermal, walther) = thermal_30x62();
    let mut last = 0.0;
    let mut row = Vec::new();
    for rpm in [9000.0, 13_000.0, 17_000.0] {
        let s = coupled_steady(
            &CoupledProblem {
                geometry: &g,
                ball: &steel,
                rings: &steel,
                hertz: HertzModel::Exact,
                conditions: conditions(rpm, 3000.0, 780.0),
                options: SolverOptions::default(),
                power: inputs(),
                thermal: thermal.clone(),
                viscosity: Some(walther),
                expansion: Expansion {
                    ring: 11.9e-6,
                    ball: 11.9e-6,
                    reference_temperature: 293.15,
                },
            },
            &CoupledOptions::default(),
        )
        .unwrap();
        assert!(s.converged, "{rpm} rpm: {:?}", s.history);
        let t = s.thermal.temperature("outer_ring").unwrap() - 273.15;
        assert!(t > last);
        last = t;
        row.push((rpm, t, s.history.len()));
    }
    eprintln!("C8 outer ring: {row:.2?} (rpm, °C, passes)");
}
