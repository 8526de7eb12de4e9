//! Layout of the dynamic state vector (docs/model.md §1).

/// Offsets of the parts of the state vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateLayout {
    /// Number of balls.
    pub balls: usize,
    /// Whether each ball carries its spin angle ψ (10th ball state, docs/model.md
    /// §1): only when the balls have surfaces (waviness, spalls).
    pub ball_spin_angle: bool,
    /// Whether a third accumulator holds the work of the films: only with
    /// the film in the normal approach (docs/model.md §4, `dynamics::film`).
    pub film_work: bool,
    /// Whether the inner ring's rotation (angle, speed) is a state: a
    /// torque drive (`operating::TorqueDrive`) instead of a prescribed speed.
    pub driven: bool,
    /// Whether the outer ring's axial position and velocity are states: it
    /// slides in its bore (`dynamics::SlidingRing`).
    pub sliding: bool,
}

impl StateLayout {
    /// Mechanical states per ball (x, r, φ, their rates, ω_x, ω_r, ω_t).
    pub const BALL: usize = 9;
    /// Offset of the spin angle ψ in a ball's block, when present.
    pub const SPIN_ANGLE: usize = 9;
    /// Inner-ring states.
    pub const RING: usize = 10;
    /// Outer-ring states (y_o, z_o and rates).
    pub const OUTER: usize = 4;
    /// Cage states.
    pub const CAGE: usize = 6;
    /// States per ball: 9, or 10 with the spin angle.
    pub fn ball_len(&self) -> usize {
        Self::BALL + usize::from(self.ball_spin_angle)
    }
    /// First state of ball j.
    pub fn ball(&self, j: usize) -> usize {
        self.ball_len() * j
    }
    /// First inner-ring state.
    pub fn ring(&self) -> usize {
        self.ball_len() * self.balls
    }
    /// First of the inner ring's rotation states (angle, speed), present
    /// when [`Self::driven`]: right after its other states, so that a
    /// shaft's bearing has its inner ring's states in one run.
    pub fn spin(&self) -> usize {
        self.ring() + Self::RING
    }
    /// First outer-ring state.
    pub fn outer(&self) -> usize {
        self.spin() + 2 * usize::from(self.driven)
    }
    /// First of a sliding outer ring's axial states (x_o, ẋ_o), present
    /// when [`Self::sliding`].
    pub fn slide(&self) -> usize {
        self.outer() + Self::OUTER
    }
    /// First cage state.
    pub fn cage(&self) -> usize {
        self.slide() + 2 * usize::from(self.sliding)
    }
    /// The states that the contacts of ball j touch (read or write): its
    /// own block, both rings (a driven inner ring's rotation too) and the
    /// cage. Nothing else couples the balls, so the Jacobian is bordered
    /// block-diagonal (docs/model.md §8).
    pub fn ball_coupling(&self, j: usize) -> [std::ops::Range<usize>; 2] {
        [
            self.ball(j)..self.ball(j) + self.ball_len(),
            self.ring()..self.cage() + Self::CAGE,
        ]
    }
    /// The energy accumulators: drive work and dissipated energy \[J\],
    /// then, with the film in the approach, the films' work.
    pub fn work(&self) -> usize {
        self.cage() + Self::CAGE
    }
    /// Total number of states.
    pub fn len(&self) -> usize {
        self.work() + 2 + usize::from(self.film_work)
    }
    /// What state `index` is, in words (integration failures name it).
    pub fn state_name(&self, index: usize) -> String {
        const BALL: [&str; 10] = [
            "axial position x",
            "radial position r",
            "orbital angle φ",
            "axial velocity ẋ",
            "radial velocity ṙ",
            "orbital speed φ̇",
            "angular velocity ω_x",
            "angular velocity ω_r",
            "angular velocity ω_t",
            "spin angle ψ",
        ];
        const RING: [&str; 10] = [
            "axial position x",
            "position y",
            "position z",
            "tilt θ_y",
            "tilt θ_z",
            "axial velocity",
            "velocity y",
            "velocity z",
            "tilt rate θ̇_y",
            "tilt rate θ̇_z",
        ];
        const OUTER: [&str; 4] = ["position y", "position z", "velocity y", "velocity z"];
        const CAGE: [&str; 6] = [
            "centre y",
            "centre z",
            "angle",
            "centre velocity y",
            "centre velocity z",
            "speed",
        ];
        let n = self.ball_len() * self.balls;
        if index < n {
            let (j, k) = (index / self.ball_len(), index % self.ball_len());
            format!("ball {j} {}", BALL[k])
        } else if index < self.spin() {
            format!("inner ring {}", RING[index - self.ring()])
        } else if index < self.outer() {
            ["inner ring rotation angle", "inner ring speed"][index - self.spin()].into()
        } else if index < self.slide() {
            format!("outer ring {}", OUTER[index - self.outer()])
        } else if index < self.cage() {
            ["outer ring axial position x", "outer ring axial velocity"][index - self.slide()]
                .into()
        } else if index < self.work() {
            format!("cage {}", CAGE[index - self.cage()])
        } else if index == self.work() {
            "drive work accumulator".into()
        } else if index == self.work() + 1 {
            "dissipated energy accumulator".into()
        } else if index == self.work() + 2 && self.film_work {
            "film work accumulator".into()
        } else {
            format!("state {index}")
        }
    }

    /// Whether there are no states (never, for a valid bearing).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names_of(l: &StateLayout) -> Vec<String> {
        (0..l.len()).map(|i| l.state_name(i)).collect()
    }

    #[test]
    fn every_state_has_a_name() {
        for (spin, films, driven) in [
            (false, false, false),
            (true, false, true),
            (false, true, false),
            (true, true, true),
        ] {
            let l = StateLayout {
                balls: 2,
                ball_spin_angle: spin,
                film_work: films,
                driven,
                sliding: driven,
            };
            if driven {
                assert_eq!(names_of(&l)[l.spin() + 1], "inner ring speed");
                assert_eq!(names_of(&l)[l.slide()], "outer ring axial position x");
            }
            let names = names_of(&l);
            assert_eq!(names[0], "ball 0 axial position x");
            if spin {
                assert_eq!(names[l.ball(1) + 9], "ball 1 spin angle ψ");
            }
            if films {
                assert_eq!(names[l.work() + 2], "film work accumulator");
            }
            assert_eq!(names[l.ring() + 2], "inner ring position z");
            assert_eq!(names[l.outer() + 3], "outer ring velocity z");
            assert_eq!(names[l.cage() + 5], "cage speed");
            assert_eq!(names[l.work() + 1], "dissipated energy accumulator");
            assert!(names.iter().all(|n| !n.starts_with("state")));
        }
    }
}
