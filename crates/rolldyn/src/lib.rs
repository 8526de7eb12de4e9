//! # rolldyn — ball-bearing dynamics engine
//!
//! The core library: no I/O, no printing, SI units throughout. The data flow
//! follows the physics (see `ARCHITECTURE.md`):
//!
//! * [`geometry`] — bearing internal geometry and groove-centre circles (docs/model.md §2);
//! * [`material`] — elastic materials and the Hertz effective modulus;
//! * [`contact`] — exact torus contact, Hertz point contact, precomputed
//!   contact tables and normal force laws (docs/model.md §2.1–§2.3);
//! * [`operating`] — speed profiles and applied loads (docs/model.md §8);
//! * [`quasistatic`] — static and Jones–Harris equilibria, stiffness, films and
//!   modes of a solution, bearing sets and shafts (docs/model.md §7, docs/systems.md);
//! * [`life`] — basic load rating and rating life (ISO 281, ISO 76, ISO/TS 16281);
//! * [`kinematics`] — pure-rolling speeds, defect frequencies, waviness
//!   excitation map (docs/model.md §7);
//! * [`integrate`] — the stiff Rosenbrock–W method ROS34PW2 (the default) with a
//!   block-structured Jacobian, explicit Runge–Kutta (RK4, Dormand–Prince 5(4)),
//!   their switching, energy-balance step control, checkpoints and the run
//!   driver; integrators are set up by one [`integrate::Builder`];
//! * [`dynamics`] — the dynamic bearing model, and several bearings on a shaft
//!   (docs/model.md §1, §2.3, §3, §5; docs/systems.md);
//! * [`cage`] — pocket laws and shapes, guide land, unbalance (docs/model.md §5);
//! * [`lubrication`] — Hamrock–Dowson films, pressure–viscosity, starvation, mixed
//!   lubrication, EHL rolling resistance, churning (docs/model.md §4, docs/lubrication.md);
//! * [`seals`] — the contact seals' friction moment;
//! * [`threads`] — the pool's other threads kept waiting actively during a run;
//! * [`traction`] — traction stress laws and their integration over the contact ellipse (docs/model.md §3);
//! * [`surface`] — raceway and ball waviness, spalls (docs/model.md §6);
//! * [`signal`] — spectra, envelope, velocity RMS, characteristic lines, cage whirl (docs/model.md §9);
//! * [`power`] — dissipation by component (dynamic) and Harris's local method (docs/model.md §10, Lei et al. 2023);
//! * [`thermal`] — thermal network, viscosity–temperature law, coupled iteration (docs/model.md §10, Lei et al. 2023);
//! * [`stability`] — linear stability of a running state: the model's Jacobian,
//!   averaged over a period, and its eigenmodes (docs/dynamics.md);
//! * [`math`] — elliptic integrals, root finding, monotone interpolation, random numbers.
//!
//! Equation numbers refer to `docs/model.md` and the source papers (docs/references.md);
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
pub mod seals;
pub mod signal;
pub mod stability;
pub mod surface;
pub mod testing;
pub mod thermal;
pub mod threads;
pub mod traction;

pub use error::InvalidParameter;
pub use geometry::{BearingGeometry, Clearance, GeometrySpec, RingKind};
pub use material::Material;
