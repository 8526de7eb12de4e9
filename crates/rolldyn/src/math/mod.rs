//! Numerical building blocks with no bearing physics in them: complete
//! elliptic integrals (Carlson's symmetric forms), a bracketed scalar root
//! finder (Brent), monotone cubic (Fritsch–Carlson / PCHIP) interpolation,
//! a logarithm and an exponential that vectorize, and a cube root by plain arithmetic.

pub mod cube_root;
pub mod elliptic;
pub mod exponential;
pub mod interp;
pub mod logarithm;
pub mod random;
pub mod roots;
