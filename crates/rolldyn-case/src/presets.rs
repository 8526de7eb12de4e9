//! Built-in bearings: each is a complete, commented case file (in
//! `presets/`), with the source of every dimension and every assumed value
//! listed under `[assumptions]`.

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
