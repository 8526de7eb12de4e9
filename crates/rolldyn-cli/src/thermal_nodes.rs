//! The bearing thermal network's node temperatures as reported: in °C by
//! node name (`rolldyn thermal`, and a coupled run's summary).

use rolldyn::thermal::bearing::NODES;
use std::collections::BTreeMap;

const KELVIN: f64 = 273.15;

/// Node temperatures in °C by node name.
pub fn temperatures(t: &[f64; 10]) -> BTreeMap<&'static str, f64> {
    NODES.iter().zip(t).map(|(n, v)| (*n, v - KELVIN)).collect()
}
