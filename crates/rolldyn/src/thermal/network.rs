//! A lumped thermal network (Lei et al. 2023 §4; docs/model.md §10): nodes with heat
//! capacities and heat sources, joined by thermal conductances G = 1/R;
//! some nodes held at a given temperature (ambient, oil inlet).
//!
//! Steady state: the heat balance of every free node (Lei et al. 2023 eqs 44–45),
//! ```text
//! Σ_j G_ij (T_j − T_i) + H_i = 0,
//! ```
//! solved directly (LU of the free nodes' conductance matrix; Lei et al. 2023's
//! Gauss–Seidel iteration is not needed). Transient:
//! C_i dT_i/dt = Σ_j G_ij (T_j − T_i) + H_i by the trapezoidal rule
//! (Crank–Nicolson: second order, A-stable), a fixed step; nodes without
//! heat capacity (contact nodes, the oil) follow quasi-statically (their
//! balance holds at every step).

use crate::error::InvalidParameter;
use nalgebra::{DMatrix, DVector};

/// Index of a node.
pub type NodeId = usize;

/// One node.
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    /// Name for reports.
    pub name: String,
    /// Heat capacity C \[J/K\] (transient only).
    pub capacity: f64,
    /// Heat generated in the node H \[W\].
    pub heat: f64,
    /// Temperature held fixed \[K\], if any (a boundary).
    pub fixed: Option<f64>,
}

/// A thermal network.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThermalNetwork {
    nodes: Vec<Node>,
    /// Links (i, j, G \[W/K\]).
    links: Vec<(NodeId, NodeId, f64)>,
}

/// Heat flows of a solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Node temperatures \[K\].
    pub temperatures: Vec<f64>,
    /// Heat flowing into the network at each fixed node (negative: the
    /// boundary absorbs it) \[W\]; zero for free nodes.
    pub boundary_heat: Vec<f64>,
}

impl ThermalNetwork {
    /// Adds a free node with heat capacity `capacity` \[J/K\].
    pub fn node(&mut self, name: &str, capacity: f64) -> NodeId {
        self.nodes.push(Node {
            name: name.to_string(),
            capacity,
            heat: 0.0,
            fixed: None,
        });
        self.nodes.len() - 1
    }

    /// Adds a node held at `temperature` \[K\].
    pub fn boundary(&mut self, name: &str, temperature: f64) -> NodeId {
        self.nodes.push(Node {
            name: name.to_string(),
            capacity: 0.0,
            heat: 0.0,
            fixed: Some(temperature),
        });
        self.nodes.len() - 1
    }

    /// Joins `a` and `b` by a thermal resistance `resistance` \[K/W\]
    /// (infinite: no link).
    pub fn resistance(&mut self, a: NodeId, b: NodeId, resistance: f64) {
        if resistance.is_finite() && resistance > 0.0 {
            self.links.push((a, b, 1.0 / resistance));
        }
    }

    /// Joins `a` and `b` by a conductance \[W/K\].
    pub fn conductance(&mut self, a: NodeId, b: NodeId, conductance: f64) {
        if conductance > 0.0 {
            self.links.push((a, b, conductance));
        }
    }

    /// Sets the heat generated in node `id` \[W\].
    pub fn set_heat(&mut self, id: NodeId, heat: f64) {
        self.nodes[id].heat = heat;
    }

    /// The nodes.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// Conductance between `a` and `b` (sum over their links) \[W/K\].
    pub fn conductance_between(&self, a: NodeId, b: NodeId) -> f64 {
        self.links
            .iter()
            .filter(|&&(i, j, _)| (i, j) == (a, b) || (i, j) == (b, a))
            .map(|l| l.2)
            .sum()
    }

    /// The free nodes' conductance matrix A (A T = rhs at steady state)
    /// and the constant part of the right-hand side.
    fn assemble(&self) -> (Vec<usize>, DMatrix<f64>, DVector<f64>) {
        let free: Vec<usize> = (0..self.nodes.len())
            .filter(|&i| self.nodes[i].fixed.is_none())
            .collect();
        let mut index = vec![usize::MAX; self.nodes.len()];
        for (k, &i) in free.iter().enumerate() {
            index[i] = k;
        }
        let n = free.len();
        let mut a = DMatrix::zeros(n, n);
        let mut rhs = DVector::from_iterator(n, free.iter().map(|&i| self.nodes[i].heat));
        for &(i, j, g) in &self.links {
            for (p, q) in [(i, j), (j, i)] {
                if index[p] == usize::MAX {
                    continue;
                }
                a[(index[p], index[p])] += g;
                match self.nodes[q].fixed {
                    Some(t) => rhs[index[p]] += g * t,
                    None => a[(index[p], index[q])] -= g,
                }
            }
        }
        (free, a, rhs)
    }

    fn solution(&self, free: &[usize], t_free: &DVector<f64>) -> Solution {
        let mut temperatures: Vec<f64> =
            self.nodes.iter().map(|n| n.fixed.unwrap_or(0.0)).collect();
        for (k, &i) in free.iter().enumerate() {
            temperatures[i] = t_free[k];
        }
        let mut boundary_heat = vec![0.0; self.nodes.len()];
        for &(i, j, g) in &self.links {
            for (p, q) in [(i, j), (j, i)] {
                if self.nodes[p].fixed.is_some() {
                    boundary_heat[p] += g * (temperatures[p] - temperatures[q]);
                }
            }
        }
        Solution {
            temperatures,
            boundary_heat,
        }
    }

