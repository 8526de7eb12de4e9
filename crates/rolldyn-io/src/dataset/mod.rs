//! A time series written as it is produced: a Parquet dataset.
//!
//! `DIR/timeseries.parquet` is a directory of part files
//! `part-000000.parquet`, `part-000001.parquet`, … in time order, each a
//! complete Parquet file of one row group (the layout Spark, pyarrow's
//! `dataset`, pandas, polars and DuckDB read as one table). Part `k` holds
//! rows `k·n … (k+1)·n − 1`, `n` = [`part_rows`] of the series' width, so
//! the parts of a run do not depend on when it was checkpointed or
//! interrupted. The rows of the last, growing part are kept in memory and
//! written (atomically, as a provisional part under its final name) at
//! every [`SeriesWriter::sync`]; a checkpoint writes only what is new.
//!
//! A full part is encoded and written on a thread of its own while the
//! run goes on (its compression and its flush to disk would otherwise hold
//! up the integration: docs/performance.md); the next full part,
//! [`SeriesWriter::sync`] and dropping the writer wait for it. So memory
//! is bounded by two parts whatever the run's length, a sync still means
//! on disk, and the bytes are those of a write on the caller's thread.
//!
//! After a kill at any moment every part on disk is whole (each is written
//! to a temporary file and renamed), and the rows up to the last
//! [`SeriesWriter::sync`] read back. [`SeriesWriter::resume`] keeps the
//! first `rows` rows (the ones a checkpoint vouches for) and drops the rest.

use crate::{InputError, OutputError, TimeSeries, write_atomic};
use arrow_array::{Array, ArrayRef, Float32Array, Float64Array, RecordBatch};
use arrow_schema::DataType;
use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use parquet::arrow::{ArrowSchemaConverter, ProjectionMask, add_encoded_arrow_schema_to_metadata};
use parquet::basic::{Compression, ZstdLevel};
use parquet::data_type::{DoubleType, FloatType};
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::thread::JoinHandle;

/// Largest part in memory \[bytes of f64 samples\].
const PART_BYTES: usize = 4 * 1024 * 1024;

/// Rows per part of a series of `width` channels: 4 MiB of samples,
/// between 1 024 and 65 536 rows.
pub fn part_rows(width: usize) -> usize {
    (PART_BYTES / (8 * width.max(1))).clamp(1024, 65_536)
}

/// The file name of part `index`.
fn part_name(index: usize) -> String {
    format!("part-{index:06}.parquet")
}

/// The part files of a dataset directory, in order (by name).
pub fn part_files(dir: &Path) -> Result<Vec<PathBuf>, InputError> {
    let io = |source| InputError::Io {
        path: dir.display().to_string(),
        source,
    };
    let mut parts: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io)?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("part-") && n.ends_with(".parquet"))
        })
        .collect();
    parts.sort();
    Ok(parts)
}

/// Encodes `series` as one Parquet file of one row group (zstd, no
/// dictionary, units in the Arrow field metadata, `metadata` as key–value
/// pairs). The columns are written one after the other, so that one
/// column's encoder and compressor are in memory at a time (the Arrow
/// writer opens all of them at once: ~100 kB each, 35 MB for the default
/// case's 362 channels).
pub(crate) fn encode(
    series: &TimeSeries,
    metadata: &[(String, String)],
    path: &Path,
    float32: bool,
) -> Result<Vec<u8>, OutputError> {
    let encode = |message: String| OutputError::Encode {
        path: path.display().to_string(),
        message,
    };
    let schema = series.schema_of(if float32 {
        DataType::Float32
    } else {
        DataType::Float64
    });
    let kv: Vec<KeyValue> = metadata
        .iter()
        .map(|(k, v)| KeyValue::new(k.clone(), v.clone()))
        .collect();
    let mut props = WriterProperties::builder()
        .set_compression(Compression::ZSTD(ZstdLevel::default()))
        .set_key_value_metadata(Some(kv))
        .set_max_row_group_row_count(Some(series.len().max(1)))
        // Samples rarely repeat: a dictionary per column costs memory and
        // time for nothing (zstd still shrinks constant channels).
        .set_dictionary_enabled(false)
        .build();
    // Readers (pyarrow, the units) see the Arrow schema, as ArrowWriter
    // writes it.
    add_encoded_arrow_schema_to_metadata(&schema, &mut props);
    let descriptor = ArrowSchemaConverter::new()
        .convert(&schema)
        .map_err(|e| encode(e.to_string()))?;
    let mut bytes = Vec::new();
    let mut writer =
        SerializedFileWriter::new(&mut bytes, descriptor.root_schema_ptr(), Arc::new(props))
            .map_err(|e| encode(e.to_string()))?;
    let mut group = writer.next_row_group().map_err(|e| encode(e.to_string()))?;
    for values in &series.columns {
        let mut column = group
            .next_column()
            .map_err(|e| encode(e.to_string()))?
            .ok_or_else(|| encode("fewer columns in the schema than in the series".into()))?;
        if float32 {
            let narrow: Vec<f32> = values.iter().map(|&v| v as f32).collect();
            column
                .typed::<FloatType>()
                .write_batch(&narrow, None, None)
                .map_err(|e| encode(e.to_string()))?;
        } else {
            column
                .typed::<DoubleType>()
                .write_batch(values, None, None)
                .map_err(|e| encode(e.to_string()))?;
        }
        column.close().map_err(|e| encode(e.to_string()))?;
    }
    group.close().map_err(|e| encode(e.to_string()))?;
    writer.close().map_err(|e| encode(e.to_string()))?;
    Ok(bytes)
}

