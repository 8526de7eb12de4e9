//! Bearings on an elastic shaft (docs/systems.md, "Elastic shaft"): the
//! shaft as Euler–Bernoulli beam elements between nodes at the bearings'
//! pitch planes, the loads and the reference point, each bearing with its
//! full quasi-static solution at its node; the shaft's bending tilts the
//! inner rings against the outer rings (misalignment).
//!
//! # Equations
//! Node n has the displacement U_n = (x, y, z, θ_y, θ_z) (small rotations;
//! θ_z = dy/dx, θ_y = −dz/dx as for the rigid shaft, whose P_i maps the
//! reference point's to y + x_i θ_z and z − x_i θ_y). Between nodes a and
//! b (length L, uniform section: E A, E I) the element stiffness is the
//! bar's E A/L [1 −1; −1 1] along x and the cubic beam's
//!
//! ```text
//! E I / L³ [ 12   6L  −12   6L ;
//!            6L  4L²  −6L  2L² ;
//!           −12  −6L   12  −6L ;
//!            6L  2L²  −6L  4L² ]
//! ```
//!
//! in each bending plane, on (y_a, θ_z,a, y_b, θ_z,b) and on (z_a, −θ_y,a,
//! z_b, −θ_y,b) (Przemieniecki, *Theory of Matrix Structural Analysis*, §5;
//! exact for Euler–Bernoulli beams loaded at their nodes). Bearing i at
//! node n_i carries its ring at M_i U_{n_i} + s_i e_x (the rigid shaft's
//! kinematics with its own node as reference), so the shaft is in
//! equilibrium when
//!
//! ```text
//! K_shaft U + Σ_i E_iᵀ M_i R_i = F,   Jacobian K_shaft + Σ_i E_iᵀ M_i K_i M_i E_i
//! ```
//!
//! (E_i picks node n_i's five states, F the loads at their nodes): Newton
//! with a backtracking line search from the rigid shaft's solution, to
//! 1e-10 of the load. The system's compliance at the reference point is
//! the reference node's block of the Jacobian's inverse.

use super::system::{
    Matrix5, MountedBearing, ShaftSystem, SystemConditions, SystemEquilibrium, SystemError,
};
use super::{Equilibrium, SolverOptions};
use crate::error::InvalidParameter;
use crate::operating::Loads;
use nalgebra::{DMatrix, DVector};

/// Newton iteration limit.
const MAX_ITERATIONS: usize = 60;
/// Relative residual that ends the iteration.
const TOLERANCE: f64 = 1e-10;

/// A uniform round shaft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaftSection {
    /// Outside diameter \[m\].
    pub diameter: f64,
    /// Bore (0: solid) \[m\].
    pub bore: f64,
    /// Young's modulus \[Pa\].
    pub elastic_modulus: f64,
}

impl ShaftSection {
    /// Cross-section area \[m²\].
    pub fn area(&self) -> f64 {
        std::f64::consts::FRAC_PI_4 * (self.diameter.powi(2) - self.bore.powi(2))
    }

    /// Second moment of area about a diameter \[m⁴\].
    pub fn second_moment(&self) -> f64 {
        std::f64::consts::PI / 64.0 * (self.diameter.powi(4) - self.bore.powi(4))
    }
}

/// Bearings and loads on an elastic shaft.
#[derive(Debug, Clone)]
pub struct ElasticShaft {
    /// The section.
    pub section: ShaftSection,
    /// The bearings (their positions on the shaft, orientations, offsets).
    pub system: ShaftSystem,
    /// Loads at positions: (x \[m\], force and moment there).
    pub loads: Vec<(f64, Loads)>,
    /// Node positions, increasing: every bearing's, every load's and the
    /// reference point x = 0.
    nodes: Vec<f64>,
}

/// The elastic shaft's equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct ElasticEquilibrium {
    /// Node positions \[m\].
    pub nodes: Vec<f64>,
    /// Each node's displacement (x, y, z \[m\], θ_y, θ_z \[rad\]).
    pub displacements: Vec<[f64; 5]>,
    /// As for a rigid shaft, with the reference node's displacement, each
    /// bearing's load on the shaft at its own node, and the stiffness at
    /// the reference point (the inverse of its compliance block).
    pub system: SystemEquilibrium,
}