    /// Steady-state temperatures. Fails when a group of free nodes has no
    /// path to a fixed node (its temperature is undefined).
    pub fn steady(&self) -> Result<Solution, InvalidParameter> {
        let (free, a, rhs) = self.assemble();
        let t = a
            .lu()
            .solve(&rhs)
            .filter(|t| t.iter().all(|v| v.is_finite()));
        match t {
            Some(t) => Ok(self.solution(&free, &t)),
            None => Err(InvalidParameter::new(
                "thermal network",
                free.len() as f64,
                "every node must connect to a boundary (ambient or oil inlet)",
            )),
        }
    }

    /// Temperatures after `duration` \[s\] from `initial` (all nodes; the
    /// fixed ones are ignored) in `steps` trapezoidal steps. Nodes of zero
    /// heat capacity are in balance at every step.
    pub fn transient(
        &self,
        initial: &[f64],
        duration: f64,
        steps: usize,
    ) -> Result<Solution, InvalidParameter> {
        let (free, a, rhs) = self.assemble();
        if let Some(&i) = free.iter().find(|&&i| self.nodes[i].capacity < 0.0) {
            return Err(InvalidParameter::new(
                "heat capacity",
                self.nodes[i].capacity,
                "must not be negative",
            ));
        }
        let c = DVector::from_iterator(free.len(), free.iter().map(|&i| self.nodes[i].capacity));
        let h = duration / steps.max(1) as f64;
        // (C/h + A/2) T⁺ = (C/h − A/2) T + rhs; rows without capacity:
        // A T⁺ = rhs.
        let mut left = a.clone() * 0.5;
        let mut right = -a * 0.5;
        for k in 0..free.len() {
            if c[k] > 0.0 {
                left[(k, k)] += c[k] / h;
                right[(k, k)] += c[k] / h;
            } else {
                left.row_mut(k).scale_mut(2.0);
                right.row_mut(k).fill(0.0);
            }
        }
        let lu = left.lu();
        let mut t = DVector::from_iterator(free.len(), free.iter().map(|&i| initial[i]));
        for _ in 0..steps.max(1) {
            let b = &right * &t + &rhs;
            t = lu.solve(&b).ok_or_else(|| {
                InvalidParameter::new("thermal network", h, "transient step matrix is singular")
            })?;
        }
        Ok(self.solution(&free, &t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two resistances in series from a heated node to ambient through a
    /// middle node: T₁ = T_a + H (R₁ + R₂), T₂ = T_a + H R₂; all the heat
    /// leaves through the boundary.
    #[test]
    fn series_chain_matches_the_analytic_solution() {
        let mut net = ThermalNetwork::default();
        let hot = net.node("hot", 1.0);
        let mid = net.node("mid", 1.0);
        let amb = net.boundary("ambient", 293.15);
        net.resistance(hot, mid, 0.7);
        net.resistance(mid, amb, 1.9);
        net.set_heat(hot, 25.0);
        let s = net.steady().unwrap();
        assert!((s.temperatures[hot] - (293.15 + 25.0 * 2.6)).abs() < 1e-10);
        assert!((s.temperatures[mid] - (293.15 + 25.0 * 1.9)).abs() < 1e-10);
        assert!((s.boundary_heat[amb] + 25.0).abs() < 1e-10);
    }

    /// Heat in = heat out with two boundaries and a loop.
    #[test]
    fn steady_state_balances_heat() {
        let mut net = ThermalNetwork::default();
        let n: Vec<_> = (0..4).map(|i| net.node(&format!("n{i}"), 1.0)).collect();
        let a = net.boundary("a", 300.0);
        let b = net.boundary("b", 320.0);
        net.resistance(n[0], n[1], 1.0);
        net.resistance(n[1], n[2], 2.0);
        net.resistance(n[2], n[3], 0.5);
        net.resistance(n[3], n[0], 3.0);
        net.resistance(n[1], a, 4.0);
        net.resistance(n[3], b, 1.5);
        for (i, h) in [10.0, 0.0, 5.0, 2.0].into_iter().enumerate() {
            net.set_heat(n[i], h);
        }
        let s = net.steady().unwrap();
        assert!((s.boundary_heat[a] + s.boundary_heat[b] + 17.0).abs() < 1e-10);
    }

    /// One node of capacity C on R to ambient, heated by H from T_a:
    /// T = T_a + H R (1 − e^{−t/RC}); 1e-4 K of a 20 K rise at 200 steps
    /// per time constant, and the error falls 4× when the step halves
    /// (second order).
    #[test]
    fn single_node_transient_is_the_rc_exponential() {
        let mut net = ThermalNetwork::default();
        let node = net.node("ring", 50.0);
        let amb = net.boundary("ambient", 293.15);
        net.resistance(node, amb, 2.0);
        net.set_heat(node, 10.0);
        let tau = 100.0;
        for t in [30.0, 100.0, 400.0] {
            let s = net
                .transient(&[293.15, 293.15], t, (200.0 * t / tau) as usize)
                .unwrap();
            let exact = 293.15 + 20.0 * (1.0 - (-t / tau).exp());
            assert!(
                (s.temperatures[node] - exact).abs() < 1e-4,
                "{t}: {}",
                s.temperatures[node]
            );
        }
        let error = |steps| {
            let s = net.transient(&[293.15, 293.15], 100.0, steps).unwrap();
            (s.temperatures[node] - 293.15 - 20.0 * (1.0 - (-1.0f64).exp())).abs()
        };
        let ratio = error(50) / error(100);
        assert!((ratio - 4.0).abs() < 0.1, "order ratio {ratio}");
    }

    #[test]
    fn floating_nodes_are_refused() {
        let mut net = ThermalNetwork::default();
        let a = net.node("a", 1.0);
        let b = net.node("b", 1.0);
        net.resistance(a, b, 1.0);
        net.set_heat(a, 1.0);
        assert!(net.steady().is_err());
    }
}
