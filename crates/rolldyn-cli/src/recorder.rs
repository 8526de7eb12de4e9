//! The recorder of `rolldyn run`: the channels of a sample (names, units,
//! the order a row is written in; docs/cli.md lists them), one row per
//! sample from the model's state, and where the row goes: into the
//! summary's statistics whole ([`crate::run_stats`]) and into the time
//! series' writer with the channels the case records
//! ([`crate::channel_groups`]).

use crate::run_stats::RunStatistics;
use rolldyn::dynamics::{BearingModel, ContactSample};
use rolldyn::traction::TractionModel;
use rolldyn_io::{OutputError, SeriesWriter, TimeSeries};

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Per-ball channels (name suffix, unit), in the order `record` writes them.
const BALL_CHANNELS: [(&str, &str); 14] = [
    ("azimuth_rad", "rad"),
    ("orbital_speed_rpm", "rpm"),
    ("load_inner_n", "N"),
    ("load_outer_n", "N"),
    ("contact_angle_inner_deg", "deg"),
    ("contact_angle_outer_deg", "deg"),
    ("slide_to_roll_inner", "1"),
    ("slide_to_roll_outer", "1"),
    ("spin_to_roll_inner", "1"),
    ("spin_to_roll_outer", "1"),
    ("film_inner_m", "m"),
    ("film_outer_m", "m"),
    ("attitude_deg", "deg"),
    ("yaw_deg", "deg"),
];

/// Per-ball FASTSIM channels (name suffix, unit), after [`BALL_CHANNELS`]
/// when the traction model is FASTSIM.
const CREEP_CHANNELS: [(&str, &str); 8] = [
    ("creepage_longitudinal_inner", "1"),
    ("creepage_longitudinal_outer", "1"),
    ("creepage_lateral_inner", "1"),
    ("creepage_lateral_outer", "1"),
    ("creepage_spin_inner_1_m", "1/m"),
    ("creepage_spin_outer_1_m", "1/m"),
    ("stick_fraction_inner", "1"),
    ("stick_fraction_outer", "1"),
];

/// The channels recorded at the slow rate, into their own dataset.
pub(crate) struct SlowChannels {
    /// Their names and units (`time_s` first).
    pub(crate) recorded: TimeSeries,
    /// Their indices in a row.
    selected: Vec<usize>,
    /// Scratch row.
    projected: Vec<f64>,
    /// One sample in `every` is recorded (the first one included).
    pub(crate) every: u64,
    pub(crate) writer: Option<SeriesWriter>,
}

impl SlowChannels {
    /// Rows of the slow dataset when the main one has `rows`.
    pub(crate) fn rows_for(&self, rows: u64) -> u64 {
        rows.div_ceil(self.every)
    }
}

/// The channels of `series` that `keep` names, as a series and indices.
fn subset(series: &TimeSeries, keep: impl Fn(&str) -> bool) -> (TimeSeries, Vec<usize>) {
    let selected: Vec<usize> = (0..series.width())
        .filter(|&i| keep(&series.names()[i]))
        .collect();
    let mut recorded = TimeSeries::default();
    for &i in &selected {
        recorded.channel(series.names()[i].clone(), series.units()[i].clone());
    }
    (recorded, selected)
}

/// Channel layout of the recorder, and where its rows go: the writer of
/// the time series and the summary's statistics.
pub(crate) struct Channels {
    /// The channels' names and units (no rows).
    pub(crate) series: TimeSeries,
    /// The recorded ones (`output.channels`, `output.balls`).
    pub(crate) recorded: TimeSeries,
    /// Their indices in a row (None: every channel is recorded).
    selected: Option<Vec<usize>>,
    /// Scratch row of the recorded channels.
    projected: Vec<f64>,
    pub(crate) stats: RunStatistics,
    pub(crate) writer: Option<SeriesWriter>,
    /// The first failure to write a part (the run then stops).
    pub(crate) write_error: Option<OutputError>,
    /// The channels recorded at the slow rate (`output.slow_channels`).
    pub(crate) slow: Option<SlowChannels>,
    balls: usize,
    /// Whether the FASTSIM channels are recorded.
    creep: bool,
    /// Whether the per-ball power channels are recorded.
    power_per_ball: bool,
    /// Whether the per-ball asperity shares are recorded (mixed lubrication).
    mixed: bool,
    /// Whether the sensor's channels are recorded (`[sensor]`).
    sensor: bool,
    /// Growing spalls (their lengths are recorded).
    growing_spalls: usize,
    /// Scratch derivative vector (accelerations of the rings).
    derivative: Vec<f64>,
}

