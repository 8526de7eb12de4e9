//! Quantities with explicit units at the case-file boundary.
//!
//! Every dimensional value in a case file is a string "number unit", e.g.
//! "6.35 mm", "10000 rpm", "206 GPa", "40 degC", "2 L/min". [`Quantity<D>`]
//! parses it into SI for the dimension `D` and keeps the text for messages.
//! Bare numbers, unknown units and units of the wrong dimension are
//! rejected with a message that names the accepted units.
//!
//! Unit spellings are normalised before lookup: spaces, `*` and `·` between
//! factors become `.`, `²`/`³` become `^2`/`^3`, and the micro sign may be
//! `µ`, `μ` or `u`.

use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};
use std::borrow::Cow;
use std::fmt;
use std::marker::PhantomData;

/// A physical dimension and the units accepted for it.
pub trait Dimension {
    /// Human name, e.g. "length".
    const NAME: &'static str;
    /// An example value for messages and the schema, e.g. "6.35 mm".
    const EXAMPLE: &'static str;
    /// Accepted units: (normalised symbol, factor to SI, offset to SI).
    const UNITS: UnitTable;
    /// Practical range: no value of this dimension in a bearing case
    /// exceeds this magnitude in SI (far beyond any bearing; a larger one is
    /// a unit or exponent slip). Keys add their own physical rules.
    const LIMIT: f64;
    /// The SI unit's symbol, for messages.
    const SI: &'static str;
}

macro_rules! dimension {
    ($(#[$doc:meta])* $name:ident, $human:literal, $example:literal, $limit:expr, $si:literal, [$(($sym:literal, $scale:expr $(, $offset:expr)?)),* $(,)?]) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum $name {}
        impl Dimension for $name {
            const NAME: &'static str = $human;
            const EXAMPLE: &'static str = $example;
            const LIMIT: f64 = $limit;
            const SI: &'static str = $si;
            const UNITS: &'static [(&'static str, f64, f64)] = &[$(($sym, $scale, dimension!(@offset $($offset)?))),*];
        }
    };
    (@offset) => { 0.0 };
    (@offset $o:expr) => { $o };
}

const INCH: f64 = 0.0254;
const LBF: f64 = 4.448_221_615_260_5;
const PSI: f64 = 6_894.757_293_168;
const TAU: f64 = std::f64::consts::TAU;

