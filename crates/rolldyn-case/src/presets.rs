//! Built-in bearings: each is a complete, commented case file (in
//! `presets/`), with the source of every dimension and every assumed value
//! listed under `[assumptions]`.
//!
//! Each bearing is mounted as on a machine (docs/dynamics.md, "Mounting"):
//! its inner ring carries a shaft share, the shaft's other bearing holds
//! the ring's tilt, gravity acts, and an accelerometer on the housing
//! records what a test rig's would (`[sensor]`). Those lines end in [`MOUNTING_TAG`];
//! [`Preset::without_mounting`] gives the bearing as its source paper
//! models it, free ring and all (the examples reproduce the papers so).

/// A built-in bearing case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Preset {
    /// Name used in `bearing.preset` and `rolldyn new --preset`.
    pub name: &'static str,
    /// One-line description with the source.
    pub summary: &'static str,
    /// The case file text.
    pub text: &'static str,
}

/// The comment that ends each mounting line of a case file (presets,
/// `rolldyn new --bearing`): [`Preset::without_mounting`]
/// removes those lines.
pub const MOUNTING_TAG: &str = "# mounting";

/// `text` without its mounting (the lines carrying [`MOUNTING_TAG`] left
/// empty, so that the others keep their numbers): the bearing alone, as
/// its source paper models it, or as a set or a shaft mounts it (they are
/// their own mounting).
pub fn without_mounting(text: &str) -> String {
    text.lines()
        .map(|line| {
            if line.contains(MOUNTING_TAG) {
                "\n".to_string()
            } else {
                format!("{line}\n")
            }
        })
        .collect()
}

/// The `[assumptions]` entries of a case file's mounting, key and text.
pub const MOUNTING_ASSUMPTIONS: [(&str, &str); 5] = [
    (
        "inner_ring.mass",
        "mounting: the ring with half a solid steel shaft of the bore diameter, 10 bores long, that turns with it (docs/dynamics.md, \\\"Mounting\\\"); write your shaft's share when you know it",
    ),
    (
        "operating.fixed_tilt",
        "mounting: the shaft's other bearing holds the ring's tilt (its radial stiffness times the span squared is hundreds of times the bearing's own moment stiffness); false for a free ring, as in the source papers",
    ),
    (
        "model.gravity",
        "mounting: a horizontal shaft; the weights of the shaft share, the balls and the cage load the bearing",
    ),
    (
        "model.bearing_damping",
        "mounting: the bearing's damping between its rings, c = tau k_r with tau = 1.25e-5 s on its quasi-static radial stiffness, the ROSS rotordynamics library's ball-bearing default (typical range 0.25e-5 to 2.5e-5 s; docs/dynamics.md, \\\"Bearing damping\\\"): the lubricant, fits and housing joints damp the ring's mode on the bearing, which the contacts' material law leaves undamped; write your rig's when you know it",
    ),
    (
        "sensor",
        "mounting: an accelerometer on top of the housing (12 o'clock) with the [sensor] defaults (docs/signal.md): one housing mode at 3 kHz, damping ratio 0.05, 1 kg, driven one way by the force into the housing; write your rig's modes (an impact hammer test gives them) when you know them",
    ),
];

impl Preset {
    /// The case text without its mounting (its lines carrying
    /// [`MOUNTING_TAG`] left empty): the inner ring alone, its tilts free,
    /// no gravity unless the source paper has it.
    pub fn without_mounting(&self) -> String {
        without_mounting(self.text)
    }
}

