//! Static load distribution (docs/model.md §7.1):
//! * pure thrust at zero speed reproduces the textbook equation
//!   F_a = Z K_n (BD)^1.5 sin α (cos α₀/cos α − 1)^1.5 (Harris & Kotzalas,
//!   *Essential Concepts*, eq. 7.30 form) to 1e-6, with K_n the series
//!   stiffness of the two contacts at α;
//! * pure radial load with zero clearance: Q_max Z / F_r → 4.37 (Stribeck)
//!   for many balls, within 1 %;
//! * B4: pure axial load gives identical balls;
//! * B5: residual < 1e-8 of the applied load; the stiffness matrix (implicit
//!   function theorem) equals finite differences of re-solves.

use super::common::{bearing_6304, bearing_7008c, bearing_7218b, rel, steel_solver, thrust_curve};
use rolldyn::operating::Loads;
use rolldyn::quasistatic::{
    Conditions, Equilibrium, QuasiStaticError, QuasiStaticSolver, RacewayControl, SolverOptions,
};
use rolldyn::{BearingGeometry, Clearance, GeometrySpec};

/// Static solve (zero speed).
trait SolveStatic {
    fn solve_static(
        &self,
        loads: &Loads,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError>;
}

impl SolveStatic for QuasiStaticSolver {
    fn solve_static(
        &self,
        loads: &Loads,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        self.solve(
            &Conditions {
                loads: *loads,
                inner_speed: 0.0,
                control: RacewayControl::Outer,
            },
            options,
        )
    }
}

fn loads(fx: f64, fy: f64, fz: f64, my: f64, mz: f64) -> Loads {
    Loads {
        force: [fx, fy, fz],
        moment: [my, mz],
    }
}

#[test]
fn thrust_equation() {
    for (g, fa) in [
        (bearing_7008c(), 200.0),
        (bearing_7008c(), 5000.0),
        (bearing_7218b(), 40_000.0),
    ] {
        let sol = steel_solver(&g)
            .solve_static(&loads(fa, 0.0, 0.0, 0.0, 0.0), &SolverOptions::default())
            .unwrap();
        let alpha = sol.balls[0].inner.contact_angle;
        let (_, textbook) = thrust_curve(&g, alpha);
        eprintln!(
            "thrust {fa} N: α = {:.4}°, textbook F_a = {textbook:.6} N, {} iterations",
            alpha.to_degrees(),
            sol.iterations
        );
        assert!(rel(textbook, fa) < 1e-6, "F_a {fa}: textbook {textbook}");
    }
}

#[test]
fn stribeck_limit_for_many_balls() {
    // Zero clearance, pure radial load, 60 balls of 2 mm on a 46 mm pitch
    // circle (chord 2.41 mm), one ball on the load line.
    let g = BearingGeometry::new(&GeometrySpec {
        ball_diameter: 2e-3,
        ball_count: 60,
        pitch_diameter: 46e-3,
        inner_groove_curvature: 0.52,
        outer_groove_curvature: 0.52,
        clearance: Clearance::Diametral(0.0),
        preload: false,
    })
    .unwrap();
    let options = SolverOptions {
        first_ball_azimuth: std::f64::consts::FRAC_PI_2,
        ..Default::default()
    };
    let fr = 500.0;
    let sol = steel_solver(&g)
        .solve_static(&loads(0.0, 0.0, fr, 0.0, 0.0), &options)
        .unwrap();
    let q_max = sol.balls.iter().map(|b| b.inner.load).fold(0.0, f64::max);
    let ratio = q_max * g.ball_count as f64 / fr;
    // Exact many-ball limit: 1/J_r(ε = 0.5) = 1/((1/2π)∫cos^{5/2}) = 4.3707.
    eprintln!("Stribeck: Q_max Z / F_r = {ratio:.5} (limit 4.3707)");
    assert!(rel(ratio, 4.3707) < 0.01, "{ratio}");
}

#[test]
fn b4_pure_axial_load_gives_identical_balls() {
    let g = bearing_7008c();
    let sol = steel_solver(&g)
        .solve_static(&loads(300.0, 0.0, 0.0, 0.0, 0.0), &SolverOptions::default())
        .unwrap();
    let first = sol.balls[0];
    for b in &sol.balls {
        assert!(rel(b.inner.load, first.inner.load) < 1e-9);
        assert!(rel(b.outer.load, first.outer.load) < 1e-9);
        assert!((b.inner.contact_angle - first.inner.contact_angle).abs() < 1e-9);
        assert!((b.radial_position - first.radial_position).abs() < 1e-12);
    }
    assert!(sol.displacement[1].abs() < 1e-12 && sol.displacement[2].abs() < 1e-12);
    assert!(sol.displacement[3].abs() < 1e-10 && sol.displacement[4].abs() < 1e-10);
    // At zero speed the two contacts of a ball carry the same load.
    assert!(rel(first.inner.load, first.outer.load) < 1e-9);
    assert!(
        rel(
            first.inner.load * first.inner.contact_angle.sin() * g.ball_count as f64,
            300.0
        ) < 1e-9
    );
}

#[test]
fn b5_residual_and_stiffness_against_finite_differences() {
    let g = bearing_7008c();
    let s = steel_solver(&g);
    let options = SolverOptions::default();
    let base = loads(400.0, 150.0, -250.0, 2.0, -1.5);
    let sol = s.solve_static(&base, &options).unwrap();
    assert!(sol.residual < 1e-8, "relative residual {}", sol.residual);
    // Compliance by re-solving with perturbed loads: du/dF ≈ K⁻¹.
    let k = nalgebra::SMatrix::<f64, 5, 5>::from_fn(|i, j| sol.stiffness[i][j]);
    let compliance = k.try_inverse().unwrap();
    let steps = [1.0, 1.0, 1.0, 0.01, 0.01];
    let at = |l: Loads| Conditions {
        loads: l,
        inner_speed: 0.0,
        control: RacewayControl::Outer,
    };
    for col in 0..5 {
        let mut plus = base;
        let mut minus = base;
        let h = steps[col];
        if col < 3 {
            plus.force[col] += h;
            minus.force[col] -= h;
        } else {
            plus.moment[col - 3] += h;
            minus.moment[col - 3] -= h;
        }
        let up = s
            .solve_from(&sol, &at(plus), &options)
            .unwrap()
            .displacement;
        let um = s
            .solve_from(&sol, &at(minus), &options)
            .unwrap()
            .displacement;
        for row in 0..5 {
            let fd = (up[row] - um[row]) / (2.0 * h);
            let analytic = compliance[(row, col)];
            let norm = compliance.column(col).amax();
            assert!(
                (fd - analytic).abs() < 1e-4 * norm,
                "compliance ({row},{col}): FD {fd:e} vs {analytic:e}"
            );
        }
    }
}

#[test]
fn radial_load_with_clearance_loads_a_sector() {
    // 6304 (Shan et al. 2023), P_d = 20 µm, F_r = 1000 N along z.
    let g = bearing_6304();
    let options = SolverOptions {
        first_ball_azimuth: std::f64::consts::FRAC_PI_2,
        ..Default::default()
    };
    let sol = steel_solver(&g)
        .solve_static(&loads(0.0, 0.0, 1000.0, 0.0, 0.0), &options)
        .unwrap();
    let loaded = sol.balls.iter().filter(|b| b.inner.load > 0.0).count();
    assert!((1..7).contains(&loaded), "{loaded} balls loaded");
    assert!(sol.residual < 1e-8, "relative residual {}", sol.residual);
    // The ball on the load line carries the most; its opposite carries nothing.
    let top = sol.balls.iter().map(|b| b.inner.load).fold(0.0, f64::max);
    assert_eq!(top, sol.balls[0].inner.load);
    assert_eq!(sol.balls[3].inner.load, 0.0);
    // The ring moves towards the load by more than half the clearance.
    assert!(sol.displacement[2] > g.diametral_clearance / 2.0);
}

#[test]
fn zero_load_inside_clearance_is_reported() {
    let g = bearing_6304();
    // Zero load: the ring is anywhere in the clearance; rolldyn reports the
    // centred position with all balls unloaded and zero stiffness.
    let sol = steel_solver(&g)
        .solve_static(&loads(0.0, 0.0, 0.0, 0.0, 0.0), &SolverOptions::default())
        .unwrap();
    assert!(
        sol.balls
            .iter()
            .all(|b| b.inner.load == 0.0 && b.outer.load == 0.0)
    );
    assert_eq!(sol.displacement, [0.0; 5]);
    // A preloaded bearing at zero load is loaded internally.
    let mut spec = GeometrySpec {
        ball_diameter: 9.52e-3,
        ball_count: 7,
        pitch_diameter: 36.01e-3,
        inner_groove_curvature: 0.52,
        outer_groove_curvature: 0.52,
        clearance: Clearance::Diametral(-4e-6),
        preload: true,
    };
    let pre = steel_solver(&BearingGeometry::new(&spec).unwrap())
        .solve_static(&loads(0.0, 0.0, 0.0, 0.0, 0.0), &SolverOptions::default())
        .unwrap();
    assert!(pre.balls.iter().all(|b| b.inner.load > 0.0));
    // Centred ring: each ball takes the whole interference −P_d/2.
    assert!(
        rel(
            pre.balls[0].inner.penetration + pre.balls[0].outer.penetration,
            2e-6
        ) < 1e-6
    );
    spec.clearance = Clearance::Diametral(0.0);
    let _ = spec;
}
