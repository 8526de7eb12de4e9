//! Numerical building blocks with no bearing physics in them: complete
//! elliptic integrals (Carlson's symmetric forms), a bracketed scalar root
//! finder (Brent) and monotone cubic (Fritsch–Carlson / PCHIP) interpolation.

pub mod elliptic;
pub mod interp;
pub mod random;
pub mod roots;