/// All presets, papers' bearings first.
pub const PRESETS: &[Preset] = &[
    Preset {
        name: "7008C",
        summary: "angular contact 40x68x15, 22 balls, 17.7 deg (Deng et al. 2022 Table 1); the default case",
        text: include_str!("../presets/7008C.toml"),
    },
    Preset {
        name: "6304",
        summary: "deep groove 20x52x15, 7 balls, clearance 0.005 mm (Shan et al. 2023 Table 1)",
        text: include_str!("../presets/6304.toml"),
    },
    Preset {
        name: "7218B",
        summary: "angular contact 90x160x30, 16 balls, 40 deg (Zhang et al. 2025 Table 2 + Harris's 218 example)",
        text: include_str!("../presets/7218B.toml"),
    },
    Preset {
        name: "ceramic_45x75",
        summary: "hybrid angular contact 45x75, 18 Si3N4 balls, 15 deg (Zhang et al. 2020 Table 1)",
        text: include_str!("../presets/ceramic_45x75.toml"),
    },
    Preset {
        name: "acbb_30x62",
        summary: "angular contact 30x62x16, 11 balls, 30 deg (Lei et al. 2023 Table 1)",
        text: include_str!("../presets/acbb_30x62.toml"),
    },
    Preset {
        name: "6205",
        summary: "deep groove 25x52x15, 9 balls (SKF 6205-2RS as documented by the CWRU Bearing Data Center)",
        text: include_str!("../presets/6205.toml"),
    },
    Preset {
        name: "6203",
        summary: "deep groove 17x40x12, 8 balls (SKF 6203-2RS as documented by the CWRU Bearing Data Center)",
        text: include_str!("../presets/6203.toml"),
    },
    Preset {
        name: "6206",
        summary: "deep groove 30x62x16, 9 balls (usual design; internal geometry assumed)",
        text: include_str!("../presets/6206.toml"),
    },
];

/// The built-in default case (7008C at 10 000 rpm, F_x = 200 N).
pub const DEFAULT_PRESET: &str = "7008C";

/// Looks a preset up by name, ignoring case.
pub fn find(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

/// Comma-separated preset names, for messages.
pub fn names() -> String {
    PRESETS
        .iter()
        .map(|p| p.name)
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::load::load_case;

    /// Every preset but the 6304 (whose ring carries Shan et al. 2023's rig
    /// shaft, planar) and the catalogue's cases are mounted by the rule of
    /// docs/dynamics.md: its
    /// stated inner-ring mass is the rule's to the three digits written,
    /// its tilts are held, gravity acts and a housing sensor records;
    /// without its mounting it parses with the tilts free and no sensor.
    #[test]
    fn presets_and_catalogue_cases_are_mounted_by_the_rule() {
        let catalogue: Vec<(String, String)> = ["6308", "7206B"]
            .iter()
            .map(|d| {
                let b = crate::catalogue::CatalogueBearing::lookup(d, None).unwrap();
                (d.to_string(), b.case_text().unwrap())
            })
            .collect();
        let cases = PRESETS
            .iter()
            .filter(|p| p.name != "6304")
            .map(|p| (p.name.to_string(), p.text.to_string()))
            .chain(catalogue);
        for (name, text) in cases {
            let case = load_case(&name, &text, &[]).unwrap();
            let g = &case.bearing.geometry;
            let rule = crate::mounting::Mounting::by_rule(
                case.bearing.bore.unwrap(),
                case.bearing.outside_diameter.unwrap(),
                case.bearing.width.unwrap(),
                g.pitch_diameter,
                g.ball_diameter,
            );
            let mass = case.inner_ring_mass.unwrap();
            assert!(
                (mass / rule.inner_ring_mass() - 1.0).abs() < 5e-3,
                "{name}: {mass} kg against the rule's {} kg",
                rule.inner_ring_mass()
            );
            assert_eq!(case.prescribed_displacement[3..], [Some(0.0), Some(0.0)]);
            assert!(case.gravity, "{name}");
            assert!(case.sensor.is_some(), "{name}: no housing sensor");
            let bare_text = without_mounting(&text);
            assert!(!bare_text.contains(MOUNTING_TAG));
            assert_eq!(bare_text.lines().count(), text.lines().count());
            let bare = load_case(&name, &bare_text, &[]).unwrap();
            assert_eq!(bare.prescribed_displacement, [None; 5], "{name}");
            assert!(!bare.gravity, "{name}");
            assert!(bare.sensor.is_none(), "{name}");
            for (key, assumption) in MOUNTING_ASSUMPTIONS {
                let line = format!("\"{key}\" = \"{assumption}\"  {MOUNTING_TAG}");
                assert!(text.contains(&line), "{name}: {line}");
            }
        }
    }
}
