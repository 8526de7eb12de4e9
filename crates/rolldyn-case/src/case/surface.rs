//! The case's surfaces (`[surface]`, docs/model.md §6): waviness terms and random
//! laws, spalls on either raceway or on a ball, checked with the key of
//! the offending entry.

use super::Invalid;
use crate::raw::{
    RawBallSurfaces, RawEdge, RawRaceSurface, RawRandomWaviness, RawSpall, RawSurface,
    RawWavinessTerm,
};
use rolldyn::InvalidParameter;
use rolldyn::surface::{
    BallSurface, Edge, RaceSurface, RandomWaviness, Spall, SpallSize, SurfaceModel, Waviness,
    WavinessTerm,
};

/// Converts a rule broken inside an entry into the entry's dotted key.
fn located(key: &str) -> impl Fn(InvalidParameter) -> Invalid + '_ {
    move |e| Invalid::new(format!("{key}.{}", e.field), Some(e.value), e.rule)
}

pub(super) fn surface(
    raw: &RawSurface,
    ball_count: usize,
    ball_diameter: f64,
) -> Result<SurfaceModel, Invalid> {
    let mut model = SurfaceModel::default();
    if let Some(inner) = &raw.inner {
        model.inner = race("surface.inner", inner)?;
        small(
            "surface.inner.radial_waviness",
            &model.inner.radial,
            ball_diameter,
        )?;
        small(
            "surface.inner.axial_waviness",
            &model.inner.axial,
            ball_diameter,
        )?;
    }
    if let Some(outer) = &raw.outer {
        model.outer = race("surface.outer", outer)?;
        small(
            "surface.outer.radial_waviness",
            &model.outer.radial,
            ball_diameter,
        )?;
        small(
            "surface.outer.axial_waviness",
            &model.outer.axial,
            ball_diameter,
        )?;
    }
    if let Some(balls) = &raw.balls {
        model.balls = ball_surfaces(balls, ball_count)?;
        model.ball_roughness = roughness("surface.balls.roughness", &balls.roughness)?;
        for ball in &model.balls {
            small("surface.balls.waviness", &ball.waviness, ball_diameter)?;
        }
    }
    Ok(model)
}

/// Largest sum of waviness amplitudes on one surface, as a fraction of the
/// ball diameter. Waviness is a small deviation from the geometry (0.01–1
/// µm on bearing raceways and balls, tens of µm for a ring's ovality in its
/// housing); beyond 1 % of the ball diameter the contacts would be crushed
/// by geometry, not loaded, and the run would never advance.
const MAX_WAVINESS_SHARE: f64 = 0.01;

/// Checks that a surface's waviness (its terms and random terms together)
/// is small against the ball.
fn small(key: &str, waviness: &Waviness, ball_diameter: f64) -> Result<(), Invalid> {
    let sum: f64 = waviness.terms.iter().map(|t| t.amplitude.abs()).sum();
    let limit = MAX_WAVINESS_SHARE * ball_diameter;
    if sum > limit {
        return Err(Invalid::new(
            key,
            Some(format!("{:.4} mm summed over its terms", sum * 1e3)),
            format!(
                "the amplitudes of a surface's waviness must sum to at most 1 % of the ball diameter ({:.4} mm here); waviness is a deviation of 0.01-1 um, not a change of the geometry",
                limit * 1e3
            ),
        ));
    }
    Ok(())
}

fn roughness(
    key: &str,
    value: &Option<crate::units::Quantity<crate::units::Length>>,
) -> Result<f64, Invalid> {
    match value {
        None => Ok(0.0),
        Some(q) if q.si.is_finite() && q.si >= 0.0 => Ok(q.si),
        Some(q) => Err(Invalid::new(
            key,
            Some(q.to_string()),
            "must not be negative",
        )),
    }
}

fn race(key: &str, raw: &RawRaceSurface) -> Result<RaceSurface, Invalid> {
    Ok(RaceSurface {
        roughness: roughness(&format!("{key}.roughness"), &raw.roughness)?,
        radial: waviness(
            &format!("{key}.radial_waviness"),
            &raw.radial_waviness,
            raw.random_radial_waviness.as_ref(),
            &format!("{key}.random_radial_waviness"),
            0,
        )?,
        axial: waviness(
            &format!("{key}.axial_waviness"),
            &raw.axial_waviness,
            raw.random_axial_waviness.as_ref(),
            &format!("{key}.random_axial_waviness"),
            0,
        )?,
        spalls: raw
            .spall
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let key = format!("{key}.spall[{i}]");
                if s.ball.is_some() {
                    return Err(Invalid::new(
                        format!("{key}.ball"),
                        None,
                        "only ball spalls ([[surface.balls.spall]]) name a ball",
                    ));
                }
                spall(&key, s)
            })
            .collect::<Result<_, _>>()?,
    })
}

