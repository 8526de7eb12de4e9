//! The case file of a catalogue bearing: its estimated geometry, an
//! assumed lubricant and operating point, and every estimated or assumed
//! value under `[assumptions]` (docs/catalogue.md).

use super::{BALL_SECTION_FRACTION, BearingKind, CatalogueBearing, Ratings};
use crate::mounting::Mounting;
use crate::presets::{MOUNTING_ASSUMPTIONS, MOUNTING_TAG};
use rolldyn::error::InvalidParameter;

impl CatalogueBearing {
    /// A complete case file for the bearing: 3000 rpm, a load of 5 % of the
    /// estimated C_r (radial on a deep-groove bearing, axial on an
    /// angular-contact one), an ISO VG 68 mineral oil at 40 °C with EHL
    /// traction on a graded 16 × 8 grid; every estimated or assumed value under
    /// `[assumptions]`.
    pub fn case_text(&self) -> Result<String, InvalidParameter> {
        let ratings = self.ratings()?;
        let mut t = self.header(&ratings);
        self.bearing_section(&mut t);
        self.cage_section(&mut t);
        self.running_sections(&mut t, &ratings);
        self.assumptions(&mut t);
        Ok(t)
    }

    /// The file's opening comment (what is estimated, the ratings) and title.
    fn header(&self, ratings: &Ratings) -> String {
        let kind_text = match self.kind {
            BearingKind::DeepGroove => "deep-groove",
            BearingKind::AngularContact => "angular-contact",
        };
        let published = match (ratings.published_dynamic, ratings.published_static) {
            (Some(c), Some(c0)) => format!(
                "\n# NSK lists C_r {:.2} kN, C_0r {:.2} kN for its own ball set.",
                c * 1e-3,
                c0 * 1e-3
            ),
            _ => String::new(),
        };
        let mut t = String::new();
        t.push_str(&format!(
            "# rolldyn case — {} {} ball bearing, {} × {} × {} mm (ISO 15), catalogue\n\
             # estimate: the internal geometry is not published, and every value below\n\
             # marked \"estimated\" comes from the rules of docs/catalogue.md. Measure\n\
             # the bearing or ask its maker before trusting absolute numbers.\n\
             # ISO 281 C_r {:.2} kN and ISO 76 C_0r {:.2} kN of this estimated geometry.{}\n",
            self.designation,
            kind_text,
            trim(self.bore * 1e3, 1),
            trim(self.outside_diameter * 1e3, 1),
            trim(self.width * 1e3, 1),
            ratings.dynamic * 1e-3,
            ratings.r#static * 1e-3,
            published
        ));
        t.push_str(&format!(
            "title = \"{} (catalogue estimate) at 3000 rpm\"\n\n",
            self.designation
        ));
        t
    }

    /// `[bearing]`: the estimated geometry.
    fn bearing_section(&self, t: &mut String) {
        t.push_str("[bearing]\n");
        t.push_str(&format!(
            "designation = \"{} (catalogue estimate)\"\n",
            self.designation
        ));
        t.push_str(&format!(
            "{:<37}{EST}\n",
            format!("ball_diameter = \"{}\"", mm(self.ball_diameter))
        ));
        t.push_str(&format!(
            "{:<37}{EST}\n",
            format!("ball_count = {}", self.ball_count)
        ));
        t.push_str(&format!(
            "{:<37}{EST}\n",
            format!("pitch_diameter = \"{}\"", mm(self.pitch_diameter))
        ));
        if let Some(p_d) = self.diametral_clearance {
            t.push_str(&format!(
                "{:<37}{EST}\n",
                format!("diametral_clearance = \"{}\"", mm(p_d))
            ));
        }
        if let Some(angle) = self.contact_angle {
            t.push_str(&format!(
                "{:<37}# contact angle code of the designation\n",
                format!(
                    "free_contact_angle = \"{} deg\"",
                    trim(angle.to_degrees(), 1)
                )
            ));
        }
        for ring in ["inner", "outer"] {
            t.push_str(&format!(
                "{:<37}{EST}\n",
                format!("{ring}_groove_curvature = {}", self.groove_curvature)
            ));
        }
        t.push_str(&format!(
            "{:<37}# ISO 15\n",
            format!("bore = \"{}\"", mm(self.bore))
        ));
        t.push_str(&format!(
            "outside_diameter = \"{}\"\nwidth = \"{}\"\n\n",
            mm(self.outside_diameter),
            mm(self.width)
        ));
    }

