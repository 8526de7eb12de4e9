//! # rolldyn-io — result files
//!
//! * [`TimeSeries`]: named channels of f64 samples, each with its unit.
//! * [`write_parquet`]: a time series as a Parquet file (zstd). Each column
//!   carries its unit in the field metadata (`unit`), and the file carries
//!   key–value metadata (rolldyn version, case). pandas, polars and
//!   pyarrow read it.
//! * [`SeriesWriter`]: a run's time series written as it is produced, a
//!   Parquet dataset of part files (`dataset`'s module doc has the layout).
//! * [`read_parquet`], [`read_columns`], [`for_each_batch`],
//!   [`for_each_row`]: a file or dataset back, whole, by columns or
//!   streamed (the post-processing commands, e.g. `rolldyn spectrum`).
//! * [`RunDir`]: a run directory's files by name (`run_dir`'s module doc
//!   has the layout).
//! * [`write_atomic`]: any bytes, written to a temporary file in the same
//!   directory and renamed, so a reader never sees a half-written result.

use arrow_array::{ArrayRef, Float64Array, RecordBatch};
use arrow_schema::{DataType, Field, Schema};
mod dataset;
mod run_dir;

pub use dataset::{
    SeriesWriter, float_columns, for_each_batch, for_each_row, part_files, part_rows, read_columns,
    read_parquet, read_schema, row_count,
};
pub use run_dir::RunDir;
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

/// Errors of result writing.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// File system.
    #[error("cannot write {path}: {source}")]
    Io {
        /// File.
        path: String,
        /// Cause.
        source: std::io::Error,
    },
    /// Parquet/Arrow encoding.
    #[error("cannot encode {path}: {message}")]
    Encode {
        /// File.
        path: String,
        /// Cause.
        message: String,
    },
}

/// Errors of result reading.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    /// File system.
    #[error("cannot read {path}: {source}")]
    Io {
        /// File.
        path: String,
        /// Cause.
        source: std::io::Error,
    },
    /// Not a rolldyn time series.
    #[error("{path} is not a rolldyn time series: {message}")]
    Decode {
        /// File.
        path: String,
        /// Cause.
        message: String,
    },
}

/// Named channels of samples, all of the same length.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TimeSeries {
    names: Vec<String>,
    units: Vec<String>,
    columns: Vec<Vec<f64>>,
}

impl TimeSeries {
    /// Adds a channel (before any sample is pushed); returns its index.
    pub fn channel(&mut self, name: impl Into<String>, unit: impl Into<String>) -> usize {
        self.names.push(name.into());
        self.units.push(unit.into());
        self.columns.push(Vec::new());
        self.names.len() - 1
    }

    /// Unit of a channel.
    pub fn unit(&self, name: &str) -> Option<&str> {
        let i = self.names.iter().position(|n| n == name)?;
        Some(&self.units[i])
    }

    /// Number of channels.
    pub fn width(&self) -> usize {
        self.names.len()
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Appends one sample: one value per channel, in channel order.
    pub fn push(&mut self, row: &[f64]) {
        for (c, v) in self.columns.iter_mut().zip(row) {
            c.push(*v);
        }
    }

    /// Replaces the samples (one vector per channel, in channel order, of
    /// equal lengths).
    pub(crate) fn set_columns(&mut self, columns: Vec<Vec<f64>>) {
        self.columns = columns;
        self.columns.resize(self.names.len(), Vec::new());
    }

    /// Reserves room for `rows` more samples in every channel.
    pub fn reserve(&mut self, rows: usize) {
        for c in &mut self.columns {
            c.reserve_exact(rows);
        }
    }

    /// Appends the samples of `other` (same channels, in order).
    pub fn append(&mut self, other: &TimeSeries) {
        for (c, o) in self.columns.iter_mut().zip(&other.columns) {
            c.extend_from_slice(o);
        }
    }

    /// Keeps the first `rows` samples (a resumed run drops what was
    /// recorded after its checkpoint).
    pub fn truncate(&mut self, rows: usize) {
        for c in &mut self.columns {
            c.truncate(rows);
        }
    }

    /// Channel units, in channel order.
    pub fn units(&self) -> &[String] {
        &self.units
    }

    /// Channel names.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The samples of a channel by name.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.names
            .iter()
            .position(|n| n == name)
            .map(|i| self.columns[i].as_slice())
    }

    /// The Arrow schema: one non-null Float64 field per channel, its unit
    /// in the field metadata (`unit`).
    pub fn schema(&self) -> Arc<Schema> {
        self.schema_of(DataType::Float64)
    }

