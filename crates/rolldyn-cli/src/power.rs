//! `rolldyn power`: the friction power loss of a case at its Jones–Harris
//! equilibrium by Harris's local method (Lei et al. 2023 §3; docs/power.md), by
//! component, with the friction torque; text or JSON (keys in docs/cli.md).

use crate::{CaseArgs, Failure, emit, json};
use clap::Args;
use rolldyn::power::{LocalPowerLoss, RaceLosses};
use rolldyn::quasistatic::Equilibrium;
use rolldyn_case::Case;
use serde::Serialize;
use std::fmt::Write as _;

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Arguments of `rolldyn power`.
#[derive(Args, Debug)]
pub struct PowerArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// One raceway's losses \[W\].
#[derive(Serialize)]
pub struct RaceRow {
    pub hysteresis_w: f64,
    pub differential_sliding_w: f64,
    pub spin_w: f64,
    pub total_w: f64,
}

impl From<&RaceLosses> for RaceRow {
    fn from(r: &RaceLosses) -> Self {
        Self {
            hysteresis_w: r.hysteresis,
            differential_sliding_w: r.differential_sliding,
            spin_w: r.spin,
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
    pub power_loss_w: f64,
    pub friction_torque_n_m: f64,
}

impl PowerReport {
    pub fn new(case: &Case, eq: &Equilibrium, p: &LocalPowerLoss) -> Result<Self, Failure> {
        Ok(Self {
            speed_rpm: eq.inner_speed / RPM,
            cage_speed_rpm: eq.cage_speed() / RPM,
            sliding_friction: case.sliding_friction().map_err(bad)?,
            hysteresis_coefficient: case.rolling_hysteresis,
            pocket_friction: case.cage.pocket_friction,
            inner: RaceRow::from(&p.inner),
            outer: RaceRow::from(&p.outer),
            cage_land_w: p.cage_land,
            ball_pocket_w: p.ball_pocket,
            ball_drag_w: p.ball_drag,
            cage_drag_w: p.cage_drag,
            seals_w: p.seals,
            power_loss_w: p.total(),
            friction_torque_n_m: p.friction_torque(),
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
        ] {
            let _ = writeln!(out, "  {name:<22} {v:>12.4}");
        }
        let _ = writeln!(
            out,
            "  total {:.4} W, friction torque {:.5} N·m",
            self.power_loss_w, self.friction_torque_n_m
        );
    }
}

fn bad(e: rolldyn_case::case::Invalid) -> Failure {
    Failure::BadInput(format!("{}: {}", e.key, e.rule))
}

/// Jones–Harris solution and local power loss of a case.
pub fn solve(case: &Case) -> Result<(Equilibrium, LocalPowerLoss), Failure> {
    rolldyn_case::simulation::power_loss(case).map_err(crate::simulation_failure)
}

pub fn command(args: PowerArgs) -> Result<(), Failure> {
    let report = report(&args)?;
    if args.json {
        json(&report)
    } else {
        let mut out = String::new();
        report.text(&mut out);
        emit(&out)
    }
}

/// What `rolldyn power --json` prints.
pub fn report(args: &PowerArgs) -> Result<PowerReport, Failure> {
    let (_, case) = args.case.load()?;
    let (eq, p) = solve(&case)?;
    PowerReport::new(&case, &eq, &p)
}
