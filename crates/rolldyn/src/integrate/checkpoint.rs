//! Checkpoints: the complete state of an integration (integrator and
//! system) as bytes, so that an interrupted run continues bit-identically
//!.
//!
//! The format is a flat little-endian record: every `f64` is stored as its
//! bit pattern (`to_bits`), so nothing is rounded through text. A
//! checkpoint starts with a tag per part and a length check, so restoring
//! into a differently shaped integrator or system (another case, another
//! ball count) fails with [`CheckpointError`] instead of silently mixing
//! states.
//!
//! What is saved is what a step reads and cannot recompute: the state and
//! its derivative at the current point (FSAL), the step size and the PI
//! controller's memory, the last step (dense output), the Jacobian and its
//! age (Rosenbrock: the factorization is rebuilt from it, which gives the
//! same bits), the counters, and the system's own memory
//! ([`Checkpoint`] for the bearing model: contact episodes and the
//! coupled thermal network). Work vectors are not saved.

/// Why a checkpoint could not be restored.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CheckpointError {
    /// The bytes end early.
    #[error("checkpoint is truncated (needed {needed} more bytes at offset {offset})")]
    Truncated {
        /// Where reading stopped.
        offset: usize,
        /// Bytes missing.
        needed: usize,
    },
    /// A part does not match what is being restored.
    #[error("checkpoint does not match this run: {0}")]
    Mismatch(String),
}

/// Appends values to a checkpoint.
#[derive(Debug, Default, Clone)]
pub struct StateWriter {
    bytes: Vec<u8>,
}

impl StateWriter {
    /// An empty record.
    pub fn new() -> Self {
        Self::default()
    }

    /// The bytes written so far.
    pub fn into_bytes(self) -> Vec<u8> {
        self.bytes
    }

    /// A tag naming the next part (checked on reading).
    pub fn tag(&mut self, tag: &str) {
        self.u64(tag.len() as u64);
        self.bytes.extend_from_slice(tag.as_bytes());
    }

    /// An unsigned integer.
    pub fn u64(&mut self, v: u64) {
        self.bytes.extend_from_slice(&v.to_le_bytes());
    }

    /// A float, bit for bit.
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }

    /// An optional float.
    pub fn opt_f64(&mut self, v: Option<f64>) {
        match v {
            Some(x) => {
                self.u64(1);
                self.f64(x);
            }
            None => self.u64(0),
        }
    }

    /// A slice of floats with its length.
    pub fn f64s(&mut self, v: &[f64]) {
        self.u64(v.len() as u64);
        for x in v {
            self.f64(*x);
        }
    }
}

/// Reads values back in the order they were written.
#[derive(Debug, Clone)]
pub struct StateReader<'a> {
    bytes: &'a [u8],
    offset: usize,
}

impl<'a> StateReader<'a> {
    /// Reads `bytes` from the start.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes, offset: 0 }
    }

    /// Whether every byte was read.
    pub fn is_done(&self) -> bool {
        self.offset == self.bytes.len()
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], CheckpointError> {
        let end = self
            .offset
            .checked_add(n)
            .filter(|&e| e <= self.bytes.len());
        let Some(end) = end else {
            return Err(CheckpointError::Truncated {
                offset: self.offset,
                needed: n.saturating_sub(self.bytes.len() - self.offset),
            });
        };
        let out = &self.bytes[self.offset..end];
        self.offset = end;
        Ok(out)
    }

    /// Checks that the next part carries `tag`.
    pub fn tag(&mut self, tag: &str) -> Result<(), CheckpointError> {
        let len = self.u64()?;
        if len != tag.len() as u64 {
            return Err(CheckpointError::Mismatch(format!("expected part {tag:?}")));
        }
        let found = self.take(tag.len())?;
        if found != tag.as_bytes() {
            return Err(CheckpointError::Mismatch(format!(
                "expected part {tag:?}, found {:?}",
                String::from_utf8_lossy(found)
            )));
        }
        Ok(())
    }

    /// An unsigned integer.
    pub fn u64(&mut self) -> Result<u64, CheckpointError> {
        let b = self.take(8)?;
        let mut a = [0u8; 8];
        a.copy_from_slice(b);
        Ok(u64::from_le_bytes(a))
    }

    /// A float.
    pub fn f64(&mut self) -> Result<f64, CheckpointError> {
        Ok(f64::from_bits(self.u64()?))
    }

    /// An optional float.
    pub fn opt_f64(&mut self) -> Result<Option<f64>, CheckpointError> {
        match self.u64()? {
            0 => Ok(None),
            1 => Ok(Some(self.f64()?)),
            other => Err(CheckpointError::Mismatch(format!(
                "bad option flag {other}"
            ))),
        }
    }

    /// Floats into `out`, whose length must match the stored one.
    pub fn f64s_into(&mut self, what: &str, out: &mut [f64]) -> Result<(), CheckpointError> {
        let len = self.u64()?;
        if len != out.len() as u64 {
            return Err(CheckpointError::Mismatch(format!(
                "{what} has {len} values, this run {}",
                out.len()
            )));
        }
        for x in out.iter_mut() {
            *x = self.f64()?;
        }
        Ok(())
    }
}