/// A thread writing a part, and what it returns.
type Writing = JoinHandle<Result<(), OutputError>>;

/// Writes a time series part by part into a dataset directory.
#[derive(Debug)]
pub struct SeriesWriter {
    dir: PathBuf,
    /// Rows not yet in a complete part (channels as the series').
    pending: TimeSeries,
    part_rows: usize,
    /// Complete parts written.
    complete: usize,
    metadata: Arc<Vec<(String, String)>>,
    /// Whether the provisional part on disk is behind `pending`.
    dirty: bool,
    /// Samples stored as 32-bit floats.
    float32: bool,
    /// The full part being encoded and written, if any: its rows (whose
    /// room holds the next part's once written) and the writing thread.
    in_flight: Option<(Arc<TimeSeries>, Writing)>,
    /// A series with the channels and room for a part, no rows.
    spare: Option<TimeSeries>,
}

impl SeriesWriter {
    /// Starts a new dataset at `dir` with the channels of `template` (its
    /// rows are ignored): whatever was at `dir` (an older run's dataset, or
    /// a single file of earlier versions) is removed.
    pub fn create(
        dir: &Path,
        template: &TimeSeries,
        metadata: &[(&str, String)],
        float32: bool,
    ) -> Result<Self, OutputError> {
        let io = |source| OutputError::Io {
            path: dir.display().to_string(),
            source,
        };
        if dir.is_dir() {
            std::fs::remove_dir_all(dir).map_err(io)?;
        } else if dir.exists() {
            std::fs::remove_file(dir).map_err(io)?;
        }
        std::fs::create_dir_all(dir).map_err(io)?;
        // An empty first part: the dataset reads (its channels, no rows)
        // from the start, even if the run is killed before any sync.
        let writer = Self::new(dir, template, metadata, float32);
        write_part(
            &writer.pending,
            &writer.metadata,
            &dir.join(part_name(0)),
            float32,
        )?;
        Ok(writer)
    }

    fn new(dir: &Path, template: &TimeSeries, metadata: &[(&str, String)], float32: bool) -> Self {
        let part_rows = part_rows(template.width());
        Self {
            dir: dir.to_path_buf(),
            part_rows,
            pending: empty_like(template, part_rows),
            complete: 0,
            metadata: Arc::new(
                metadata
                    .iter()
                    .map(|(k, v)| (k.to_string(), v.clone()))
                    .collect(),
            ),
            dirty: false,
            float32,
            in_flight: None,
            spare: None,
        }
    }

