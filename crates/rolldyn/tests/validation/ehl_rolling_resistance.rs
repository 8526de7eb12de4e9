//! EHL rolling resistance (Biboulet & Houpert 2010; docs/lubrication.md,
//! "Rolling resistance"): the dynamic model and Harris's local method apply
//! the same law. At the Jones–Harris state of the 7008C (10 000 rpm,
//! F_x = 200 N, η₀ = 46.7 mPa·s, inlet heating with β_T = 0.04 1/K) the
//! dynamic model's rolling-resistance power of each ring's contacts equals
//! the local method's Σ 2 F_R u (1 %: the dynamic model's force also works
//! on the J–H state's ~1e-3 slip, and its couple on the relative rolling
//! rather than u/R_x); and the power is the model's dissipation with the
//! law minus that without it, to rounding.

use super::common::{bearing_7008c, dynamics_7008c, rolling_resistance_7008c};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::OdeSystem;
use rolldyn::lubrication::Supply;
use rolldyn::material::{Material, effective_modulus};
use rolldyn::power::harris::LubricatedContacts;
use rolldyn::power::{LocalMethodInputs, local_power_loss};
use rolldyn::quasistatic::films::FilmInputs;

#[test]
fn dynamic_and_local_method_rolling_resistance_agree() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let lubricant = *params.traction.lubricant().unwrap();
    let law = rolling_resistance_7008c(lubricant);
    let dissipation = |with: bool| {
        let mut p = params.clone();
        p.rolling_resistance = with.then_some(law);
        let m = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, p).unwrap();
        let y = m.state_from_equilibrium(&eq);
        let mut dy = vec![0.0; m.dimension()];
        let power = m.rhs_with_power(0.0, &y, &mut dy);
        (power, dy[m.layout().work() + 1])
    };
    let (dynamic, with) = dissipation(true);
    let (_, without) = dissipation(false);
    let rolling = dynamic.inner.rolling_resistance + dynamic.outer.rolling_resistance;
    assert!(
        ((with - without) / rolling - 1.0).abs() < 1e-6,
        "{with} − {without} W vs {rolling} W"
    );
    let inputs = LocalMethodInputs {
        sliding_friction: 0.08,
        hysteresis: 0.0,
        pocket_friction: 0.05,
        cage_weight: 0.0,
        pocket_radius: 27e-3,
        guide: None,
        drag: DragParameters::default(),
        seals: None,
        rolling_resistance: Some(LubricatedContacts {
            model: law,
            films: FilmInputs {
                lubricant,
                supply: [Supply::Flooded; 2],
                roughness: [0.0; 2],
                effective_modulus: effective_modulus(&steel, &steel),
            },
        }),
        churning: None,
    };
    let local = local_power_loss(&g, &eq, &inputs);
    eprintln!(
        "rolling resistance: dynamic {:.4} + {:.4} W, local method {:.4} + {:.4} W",
        dynamic.inner.rolling_resistance,
        dynamic.outer.rolling_resistance,
        local.inner.rolling_resistance,
        local.outer.rolling_resistance
    );
    for (d, q) in [
        (
            dynamic.inner.rolling_resistance,
            local.inner.rolling_resistance,
        ),
        (
            dynamic.outer.rolling_resistance,
            local.outer.rolling_resistance,
        ),
    ] {
        assert!(
            q > 0.0 && (d / q - 1.0).abs() < 0.01,
            "dynamic {d} W, local {q} W"
        );
    }
}
