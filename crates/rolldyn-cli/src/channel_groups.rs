//! Which group (`output.channels`) a time-series channel belongs to, and
//! which ball; `rolldyn run` records the channels of the groups and balls
//! the case selects (docs/cli.md, "Choose what to record").

use rolldyn_case::case::{ChannelGroup, OutputSelection};

/// Per-ball channel suffixes of the `balls` group (the rest are
/// `contacts`).
const BALL_KINEMATICS: [&str; 4] = [
    "azimuth_rad",
    "orbital_speed_rpm",
    "attitude_deg",
    "yaw_deg",
];

/// The group of channel `name` and its ball, or None for `time_s` (always
/// recorded).
pub fn group_of(name: &str) -> Option<(ChannelGroup, Option<usize>)> {
    if name == "time_s" {
        return None;
    }
    if let Some((j, suffix)) = name
        .strip_prefix("ball")
        .and_then(|rest| rest.split_once('_'))
        .and_then(|(j, suffix)| j.parse::<usize>().ok().map(|j| (j, suffix)))
    {
        let group = if BALL_KINEMATICS.contains(&suffix) {
            ChannelGroup::Balls
        } else {
            ChannelGroup::Contacts
        };
        return Some((group, Some(j)));
    }
    if name.starts_with("peak_load_") {
        return Some((ChannelGroup::Contacts, None));
    }
    let group = if name.starts_with("cage_")
        || name.starts_with("pocket_force_")
        || name == "pure_rolling_cage_speed_ratio"
    {
        ChannelGroup::Cage
    } else if name.starts_with("power_") || name == "friction_torque_n_m" {
        ChannelGroup::Power
    } else if name.starts_with("temperature_") || name == "oil_viscosity_pa_s" {
        ChannelGroup::Thermal
    } else if name.starts_with("sensor_") {
        ChannelGroup::Sensor
    } else if name.ends_with("_work_j") || name.ends_with("_energy_j") {
        ChannelGroup::Energy
    } else {
        ChannelGroup::Rings
    };
    Some((group, None))
}

/// Whether `selection` records channel `name` at the sample rate
/// (`slow`: false) or at the slow rate (`slow`: true); `time_s` is in both.
pub fn recorded(selection: &OutputSelection, name: &str, slow: bool) -> bool {
    match group_of(name) {
        None => true,
        Some((group, ball)) => {
            selection.records(group)
                && selection.is_slow(group) == slow
                && ball.is_none_or(|j| selection.records_ball(j))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channels_fall_into_their_groups() {
        for (name, group, ball) in [
            ("inner_ring_speed_rpm", ChannelGroup::Rings, None),
            ("housing_force_y_n", ChannelGroup::Rings, None),
            ("sensor_acceleration_m_s2", ChannelGroup::Sensor, None),
            ("outer_ring_acceleration_z_m_s2", ChannelGroup::Rings, None),
            ("cage_velocity_y_m_s", ChannelGroup::Cage, None),
            ("pocket_force_max_n", ChannelGroup::Cage, None),
            ("pure_rolling_cage_speed_ratio", ChannelGroup::Cage, None),
            ("drive_work_j", ChannelGroup::Energy, None),
            ("mechanical_energy_j", ChannelGroup::Energy, None),
            ("power_inner_spin_w", ChannelGroup::Power, None),
            ("friction_torque_n_m", ChannelGroup::Power, None),
            ("temperature_oil_c", ChannelGroup::Thermal, None),
            ("oil_viscosity_pa_s", ChannelGroup::Thermal, None),
            ("ball3_yaw_deg", ChannelGroup::Balls, Some(3)),
            ("ball12_load_inner_n", ChannelGroup::Contacts, Some(12)),
            ("peak_load_outer_n", ChannelGroup::Contacts, None),
            (
                "ball0_creepage_spin_outer_1_m",
                ChannelGroup::Contacts,
                Some(0),
            ),
        ] {
            assert_eq!(group_of(name), Some((group, ball)), "{name}");
        }
        assert_eq!(group_of("time_s"), None);
        let only = OutputSelection {
            groups: vec![ChannelGroup::Cage, ChannelGroup::Contacts],
            balls: Some(vec![2]),
            float32: false,
            slow: Some((vec![ChannelGroup::Cage], 100.0)),
        };
        assert!(recorded(&only, "time_s", false) && recorded(&only, "time_s", true));
        assert!(recorded(&only, "cage_speed_rpm", true));
        assert!(!recorded(&only, "cage_speed_rpm", false));
        assert!(recorded(&only, "ball2_load_outer_n", false));
        assert!(!recorded(&only, "ball2_load_outer_n", true));
        assert!(!recorded(&only, "ball1_load_outer_n", false));
        assert!(!recorded(&only, "ball2_yaw_deg", false));
        assert!(!recorded(&only, "drive_work_j", false));
    }
}