/// The sensor's channels (`[sensor]`, docs/signal.md): the acquired
/// acceleration and the housing's true acceleration at the sensor.
pub(crate) const SENSOR_CHANNELS: [&str; 2] = [
    "sensor_acceleration_m_s2",
    "sensor_housing_acceleration_m_s2",
];

/// Where the summary times the balls' passages: the radial load's
/// direction in the (y, z) plane, the centre of a stationary load zone
/// \[rad\]; 6 o'clock (−z, the presets' gravity) without a radial load.
fn passage_azimuth(loads: &rolldyn::operating::Loads) -> f64 {
    let [_, y, z] = loads.force;
    if y == 0.0 && z == 0.0 {
        -std::f64::consts::FRAC_PI_2
    } else {
        z.atan2(y)
    }
}

/// The channels of every run, in the time series' order (the power
/// channels, sensor, spalls and balls follow): time, the rings', cage's and
/// housing's motion, pocket and peak loads, the energy accumulators.
const RUN_CHANNELS: [(&str, &str); 36] = [
    ("time_s", "s"),
    ("inner_ring_speed_rpm", "rpm"),
    ("cage_angle_rad", "rad"),
    ("cage_speed_rpm", "rpm"),
    ("cage_y_m", "m"),
    ("cage_z_m", "m"),
    ("inner_ring_x_m", "m"),
    ("inner_ring_y_m", "m"),
    ("inner_ring_z_m", "m"),
    ("inner_ring_tilt_y_rad", "rad"),
    ("inner_ring_tilt_z_rad", "rad"),
    ("inner_ring_velocity_y_m_s", "m/s"),
    ("inner_ring_velocity_z_m_s", "m/s"),
    ("outer_ring_y_m", "m"),
    ("outer_ring_z_m", "m"),
    ("inner_ring_velocity_x_m_s", "m/s"),
    ("inner_ring_acceleration_x_m_s2", "m/s^2"),
    ("inner_ring_acceleration_y_m_s2", "m/s^2"),
    ("inner_ring_acceleration_z_m_s2", "m/s^2"),
    ("outer_ring_velocity_y_m_s", "m/s"),
    ("outer_ring_velocity_z_m_s", "m/s"),
    ("outer_ring_acceleration_y_m_s2", "m/s^2"),
    ("outer_ring_acceleration_z_m_s2", "m/s^2"),
    ("housing_force_y_n", "N"),
    ("housing_force_z_n", "N"),
    ("cage_velocity_y_m_s", "m/s"),
    ("cage_velocity_z_m_s", "m/s"),
    ("pocket_force_sum_n", "N"),
    ("pocket_force_max_n", "N"),
    ("peak_load_inner_n", "N"),
    ("peak_load_outer_n", "N"),
    ("drive_work_j", "J"),
    ("dissipated_energy_j", "J"),
    ("mechanical_energy_j", "J"),
    ("film_work_j", "J"),
    ("pure_rolling_cage_speed_ratio", "1"),
];