    /// Continues the dataset at `dir` after its first `rows` rows: later
    /// parts are removed and the rows of the last, partial part are read
    /// back into memory. The channels must be `template`'s.
    pub fn resume(
        dir: &Path,
        template: &TimeSeries,
        metadata: &[(&str, String)],
        rows: u64,
        float32: bool,
    ) -> Result<Self, InputError> {
        let mut writer = Self::new(dir, template, metadata, float32);
        let corrupt = |message: String| InputError::Decode {
            path: dir.display().to_string(),
            message,
        };
        if !dir.is_dir() {
            return Err(corrupt(
                "not a dataset directory of part files (written by an older rolldyn, or removed); start the run again".into(),
            ));
        }
        let n = writer.part_rows as u64;
        let complete = (rows / n) as usize;
        let remainder = (rows % n) as usize;
        let parts = part_files(dir)?;
        for k in 0..complete + usize::from(remainder > 0) {
            let expected = dir.join(part_name(k));
            if parts.get(k) != Some(&expected) {
                return Err(corrupt(format!(
                    "{} is missing: the checkpoint's {rows} rows are not all on disk",
                    expected.display()
                )));
            }
        }
        for part in &parts[..complete] {
            if read_schema(part)?.names() != template.names() {
                return Err(corrupt(format!(
                    "{} holds other channels than this run records",
                    part.display()
                )));
            }
        }
        if remainder > 0 {
            let part = read_parquet(&parts[complete])?;
            if part.names() != template.names() || part.len() < remainder {
                return Err(corrupt(format!(
                    "{} holds {} rows of other channels, not the checkpoint's {remainder}",
                    parts[complete].display(),
                    part.len()
                )));
            }
            let mut part = part;
            part.truncate(remainder);
            writer.pending = empty_like(template, writer.part_rows);
            writer.pending.append(&part);
        }
        for path in parts.iter().skip(complete + usize::from(remainder > 0)) {
            std::fs::remove_file(path).map_err(|source| InputError::Io {
                path: path.display().to_string(),
                source,
            })?;
        }
        writer.complete = complete;
        Ok(writer)
    }

    /// Rows written so far (complete parts and pending rows).
    pub fn rows(&self) -> u64 {
        (self.complete * self.part_rows + self.pending.len()) as u64
    }

    /// Rows per part.
    pub fn part_rows(&self) -> usize {
        self.part_rows
    }

    /// Appends one row (one value per channel, in channel order); a full
    /// part goes to the background to be written, after the one before it
    /// is on disk (whose write error, if any, is returned here).
    pub fn push(&mut self, row: &[f64]) -> Result<(), OutputError> {
        self.pending.push(row);
        self.dirty = true;
        if self.pending.len() >= self.part_rows {
            self.hand_over_full_part()?;
        }
        Ok(())
    }

    /// Makes every row pushed so far readable on disk: waits for the full
    /// part in the background, then writes the pending rows as a
    /// provisional part (rewritten as it grows; at most one part).
    pub fn sync(&mut self) -> Result<(), OutputError> {
        self.wait_in_flight()?;
        if self.dirty {
            let path = self.dir.join(part_name(self.complete));
            write_part(&self.pending, &self.metadata, &path, self.float32)?;
            self.dirty = false;
        }
        Ok(())
    }

    /// Writes the pending rows (a full part) as part `complete` on a
    /// thread of its own (on this one if the system gives no thread); the
    /// writer goes on with the spare rows.
    fn hand_over_full_part(&mut self) -> Result<(), OutputError> {
        self.wait_in_flight()?;
        let spare = match self.spare.take() {
            Some(spare) => spare,
            None => empty_like(&self.pending, self.part_rows),
        };
        let rows = Arc::new(std::mem::replace(&mut self.pending, spare));
        let path = self.dir.join(part_name(self.complete));
        self.complete += 1;
        self.dirty = false;
        let (shared, metadata, float32) = (rows.clone(), self.metadata.clone(), self.float32);
        let target = path.clone();
        let spawned = std::thread::Builder::new()
            .name("rolldyn-parquet".into())
            .spawn(move || write_part(&shared, &metadata, &target, float32));
        match spawned {
            Ok(writing) => self.in_flight = Some((rows, writing)),
            Err(_) => {
                write_part(&rows, &self.metadata, &path, self.float32)?;
                self.keep_spare(rows);
            }
        }
        Ok(())
    }

    /// Waits for the part in the background, if any, and keeps its rows'
    /// room as the spare.
    fn wait_in_flight(&mut self) -> Result<(), OutputError> {
        let Some((rows, writing)) = self.in_flight.take() else {
            return Ok(());
        };
        // The thread has dropped its share of the rows when it returns.
        let written = writing.join();
        self.keep_spare(rows);
        written.unwrap_or_else(|_| {
            Err(OutputError::Encode {
                path: self
                    .dir
                    .join(part_name(self.complete - 1))
                    .display()
                    .to_string(),
                message: "the thread writing this part stopped unexpectedly".into(),
            })
        })
    }

    /// Keeps the room of a written part's rows for the next part.
    fn keep_spare(&mut self, rows: Arc<TimeSeries>) {
        self.spare = Arc::try_unwrap(rows).ok().map(|mut rows| {
            rows.truncate(0);
            rows
        });
    }
}

