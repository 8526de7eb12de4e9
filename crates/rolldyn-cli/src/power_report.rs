//! The power report of one bearing (`rolldyn power`, and each bearing of
//! `rolldyn thermal`): Harris's local method's losses by component, the
//! friction torque by mechanism and the models used (keys in docs/cli.md).

use crate::Failure;
use rolldyn::lubrication::rolling_resistance::RollingForceLaw;
use rolldyn::power::{LocalPowerLoss, RaceLosses};
use rolldyn::quasistatic::Equilibrium;
use rolldyn_case::Case;
use serde::Serialize;
use std::fmt::Write as _;

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// One raceway's losses \[W\].
#[derive(Serialize)]
pub struct RaceRow {
    pub hysteresis_w: f64,
    pub differential_sliding_w: f64,
    pub spin_w: f64,
    pub rolling_resistance_w: f64,
    pub total_w: f64,
}

impl From<&RaceLosses> for RaceRow {
    fn from(r: &RaceLosses) -> Self {
        Self {
            hysteresis_w: r.hysteresis,
            differential_sliding_w: r.differential_sliding,
            spin_w: r.spin,
            rolling_resistance_w: r.rolling_resistance,
            total_w: r.total(),
        }
    }
}

/// `rolldyn power --json` (also the `power` object of `rolldyn thermal`).
#[derive(Serialize)]
pub struct PowerReport {
    pub speed_rpm: f64,
    pub cage_speed_rpm: f64,
    pub sliding_friction: f64,
    pub hysteresis_coefficient: f64,
    pub pocket_friction: f64,
    pub inner: RaceRow,
    pub outer: RaceRow,
    pub cage_land_w: f64,
    pub ball_pocket_w: f64,
    pub ball_drag_w: f64,
    pub cage_drag_w: f64,
    pub seals_w: f64,
    pub churning_w: f64,
    pub power_loss_w: f64,
    pub friction_torque_n_m: f64,
    /// The friction torque by mechanism: each power over the ring speed.
    pub friction_torque_split_n_m: TorqueSplit,
    /// How the bearing is lubricated and which laws were used.
    pub models: Models,
}

/// The friction torque by mechanism \[N·m\] (power / inner-ring speed).
#[derive(Serialize)]
pub struct TorqueSplit {
    /// Differential (Heathcote) sliding of both raceways.
    pub sliding: f64,
    pub spin: f64,
    /// EHL rolling resistance.
    pub rolling_resistance: f64,
    /// Elastic hysteresis.
    pub hysteresis: f64,
    /// Guide land and ball–pocket friction.
    pub cage: f64,
    /// Ball and cage drag of the air–oil mixture, and churning.
    pub drag_churning: f64,
    pub seals: f64,
}

/// The lubrication and the laws behind the numbers.
#[derive(Serialize)]
pub struct Models {
    /// `lubrication.method`: none, oil_bath, oil_jet, air_oil, grease.
    pub lubrication_method: &'static str,
    /// "houpert", "biboulet_houpert_2010" or "none".
    pub rolling_resistance: &'static str,
    /// "aihara_1987" or "none".
    pub inlet_heating: &'static str,
    /// The rolling resistance's starvation: "film_supply" (the films'
    /// supply, flooded unless stated) or "skf_2013_replenishment" (SKF's
    /// kinematic replenishment of the method).
    pub starvation: &'static str,
    /// "skf_2013_oil_bath", "skf_2013_oil_jet" or "none".
    pub churning: &'static str,
    /// Notes on what is not counted.
    pub notes: Vec<String>,
}

impl Models {
    fn of(case: &Case) -> Self {
        use rolldyn_case::case::Method;
        let rolling = case.rolling_resistance().ok().flatten();
        let method = case.lubrication.method;
        Self {
            lubrication_method: match method {
                Method::None => "none",
                Method::OilBath => "oil_bath",
                Method::OilJet => "oil_jet",
                Method::AirOil => "air_oil",
                Method::Grease => "grease",
            },
            rolling_resistance: match rolling.map(|r| r.law) {
                Some(RollingForceLaw::BibouletHoupert) => "biboulet_houpert_2010",
                Some(RollingForceLaw::Houpert) => "houpert",
                None => "none",
            },
            starvation: match rolling.and_then(|r| r.replenishment) {
                Some(_) => "skf_2013_replenishment",
                None => "film_supply",
            },
            inlet_heating: if rolling.is_some_and(|r| r.heating.is_some()) {
                "aihara_1987"
            } else {
                "none"
            },
            churning: match method {
                Method::OilBath => "skf_2013_oil_bath",
                Method::OilJet => "skf_2013_oil_jet",
                _ => "none",
            },
            notes: case.lubrication_note().into_iter().collect(),
        }
    }
}