impl Channels {
    /// The channels of `model`'s run (`power_per_ball`: the case's
    /// per-ball power channels) over `duration` at `sample_rate`, recorded
    /// as `selection` says.
    pub(crate) fn new(
        model: &BearingModel,
        power_per_ball: bool,
        [duration, sample_rate]: [f64; 2],
        selection: &rolldyn_case::case::OutputSelection,
    ) -> Self {
        let params = model.parameters();
        let balls = model.layout().balls;
        let creep = matches!(
            params.traction,
            TractionModel::Fastsim(_) | TractionModel::ExactTable(_)
        );
        let thermal = model.thermal().is_some();
        let mixed = params.mixed_lubrication.is_some();
        let sensor = model.sensor().is_some();
        let growing_spalls = model.growing_spall_lengths().count();
        let states = model.layout().len();
        let mut series = TimeSeries::default();
        for (name, unit) in RUN_CHANNELS {
            series.channel(name, unit);
        }
        crate::power_channels::add_channels(&mut series, thermal);
        if sensor {
            for name in SENSOR_CHANNELS {
                series.channel(name, "m/s^2");
            }
        }
        for k in 0..growing_spalls {
            series.channel(format!("spall{k}_length_m"), "m");
        }
        for j in 0..balls {
            for (name, unit) in BALL_CHANNELS {
                series.channel(format!("ball{j}_{name}"), unit);
            }
            if creep {
                for (name, unit) in CREEP_CHANNELS {
                    series.channel(format!("ball{j}_{name}"), unit);
                }
            }
            if power_per_ball {
                series.channel(format!("ball{j}_power_inner_w"), "W");
                series.channel(format!("ball{j}_power_outer_w"), "W");
            }
            if mixed {
                series.channel(format!("ball{j}_asperity_share_inner"), "1");
                series.channel(format!("ball{j}_asperity_share_outer"), "1");
            }
        }
        let recorded_at = |slow: bool| {
            subset(&series, |name| {
                crate::channel_groups::recorded(selection, name, slow)
            })
        };
        let (recorded, selected) = recorded_at(false);
        let slow = selection.slow.as_ref().map(|(_, rate)| {
            let (recorded, selected) = recorded_at(true);
            SlowChannels {
                projected: Vec::with_capacity(selected.len()),
                recorded,
                selected,
                every: (sample_rate / rate).round().max(1.0) as u64,
                writer: None,
            }
        });
        Self {
            slow,
            stats: RunStatistics::new(
                &series,
                duration,
                sample_rate,
                passage_azimuth(&params.loads.at(duration)),
            ),
            projected: Vec::with_capacity(selected.len()),
            selected: (selected.len() < series.width()).then_some(selected),
            recorded,
            series,
            writer: None,
            write_error: None,
            balls,
            creep,
            power_per_ball,
            mixed,
            sensor,
            growing_spalls,
            derivative: vec![0.0; states],
        }
    }

    pub(crate) fn record(
        &mut self,
        model: &BearingModel,
        t: f64,
        y: &[f64],
        row: &mut Vec<f64>,
        contacts: &mut [ContactSample],
    ) {
        self.fill(model, t, y, row, contacts);
        self.sink(row);
    }

    /// The derivative of the last filled row's state (its rings'
    /// accelerations).
    pub(crate) fn derivative(&self) -> &[f64] {
        &self.derivative
    }

