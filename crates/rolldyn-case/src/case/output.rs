//! What `rolldyn run` records (`[output]`): the channel groups, the balls
//! whose channels are kept, and the storage precision, checked with the
//! key of the offending entry.

use super::Invalid;
use crate::raw::{RawOutput, RawPrecision};

/// A group of time-series channels (`output.channels`). The summary's
/// statistics use every channel whatever is recorded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum ChannelGroup {
    /// Ring speeds, displacements, velocities, accelerations, housing force.
    Rings,
    /// Cage angle, speed, orbit, pocket forces, pure-rolling cage ratio.
    Cage,
    /// Per ball: azimuth, orbital speed, attitude and yaw.
    Balls,
    /// Per ball and contact: loads, angles, slip, films, creepages, power.
    Contacts,
    /// Drive work, dissipated energy, mechanical energy, film work.
    Energy,
    /// Dissipated power by component and friction torque.
    Power,
    /// Temperatures and oil viscosity of a thermally coupled run.
    Thermal,
    /// The housing accelerometer's channels (a case with `[sensor]`).
    Sensor,
}

impl ChannelGroup {
    /// Every group, in the order of their names.
    pub const ALL: [ChannelGroup; 8] = [
        Self::Rings,
        Self::Cage,
        Self::Balls,
        Self::Contacts,
        Self::Energy,
        Self::Power,
        Self::Thermal,
        Self::Sensor,
    ];

    /// Name in case files.
    pub fn name(self) -> &'static str {
        match self {
            Self::Rings => "rings",
            Self::Cage => "cage",
            Self::Balls => "balls",
            Self::Contacts => "contacts",
            Self::Energy => "energy",
            Self::Power => "power",
            Self::Thermal => "thermal",
            Self::Sensor => "sensor",
        }
    }
}

/// What a run records.
#[derive(Debug, Clone, PartialEq)]
pub struct OutputSelection {
    /// Recorded groups (all by default); `time_s` always is.
    pub groups: Vec<ChannelGroup>,
    /// Balls whose per-ball channels are recorded (None: all).
    pub balls: Option<Vec<usize>>,
    /// Samples stored as 32-bit floats (7 significant digits).
    pub float32: bool,
    /// Groups recorded at a lower rate into a second dataset, and that
    /// rate \[Hz\] (`output.slow_channels`, `output.slow_rate`).
    pub slow: Option<(Vec<ChannelGroup>, f64)>,
}

impl Default for OutputSelection {
    fn default() -> Self {
        Self {
            groups: ChannelGroup::ALL.to_vec(),
            balls: None,
            float32: false,
            slow: None,
        }
    }
}

impl OutputSelection {
    /// Whether `group` is recorded (at the sample rate or the slow one).
    pub fn records(&self, group: ChannelGroup) -> bool {
        self.groups.contains(&group)
    }

    /// Whether `group` is recorded at the slow rate.
    pub fn is_slow(&self, group: ChannelGroup) -> bool {
        self.slow.as_ref().is_some_and(|(g, _)| g.contains(&group))
    }

    /// Whether ball `j`'s channels are recorded.
    pub fn records_ball(&self, j: usize) -> bool {
        self.balls.as_ref().is_none_or(|b| b.contains(&j))
    }
}

/// A list of group names under `key`, sorted, without repeats.
fn groups(key: &str, names: &[String]) -> Result<Vec<ChannelGroup>, Invalid> {
    if names.is_empty() {
        return Err(Invalid::new(
            key,
            Some("[]".into()),
            "give at least one group (time_s is always recorded)",
        ));
    }
    let mut groups = Vec::with_capacity(names.len());
    for (i, name) in names.iter().enumerate() {
        let group = ChannelGroup::ALL
            .into_iter()
            .find(|g| g.name() == name)
            .ok_or_else(|| {
                Invalid::new(
                    format!("{key}[{i}]"),
                    Some(format!("\"{name}\"")),
                    format!(
                        "unknown group; expected {}",
                        ChannelGroup::ALL.map(ChannelGroup::name).join(", ")
                    ),
                )
            })?;
        groups.push(group);
    }
    groups.sort();
    groups.dedup();
    Ok(groups)
}

/// Rate of the slow channels when `output.slow_rate` is not given \[Hz\].
pub const DEFAULT_SLOW_RATE: f64 = 100.0;

pub(super) fn selection(raw: &RawOutput, ball_count: usize) -> Result<OutputSelection, Invalid> {
    let mut out = OutputSelection::default();
    if let Some(names) = &raw.channels {
        out.groups = groups("output.channels", names)?;
    }
    match (&raw.slow_channels, &raw.slow_rate) {
        (None, None) => {}
        (Some(names), rate) => {
            let slow = groups("output.slow_channels", names)?;
            if let Some(g) = slow.iter().find(|g| !out.groups.contains(g)) {
                return Err(Invalid::new(
                    "output.slow_channels",
                    Some(format!("\"{}\"", g.name())),
                    "names a group output.channels does not record",
                ));
            }
            let hz = rate.as_ref().map_or(DEFAULT_SLOW_RATE, |q| q.si);
            if !(hz.is_finite() && hz > 0.0) {
                return Err(Invalid::new(
                    "output.slow_rate",
                    rate.as_ref().map(|q| q.to_string()),
                    "must be a positive frequency",
                ));
            }
            out.slow = Some((slow, hz));
        }
        (None, Some(rate)) => {
            return Err(Invalid::new(
                "output.slow_rate",
                Some(rate.to_string()),
                "is used only with output.slow_channels",
            ));
        }
    }
    if let Some(balls) = &raw.balls {
        let mut indices = Vec::with_capacity(balls.len());
        for (k, &b) in balls.iter().enumerate() {
            let j = usize::try_from(b)
                .ok()
                .filter(|&j| j < ball_count)
                .ok_or_else(|| {
                    Invalid::new(
                        format!("output.balls[{k}]"),
                        Some(b.to_string()),
                        format!(
                            "ball indices run from 0 to {} (Z = {ball_count})",
                            ball_count - 1
                        ),
                    )
                })?;
            indices.push(j);
        }
        indices.sort_unstable();
        indices.dedup();
        out.balls = Some(indices);
    }
    out.float32 = matches!(raw.precision, Some(RawPrecision::Float32));
    Ok(out)
}