dimension!(/// Length, SI metre.
    Length, "length", "6.35 mm", 1e2, "m",
    [("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9), ("cm", 1e-2), ("in", INCH), ("mil", 1e-3 * INCH)]);
dimension!(/// Plane angle, SI radian.
    Angle, "angle", "17.7 deg", 1e4, "rad",
    [("deg", std::f64::consts::PI / 180.0), ("°", std::f64::consts::PI / 180.0), ("rad", 1.0), ("mrad", 1e-3), ("arcmin", std::f64::consts::PI / 10_800.0)]);
dimension!(/// Rotational speed, SI rad/s. "Hz" and "rps" mean revolutions per second.
    AngularSpeed, "rotational speed", "10000 rpm", 1e6, "rad/s",
    [("rpm", TAU / 60.0), ("r/min", TAU / 60.0), ("rev/min", TAU / 60.0), ("rad/s", 1.0), ("hz", TAU), ("rps", TAU), ("krpm", TAU * 1000.0 / 60.0)]);
dimension!(/// Force, SI newton.
    Force, "force", "200 N", 1e9, "N",
    [("n", 1.0), ("kn", 1e3), ("mn", 1e-3), ("lbf", LBF)]);
dimension!(/// Moment, SI N·m.
    Moment, "moment", "5 N.m", 1e9, "N·m",
    [("n.m", 1.0), ("nm", 1.0), ("n.mm", 1e-3), ("nmm", 1e-3), ("kn.m", 1e3), ("lbf.in", LBF * INCH), ("lbf.ft", LBF * 0.3048)]);
dimension!(/// Pressure, stress and elastic modulus, SI pascal.
    Pressure, "pressure or modulus", "206 GPa", 1e13, "Pa",
    [("pa", 1.0), ("kpa", 1e3), ("mpa", 1e6), ("gpa", 1e9), ("n/mm^2", 1e6), ("n/m^2", 1.0), ("bar", 1e5), ("psi", PSI), ("ksi", 1e3 * PSI), ("msi", 1e6 * PSI)]);
dimension!(/// Mass density, SI kg/m³.
    Density, "density", "7800 kg/m^3", 1e5, "kg/m³",
    [("kg/m^3", 1.0), ("kg/m3", 1.0), ("g/cm^3", 1e3), ("g/cm3", 1e3), ("kg/dm^3", 1e3), ("kg/l", 1e3)]);
dimension!(/// Dynamic viscosity, SI Pa·s.
    Viscosity, "dynamic viscosity", "0.0467 Pa.s", 1e6, "Pa·s",
    [("pa.s", 1.0), ("mpa.s", 1e-3), ("cp", 1e-3), ("p", 0.1)]);
dimension!(/// Pressure–viscosity coefficient α_p, SI 1/Pa.
    PressureViscosity, "pressure-viscosity coefficient", "2.2e-8 1/Pa", 1e-5, "1/Pa",
    [("1/pa", 1.0), ("1/mpa", 1e-6), ("1/gpa", 1e-9), ("pa^-1", 1.0), ("gpa^-1", 1e-9), ("m^2/n", 1.0), ("mm^2/n", 1e-6)]);
dimension!(/// Temperature, SI kelvin.
    Temperature, "temperature", "40 degC", 1e4, "K",
    [("k", 1.0), ("degc", 1.0, 273.15), ("°c", 1.0, 273.15), ("degf", 5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0), ("°f", 5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0)]);
dimension!(/// Time, SI second.
    Time, "time", "0.05 s", 1e8, "s",
    [("s", 1.0), ("ms", 1e-3), ("us", 1e-6), ("ns", 1e-9), ("min", 60.0), ("h", 3600.0)]);
dimension!(/// Frequency (sampling), SI hertz.
    Frequency, "frequency", "20 kHz", 1e10, "Hz",
    [("hz", 1.0), ("khz", 1e3), ("mhz", 1e6)]);
dimension!(/// Volume flow rate, SI m³/s.
    VolumeFlow, "volume flow", "2 L/min", 1e2, "m³/s",
    [("m^3/s", 1.0), ("l/min", 1e-3 / 60.0), ("ml/min", 1e-6 / 60.0), ("l/h", 1e-3 / 3600.0), ("l/s", 1e-3), ("cm^3/min", 1e-6 / 60.0)]);
dimension!(/// Thermal conductivity, SI W/(m·K).
    ThermalConductivity, "thermal conductivity", "0.14 W/(m.K)", 1e4, "W/(m·K)",
    [("w/(m.k)", 1.0), ("w/m/k", 1.0), ("w/m.k", 1.0), ("w/mk", 1.0)]);
dimension!(/// Specific heat capacity, SI J/(kg·K).
    SpecificHeat, "specific heat", "2000 J/(kg.K)", 1e6, "J/(kg·K)",
    [("j/(kg.k)", 1.0), ("j/kg/k", 1.0), ("j/kg.k", 1.0), ("kj/(kg.k)", 1e3), ("kj/kg/k", 1e3)]);
dimension!(/// Convective heat-transfer coefficient, SI W/(m²·K).
    HeatTransferCoefficient, "heat-transfer coefficient", "15 W/(m^2.K)", 1e7, "W/(m²·K)",
    [("w/(m^2.k)", 1.0), ("w/m^2/k", 1.0), ("w/m^2.k", 1.0), ("w/(m2.k)", 1.0), ("w/m2k", 1.0)]);
dimension!(/// Linear thermal-expansion coefficient, SI 1/K.
    ThermalExpansion, "thermal-expansion coefficient", "11.9e-6 1/K", 1e-2, "1/K",
    [("1/k", 1.0), ("k^-1", 1.0), ("um/(m.k)", 1e-6), ("ppm/k", 1e-6)]);
dimension!(/// Linear speed, SI m/s.
    Velocity, "speed", "1 mm/s", 1e4, "m/s",
    [("m/s", 1.0), ("mm/s", 1e-3), ("um/s", 1e-6), ("cm/s", 1e-2)]);
dimension!(/// Mass, SI kilogram.
    Mass, "mass", "0.0035 kg", 1e6, "kg",
    [("kg", 1.0), ("g", 1e-3), ("mg", 1e-6)]);
dimension!(/// Mass moment of inertia, SI kg·m².
    Inertia, "moment of inertia", "8.2e-7 kg.m^2", 1e6, "kg·m²",
    [("kg.m^2", 1.0), ("kg.mm^2", 1e-6), ("g.mm^2", 1e-9), ("g.cm^2", 1e-7)]);

/// A dimension's unit table: (normalised symbol, factor to SI, offset to SI).
type UnitTable = &'static [(&'static str, f64, f64)];

dimension!(/// Contact stiffness (linear), SI N/m.
    Stiffness, "stiffness", "1e7 N/m", 1e16, "N/m",
    [("n/m", 1.0), ("n/mm", 1e3), ("n/um", 1e6), ("kn/mm", 1e6)]);
dimension!(/// Viscous damping coefficient, SI N·s/m.
    Damping, "damping coefficient", "20 N.s/m", 1e12, "N·s/m",
    [("n.s/m", 1.0), ("n.s/mm", 1e3), ("kg/s", 1.0)]);

dimension!(/// Rotational viscous damping, SI N·m·s.
    RotationalDamping, "rotational damping", "1e-6 N.m.s", 1e6, "N·m·s",
    [("n.m.s", 1.0), ("n.mm.s", 1e-3)]);
dimension!(/// Windage (quadratic rotational drag) coefficient, SI N·m·s².
    WindageCoefficient, "windage coefficient", "1e-9 N.m.s^2", 1e6, "N·m·s²",
    [("n.m.s^2", 1.0), ("n.mm.s^2", 1e-3)]);

dimension!(/// Unbalance (mass × radius), SI kg·m.
    Unbalance, "unbalance", "50 g.mm", 1e3, "kg·m",
    [("kg.m", 1.0), ("g.mm", 1e-6), ("g.cm", 1e-5), ("kg.mm", 1e-3)]);

dimension!(/// Acceleration, SI m/s². "g" and "mg" are the standard gravity
    /// g_n = 9.806 65 m/s² and its thousandth (in an acceleration's place
    /// only: elsewhere they are grams).
    Acceleration, "acceleration", "0.01 m/s^2", 1e9, "m/s²",
    [("m/s^2", 1.0), ("mm/s^2", 1e-3), ("g", 9.806_65), ("mg", 9.806_65e-3)]);

/// Every dimension's name and units, for "that is a unit of X" messages.
fn all_units() -> [(&'static str, UnitTable); 26] {
    [
        (Length::NAME, Length::UNITS),
        (Angle::NAME, Angle::UNITS),
        (AngularSpeed::NAME, AngularSpeed::UNITS),
        (Force::NAME, Force::UNITS),
        (Moment::NAME, Moment::UNITS),
        (Pressure::NAME, Pressure::UNITS),
        (Density::NAME, Density::UNITS),
        (Viscosity::NAME, Viscosity::UNITS),
        (PressureViscosity::NAME, PressureViscosity::UNITS),
        (Temperature::NAME, Temperature::UNITS),
        (Time::NAME, Time::UNITS),
        (Frequency::NAME, Frequency::UNITS),
        (VolumeFlow::NAME, VolumeFlow::UNITS),
        (ThermalConductivity::NAME, ThermalConductivity::UNITS),
        (SpecificHeat::NAME, SpecificHeat::UNITS),
        (
            HeatTransferCoefficient::NAME,
            HeatTransferCoefficient::UNITS,
        ),
        (ThermalExpansion::NAME, ThermalExpansion::UNITS),
        (Velocity::NAME, Velocity::UNITS),
        (Mass::NAME, Mass::UNITS),
        (Inertia::NAME, Inertia::UNITS),
        (Stiffness::NAME, Stiffness::UNITS),
        (Damping::NAME, Damping::UNITS),
        (RotationalDamping::NAME, RotationalDamping::UNITS),
        (WindageCoefficient::NAME, WindageCoefficient::UNITS),
        (Unbalance::NAME, Unbalance::UNITS),
        (Acceleration::NAME, Acceleration::UNITS),
    ]
}

/// Normalised spelling of a unit: lower case, factors joined by '.',
/// superscripts as ^n, micro as 'u'. Case-insensitive matching keeps "MPa"
/// and "mPa.s" apart because the tables list them under different
/// dimensions only where they do not collide ("mpa" is pressure; "mpa.s"
/// is viscosity).
pub fn normalise_unit(unit: &str) -> String {
    let mut s = String::with_capacity(unit.len());
    let mut prev_space = false;
    for ch in unit.trim().chars() {
        match ch {
            ' ' | '*' | '·' | '⋅' => {
                if !prev_space {
                    s.push('.');
                }
                prev_space = true;
                continue;
            }
            'µ' | 'μ' => s.push('u'),
            '²' => s.push_str("^2"),
            '³' => s.push_str("^3"),
            c => s.extend(c.to_lowercase()),
        }
        prev_space = false;
    }
    // "m3" style exponents without caret, and "sec".
    s.replace("m3", "m^3")
        .replace("m2", "m^2")
        .replace("^^", "^")
        .replace("sec", "s")
}

fn unit_list(units: &[(&'static str, f64, f64)]) -> String {
    let mut names: Vec<&str> = units.iter().map(|u| u.0).collect();
    names.dedup();
    names.join(", ")
}

/// Parses "number unit" into SI for dimension `D`. Errors are complete
/// sentences naming the rule.
pub fn parse_quantity<D: Dimension>(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let split = t
        .char_indices()
        .find(|&(i, c)| {
            !(c.is_ascii_digit()
                || c == '.'
                || c == '_'
                || ((c == '+' || c == '-')
                    && (i == 0 || matches!(t.as_bytes()[i - 1], b'e' | b'E')))
                || ((c == 'e' || c == 'E')
                    && i > 0
                    && t.as_bytes()[i - 1].is_ascii_digit()
                    && t[i + 1..]
                        .starts_with(|n: char| n.is_ascii_digit() || n == '-' || n == '+')))
        })
        .map(|(i, _)| i)
        .unwrap_or(t.len());
    let (number, unit) = (t[..split].replace('_', ""), t[split..].trim());
    let article = if D::NAME.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    };
    let expected = format!(
        "{article} {} such as \"{}\" (units: {})",
        D::NAME,
        D::EXAMPLE,
        unit_list(D::UNITS)
    );
    if number.is_empty() {
        return Err(format!(
            "\"{text}\" does not start with a number; expected {expected}"
        ));
    }
    let value: f64 = number
        .parse()
        .map_err(|_| format!("\"{number}\" is not a number; expected {expected}"))?;
    if !value.is_finite() {
        return Err(format!("\"{text}\" is not a finite number"));
    }
    if unit.is_empty() {
        return Err(format!("missing unit in \"{text}\"; expected {expected}"));
    }
    // Lower-casing would merge milli- and mega-: refuse the spellings that
    // differ only in that case instead of guessing.
    if (unit.starts_with("mPa")
        && !unit.starts_with("mPa.s")
        && !unit.starts_with("mPa s")
        && !unit.starts_with("mPa*s")
        && !unit.starts_with("mPa·s"))
        || unit.starts_with("MN")
    {
        return Err(format!(
            "\"{unit}\" is ambiguous (milli- or mega-?); expected {expected}"
        ));
    }
    let key = normalise_unit(unit);
    let key = key.as_str();
    if let Some(&(_, scale, offset)) = D::UNITS.iter().find(|u| u.0 == key) {
        let si = value * scale + offset;
        if si.abs() > D::LIMIT {
            return Err(format!(
                "\"{text}\" is beyond the practical range of a {}: at most {:e} {} in magnitude (a unit or exponent slip?)",
                D::NAME,
                D::LIMIT,
                D::SI
            ));
        }
        return Ok(si);
    }
    if let Some((other, _)) = all_units()
        .iter()
        .find(|(_, units)| units.iter().any(|u| u.0 == key))
    {
        return Err(format!("\"{unit}\" is a unit of {other}, but {expected}"));
    }
    Err(format!("unknown unit \"{unit}\"; expected {expected}"))
}

/// A value of dimension `D` in SI, with the text it was written as.
#[derive(Clone, PartialEq)]
pub struct Quantity<D> {
    /// Value in SI units.
    pub si: f64,
    /// The text from the case file (or a formatted SI value).
    pub text: String,
    _dimension: PhantomData<D>,
}

impl<D: Dimension> Quantity<D> {
    /// Parses a "number unit" string.
    pub fn parse(text: &str) -> Result<Self, String> {
        Ok(Self {
            si: parse_quantity::<D>(text)?,
            text: text.to_string(),
            _dimension: PhantomData,
        })
    }
}

impl<D> fmt::Debug for Quantity<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.text)
    }
}

