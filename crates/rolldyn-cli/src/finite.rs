//! No non-finite output: serde_json writes NaN and ±∞ as
//! `null`, the same as an absent value, so a bug that produces one would
//! pass unseen. [`non_finite`] walks a value through serde and names the
//! first number that is not finite; every JSON writer of the CLI calls
//! [`to_json`], which warns on standard error (the fuzzing harness fails
//! on that warning). Absent values (`Option::None`, documented in
//! docs/cli.md) are not reported.

use serde::Serialize;
use serde::ser;

/// Pretty JSON of `value`, with a warning on standard error naming any
/// non-finite number (written as `null`).
pub fn to_json<T: Serialize + ?Sized>(value: &T) -> Result<String, serde_json::Error> {
    if let Some(path) = non_finite(value) {
        eprintln!(
            "warning: non-finite number at {path} written as null (a rolldyn bug: please report it with the case)"
        );
    }
    serde_json::to_string_pretty(value)
}

/// The path of the first non-finite number in `value`, if any.
pub fn non_finite<T: Serialize + ?Sized>(value: &T) -> Option<String> {
    let mut finder = Finder::default();
    match value.serialize(&mut finder) {
        Err(Found(path)) => Some(if path.is_empty() { "$".into() } else { path }),
        Ok(()) => None,
    }
}

#[derive(Default)]
struct Finder {
    path: Vec<String>,
}

/// The "error" that stops the walk at a non-finite number.
#[derive(Debug)]
struct Found(String);

impl std::fmt::Display for Found {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "non-finite number at {}", self.0)
    }
}
impl std::error::Error for Found {}
impl ser::Error for Found {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        // A serialization error of the value itself is not ours to report.
        Found(String::new())
    }
}

impl Finder {
    fn check(&self, v: f64) -> Result<(), Found> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Found(self.path.join("")))
        }
    }
    fn nested<T: Serialize + ?Sized>(&mut self, segment: String, v: &T) -> Result<(), Found> {
        self.path.push(segment);
        v.serialize(&mut *self)?;
        self.path.pop();
        Ok(())
    }
}

macro_rules! ok {
    ($($name:ident: $t:ty),*) => {
        $(fn $name(self, _: $t) -> Result<(), Found> { Ok(()) })*
    };
}

impl<'a> ser::Serializer for &'a mut Finder {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Seq<'a>;
    type SerializeTuple = Seq<'a>;
    type SerializeTupleStruct = Seq<'a>;
    type SerializeTupleVariant = Seq<'a>;
    type SerializeMap = Map<'a>;
    type SerializeStruct = Seq<'a>;
    type SerializeStructVariant = Seq<'a>;

    ok!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str,
        serialize_bytes: &[u8], serialize_unit_struct: &'static str);

    fn serialize_f32(self, v: f32) -> Result<(), Found> {
        self.check(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), Found> {
        self.check(v)
    }
    fn serialize_none(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> Result<(), Found> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        v: &T,
    ) -> Result<(), Found> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        v: &T,
    ) -> Result<(), Found> {
        self.nested(format!(".{variant}"), v)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Seq<'a>, Found> {
        Ok(Seq { f: self, index: 0 })
    }
    fn serialize_tuple(self, _: usize) -> Result<Seq<'a>, Found> {
        Ok(Seq { f: self, index: 0 })
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Seq<'a>, Found> {
        Ok(Seq { f: self, index: 0 })
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Seq<'a>, Found> {
        Ok(Seq { f: self, index: 0 })
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Map<'a>, Found> {
        Ok(Map { f: self, key: None })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Seq<'a>, Found> {
        Ok(Seq { f: self, index: 0 })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Seq<'a>, Found> {
        Ok(Seq { f: self, index: 0 })
    }
}

/// Sequences, tuples and structs.
struct Seq<'a> {
    f: &'a mut Finder,
    index: usize,
}

impl Seq<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Found> {
        let segment = format!("[{}]", self.index);
        self.index += 1;
        self.f.nested(segment, v)
    }
    fn field<T: Serialize + ?Sized>(&mut self, key: &'static str, v: &T) -> Result<(), Found> {
        self.f.nested(format!(".{key}"), v)
    }
}

macro_rules! sequence {
    ($($trait:ident :: $method:ident),*) => {$(
        impl ser::$trait for Seq<'_> {
            type Ok = ();
            type Error = Found;
            fn $method<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Found> {
                self.element(v)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}
sequence!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

macro_rules! record {
    ($($trait:ident),*) => {$(
        impl ser::$trait for Seq<'_> {
            type Ok = ();
            type Error = Found;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                v: &T,
            ) -> Result<(), Found> {
                self.field(key, v)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}
record!(SerializeStruct, SerializeStructVariant);

/// Maps: keys are rendered for the path.
struct Map<'a> {
    f: &'a mut Finder,
    key: Option<String>,
}

impl ser::SerializeMap for Map<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Found> {
        self.key = Some(
            serde_json::to_string(key)
                .map(|k| k.trim_matches('"').to_string())
                .unwrap_or_default(),
        );
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, v: &T) -> Result<(), Found> {
        let key = self.key.take().unwrap_or_default();
        self.f.nested(format!(".{key}"), v)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Report {
        speed: f64,
        ratio: Option<f64>,
        rows: Vec<Row>,
        by_name: std::collections::BTreeMap<String, f64>,
    }
    #[derive(Serialize)]
    struct Row {
        load: f64,
        angles: [f64; 2],
    }

    fn report() -> Report {
        Report {
            speed: 1.0,
            ratio: None,
            rows: vec![Row {
                load: 2.0,
                angles: [0.1, 0.2],
            }],
            by_name: [("a".to_string(), 3.0)].into_iter().collect(),
        }
    }

    #[test]
    fn absent_values_pass_non_finite_numbers_are_named() {
        assert_eq!(non_finite(&report()), None);
        let mut r = report();
        r.rows[0].angles[1] = f64::NAN;
        assert_eq!(non_finite(&r).as_deref(), Some(".rows[0].angles[1]"));
        let mut r = report();
        r.ratio = Some(f64::INFINITY);
        assert_eq!(non_finite(&r).as_deref(), Some(".ratio"));
        let mut r = report();
        r.by_name.insert("b".into(), f64::NEG_INFINITY);
        assert_eq!(non_finite(&r).as_deref(), Some(".by_name.b"));
        assert_eq!(non_finite(&f64::NAN).as_deref(), Some("$"));
        // serde_json alone cannot tell them apart.
        assert_eq!(serde_json::to_string(&f64::NAN).unwrap(), "null");
    }
}