/// Names of the solution vectors every adaptive integrator keeps, in the
/// order [`save_step`] writes them.
const STEP_VECTORS: [&str; 4] = ["y", "f", "y_prev", "f_prev"];

/// Writes the step state the adaptive integrators share: t, h, t_prev,
/// h_prev, then y, f, y_prev, f_prev.
pub(crate) fn save_step(out: &mut StateWriter, times: [f64; 4], vectors: [&[f64]; 4]) {
    for v in times {
        out.f64(v);
    }
    for v in vectors {
        out.f64s(v);
    }
}

/// Reads what [`save_step`] wrote into the integrator's fields.
pub(crate) fn restore_step(
    input: &mut StateReader,
    times: [&mut f64; 4],
    vectors: [&mut [f64]; 4],
) -> Result<(), CheckpointError> {
    for t in times {
        *t = input.f64()?;
    }
    for (name, v) in STEP_VECTORS.into_iter().zip(vectors) {
        input.f64s_into(name, v)?;
    }
    Ok(())
}

/// A part of a run whose state a checkpoint carries.
pub trait Checkpoint {
    /// Appends the state.
    fn save(&self, out: &mut StateWriter);
    /// Restores the state saved by [`Checkpoint::save`] on an object built
    /// the same way (same case, same settings).
    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError>;
}

impl Checkpoint for super::IntegrationStats {
    fn save(&self, out: &mut StateWriter) {
        out.tag("stats");
        for v in [
            self.steps,
            self.rejected_steps,
            self.rhs_evaluations,
            self.jacobian_evaluations,
            self.jacobian_rhs_evaluations,
            self.factorizations,
            self.fast_part_jacobians,
        ] {
            out.u64(v);
        }
    }

    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("stats")?;
        self.steps = input.u64()?;
        self.rejected_steps = input.u64()?;
        self.rhs_evaluations = input.u64()?;
        self.jacobian_evaluations = input.u64()?;
        self.jacobian_rhs_evaluations = input.u64()?;
        self.factorizations = input.u64()?;
        self.fast_part_jacobians = input.u64()?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_bit_for_bit() {
        let mut w = StateWriter::new();
        w.tag("part");
        w.f64(-0.0);
        w.f64(f64::MIN_POSITIVE / 3.0);
        w.opt_f64(None);
        w.opt_f64(Some(0.1 + 0.2));
        w.f64s(&[1.0, f64::NAN, 3.0]);
        let bytes = w.into_bytes();
        let mut r = StateReader::new(&bytes);
        r.tag("part").unwrap();
        assert_eq!(r.f64().unwrap().to_bits(), (-0.0f64).to_bits());
        assert_eq!(r.f64().unwrap(), f64::MIN_POSITIVE / 3.0);
        assert_eq!(r.opt_f64().unwrap(), None);
        assert_eq!(r.opt_f64().unwrap(), Some(0.1 + 0.2));
        let mut v = [0.0; 3];
        r.f64s_into("v", &mut v).unwrap();
        assert!(v[1].is_nan() && v[2] == 3.0);
        assert!(r.is_done());
    }

    #[test]
    fn mismatches_and_truncation_are_errors() {
        let mut w = StateWriter::new();
        w.tag("a");
        w.f64s(&[1.0, 2.0]);
        let bytes = w.into_bytes();
        assert!(matches!(
            StateReader::new(&bytes).tag("b"),
            Err(CheckpointError::Mismatch(_))
        ));
        let mut r = StateReader::new(&bytes);
        r.tag("a").unwrap();
        let mut three = [0.0; 3];
        assert!(matches!(
            r.f64s_into("v", &mut three),
            Err(CheckpointError::Mismatch(_))
        ));
        let mut r = StateReader::new(&bytes[..bytes.len() - 3]);
        r.tag("a").unwrap();
        let mut two = [0.0; 2];
        assert!(matches!(
            r.f64s_into("v", &mut two),
            Err(CheckpointError::Truncated { .. })
        ));
    }
}