impl PowerReport {
    pub fn new(case: &Case, eq: &Equilibrium, p: &LocalPowerLoss) -> Result<Self, Failure> {
        Ok(Self {
            speed_rpm: eq.inner_speed / RPM,
            cage_speed_rpm: eq.cage_speed() / RPM,
            sliding_friction: case.sliding_friction().map_err(crate::invalid)?,
            hysteresis_coefficient: case.rolling_hysteresis,
            pocket_friction: case.cage.pocket_friction,
            inner: RaceRow::from(&p.inner),
            outer: RaceRow::from(&p.outer),
            cage_land_w: p.cage_land,
            ball_pocket_w: p.ball_pocket,
            ball_drag_w: p.ball_drag,
            cage_drag_w: p.cage_drag,
            seals_w: p.seals,
            churning_w: p.churning,
            power_loss_w: p.total(),
            friction_torque_n_m: p.friction_torque(),
            friction_torque_split_n_m: {
                let w = eq.inner_speed.abs();
                let t = |power: f64| if w > 0.0 { power / w } else { 0.0 };
                let both = |f: fn(&RaceLosses) -> f64| t(f(&p.inner) + f(&p.outer));
                TorqueSplit {
                    sliding: both(|r| r.differential_sliding),
                    spin: both(|r| r.spin),
                    rolling_resistance: both(|r| r.rolling_resistance),
                    hysteresis: both(|r| r.hysteresis),
                    cage: t(p.cage_land + p.ball_pocket),
                    drag_churning: t(p.ball_drag + p.cage_drag + p.churning),
                    seals: t(p.seals),
                }
            },
            models: Models::of(case),
        })
    }

    pub fn text(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "Power loss by Harris's local method at {:.0} rpm (cage {:.1} rpm; f_s {}, α_h {}, f_c {})",
            self.speed_rpm,
            self.cage_speed_rpm,
            self.sliding_friction,
            self.hysteresis_coefficient,
            self.pocket_friction
        );
        let _ = writeln!(
            out,
            "  {:<22} {:>12} {:>12}",
            "component", "inner W", "outer W"
        );
        for (name, i, o) in [
            (
                "elastic hysteresis",
                self.inner.hysteresis_w,
                self.outer.hysteresis_w,
            ),
            (
                "differential sliding",
                self.inner.differential_sliding_w,
                self.outer.differential_sliding_w,
            ),
            ("spin", self.inner.spin_w, self.outer.spin_w),
            (
                "EHL rolling resistance",
                self.inner.rolling_resistance_w,
                self.outer.rolling_resistance_w,
            ),
            ("raceway total", self.inner.total_w, self.outer.total_w),
        ] {
            let _ = writeln!(out, "  {name:<22} {i:>12.4} {o:>12.4}");
        }
        for (name, v) in [
            ("cage land", self.cage_land_w),
            ("ball–pocket", self.ball_pocket_w),
            ("ball drag", self.ball_drag_w),
            ("cage drag", self.cage_drag_w),
            ("seals", self.seals_w),
            ("churning", self.churning_w),
        ] {
            let _ = writeln!(out, "  {name:<22} {v:>12.4}");
        }
        let _ = writeln!(
            out,
            "  total {:.4} W, friction torque {:.5} N·m",
            self.power_loss_w, self.friction_torque_n_m
        );
        let t = &self.friction_torque_split_n_m;
        let _ = writeln!(
            out,
            "  friction torque by mechanism [N·mm]: sliding {:.3}, spin {:.3}, rolling resistance {:.3}, hysteresis {:.3}, cage {:.3}, drag and churning {:.3}, seals {:.3}",
            t.sliding * 1e3,
            t.spin * 1e3,
            t.rolling_resistance * 1e3,
            t.hysteresis * 1e3,
            t.cage * 1e3,
            t.drag_churning * 1e3,
            t.seals * 1e3
        );
        let m = &self.models;
        let _ = writeln!(
            out,
            "  lubrication: method {}; rolling resistance {} (inlet heating {}, starvation {}); churning {}",
            m.lubrication_method, m.rolling_resistance, m.inlet_heating, m.starvation, m.churning
        );
        for note in &m.notes {
            let _ = writeln!(out, "  note: {note}");
        }
    }
}
