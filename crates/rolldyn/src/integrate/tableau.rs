//! Butcher tableaus of explicit Runge–Kutta methods, as data.

/// An explicit Runge–Kutta tableau with an optional embedded error
/// estimate and optional dense-output polynomial.
#[derive(Debug, Clone, PartialEq)]
pub struct Tableau {
    /// Name for statistics.
    pub name: &'static str,
    /// Order of the solution.
    pub order: u32,
    /// Nodes c_i.
    pub c: &'static [f64],
    /// Lower-triangular coefficients a_ij, row by row (row i has i entries).
    pub a: &'static [&'static [f64]],
    /// Weights b_i of the solution.
    pub b: &'static [f64],
    /// Error weights e_i = b_i − b̂_i (empty: no error estimate).
    pub error: &'static [f64],
    /// First-same-as-last: the last stage is f(t + h, y_{n+1}).
    pub fsal: bool,
    /// Dense output of Hairer's DOPRI5 (`contd5`) weights d_i, if any.
    pub dense: &'static [f64],
}

/// The classical 4th-order Runge–Kutta method (fixed step; Deng et al. 2022, Zhang et al. 2025).
pub const RK4: Tableau = Tableau {
    name: "rk4",
    order: 4,
    c: &[0.0, 0.5, 0.5, 1.0],
    a: &[&[], &[0.5], &[0.0, 0.5], &[0.0, 0.0, 1.0]],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    error: &[],
    fsal: false,
    dense: &[],
};

/// Dormand–Prince 5(4) (J. R. Dormand & P. J. Prince, J. Comput. Appl.
/// Math. 6 (1980) 19–26), FSAL, with the 4th-order continuous extension of
/// Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.6 (code DOPRI5).
pub const DOPRI5: Tableau = Tableau {
    name: "dopri5",
    order: 5,
    c: &[0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    a: &[
        &[],
        &[1.0 / 5.0],
        &[3.0 / 40.0, 9.0 / 40.0],
        &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
        &[
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
        ],
        &[
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
        ],
        &[
            35.0 / 384.0,
            0.0,
            500.0 / 1113.0,
            125.0 / 192.0,
            -2187.0 / 6784.0,
            11.0 / 84.0,
        ],
    ],
    b: &[
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
        0.0,
    ],
    error: &[
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ],
    fsal: true,
    dense: &[
        -12715105075.0 / 11282082432.0,
        0.0,
        87487479700.0 / 32700410799.0,
        -10690763975.0 / 1880347072.0,
        701980252875.0 / 199316789632.0,
        -1453857185.0 / 822651844.0,
        69997945.0 / 29380423.0,
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    fn consistent(t: &Tableau) {
        // Row sums of a equal c; weights sum to 1; error weights sum to 0.
        for (i, row) in t.a.iter().enumerate() {
            let sum: f64 = row.iter().sum();
            assert!((sum - t.c[i]).abs() < 1e-14, "{} row {i}", t.name);
        }
        assert!((t.b.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        if !t.error.is_empty() {
            assert!(t.error.iter().sum::<f64>().abs() < 1e-14);
        }
    }

    #[test]
    fn tableaus_are_consistent() {
        consistent(&RK4);
        consistent(&DOPRI5);
        // DOPRI5 is FSAL: its last row equals b.
        assert_eq!(DOPRI5.a[6], &DOPRI5.b[..6]);
    }
}
