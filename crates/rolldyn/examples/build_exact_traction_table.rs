//! Builds the exact-theory traction table embedded in the library
//! (`rolldyn::traction::table`) and writes it to
//! `crates/rolldyn/data/exact_traction_table.bin`, or to the path given:
//!
//! ```text
//! cargo run --release -p rolldyn --example build_exact_traction_table [OUT]
//! ```
//!
//! About 24 minutes on two cores; the result does not depend on the
//! thread count.

use rolldyn::traction::table::{build, layout::Layout};

/// The embedded table's grid.
const LAYOUT: Layout = Layout::EMBEDDED;

/// Poisson ratio of the table's shape.
const POISSON_RATIO: f64 = 0.28;

/// Cells per direction of the finer exact grid.
const CELLS: usize = 32;

fn main() -> std::io::Result<()> {
    let out = std::env::args().nth(1).unwrap_or_else(|| {
        concat!(env!("CARGO_MANIFEST_DIR"), "/data/exact_traction_table.bin").to_string()
    });
    let start = std::time::Instant::now();
    let table = build::build(LAYOUT, POISSON_RATIO, CELLS);
    let tmp = format!("{out}.tmp");
    std::fs::write(&tmp, table.to_bytes())?;
    std::fs::rename(&tmp, &out)?;
    eprintln!(
        "{} nodes written to {out} in {:.0} s",
        LAYOUT.nodes(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
