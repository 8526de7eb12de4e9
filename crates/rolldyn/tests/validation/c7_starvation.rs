//! C7 building blocks (Zhang et al. 2020 §2.3, docs/model.md §4): the dynamic model's EHL
//! film is the Hamrock–Dowson film starved by the ring's supply.
//!
//! 7008C default configuration at its Jones–Harris state: with
//! L = 1.2 on the inner ring only, every loaded inner contact's central
//! film equals the flooded one times ((L − 1)/(L* − 1))^0.25 with L* of
//! Zhang et al. 2020 eq 29 from that contact's own b, R_x and h_c (recomputed here
//! from an independent Hertz solve), and the outer films are unchanged.

use super::common::{bearing_7008c, dynamics_7008c};
use rolldyn::contact::{Curvature, HertzCoefficients, HertzModel};
use rolldyn::dynamics::{BearingModel, ContactSample, DragParameters};
use rolldyn::lubrication::{Supply, hamrock_dowson};
use rolldyn::material::{Material, effective_modulus};
use rolldyn::traction::TractionModel;

#[test]
fn c7_inner_starvation_scales_the_inner_films_only() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let flooded = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params.clone()).unwrap();
    let mut starved_params = params.clone();
    starved_params.film_supply = [Supply::InletDistance(1.2), Supply::Flooded];
    let starved = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, starved_params).unwrap();
    let y = flooded.state_from_equilibrium(&eq);
    let mut a = vec![ContactSample::default(); 22];
    let mut b = vec![ContactSample::default(); 22];
    flooded.contact_samples(0.0, &y, &mut a);
    starved.contact_samples(0.0, &y, &mut b);
    let TractionModel::Ehl(ehl) = &params.traction else {
        panic!("the default configuration has EHL traction");
    };
    let ep = effective_modulus(&steel, &steel);
    let mut worst = 0.0f64;
    for (f, s) in a.iter().zip(&b) {
        assert_eq!(f.outer.film, s.outer.film);
        let c = Curvature::of_raceway(&g.inner, g.ball_diameter, g.pitch_diameter, f.inner.angle);
        let hertz = HertzCoefficients::exact(&c, ep)
            .unwrap()
            .at_load(f.inner.load);
        let h = hamrock_dowson(
            &ehl.lubricant,
            f.inner.entrainment_speed,
            f.inner.load,
            c.rolling_radius,
            ep,
            hertz.semi_major / hertz.semi_minor,
        );
        let l_star = 1.0
            + 3.06
                * ((c.rolling_radius / hertz.semi_minor).powi(2) * h.central / c.rolling_radius)
                    .powf(0.56);
        let expected = f.inner.film * ((1.2 - 1.0) / (l_star - 1.0)).powf(0.25);
        assert!(
            l_star > 1.2,
            "the inner contacts are starved at L = 1.2 (L* = {l_star})"
        );
        worst = worst.max((s.inner.film / expected - 1.0).abs());
    }
    eprintln!("C7 blocks: starved inner film vs formula, worst {worst:.1e}");
    assert!(worst < 1e-6, "{worst}");
}