fn ball_surfaces(raw: &RawBallSurfaces, ball_count: usize) -> Result<Vec<BallSurface>, Invalid> {
    let index = |key: String, i: i64| -> Result<usize, Invalid> {
        usize::try_from(i)
            .ok()
            .filter(|&i| i < ball_count)
            .ok_or_else(|| {
                Invalid::new(
                    key,
                    Some(i.to_string()),
                    format!(
                        "ball indices run from 0 to {} (Z = {ball_count})",
                        ball_count - 1
                    ),
                )
            })
    };
    let carriers: Vec<usize> = match &raw.balls {
        None => (0..ball_count).collect(),
        Some(list) => list
            .iter()
            .enumerate()
            .map(|(k, &i)| index(format!("surface.balls.balls[{k}]"), i))
            .collect::<Result<_, _>>()?,
    };
    let mut balls = vec![BallSurface::default(); ball_count];
    for &j in &carriers {
        // Each ball draws its own random phases (stream j).
        balls[j].waviness = waviness(
            "surface.balls.waviness",
            &raw.waviness,
            raw.random_waviness.as_ref(),
            "surface.balls.random_waviness",
            j as u64,
        )?;
    }
    for (i, s) in raw.spall.iter().enumerate() {
        let key = format!("surface.balls.spall[{i}]");
        let j = match s.ball {
            Some(b) => index(format!("{key}.ball"), b)?,
            None => {
                return Err(Invalid::missing(
                    &format!("{key}.ball"),
                    "the index of the ball that carries the spall",
                ));
            }
        };
        if s.axial_position.is_some() || s.axial_width.is_some() {
            return Err(Invalid::new(
                format!("{key}.axial_width"),
                None,
                "ball spalls lie on the ball's rolling track: no axial band",
            ));
        }
        balls[j].spalls.push(spall(&key, s)?);
    }
    Ok(balls)
}

fn waviness(
    key: &str,
    terms: &[RawWavinessTerm],
    random: Option<&RawRandomWaviness>,
    random_key: &str,
    stream: u64,
) -> Result<Waviness, Invalid> {
    let mut out = Vec::with_capacity(terms.len());
    for (i, t) in terms.iter().enumerate() {
        let key = format!("{key}[{i}]");
        let order = u32::try_from(t.order).map_err(|_| {
            Invalid::new(
                format!("{key}.order"),
                Some(t.order.to_string()),
                "must lie in [1, 10000]",
            )
        })?;
        out.push(WavinessTerm {
            order,
            amplitude: t.amplitude.si,
            phase: t.phase.as_ref().map_or(0.0, |p| p.si),
        });
    }
    let mut waviness = Waviness { terms: out };
    waviness.validate().map_err(|e| {
        // Name the entry that broke the rule.
        let i = waviness
            .terms
            .iter()
            .position(|t| Waviness { terms: vec![*t] }.validate().is_err())
            .unwrap_or(0);
        located(&format!("{key}[{i}]"))(e)
    })?;
    if let Some(r) = random {
        let order = |name: &str, v: i64| {
            u32::try_from(v).map_err(|_| {
                Invalid::new(
                    format!("{random_key}.{name}"),
                    Some(v.to_string()),
                    "must lie in [1, 10000]",
                )
            })
        };
        let law = RandomWaviness {
            min_order: order("min_order", r.min_order)?,
            max_order: order("max_order", r.max_order)?,
            amplitude: r.amplitude.si,
            exponent: r.exponent.unwrap_or(1.0),
            seed: r.seed.unwrap_or(0),
        };
        law.validate().map_err(located(random_key))?;
        waviness.terms.extend(law.terms(stream));
    }
    Ok(waviness)
}

fn spall(key: &str, s: &RawSpall) -> Result<Spall, Invalid> {
    let size = match (&s.width, &s.length) {
        (Some(w), None) => SpallSize::Angle(w.si),
        (None, Some(l)) => SpallSize::Length(l.si),
        _ => {
            return Err(Invalid::new(
                format!("{key}.width"),
                None,
                "give the spall's extent along the track as either width (angle) or length",
            ));
        }
    };
    let edge = match (s.edge.unwrap_or(RawEdge::Sharp), &s.ramp) {
        (RawEdge::Sharp, None) => Edge::Sharp,
        (RawEdge::Ramped, Some(r)) => Edge::Ramped { length: r.si },
        (RawEdge::Sharp, Some(_)) => {
            return Err(Invalid::new(
                format!("{key}.ramp"),
                None,
                "a ramp length needs edge = \"ramped\"",
            ));
        }
        (RawEdge::Ramped, None) => {
            return Err(Invalid::missing(
                &format!("{key}.ramp"),
                "the ramp length of a ramped edge, e.g. \"0.2 mm\"",
            ));
        }
    };
    let spall = Spall {
        position: s.position.si,
        size,
        depth: s.depth.si,
        axial_position: s.axial_position.as_ref().map_or(0.0, |a| a.si),
        axial_width: s.axial_width.as_ref().map(|a| a.si),
        edge,
        growth_rate: s.growth_rate.as_ref().map_or(0.0, |g| g.si),
    };
    spall.validate().map_err(located(key))?;
    Ok(spall)
}
