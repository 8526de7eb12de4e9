//! The end-to-end tests of the `rolldyn` command, one module per subject,
//! in one test binary: one link instead of one per file, and the
//! modules' tests share the test threads.

#![allow(clippy::unwrap_used)]

mod accuracy;
mod catalogue;
mod cli;
mod common;
mod cwru_records;
mod diagnostics;
mod docs;
mod driven;
mod example_tables;
mod examples;
mod fault_matrix;
mod fault_signatures;
mod fuzz;
mod fuzz_findings;
mod input_limits;
mod mounting;
mod outputs;
mod power_thermal;
mod process;
mod quasistatic_design;
mod report_sweep;
mod resume;
mod run_solver;
mod sensor;
mod sets;
mod shaft_systems;
mod surfaces_films;
mod traction;
mod triples;