impl Drop for SeriesWriter {
    /// The part in the background reaches the disk before the writer is
    /// gone (its error, if any, was not asked for: [`SeriesWriter::sync`]
    /// reports it).
    fn drop(&mut self) {
        let _ = self.wait_in_flight();
    }
}

/// Encodes `rows` and writes them atomically as the part at `path`.
fn write_part(
    rows: &TimeSeries,
    metadata: &[(String, String)],
    path: &Path,
    float32: bool,
) -> Result<(), OutputError> {
    write_atomic(path, &encode(rows, metadata, path, float32)?)
}

/// A series with the channels of `template` and no rows, with room for
/// `rows` (the columns do not grow, and fragment the heap, sample by
/// sample).
fn empty_like(template: &TimeSeries, rows: usize) -> TimeSeries {
    let mut series = TimeSeries::default();
    for (name, unit) in template.names().iter().zip(template.units()) {
        series.channel(name.clone(), unit.clone());
    }
    series.reserve(rows);
    series
}

/// The channels (names and units, no rows) of a series file or dataset.
pub fn read_schema(path: &Path) -> Result<TimeSeries, InputError> {
    files(path)?;
    let first = first_file(path)?;
    let builder = open(&first)?;
    schema_series(&first, builder.schema())
}

fn first_file(path: &Path) -> Result<PathBuf, InputError> {
    if path.is_dir() {
        part_files(path)?
            .into_iter()
            .next()
            .ok_or_else(|| InputError::Decode {
                path: path.display().to_string(),
                message: "holds no part file (part-NNNNNN.parquet)".into(),
            })
    } else {
        Ok(path.to_path_buf())
    }
}