    /// A sample's row of every channel, not yet recorded ([`Self::sink`]).
    pub(crate) fn fill(
        &mut self,
        model: &BearingModel,
        t: f64,
        y: &[f64],
        row: &mut Vec<f64>,
        contacts: &mut [ContactSample],
    ) {
        let l = model.layout();
        let (c, r) = (l.cage(), l.ring());
        let (drive, dissipated) = model.work(y);
        // Accelerations, the dissipated power by component and the
        // contacts: one evaluation of the equations of motion per sample.
        let power = model.rhs_with_samples(t, y, &mut self.derivative, contacts);
        let dy = &self.derivative;
        let o = l.outer();
        let housing = model.support_force(y).unwrap_or_default();
        let (pocket_sum, pocket_max) = model.pocket_forces(y);
        let [peak_inner, peak_outer] = model.take_peak_loads();
        row.clear();
        row.extend_from_slice(&[
            t,
            model.inner_speed(t, y) / RPM,
            y[c + 2],
            y[c + 5] / RPM,
            y[c],
            y[c + 1],
            y[r],
            y[r + 1],
            y[r + 2],
            y[r + 3],
            y[r + 4],
            y[r + 6],
            y[r + 7],
            y[o],
            y[o + 1],
            y[r + 5],
            dy[r + 5],
            dy[r + 6],
            dy[r + 7],
            y[o + 2],
            y[o + 3],
            dy[o + 2],
            dy[o + 3],
            housing.y,
            housing.z,
            y[c + 3],
            y[c + 4],
            pocket_sum,
            pocket_max,
            peak_inner,
            peak_outer,
            drive,
            dissipated,
            model.energy(t, y).total(),
            model.film_work(y),
        ]);
        row.push(model.pure_rolling_ratio(contacts, y));
        crate::power_channels::push(row, &power, model);
        if self.sensor {
            // Produced at the accepted step that reached t (NaN if the run
            // samples at another rate than the sensor acquires).
            let sample = model.sensor_sample(t);
            row.push(sample.map_or(f64::NAN, |s| s.acquired));
            row.push(sample.map_or(f64::NAN, |s| s.housing));
        }
        if self.growing_spalls > 0 {
            row.extend(model.growing_spall_lengths());
        }
        for (j, c) in contacts.iter().enumerate().take(self.balls) {
            let b = l.ball(j);
            let (attitude, yaw) = model.ball_attitude(j, y);
            row.extend_from_slice(&[
                y[b + 2],
                y[b + 5] / RPM,
                c.inner.load,
                c.outer.load,
                c.inner.angle.to_degrees(),
                c.outer.angle.to_degrees(),
                c.inner.slide_to_roll,
                c.outer.slide_to_roll,
                c.inner.spin_to_roll,
                c.outer.spin_to_roll,
                c.inner.film,
                c.outer.film,
                attitude.to_degrees(),
                yaw.to_degrees(),
            ]);
            if self.creep {
                let (i, o) = (
                    c.inner.creep.unwrap_or_default(),
                    c.outer.creep.unwrap_or_default(),
                );
                row.extend_from_slice(&[
                    i.longitudinal,
                    o.longitudinal,
                    i.lateral,
                    o.lateral,
                    i.spin,
                    o.spin,
                    i.stick_fraction,
                    o.stick_fraction,
                ]);
            }
            if self.power_per_ball {
                row.extend_from_slice(&[c.inner.losses.total(), c.outer.losses.total()]);
            }
            if self.mixed {
                row.extend_from_slice(&[c.inner.asperity_share, c.outer.asperity_share]);
            }
        }
    }

    /// The recorded channels of `row` (as [`Self::sink`] writes them).
    pub(crate) fn project<'a>(&'a mut self, row: &'a [f64]) -> &'a [f64] {
        match &self.selected {
            None => row,
            Some(selected) => {
                self.projected.clear();
                self.projected.extend(selected.iter().map(|&i| row[i]));
                &self.projected
            }
        }
    }

    /// A recorded row: into the statistics and the time series.
    pub(crate) fn sink(&mut self, row: &[f64]) {
        self.stats.push(row);
        let recorded = match &self.selected {
            None => row,
            Some(selected) => {
                self.projected.clear();
                self.projected.extend(selected.iter().map(|&i| row[i]));
                &self.projected
            }
        };
        if let Some(writer) = &mut self.writer {
            if self.write_error.is_none() {
                self.write_error = writer.push(recorded).err();
            }
        }
        if let Some(slow) = &mut self.slow {
            if (self.stats.samples() - 1) % slow.every == 0 {
                slow.projected.clear();
                slow.projected.extend(slow.selected.iter().map(|&i| row[i]));
                if let (Some(writer), None) = (&mut slow.writer, &self.write_error) {
                    self.write_error = writer.push(&slow.projected).err();
                }
            }
        }
    }

    /// Rows recorded.
    pub(crate) fn rows(&self) -> u64 {
        self.stats.samples()
    }
}
