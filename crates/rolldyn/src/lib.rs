//! # rolldyn — ball-bearing dynamics engine
//!
//! The core library: no I/O, no printing, SI units throughout. The data flow
//! follows the physics (see `ARCHITECTURE.md`):
//!
//! * [`geometry`] — bearing internal geometry and groove-centre circles (MODEL §2);
//! * [`material`] — elastic materials and the Hertz effective modulus;
//! * [`contact`] — exact torus contact, Hertz point contact, precomputed
//!   contact tables and normal force laws (MODEL §2.1–§2.3);
//! * [`operating`] — speed profiles and applied loads (MODEL §8);
//! * [`quasistatic`] — static load distribution and stiffness (MODEL §7);
//! * [`life`] — basic load rating and rating life (ISO 281);
//! * [`kinematics`] — pure-rolling speeds, defect frequencies, waviness
//!   excitation map (MODEL §7);
//! * [`integrate`] — explicit Runge–Kutta integrators (RK4, Dormand–Prince 5(4));
//! * [`dynamics`] — the dynamic bearing model (MODEL §1, §2.3, §3, §5);
//! * [`cage`] — pocket laws and shapes, guide land, unbalance (MODEL §5);
//! * [`lubrication`] — Hamrock–Dowson films, pressure–viscosity (MODEL §4);
//! * [`traction`] — traction stress laws and their integration over the contact ellipse (MODEL §3);
//! * [`surface`] — raceway and ball waviness, spalls (MODEL §6);
//! * [`signal`] — spectra, envelope, velocity RMS, characteristic lines, cage whirl (MODEL §9);
//! * [`power`] — dissipation by component (dynamic) and Harris's local method (MODEL §10, seed 004);
//! * [`thermal`] — thermal network, viscosity–temperature law, coupled iteration (MODEL §10, seed 004);
//! * [`math`] — elliptic integrals, root finding, monotone interpolation.
//!
//! Equation numbers refer to `../shared/spec/MODEL.md` and the seed papers;
//! every model's doc comment names its source and any correction.

pub mod cage;
pub mod contact;
pub mod dynamics;
pub mod error;
pub mod geometry;
pub mod integrate;
pub mod kinematics;
pub mod life;
pub mod lubrication;
pub mod material;
pub mod math;
pub mod operating;
pub mod power;
pub mod quasistatic;
pub mod signal;
pub mod surface;
pub mod thermal;
pub mod traction;

pub use error::InvalidParameter;
pub use geometry::{BearingGeometry, Clearance, GeometrySpec, RingKind};
pub use material::Material;