impl<D> fmt::Display for Quantity<D> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "\"{}\"", self.text)
    }
}

impl<D> Serialize for Quantity<D> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.text)
    }
}

struct QuantityVisitor<D>(PhantomData<D>);

impl<D: Dimension> QuantityVisitor<D> {
    fn bare_number<E: de::Error>(v: impl fmt::Display) -> E {
        E::custom(format!(
            "missing unit: {v} is a bare number; write the unit in a string, e.g. \"{}\" ({} units: {})",
            D::EXAMPLE,
            D::NAME,
            unit_list(D::UNITS)
        ))
    }
}

impl<'de, D: Dimension> Visitor<'de> for QuantityVisitor<D> {
    type Value = Quantity<D>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(
            f,
            "a {} with its unit in a string, e.g. \"{}\"",
            D::NAME,
            D::EXAMPLE
        )
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
        Quantity::parse(v).map_err(E::custom)
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
        Err(Self::bare_number(v))
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
        Err(Self::bare_number(v))
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
        Err(Self::bare_number(v))
    }
}

impl<'de, D: Dimension> Deserialize<'de> for Quantity<D> {
    fn deserialize<De: Deserializer<'de>>(d: De) -> Result<Self, De::Error> {
        d.deserialize_any(QuantityVisitor(PhantomData))
    }
}

