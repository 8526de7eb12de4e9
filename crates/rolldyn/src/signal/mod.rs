//! Signal processing for vibration analysis (docs/model.md §9): amplitude spectra,
//! Welch power spectral density, envelope spectra, spectrograms, band-limited vibration
//! velocity RMS, the bearing's characteristic frequencies with harmonics and
//! sidebands, a peak list that names the nearest line, and cage-whirl
//! metrics (Deng et al. 2022 eq 41) and the jitter of the ball passage.
//!
//! Everything works on uniformly sampled records (the recorder's fixed
//! rate). FFTs are real-to-complex (realfft/rustfft); records are
//! zero-padded to the next 5-smooth length (2ᵃ3ᵇ5ᶜ), which keeps every
//! length fast (a prime length is ~25× slower) and leaves the amplitude
//! scaling, taken from the unpadded window, exact for a tone on a bin.
//! Conventions follow `scipy.signal` (Welch: one-sided density, mean removed
//! per segment, `scaling = "density"`), so results can be checked against it.

pub mod lines;
pub mod passage;
pub mod sensor;
pub mod spectrogram;
pub mod spectrum;
pub mod statistics;
pub mod whirl;

pub use lines::{CharacteristicFrequencies, Fault, Line, Peak, find_peaks};
pub use passage::{PassageJitter, passage_jitter};
pub use sensor::{HousingMode, SensorChain, SensorSample, SensorSpec};
pub use spectrogram::{Spectrogram, spectrogram};
pub use spectrum::{
    DEFAULT_ENVELOPE_BAND, Spectrum, SpectrumError, Window, amplitude_spectrum, band_rms,
    band_velocity_rms, band_velocity_rms_of_displacement, default_envelope_band,
    envelope_band_holds, envelope_spectrum, welch_psd,
};
pub use statistics::statistics;
pub use whirl::{WhirlMetrics, whirl_metrics};
