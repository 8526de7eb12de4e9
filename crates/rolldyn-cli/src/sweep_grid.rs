//! The grid of a sweep (`quasistatic --sweep`, `run --sweep`): the swept
//! quantities, their values parsed with units, and the grid of points.

use rolldyn_case::units::{AngularSpeed, Force, Quantity};

/// The grid of `sweeps` around `base` (first sweep outermost): `set`
/// writes one swept value into a point.
pub fn grid<C: Copy>(
    base: C,
    sweeps: &[(Swept, Vec<f64>)],
    set: impl Fn(&mut C, Swept, f64),
) -> Vec<C> {
    let mut points = vec![base];
    for (swept, values) in sweeps {
        points = points
            .iter()
            .flat_map(|p| {
                values.iter().map(|&v| {
                    let mut c = *p;
                    set(&mut c, *swept, v);
                    c
                })
            })
            .collect();
    }
    points
}

/// Most points of a sweep grid without `--force`.
pub const MAX_SWEEP_POINTS: f64 = 1e6;

/// A swept quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Swept {
    Speed,
    Axial,
    Radial,
}

/// Parses `speed=0rpm..20000rpm/11` (linear, inclusive) or
/// `axial=10N,100N,1kN` (list). Values carry units as in case files.
pub fn parse_sweep(arg: &str) -> Result<(Swept, Vec<f64>), String> {
    let (name, spec) = arg
        .split_once('=')
        .ok_or("expected NAME=VALUES, e.g. speed=0rpm..20000rpm/11 or axial=10N,100N")?;
    let swept = match name.trim() {
        "speed" => Swept::Speed,
        "axial" => Swept::Axial,
        "radial" => Swept::Radial,
        other => {
            return Err(format!(
                "unknown sweep variable \"{other}\"; expected speed, axial or radial"
            ));
        }
    };
    let parse = |t: &str| -> Result<f64, String> {
        match swept {
            Swept::Speed => Quantity::<AngularSpeed>::parse(t).map(|q| q.si),
            _ => Quantity::<Force>::parse(t).map(|q| q.si),
        }
    };
    if spec.contains("..") && !spec.contains('/') {
        return Err("a range needs a point count: FROM..TO/COUNT, e.g. 0rpm..20000rpm/11".into());
    }
    let values = if let Some((range, count)) = spec.split_once('/') {
        let (from, to) = range.split_once("..").ok_or("a range is FROM..TO/COUNT")?;
        let n: usize = count
            .trim()
            .parse()
            .map_err(|_| format!("\"{count}\" is not a point count"))?;
        if !(2..=100_000).contains(&n) {
            return Err(format!("point count {n} must lie in [2, 100000]"));
        }
        let (a, b) = (parse(from)?, parse(to)?);
        (0..n)
            .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
            .collect()
    } else {
        spec.split(',').map(parse).collect::<Result<Vec<_>, _>>()?
    };
    if values.is_empty() {
        return Err("no values".into());
    }
    for &v in &values {
        let checked = match swept {
            Swept::Speed => rolldyn_case::case::check_speed("speed", v),
            _ => rolldyn_case::case::check_force(name.trim(), v),
        };
        checked.map_err(|e| format!("{}: {}", e.value.unwrap_or_default(), e.rule))?;
    }
    Ok((swept, values))
}
