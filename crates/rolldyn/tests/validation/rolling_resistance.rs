//! Rolling resistance by elastic hysteresis (docs/model.md §3; Lei et al. 2023 eq 21,
//! Harris): each loaded contact dissipates F_h |u| with
//! F_h = α_h (3/16)(b/(D/2)) Q. At the Jones–Harris state of the 7008C
//! (10 000 rpm, F_x = 200 N; balls nearly in pure rolling) the model's
//! dissipation rate with α_h = 0.007 minus that without must equal the sum
//! of F_h |u| over the contacts, with b from an independent Hertz solve at
//! each contact's load and angle. Tolerance 1 %: the model applies the
//! couple about the rolling axis of the *relative* angular velocity, which
//! equals |u|/(D/2) only in pure rolling (the J–H state slides by ~1e-3).

use super::common::{bearing_7008c, dynamics_7008c};
use rolldyn::RingKind;
use rolldyn::contact::{ContactTable, HertzModel, RacewayContactModel};
use rolldyn::dynamics::{BearingModel, ContactSample, DragParameters};
use rolldyn::integrate::OdeSystem;
use rolldyn::material::{Material, effective_modulus};
use rolldyn::traction::TractionModel;

#[test]
fn hysteresis_dissipates_f_h_times_rolling_speed() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    params.traction = TractionModel::None;
    let alpha_h = 0.007;
    let rate = |alpha: f64| {
        let mut p = params.clone();
        p.rolling_hysteresis = alpha;
        let m = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, p).unwrap();
        let y = m.state_from_equilibrium(&eq);
        let mut dy = vec![0.0; y.len()];
        m.rhs(0.0, &y, &mut dy);
        let mut samples = vec![ContactSample::default(); g.ball_count];
        m.contact_samples(0.0, &y, &mut samples);
        (dy[m.layout().work() + 1], samples)
    };
    let (with, samples) = rate(alpha_h);
    let (without, _) = rate(0.0);
    let ep = effective_modulus(&steel, &steel);
    let table = |kind| {
        ContactTable::new(RacewayContactModel::new(&g, kind, ep, HertzModel::Exact)).unwrap()
    };
    let (inner, outer) = (table(RingKind::Inner), table(RingKind::Outer));
    let radius = 0.5 * g.ball_diameter;
    let mut expected = 0.0;
    for s in &samples {
        for (c, t) in [(&s.inner, &inner), (&s.outer, &outer)] {
            if c.load > 0.0 {
                let b = t.at(c.angle).at_load(c.load).semi_minor;
                expected += alpha_h * 0.1875 * (b / radius) * c.load * c.entrainment_speed;
            }
        }
    }
    let got = with - without;
    eprintln!("hysteresis power: model {got:.5e} W, Σ F_h|u| {expected:.5e} W");
    assert!(expected > 0.0);
    assert!((got / expected - 1.0).abs() < 0.01, "{got} vs {expected}");
}