    /// `[cage]`: estimated and assumed.
    fn cage_section(&self, t: &mut String) {
        t.push_str("[cage]\n");
        t.push_str(&format!("{:<37}{EST}\n", "guidance = \"ball\"".to_string()));
        t.push_str(&format!(
            "{:<37}{EST}\n",
            format!("mass = \"{} g\"", trim(self.cage_mass * 1e3, 2))
        ));
        t.push_str(&format!(
            "{:<37}{EST}\n",
            format!("inertia = \"{:.3e} kg.m^2\"", self.cage_inertia)
        ));
        t.push_str(&format!(
            "{:<37}{EST}\n",
            format!("pocket_clearance = \"{}\"", mm(self.pocket_clearance))
        ));
        for line in [
            "pocket_stiffness = \"1e7 N/m\"",
            "pocket_damping = \"20 N.s/m\"",
            "pocket_friction = 0.05",
        ] {
            t.push_str(&format!("{line:<37}{EST}\n"));
        }
        t.push_str(&format!(
            "{:<37}{ASSUMED}\n",
            "pocket_squeeze_film = true".to_string()
        ));
        t.push_str("whirl = false                        # cage rotation only\n\n");
    }

    /// `[inner_ring]` (the mounting rule's shaft share), `[materials]`,
    /// `[lubricant]`, `[operating]` (a load of 5 % of the estimated C_r,
    /// the tilts held), `[model]` (gravity on) and `[solver]`.
    fn running_sections(&self, t: &mut String, ratings: &Ratings) {
        let load_n = ((0.05 * ratings.dynamic) / 10.0).round() * 10.0;
        let mounting = Mounting::by_rule(
            self.bore,
            self.outside_diameter,
            self.width,
            self.pitch_diameter,
            self.ball_diameter,
        );
        let mass = mounting.inner_ring_mass();
        let digits = (2 - mass.log10().floor() as i32).max(0) as usize;
        t.push_str(&format!(
            "[inner_ring]\n{:<37}{MOUNTING}\n\n",
            format!("mass = \"{mass:.digits$} kg\"")
        ));
        t.push_str("[materials]\nball = \"steel_52100\"\nrings = \"steel_52100\"\n\n");
        t.push_str("[lubricant]\nname = \"ISO VG 68 mineral oil\"\n");
        for line in [
            "viscosity = \"0.059 Pa.s\"",
            "temperature = \"40 degC\"",
            "second_viscosity = \"7.1 mPa.s\"",
            "second_temperature = \"100 degC\"",
            "pressure_viscosity = \"2.2e-8 1/Pa\"",
            "density = \"870 kg/m^3\"",
        ] {
            t.push_str(&format!("{line:<37}{ASSUMED}\n"));
        }
        t.push_str(
            "\n[operating]\nspeed = \"3000 rpm\"                   # assumed: see [assumptions]\n",
        );
        let load_key = match self.kind {
            BearingKind::DeepGroove => "force_z",
            BearingKind::AngularContact => "force_x",
        };
        t.push_str(&format!(
            "{:<37}# 5 % of the estimated C_r\n{:<37}{MOUNTING}\n",
            format!("{load_key} = \"{load_n} N\""),
            "fixed_tilt = true"
        ));
        t.push_str(
            "\n[model]\n\
             traction = { law = \"ehl\", eyring_stress = \"5 MPa\", limiting_shear_coefficient = 0.08 }  # assumed: see [assumptions]\n\
             traction_integration = { method = \"graded\", across = 16, along = 8 }   # see [assumptions]\n\
             gravity = true                       # mounting: see [assumptions]\n\
             bearing_damping = \"1.25e-5 s\"        # mounting: see [assumptions]\n\n\
             [sensor]                             # mounting: see [assumptions]\n\n\
             [solver]\n\
             duration = \"0.1 s\"                   # about two cage revolutions at 3000 rpm\n\
             start = \"jones_harris\"\n\
             relative_tolerance = 1e-4            # see [assumptions]\n\n",
        );
    }

