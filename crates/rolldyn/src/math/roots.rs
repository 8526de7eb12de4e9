//! Brent's bracketed root finder (R. P. Brent, *Algorithms for Minimization
//! without Derivatives*, 1973, ch. 4): inverse quadratic interpolation with a
//! bisection safeguard. Guaranteed to converge on a sign-changing bracket.

/// Why a bracketed solve failed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum RootError {
    /// f(lo) and f(hi) have the same sign.
    #[error("no sign change on [{lo}, {hi}]: f = {f_lo}, {f_hi}")]
    NotBracketed {
        lo: f64,
        hi: f64,
        f_lo: f64,
        f_hi: f64,
    },
    /// f returned NaN.
    #[error("function returned NaN at {x}")]
    NotFinite { x: f64 },
}

/// Finds x in [lo, hi] with f(x) = 0 to an absolute tolerance `xtol` on x.
pub fn brent(mut f: impl FnMut(f64) -> f64, lo: f64, hi: f64, xtol: f64) -> Result<f64, RootError> {
    let (mut a, mut b) = (lo, hi);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa.is_nan() {
        return Err(RootError::NotFinite { x: a });
    }
    if fb.is_nan() {
        return Err(RootError::NotFinite { x: b });
    }
    if fa == 0.0 {
        return Ok(a);
    }
    if fb == 0.0 {
        return Ok(b);
    }
    if fa.signum() == fb.signum() {
        return Err(RootError::NotBracketed {
            lo,
            hi,
            f_lo: fa,
            f_hi: fb,
        });
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if fb.is_nan() {
            return Err(RootError::NotFinite { x: b });
        }
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_cube_root() {
        let x = brent(|x| x * x * x - 2.0, 0.0, 2.0, 1e-15).unwrap();
        assert!((x - 2f64.cbrt()).abs() < 1e-14);
    }

    #[test]
    fn rejects_unbracketed() {
        assert!(matches!(
            brent(|x| x * x + 1.0, -1.0, 1.0, 1e-12),
            Err(RootError::NotBracketed { .. })
        ));
    }
}