impl<D: Dimension> JsonSchema for Quantity<D> {
    fn schema_name() -> Cow<'static, str> {
        let mut name: String = D::NAME
            .split([' ', '-'])
            .map(|w| {
                let mut c = w.chars();
                c.next()
                    .map(|f| f.to_uppercase().chain(c).collect::<String>())
                    .unwrap_or_default()
            })
            .collect();
        name.push_str("Quantity");
        Cow::Owned(name)
    }
    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "type": "string",
            "description": format!("A {} with its unit, e.g. \"{}\". Units: {}.", D::NAME, D::EXAMPLE, unit_list(D::UNITS)),
            "examples": [D::EXAMPLE],
            "pattern": r"^\s*[-+]?[0-9_.]+([eE][-+]?[0-9]+)?\s*\S+",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1e-300)
    }

    #[test]
    fn values_beyond_the_practical_range_are_refused() {
        let e = parse_quantity::<Length>("6.35e3 m").unwrap_err();
        assert!(
            e.contains("practical range of a length") && e.contains("1e2 m"),
            "{e}"
        );
        assert!(parse_quantity::<Length>("100 m").is_ok());
        assert!(parse_quantity::<Length>("-100 m").is_ok());
        assert!(parse_quantity::<Force>("1e300 N").is_err());
        assert!(parse_quantity::<Time>("3 h").is_ok());
        // Every dimension's limit is positive and above its example value.
        fn example_fits<D: Dimension>() {
            let v = parse_quantity::<D>(D::EXAMPLE).unwrap();
            assert!(D::LIMIT > 0.0 && v.abs() <= D::LIMIT, "{}", D::NAME);
        }
        example_fits::<Length>();
        example_fits::<Pressure>();
        example_fits::<Stiffness>();
        example_fits::<PressureViscosity>();
        example_fits::<Temperature>();
        example_fits::<ThermalExpansion>();
        example_fits::<Unbalance>();
    }

    #[test]
    fn engineering_units_convert_to_si() {
        assert!(close(parse_quantity::<Length>("6.35 mm").unwrap(), 6.35e-3));
        assert!(close(parse_quantity::<Length>("0.3 µm").unwrap(), 0.3e-6));
        assert!(close(parse_quantity::<Length>("0.3um").unwrap(), 0.3e-6));
        assert!(close(parse_quantity::<Length>("1 in").unwrap(), 0.0254));
        assert!(close(
            parse_quantity::<AngularSpeed>("60 rpm").unwrap(),
            TAU
        ));
        assert!(close(parse_quantity::<AngularSpeed>("1 Hz").unwrap(), TAU));
        assert!(close(parse_quantity::<Pressure>("206 GPa").unwrap(), 206e9));
        assert!(close(
            parse_quantity::<Temperature>("40 degC").unwrap(),
            313.15
        ));
        assert!(close(
            parse_quantity::<Temperature>("212 degF").unwrap(),
            373.15
        ));
        assert!(close(
            parse_quantity::<VolumeFlow>("2 L/min").unwrap(),
            2e-3 / 60.0
        ));
        assert!(close(
            parse_quantity::<Viscosity>("46.7 mPa s").unwrap(),
            0.0467
        ));
        assert!(close(
            parse_quantity::<Density>("7800 kg/m³").unwrap(),
            7800.0
        ));
        assert!(close(
            parse_quantity::<PressureViscosity>("22 1/GPa").unwrap(),
            22e-9
        ));
        assert!(close(parse_quantity::<Force>("-1.5e3 N").unwrap(), -1500.0));
        assert!(close(parse_quantity::<Force>("1 lbf").unwrap(), LBF));
        assert!(close(
            parse_quantity::<ThermalConductivity>("0.14 W/(m K)").unwrap(),
            0.14
        ));
        assert!(close(
            parse_quantity::<Inertia>("8.2e-7 kg m^2").unwrap(),
            8.2e-7
        ));
    }

    #[test]
    fn errors_name_the_rule() {
        let e = parse_quantity::<Length>("6.35").unwrap_err();
        assert!(e.contains("missing unit"), "{e}");
        let e = parse_quantity::<Length>("6.35 mmm").unwrap_err();
        assert!(
            e.contains("unknown unit \"mmm\"") && e.contains("mm"),
            "{e}"
        );
        let e = parse_quantity::<Length>("6.35 N").unwrap_err();
        assert!(e.contains("unit of force"), "{e}");
        let e = parse_quantity::<Pressure>("206 mPa").unwrap_err();
        assert!(e.contains("ambiguous"), "{e}");
        let e = parse_quantity::<Length>("nan mm").unwrap_err();
        assert!(e.contains("does not start with a number"), "{e}");
        let e = parse_quantity::<Length>("1e999 mm").unwrap_err();
        assert!(e.contains("finite"), "{e}");
    }
}