fn open(path: &Path) -> Result<ParquetRecordBatchReaderBuilder<std::fs::File>, InputError> {
    let file = std::fs::File::open(path).map_err(|source| InputError::Io {
        path: path.display().to_string(),
        source,
    })?;
    ParquetRecordBatchReaderBuilder::try_new(file).map_err(|e| InputError::Decode {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

fn schema_series(path: &Path, schema: &arrow_schema::Schema) -> Result<TimeSeries, InputError> {
    let mut series = TimeSeries::default();
    for field in schema.fields() {
        if !matches!(field.data_type(), DataType::Float64 | DataType::Float32) {
            return Err(InputError::Decode {
                path: path.display().to_string(),
                message: format!(
                    "column {} is {}, not Float64 or Float32",
                    field.name(),
                    field.data_type()
                ),
            });
        }
        series.channel(
            field.name().clone(),
            field.metadata().get("unit").cloned().unwrap_or_default(),
        );
    }
    Ok(series)
}

/// The files of a series: the file itself, or a dataset's parts, which
/// must run from part 0 without a gap (a missing part would be a silent
/// jump in time).
fn files(path: &Path) -> Result<Vec<PathBuf>, InputError> {
    if !path.is_dir() {
        return Ok(vec![path.to_path_buf()]);
    }
    let parts = part_files(path)?;
    for (k, part) in parts.iter().enumerate() {
        let expected = path.join(part_name(k));
        if *part != expected {
            return Err(InputError::Decode {
                path: path.display().to_string(),
                message: format!(
                    "{} is missing (the parts must run from part-000000 without a gap)",
                    part_name(k)
                ),
            });
        }
    }
    Ok(parts)
}

/// Rows of the series at `path` (a file or a dataset directory), from
/// the files' footers.
pub fn row_count(path: &Path) -> Result<u64, InputError> {
    let mut rows = 0;
    for file in files(path)? {
        rows += open(&file)?.metadata().file_metadata().num_rows() as u64;
    }
    Ok(rows)
}

/// Calls `f` with each record batch of the series at `path` (a file or a
/// dataset directory), in order, holding one batch in memory; `columns`
/// selects channels by name (None: all), which come in the file's order
/// (the returned schema's). Every part must have the first part's
/// channels.
pub fn for_each_batch(
    path: &Path,
    columns: Option<&[&str]>,
    mut f: impl FnMut(&RecordBatch) -> Result<(), InputError>,
) -> Result<TimeSeries, InputError> {
    let decode = |p: &Path, message: String| InputError::Decode {
        path: p.display().to_string(),
        message,
    };
    let all = read_schema(path)?;
    let mut selected: Vec<usize> = match columns {
        None => (0..all.width()).collect(),
        Some(names) => names
            .iter()
            .map(|n| {
                all.names()
                    .iter()
                    .position(|m| m == n)
                    .ok_or_else(|| decode(path, format!("has no channel {n}")))
            })
            .collect::<Result<_, _>>()?,
    };
    // A projection yields its columns in the file's order, whatever order
    // they were asked in: the schema names them so.
    selected.sort_unstable();
    selected.dedup();
    let mut schema = TimeSeries::default();
    for &i in &selected {
        schema.channel(all.names()[i].clone(), all.units()[i].clone());
    }
    for file in files(path)? {
        let builder = open(&file)?;
        let names: Vec<&String> = builder.schema().fields().iter().map(|f| f.name()).collect();
        if names.len() != all.width() || names.iter().zip(all.names()).any(|(a, b)| *a != b) {
            return Err(decode(
                &file,
                "holds other channels than the first part".into(),
            ));
        }
        let mask = ProjectionMask::roots(builder.parquet_schema(), selected.iter().copied());
        let reader = builder
            .with_projection(mask)
            .build()
            .map_err(|e| decode(&file, e.to_string()))?;
        for batch in reader {
            let batch = widened(batch.map_err(|e| decode(&file, e.to_string()))?)
                .map_err(|e| decode(&file, e))?;
            f(&batch)?;
        }
    }
    Ok(schema)
}

/// A batch with its Float32 columns (`output.precision = "float32"`)
/// widened to Float64, the type every reader sees.
fn widened(batch: RecordBatch) -> Result<RecordBatch, String> {
    if !batch
        .columns()
        .iter()
        .any(|c| c.data_type() == &DataType::Float32)
    {
        return Ok(batch);
    }
    let mut fields = Vec::with_capacity(batch.num_columns());
    let mut columns: Vec<ArrayRef> = Vec::with_capacity(batch.num_columns());
    for (field, column) in batch.schema().fields().iter().zip(batch.columns()) {
        match column.as_any().downcast_ref::<Float32Array>() {
            Some(narrow) => {
                let wide: Float64Array = narrow
                    .values()
                    .iter()
                    .map(|&v| Some(f64::from(v)))
                    .collect();
                fields.push(field.as_ref().clone().with_data_type(DataType::Float64));
                columns.push(Arc::new(wide));
            }
            None => {
                fields.push(field.as_ref().clone());
                columns.push(column.clone());
            }
        }
    }
    RecordBatch::try_new(Arc::new(arrow_schema::Schema::new(fields)), columns)
        .map_err(|e| e.to_string())
}

/// The float columns of a batch.
pub fn float_columns(batch: &RecordBatch) -> Result<Vec<&[f64]>, InputError> {
    batch
        .columns()
        .iter()
        .enumerate()
        .map(|(i, c)| {
            c.as_any()
                .downcast_ref::<Float64Array>()
                .map(|a| a.values().as_ref())
                .ok_or_else(|| InputError::Decode {
                    path: String::new(),
                    message: format!("column {i} is not Float64"),
                })
        })
        .collect()
}

/// Reads the series at `path` (a file or a dataset directory) whole, or
/// only the `columns` named.
pub fn read_columns(path: &Path, columns: Option<&[&str]>) -> Result<TimeSeries, InputError> {
    let mut data: Vec<Vec<f64>> = Vec::new();
    let schema = for_each_batch(path, columns, |batch| {
        let cols = float_columns(batch)?;
        data.resize(cols.len(), Vec::new());
        for (d, c) in data.iter_mut().zip(cols) {
            d.extend_from_slice(c);
        }
        Ok(())
    })?;
    let mut series = schema;
    series.set_columns(data);
    Ok(series)
}

/// Reads a whole series: a Parquet file written by [`crate::write_parquet`]
/// or a dataset of [`SeriesWriter`]. Every column must be Float64; units
/// from the field metadata ("" when absent).
pub fn read_parquet(path: &Path) -> Result<TimeSeries, InputError> {
    read_columns(path, None)
}

/// Calls `f` with each of the first `rows` rows of the series at `path`
/// (all rows when None), in order, one batch in memory.
pub fn for_each_row(
    path: &Path,
    rows: Option<u64>,
    mut f: impl FnMut(&[f64]),
) -> Result<u64, InputError> {
    let mut seen = 0u64;
    let mut row = Vec::new();
    for_each_batch(path, None, |batch| {
        let cols = float_columns(batch)?;
        for r in 0..batch.num_rows() {
            if rows.is_some_and(|n| seen >= n) {
                return Ok(());
            }
            row.clear();
            row.extend(cols.iter().map(|c| c[r]));
            f(&row);
            seen += 1;
        }
        Ok(())
    })?;
    Ok(seen)
}

#[cfg(test)]
mod tests;