    /// `[assumptions]`: the source or the rule of every estimated or
    /// assumed value.
    fn assumptions(&self, t: &mut String) {
        t.push_str("[assumptions]\n");
        let rule = |key: &str, text: String| format!("\"{key}\" = \"{text}\"\n");
        t.push_str(&rule(
            "bearing.ball_diameter",
            format!(
                "estimated: 0.3 (D - d) = {} mm to the nearest 1/64 in",
                trim(
                    BALL_SECTION_FRACTION * (self.outside_diameter - self.bore) * 1e3,
                    3
                )
            ),
        ));
        t.push_str(&rule(
            "bearing.ball_count",
            match self.kind {
                BearingKind::DeepGroove => format!(
                    "estimated: the most balls with a Conrad assembly angle 2 (Z - 1) asin(D_w/d_m) <= 192 deg (this set: {:.1} deg)",
                    self.assembly_angle_deg()
                ),
                BearingKind::AngularContact => {
                    "estimated: the most balls with centres at least 1.2 D_w apart on the pitch circle (a cage bar of 0.2 D_w)".to_string()
                }
            },
        ));
        t.push_str(&rule(
            "bearing.pitch_diameter",
            "estimated: mean of bore and outside diameter".into(),
        ));
        if let (Some(group), Some((lo, hi))) = (self.clearance_group, self.clearance_range) {
            t.push_str(&rule(
                "bearing.diametral_clearance",
                format!(
                    "mid-range of ISO 5753-1 group {} ({}-{} um) for the {} mm bore",
                    group.name(),
                    trim(lo * 1e6, 0),
                    trim(hi * 1e6, 0),
                    trim(self.bore * 1e3, 0)
                ),
            ));
        }
        for ring in ["inner", "outer"] {
            t.push_str(&rule(
                &format!("bearing.{ring}_groove_curvature"),
                "estimated: 0.52, a typical value (Harris & Kotzalas: 0.515-0.53)".into(),
            ));
        }
        t.push_str(&rule(
            "cage.guidance",
            match self.kind {
                BearingKind::DeepGroove => {
                    "estimated: pressed-steel ribbon cage, centred on the balls".into()
                }
                BearingKind::AngularContact => {
                    "estimated: polyamide window cage, centred on the balls".into()
                }
            },
        ));
        t.push_str(&rule("cage.mass", match self.kind {
            BearingKind::DeepGroove => "estimated: two steel half-shells, each a strip D_w wide and 0.06 D_w thick round the pitch circle".into(),
            BearingKind::AngularContact => "estimated: polyamide 66 (1300 kg/m^3) ring 0.4 D_w thick and 0.8 B wide at the pitch circle, less the pockets".into(),
        }));
        t.push_str(&rule(
            "cage.inertia",
            "estimated: cage mass times the squared pitch radius".into(),
        ));
        t.push_str(&rule("cage.pocket_clearance", "estimated: 0.02 D_w".into()));
        t.push_str(&rule(
            "cage.pocket_stiffness",
            "not published; linear 1e7 N/m as a stiff-contact placeholder (as the 6304 preset)"
                .into(),
        ));
        t.push_str(&rule(
            "cage.pocket_damping",
            "not published; a small damping so that pocket impacts settle".into(),
        ));
        t.push_str(&rule(
            "cage.pocket_squeeze_film",
            "assumed: the oil-lubricated pockets hold oil, whose squeeze film damps each ball's approach to its pocket wall (short-bearing squeeze film, docs/dynamics.md \\\"Pocket squeeze film\\\"); without it the unloaded balls' pocket impacts ring (the 6308 at its defaults: sensor RMS 1.66 against 0.33 m/s^2)".into(),
        ));
        t.push_str(&rule(
            "cage.pocket_friction",
            "not published; a boundary-friction value for a lubricated pocket".into(),
        ));
        t.push_str(&rule(
            "lubricant",
            "assumed: an ISO VG 68 mineral oil (68 mm^2/s at 40 degC, about 8.2 mm^2/s at 100 degC, 870 kg/m^3), run isothermal at 40 degC; pressure-viscosity 2.2e-8 1/Pa typical of mineral oils (1-3e-8 1/Pa: Hamrock, Schmid & Jacobson 2004, ch. 8)".into(),
        ));
        t.push_str(&rule(
            "operating.speed",
            "assumed: a moderate speed for a first run; set your own".into(),
        ));
        t.push_str(&rule(
            "model.traction",
            "assumed: EHL traction with Eyring stress 5 MPa and limiting shear 0.08, typical of mineral oils (Johnson & Tevaarwerk 1977)".into(),
        ));
        t.push_str(&rule(
            "model.traction_integration",
            "graded 16 x 8 cells: the dissipated power within 0.5 % of a 48 x 24 grid (7210B, docs/catalogue.md)".into(),
        ));
        t.push_str(&rule(
            "solver.relative_tolerance",
            "1e-4: the mean dissipated power within 0.3 % of rtol 1e-5 over 60 ms (6205); at the general default 1e-3 it is 1 % high, the rolling resistance of the balls off the load zone (docs/catalogue.md)".into(),
        ));
        for (key, text) in MOUNTING_ASSUMPTIONS {
            t.push_str(&format!("\"{key}\" = \"{text}\"  {MOUNTING_TAG}\n"));
        }
    }
}

/// The comment of an estimated value.
const EST: &str = "# estimated: see [assumptions]";
/// The comment of an assumed value.
const ASSUMED: &str = "# assumed: see [assumptions]";
/// The comment of a mounting value.
const MOUNTING: &str = "# mounting: see [assumptions]";

/// A length in millimetres, as the case file writes it.
fn mm(x: f64) -> String {
    format!("{} mm", trim(x * 1e3, 6))
}

/// `x` with at most `digits` decimals, trailing zeros removed.
fn trim(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}
