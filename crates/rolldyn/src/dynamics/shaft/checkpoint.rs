//! Bearings on a shaft in a run's checkpoint: each bearing model's own
//! memory (`dynamics::checkpoint`) in the system's order; the shaft has
//! none beyond the integrator's state.

use super::ShaftDynamics;
use crate::integrate::checkpoint::{Checkpoint, CheckpointError, StateReader, StateWriter};

impl Checkpoint for ShaftDynamics {
    fn save(&self, out: &mut StateWriter) {
        out.tag("shaft_dynamics");
        out.u64(self.bearings.len() as u64);
        for b in &self.bearings {
            b.model.save(out);
        }
    }

    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("shaft_dynamics")?;
        let count = input.u64()?;
        if count != self.bearings.len() as u64 {
            return Err(CheckpointError::Mismatch(format!(
                "the checkpoint holds {count} bearings, this system {}",
                self.bearings.len()
            )));
        }
        for b in &mut self.bearings {
            b.model.restore(input)?;
        }
        Ok(())
    }
}
