//! A solver for a changed clearance without rebuilding its contact tables
//! (the thermal iteration changes the operating clearance every pass,
//! docs/thermal.md).

use super::QuasiStaticSolver;
use crate::contact::{ContactTable, HertzModel};
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, RingKind};

impl QuasiStaticSolver {
    /// This solver for `geometry`. The contact tables depend on the ball
    /// and pitch diameters and the groove curvatures only (the relative
    /// curvature R_x, R_y at each α, [`crate::contact::Curvature::of_raceway`]),
    /// not on the clearance: when those are unchanged and the tables are
    /// not `hertz_circular` (whose radii follow the raceway diameters) they
    /// are kept, else rebuilt.
    pub fn with_geometry(&self, geometry: &BearingGeometry) -> Result<Self, InvalidParameter> {
        let old = &self.geometry;
        let model = self.inner_table.model();
        let same_curvature = model.model != HertzModel::HertzCircular
            && old.ball_diameter == geometry.ball_diameter
            && old.pitch_diameter == geometry.pitch_diameter
            && old.inner.groove_curvature == geometry.inner.groove_curvature
            && old.outer.groove_curvature == geometry.outer.groove_curvature;
        let table = |t: &ContactTable, ring: RingKind| -> Result<ContactTable, InvalidParameter> {
            if same_curvature {
                Ok(t.clone())
            } else {
                let m = t.model();
                ContactTable::new(crate::contact::RacewayContactModel::new(
                    geometry,
                    ring,
                    m.effective_modulus,
                    m.model,
                ))
            }
        };
        Ok(Self {
            geometry: geometry.clone(),
            inner_table: table(&self.inner_table, RingKind::Inner)?,
            outer_table: table(&self.outer_table, RingKind::Outer)?,
            ball_mass: self.ball_mass,
            ball_inertia: self.ball_inertia,
            films: Vec::new(),
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::contact::HertzModel;
    use crate::material::Material;
    use crate::operating::Loads;
    use crate::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
    use crate::{BearingGeometry, Clearance, GeometrySpec};

    /// Kept tables give the same solution as rebuilt ones for a changed
    /// clearance (the tables do not depend on it).
    #[test]
    fn reused_tables_solve_like_new_ones() {
        let spec = |pd| GeometrySpec {
            ball_diameter: 9.525e-3,
            ball_count: 11,
            pitch_diameter: 46e-3,
            inner_groove_curvature: 0.52,
            outer_groove_curvature: 0.52,
            clearance: Clearance::Diametral(pd),
            preload: false,
        };
        let steel = Material::STEEL_52100;
        let a = BearingGeometry::new(&spec(100e-6)).unwrap();
        let b = BearingGeometry::new(&spec(90e-6)).unwrap();
        let base = QuasiStaticSolver::new(&a, &steel, &steel, HertzModel::Exact).unwrap();
        let fresh = QuasiStaticSolver::new(&b, &steel, &steel, HertzModel::Exact).unwrap();
        let reused = base.with_geometry(&b).unwrap();
        let c = Conditions {
            loads: Loads {
                force: [3000.0, 0.0, 780.0],
                moment: [0.0; 2],
            },
            inner_speed: 1000.0,
            control: RacewayControl::Outer,
        };
        let x = fresh.solve(&c, &SolverOptions::default()).unwrap();
        let y = reused.solve(&c, &SolverOptions::default()).unwrap();
        assert_eq!(x.displacement, y.displacement);
        assert_eq!(x.balls, y.balls);
    }
}