    /// The Arrow schema with fields of `data_type` (Float64 or Float32).
    pub fn schema_of(&self, data_type: DataType) -> Arc<Schema> {
        let fields: Vec<Field> = self
            .names
            .iter()
            .zip(&self.units)
            .map(|(n, u)| {
                Field::new(n, data_type.clone(), false)
                    .with_metadata(HashMap::from([("unit".to_string(), u.clone())]))
            })
            .collect();
        Arc::new(Schema::new(fields))
    }

    /// The series as one Arrow record batch; the columns are moved into
    /// the arrays, not copied.
    pub fn into_record_batch(self) -> Result<RecordBatch, arrow_schema::ArrowError> {
        let schema = self.schema();
        let columns: Vec<ArrayRef> = self
            .columns
            .into_iter()
            .map(|c| Arc::new(Float64Array::from(c)) as ArrayRef)
            .collect();
        RecordBatch::try_new(schema, columns)
    }
}

/// Writes `bytes` to `path` atomically: a temporary file in the same
/// directory, flushed to the disk, then renamed over `path` (and the
/// directory flushed), so that a reader, a killed process or a power
/// loss leaves either the old file or the new one, never a part.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    use std::io::Write;
    let io = |source| OutputError::Io {
        path: path.display().to_string(),
        source,
    };
    let tmp = path.with_file_name(format!(
        ".{}.tmp",
        path.file_name()
            .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned())
    ));
    let written = (|| {
        let mut file = std::fs::File::create(&tmp)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        drop(file);
        std::fs::rename(&tmp, path)
    })();
    if let Err(source) = written {
        // Nothing of a failed write stays behind (the target a directory,
        // the disk full, …).
        let _ = std::fs::remove_file(&tmp);
        return Err(io(source));
    }
    // The rename itself reaches the disk with the directory (best effort:
    // not every platform opens directories).
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if let Ok(d) = std::fs::File::open(dir) {
            let _ = d.sync_all();
        }
    }
    Ok(())
}

/// Writes `series` as one Parquet file (one row group, as a part of a
/// [`SeriesWriter`] dataset) to `path` atomically, with file metadata.
pub fn write_parquet(
    path: &Path,
    series: &TimeSeries,
    metadata: &[(&str, String)],
) -> Result<(), OutputError> {
    let metadata: Vec<(String, String)> = metadata
        .iter()
        .map(|(k, v)| (k.to_string(), v.clone()))
        .collect();
    write_atomic(path, &dataset::encode(series, &metadata, path, false)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;

    #[test]
    fn parquet_round_trip_with_units() {
        let mut ts = TimeSeries::default();
        ts.channel("time_s", "s");
        ts.channel("cage_speed_rpm", "rpm");
        for i in 0..100 {
            ts.push(&[i as f64 * 1e-3, 4400.0 + i as f64]);
        }
        let dir = std::env::temp_dir().join(format!("rolldyn-io-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("series.parquet");
        write_parquet(&path, &ts, &[("case", "test".into())]).unwrap();
        let file = std::fs::File::open(&path).unwrap();
        let builder = ParquetRecordBatchReaderBuilder::try_new(file).unwrap();
        let schema = builder.schema().clone();
        assert_eq!(schema.field(1).name(), "cage_speed_rpm");
        assert_eq!(
            schema.field(1).metadata().get("unit").map(String::as_str),
            Some("rpm")
        );
        let kv = builder
            .metadata()
            .file_metadata()
            .key_value_metadata()
            .cloned()
            .unwrap_or_default();
        assert!(
            kv.iter()
                .any(|k| k.key == "case" && k.value.as_deref() == Some("test"))
        );
        let batch = builder.build().unwrap().next().unwrap().unwrap();
        assert_eq!(batch.num_rows(), 100);
        let col = batch
            .column(1)
            .as_any()
            .downcast_ref::<Float64Array>()
            .unwrap();
        assert_eq!(col.value(99), 4499.0);
        let back = read_parquet(&path).unwrap();
        assert_eq!(back, ts);
        assert_eq!(back.unit("cage_speed_rpm"), Some("rpm"));
        assert!(matches!(
            read_parquet(&dir.join("missing.parquet")),
            Err(InputError::Io { .. })
        ));
        assert!(!dir.join(".series.parquet.tmp").exists());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_failed_write_leaves_nothing_behind() {
        let dir = std::env::temp_dir().join(format!("rolldyn-io-fail-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("taken")).unwrap();
        // The target is a directory: the rename fails.
        let err = write_atomic(&dir.join("taken"), b"x")
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with("cannot write ") && err.contains("taken"),
            "{err}"
        );
        assert_eq!(err.matches("cannot write").count(), 1, "{err}");
        assert!(!dir.join(".taken.tmp").exists());
        std::fs::remove_dir_all(&dir).ok();
    }
}