impl ElasticShaft {
    /// The bearings of `system` on a shaft of `section` with `loads` at
    /// their positions.
    pub fn new(
        section: ShaftSection,
        system: ShaftSystem,
        loads: Vec<(f64, Loads)>,
    ) -> Result<Self, InvalidParameter> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !positive(section.diameter) {
            return Err(InvalidParameter::new(
                "diameter",
                section.diameter,
                "must be positive",
            ));
        }
        if !(section.bore.is_finite() && section.bore >= 0.0 && section.bore < section.diameter) {
            return Err(InvalidParameter::new(
                "bore",
                section.bore,
                "must lie in [0, diameter)",
            ));
        }
        if !positive(section.elastic_modulus) {
            return Err(InvalidParameter::new(
                "elastic_modulus",
                section.elastic_modulus,
                "must be positive",
            ));
        }
        let mut nodes: Vec<f64> = std::iter::once(0.0)
            .chain(system.bearings.iter().map(|b| b.position))
            .chain(loads.iter().map(|l| l.0))
            .collect();
        nodes.sort_by(f64::total_cmp);
        nodes.dedup();
        Ok(Self {
            section,
            system,
            loads,
            nodes,
        })
    }

    /// Node positions \[m\].
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    fn node_of(&self, x: f64) -> usize {
        self.nodes.iter().position(|&n| n == x).unwrap_or(0)
    }

    /// The shaft's stiffness matrix (5 states per node).
    pub fn stiffness(&self) -> DMatrix<f64> {
        let n = self.nodes.len();
        let mut k = DMatrix::zeros(5 * n, 5 * n);
        let ea = self.section.elastic_modulus * self.section.area();
        let ei = self.section.elastic_modulus * self.section.second_moment();
        for e in 0..n.saturating_sub(1) {
            let l = self.nodes[e + 1] - self.nodes[e];
            let (a, b) = (5 * e, 5 * (e + 1));
            let bar = ea / l;
            for (i, j, s) in [(a, a, 1.0), (a, b, -1.0), (b, a, -1.0), (b, b, 1.0)] {
                k[(i, j)] += s * bar;
            }
            let beam = [
                [12.0, 6.0 * l, -12.0, 6.0 * l],
                [6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l],
                [-12.0, -6.0 * l, 12.0, -6.0 * l],
                [6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l],
            ];
            let c = ei / l.powi(3);
            // (y, θ_z) with θ_z = dy/dx; (z, −θ_y).
            let planes = [
                ([a + 1, a + 4, b + 1, b + 4], [1.0; 4]),
                ([a + 2, a + 3, b + 2, b + 3], [1.0, -1.0, 1.0, -1.0]),
            ];
            for (dofs, signs) in planes {
                for r in 0..4 {
                    for s in 0..4 {
                        k[(dofs[r], dofs[s])] += c * beam[r][s] * signs[r] * signs[s];
                    }
                }
            }
        }
        k
    }

    /// The external loads as a nodal vector.
    fn load_vector(&self, reference: &Loads) -> DVector<f64> {
        let mut f = DVector::zeros(5 * self.nodes.len());
        let mut add = |node: usize, l: &Loads| {
            for k in 0..3 {
                f[5 * node + k] += l.force[k];
            }
            f[5 * node + 3] += l.moment[0];
            f[5 * node + 4] += l.moment[1];
        };
        add(self.node_of(0.0), reference);
        for (x, l) in &self.loads {
            add(self.node_of(*x), l);
        }
        f
    }

    /// Each bearing as seen from its own node (position 0 there).
    fn at_nodes(&self) -> Vec<(usize, MountedBearing)> {
        self.system
            .bearings
            .iter()
            .map(|b| {
                (
                    self.node_of(b.position),
                    MountedBearing {
                        position: 0.0,
                        ..b.clone()
                    },
                )
            })
            .collect()
    }

    /// The rigid shaft's solution under the same loads (moved to x = 0)
    /// and the nodes' displacements it gives (a rigid shaft's).
    fn rigid_start(
        &self,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<(SystemEquilibrium, DVector<f64>), SystemError> {
        let mut total = conditions.loads;
        for (x, l) in &self.loads {
            for k in 0..3 {
                total.force[k] += l.force[k];
            }
            total.moment[0] += l.moment[0] - x * l.force[2];
            total.moment[1] += l.moment[1] + x * l.force[1];
        }
        let rigid = self.system.solve_general(
            &SystemConditions {
                loads: total,
                ..*conditions
            },
            options,
        )?;
        let u0 = rigid.displacement;
        let u = DVector::from_fn(5 * self.nodes.len(), |i, _| {
            let x = self.nodes[i / 5];
            match i % 5 {
                0 => u0[0],
                1 => u0[1] + x * u0[4],
                2 => u0[2] - x * u0[3],
                k => u0[k],
            }
        });
        Ok((rigid, u))
    }

    /// The equilibrium under `conditions` (their loads at the reference
    /// point, with [`Self::loads`] at theirs), from the rigid shaft's.
    pub fn solve(
        &self,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<ElasticEquilibrium, SystemError> {
        let nodes = self.nodes.len();
        let shaft = self.stiffness();
        let external = self.load_vector(&conditions.loads);
        let (rigid, mut u) = self.rigid_start(conditions, options)?;
        let bearings = self.at_nodes();
        let evaluate = |u: &DVector<f64>, warm: &[Option<Equilibrium>]| {
            let mut residual = &shaft * u - &external;
            let mut jacobian = shaft.clone();
            let mut states = Vec::with_capacity(bearings.len());
            let mut shares = Vec::with_capacity(bearings.len());
            for (index, (node, b)) in bearings.iter().enumerate() {
                let local: [f64; 5] = std::array::from_fn(|k| u[5 * node + k]);
                let near = warm.get(index).and_then(Option::as_ref);
                match b
                    .contribution(&local, conditions, options, near)
                    .map_err(|source| SystemError::Bearing { index, source })?
                {
                    Some((eq, share, k)) => {
                        for r in 0..5 {
                            residual[5 * node + r] += share[r];
                            for c in 0..5 {
                                jacobian[(5 * node + r, 5 * node + c)] += k[(r, c)];
                            }
                        }
                        states.push(Some(eq));
                        shares.push(share);
                    }
                    None => {
                        states.push(None);
                        shares.push([0.0; 5]);
                    }
                }
            }
            Ok::<_, SystemError>((residual, jacobian, states, shares))
        };
        let scale = external.amax().max(
            rigid
                .shaft_loads
                .iter()
                .flat_map(|s| s[..3].iter().map(|v| v.abs()))
                .fold(0.0, f64::max),
        );
        let scale = scale.max(1.0);
        // Moments against forces: over the shaft's length (or 10 mm).
        let lever = (self.nodes[nodes - 1] - self.nodes[0]).max(0.01);
        let relative = |r: &DVector<f64>| {
            r.iter()
                .enumerate()
                .map(|(i, v)| if i % 5 < 3 { v.abs() } else { v.abs() / lever })
                .fold(0.0, f64::max)
                / scale
        };
        let mut state = evaluate(&u, &rigid.bearings)?;
        let mut error = relative(&state.0);
        let mut iterations = 0;
        while error > TOLERANCE {
            if iterations == MAX_ITERATIONS {
                return Err(SystemError::NoConvergence {
                    iterations,
                    residual: error,
                });
            }
            iterations += 1;
            let Some(step) = state.1.clone().lu().solve(&state.0) else {
                return Err(SystemError::NoConvergence {
                    iterations,
                    residual: error,
                });
            };
            let mut factor = 1.0;
            loop {
                let trial = &u - factor * &step;
                match evaluate(&trial, &state.2) {
                    Ok(next) => {
                        let e = relative(&next.0);
                        if e < error || factor < 1e-3 {
                            (u, state, error) = (trial, next, e);
                            break;
                        }
                    }
                    Err(e) if factor < 1e-3 => return Err(e),
                    Err(_) => {}
                }
                factor *= 0.5;
            }
        }
        let reference = self.node_of(0.0);
        let compliance = state
            .1
            .clone()
            .try_inverse()
            .ok_or(SystemError::NoConvergence {
                iterations,
                residual: error,
            })?;
        let block = Matrix5::from_fn(|r, c| compliance[(5 * reference + r, 5 * reference + c)]);
        let stiffness = block.try_inverse().unwrap_or(Matrix5::zeros());
        let displacements: Vec<[f64; 5]> = (0..nodes)
            .map(|n| std::array::from_fn(|k| u[5 * n + k]))
            .collect();
        Ok(ElasticEquilibrium {
            nodes: self.nodes.clone(),
            system: SystemEquilibrium {
                displacement: displacements[reference],
                bearings: state.2,
                shaft_loads: state.3,
                stiffness: std::array::from_fn(|i| std::array::from_fn(|j| stiffness[(i, j)])),
                iterations,
            },
            displacements,
        })
    }
}
