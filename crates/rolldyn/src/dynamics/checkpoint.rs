//! The bearing model's own memory in a run's checkpoint: the
//! contact-episode records (impact speeds of the Lankarani–Nikravesh,
//! Hunt–Crossley and Flores laws, docs/model.md §2.3) and, in a thermally coupled
//! run, the thermal network's state, from which the viscosities it feeds
//! back are set again, the growing spalls' lengths and the sensor chain's
//! state. Everything else the right-hand side reads is the
//! case's data or the integrator's state.

use super::model::BearingModel;
use crate::contact::normal_law::ContactEpisode;
use crate::integrate::checkpoint::{Checkpoint, CheckpointError, StateReader, StateWriter};

impl Checkpoint for BearingModel {
    fn save(&self, out: &mut StateWriter) {
        out.tag("bearing_model");
        out.u64(self.episodes.len() as u64);
        for episode in self.episodes.iter().flatten() {
            out.opt_f64(episode.recorded());
        }
        out.f64s(&self.peak_loads.peek());
        out.u64(u64::from(self.thermal.is_some()));
        if let Some(thermal) = &self.thermal {
            thermal.save(out);
        }
        out.f64s(&self.growing_spall_lengths().collect::<Vec<_>>());
        out.u64(u64::from(self.sensor.is_some()));
        if let Some(sensor) = &self.sensor {
            sensor.save(out);
        }
    }

    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("bearing_model")?;
        let balls = input.u64()?;
        if balls != self.episodes.len() as u64 {
            return Err(CheckpointError::Mismatch(format!(
                "{balls} balls saved, the model has {}",
                self.episodes.len()
            )));
        }
        for episode in self.episodes.iter_mut().flatten() {
            *episode = ContactEpisode::with_record(input.opt_f64()?);
        }
        let mut peaks = [0.0; 2];
        input.f64s_into("peak loads", &mut peaks)?;
        self.peak_loads.set(peaks);
        let coupled = input.u64()? == 1;
        if coupled != self.thermal.is_some() {
            return Err(CheckpointError::Mismatch(
                "thermal coupling differs from the saved run".into(),
            ));
        }
        if let Some(mut thermal) = self.thermal.take() {
            let viscosities = thermal.restore(input);
            self.thermal = Some(thermal);
            self.elements.apply_viscosities(viscosities?);
        }
        let mut lengths: Vec<f64> = self.growing_spall_lengths().collect();
        input.f64s_into("growing spall lengths", &mut lengths)?;
        self.set_growing_spall_lengths(&lengths);
        let sensed = input.u64()? == 1;
        if sensed != self.sensor.is_some() {
            return Err(CheckpointError::Mismatch(
                "the sensor differs from the saved run".into(),
            ));
        }
        if let Some(sensor) = self.sensor.as_mut() {
            sensor.restore(input)?;
        }
        Ok(())
    }
}
