//! Lei et al. 2023's thermal network of a bearing (§4, Figs 3–4; docs/model.md §10):
//!
//! ```text
//!  shaft ── inner ring ── inner contact ── ball ── outer contact ── outer ring ── housing ── ambient
//!    │          │                           │                          │
//!  ambient      └──────────── oil ──────────┴──────────────────────────┘
//!                              │
//!                          oil inlet (ρ c_p Q: the oil leaves at the oil node's temperature)
//! ```
//! Resistances ([`super::resistance`]): rings and housing as cylinders
//! (raceway diameter d_m ∓ D to bore or outside diameter, over the width);
//! each race contact to the ball and to its ring by the moving-heat-source
//! resistance of its Hertz ellipse at the contact's entrainment speed, the
//! Z contacts in parallel; convection of balls, ring lands and the shaft
//! end to the oil or the air by the given coefficients or the flat-plate
//! correlation at the cage's surface speed; the housing's outside and end
//! faces to ambient. Heat: each contact's losses at its contact node (the
//! Q₁, Q₂ of Lei et al. 2023 eq 46); with equal ball and ring materials the two
//! contact resistances are equal, so half flows into each body (Burton &
//! Staph's 1:1, Lei et al. 2023 §6.1.1); ball–pocket friction into the balls;
//! cage land and drag into the oil (Lei et al. 2023 share these out half to each
//! contact). Steady state and transients from [`super::network`].

use super::network::{NodeId, Solution, ThermalNetwork};
use super::resistance::{convection, cylinder, flat_plate_coefficient, moving_contact};
use crate::error::InvalidParameter;
use std::f64::consts::PI;

/// A solid's thermal properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solid {
    /// Conductivity k \[W/(m·K)\].
    pub conductivity: f64,
    /// Density ρ \[kg/m³\].
    pub density: f64,
    /// Specific heat c \[J/(kg·K)\].
    pub specific_heat: f64,
}

impl Solid {
    /// AISI 52100 bearing steel: k = 43 W/(m·K), ρ = 7830 kg/m³,
    /// c = 458 J/(kg·K) (Harris & Kotzalas, *Essential Concepts*, Table 1.x;
    /// MatWeb values at 20 °C).
    pub const STEEL: Self = Self {
        conductivity: 43.0,
        density: 7830.0,
        specific_heat: 458.0,
    };

    /// Diffusivity κ = k/(ρ c) \[m²/s\].
    pub fn diffusivity(&self) -> f64 {
        self.conductivity / (self.density * self.specific_heat)
    }
}

/// Everything the network needs besides the heat sources.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalInputs {
    /// Bore d, outside diameter D_o, width B of the bearing \[m\].
    pub bore: f64,
    /// Outside diameter \[m\].
    pub outside_diameter: f64,
    /// Width \[m\].
    pub width: f64,
    /// Ball diameter, pitch diameter \[m\], ball count.
    pub ball_diameter: f64,
    /// Pitch diameter \[m\].
    pub pitch_diameter: f64,
    /// Number of balls.
    pub ball_count: usize,
    /// Ball material.
    pub ball: Solid,
    /// Ring and shaft material.
    pub ring: Solid,
    /// Housing material.
    pub housing: Solid,
    /// Housing outside diameter and width \[m\].
    pub housing_diameter: f64,
    /// Housing width \[m\].
    pub housing_width: f64,
    /// Shaft length exposed to the air on each side of the bearing \[m\].
    pub shaft_length: f64,
    /// Ambient air temperature \[K\].
    pub ambient_temperature: f64,
    /// Oil inlet temperature \[K\].
    pub oil_inlet_temperature: f64,
    /// Oil supply flow \[m³/s\] (0: no circulation; the oil node then only
    /// passes heat between the parts it wets).
    pub oil_flow: f64,
    /// Oil density, specific heat, conductivity.
    pub oil_density: f64,
    /// Oil specific heat \[J/(kg·K)\].
    pub oil_specific_heat: f64,
    /// Oil conductivity \[W/(m·K)\].
    pub oil_conductivity: f64,
    /// Oil kinematic viscosity at the oil's temperature \[m²/s\].
    pub oil_kinematic_viscosity: f64,
    /// Convection coefficient of the housing to ambient \[W/(m²K)\].
    pub housing_convection: f64,
    /// Convection coefficient of the shaft to ambient \[W/(m²K)\].
    pub shaft_convection: f64,
    /// Convection coefficient of balls and rings to the oil \[W/(m²K)\];
    /// None: the flat-plate correlation at the cage's surface speed.
    pub oil_convection: Option<f64>,
}

/// Heat generated in the bearing \[W\], and the speeds the resistances need.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeatSources {
    /// Losses of all ball–inner-raceway contacts.
    pub inner_contacts: f64,
    /// Losses of all ball–outer-raceway contacts.
    pub outer_contacts: f64,
    /// Ball–pocket friction (into the balls).
    pub balls: f64,
    /// Cage land and drag (into the oil).
    pub oil: f64,
    /// Mean semi-axes (a, b) of the loaded inner and outer contacts \[m\].
    pub inner_ellipse: (f64, f64),
    /// Outer contacts' mean semi-axes \[m\].
    pub outer_ellipse: (f64, f64),
    /// Mean entrainment speeds of the inner and outer contacts \[m/s\].
    pub entrainment_speed: [f64; 2],
    /// Number of loaded contacts on the inner and outer raceway.
    pub loaded_contacts: [usize; 2],
    /// Cage speed \[rad/s\] (the oil's sweep speed).
    pub cage_speed: f64,
}

impl HeatSources {
    /// Sets the loaded contacts' counts, mean semi-axes and mean entrainment
    /// speeds from `contacts`: (ring 0 inner / 1 outer, a, b, u) per loaded
    /// contact.
    pub fn set_contact_means(&mut self, contacts: impl Iterator<Item = (usize, f64, f64, f64)>) {
        let mut sums = [[0.0; 3]; 2];
        self.loaded_contacts = [0; 2];
        for (k, a, b, u) in contacts {
            sums[k][0] += a;
            sums[k][1] += b;
            sums[k][2] += u;
            self.loaded_contacts[k] += 1;
        }
        let mean = |k: usize, i: usize| sums[k][i] / self.loaded_contacts[k].max(1) as f64;
        self.inner_ellipse = (mean(0, 0), mean(0, 1));
        self.outer_ellipse = (mean(1, 0), mean(1, 1));
        self.entrainment_speed = [mean(0, 2), mean(1, 2)];
    }
}

/// Nodes of the bearing network, in this order.
pub const NODES: [&str; 10] = [
    "ball",
    "inner_contact",
    "inner_ring",
    "shaft",
    "outer_contact",
    "outer_ring",
    "housing",
    "oil",
    "ambient",
    "oil_inlet",
];

/// Index of a node of [`NODES`] by name.
pub fn node_index(name: &str) -> Option<NodeId> {
    NODES.iter().position(|&n| n == name)
}

/// The network of a bearing with its heat sources.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingThermal {
    /// The network (node indices as in [`NODES`]).
    pub network: ThermalNetwork,
    /// Total heat generated \[W\].
    pub heat: f64,
}

/// Node temperatures and where the heat goes.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalSolution {
    /// Temperatures of the nodes of [`NODES`] \[K\].
    pub temperatures: [f64; 10],
    /// Heat leaving to the ambient air \[W\].
    pub to_ambient: f64,
    /// Heat carried away by the oil \[W\].
    pub to_oil: f64,
}

impl ThermalSolution {
    fn from(s: &Solution) -> Self {
        let mut temperatures = [0.0; 10];
        temperatures.copy_from_slice(&s.temperatures[..10]);
        Self {
            temperatures,
            to_ambient: -s.boundary_heat[8],
            to_oil: -s.boundary_heat[9],
        }
    }

    /// Temperature of a node by name \[K\].
    pub fn temperature(&self, node: &str) -> Option<f64> {
        node_index(node).map(|i| self.temperatures[i])
    }
}

fn positive(field: &'static str, v: f64) -> Result<(), InvalidParameter> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(InvalidParameter::new(
            field,
            v,
            "must be positive and finite",
        ))
    }
}

impl ThermalInputs {
    /// Refuses dimensions and oil data the network cannot take: every
    /// size, property and temperature positive, and the parts nested
    /// (bore < d_m − D < d_m + D < outside diameter < housing diameter).
    fn validate(&self) -> Result<(), InvalidParameter> {
        let i = self;
        for (field, v) in [
            ("bore", i.bore),
            ("outside_diameter", i.outside_diameter),
            ("width", i.width),
            ("housing_diameter", i.housing_diameter),
            ("housing_width", i.housing_width),
            ("oil_density", i.oil_density),
            ("oil_specific_heat", i.oil_specific_heat),
            ("oil_conductivity", i.oil_conductivity),
            ("oil_kinematic_viscosity", i.oil_kinematic_viscosity),
            ("housing_convection", i.housing_convection),
            ("ambient_temperature", i.ambient_temperature),
            ("oil_inlet_temperature", i.oil_inlet_temperature),
        ] {
            positive(field, v)?;
        }
        let (d, dm) = (i.ball_diameter, i.pitch_diameter);
        if !(i.bore < dm - d
            && dm + d < i.outside_diameter
            && i.outside_diameter < i.housing_diameter)
        {
            return Err(InvalidParameter::new(
                "housing_diameter",
                i.housing_diameter,
                "need bore < d_m − D < d_m + D < outside diameter < housing diameter",
            ));
        }
        Ok(())
    }

    /// The convection coefficient of the balls and ring lands to the oil
    /// \[W/(m²K)\]: `oil_convection`, else the flat-plate coefficient at
    /// the cage's pitch surface speed over the pitch circumference.
    fn oil_convection_at(&self, cage_speed: f64) -> f64 {
        let i = self;
        i.oil_convection.unwrap_or_else(|| {
            let nu = i.oil_kinematic_viscosity;
            flat_plate_coefficient(
                i.oil_conductivity,
                nu,
                nu * i.oil_density * i.oil_specific_heat / i.oil_conductivity,
                cage_speed * 0.5 * i.pitch_diameter,
                PI * i.pitch_diameter,
            )
        })
    }
}

impl BearingThermal {
    /// Builds the network for `inputs` and `heat`.
    pub fn new(inputs: &ThermalInputs, heat: &HeatSources) -> Result<Self, InvalidParameter> {
        let i = inputs;
        i.validate()?;
        let (d, dm, big_d) = (i.ball_diameter, i.pitch_diameter, i.outside_diameter);
        let (inner_race, outer_race) = (dm - d, dm + d);
        let z = i.ball_count as f64;
        let mut net = ThermalNetwork::default();
        let annulus = |d1: f64, d2: f64, l: f64| PI / 4.0 * (d2 * d2 - d1 * d1) * l;
        let capacity = |s: &Solid, volume: f64| s.density * s.specific_heat * volume;
        let ball = net.node("ball", capacity(&i.ball, z * PI * d.powi(3) / 6.0));
        let inner_contact = net.node("inner_contact", 0.0);
        let inner_ring = net.node(
            "inner_ring",
            capacity(&i.ring, annulus(i.bore, inner_race, i.width)),
        );
        let shaft_volume = PI / 4.0 * i.bore * i.bore * (i.width + 2.0 * i.shaft_length);
        let shaft = net.node("shaft", capacity(&i.ring, shaft_volume));
        let outer_contact = net.node("outer_contact", 0.0);
        let outer_ring = net.node(
            "outer_ring",
            capacity(&i.ring, annulus(outer_race, big_d, i.width)),
        );
        let housing = net.node(
            "housing",
            capacity(
                &i.housing,
                annulus(big_d, i.housing_diameter, i.housing_width),
            ),
        );
        let oil = net.node("oil", 0.0);
        let ambient = net.boundary("ambient", i.ambient_temperature);
        let inlet = net.boundary("oil_inlet", i.oil_inlet_temperature);
        // Contacts: ball and ring sides, the loaded contacts in parallel.
        for (contact, ring, (a, b), u, n) in [
            (
                inner_contact,
                inner_ring,
                heat.inner_ellipse,
                heat.entrainment_speed[0],
                heat.loaded_contacts[0],
            ),
            (
                outer_contact,
                outer_ring,
                heat.outer_ellipse,
                heat.entrainment_speed[1],
                heat.loaded_contacts[1],
            ),
        ] {
            if n == 0 || a <= 0.0 || b <= 0.0 {
                continue;
            }
            let n = n as f64;
            let side = |s: &Solid| moving_contact(a, b, u, s.conductivity, s.diffusivity()) / n;
            net.resistance(contact, ball, side(&i.ball));
            net.resistance(contact, ring, side(&i.ring));
        }
        // Conduction through the rings and the housing.
        net.resistance(
            inner_ring,
            shaft,
            cylinder(i.bore, inner_race, i.ring.conductivity, i.width),
        );
        net.resistance(
            outer_ring,
            housing,
            cylinder(outer_race, big_d, i.ring.conductivity, i.width)
                + cylinder(
                    big_d,
                    i.housing_diameter,
                    i.housing.conductivity,
                    i.housing_width,
                ),
        );
        // Convection to ambient: housing outside and end faces, shaft ends.
        let housing_area = PI * i.housing_diameter * i.housing_width
            + 2.0 * PI / 4.0 * (i.housing_diameter.powi(2) - big_d.powi(2));
        net.resistance(
            housing,
            ambient,
            convection(i.housing_convection, housing_area),
        );
        if i.shaft_length > 0.0 && i.shaft_convection > 0.0 {
            let shaft_area = 2.0 * PI * i.bore * i.shaft_length;
            net.resistance(shaft, ambient, convection(i.shaft_convection, shaft_area));
        }
        // Convection to the oil: balls, and the ring lands over the width.
        let oil_h = i.oil_convection_at(heat.cage_speed);
        if oil_h > 0.0 {
            net.resistance(ball, oil, convection(oil_h, z * PI * d * d));
            net.resistance(
                inner_ring,
                oil,
                convection(oil_h, PI * inner_race * i.width),
            );
            net.resistance(
                outer_ring,
                oil,
                convection(oil_h, PI * outer_race * i.width),
            );
        }
        net.conductance(oil, inlet, i.oil_density * i.oil_specific_heat * i.oil_flow);
        net.set_heat(inner_contact, heat.inner_contacts);
        net.set_heat(outer_contact, heat.outer_contacts);
        net.set_heat(ball, heat.balls);
        net.set_heat(oil, heat.oil);
        debug_assert_eq!(net.nodes().len(), NODES.len());
        Ok(Self {
            network: net,
            heat: heat.inner_contacts + heat.outer_contacts + heat.balls + heat.oil,
        })
    }

    /// Steady state.
    pub fn steady(&self) -> Result<ThermalSolution, InvalidParameter> {
        Ok(ThermalSolution::from(&self.network.steady()?))
    }

    /// Temperatures after `duration` \[s\] from `initial` (per node of
    /// [`NODES`]), in `steps` steps.
    pub fn transient(
        &self,
        initial: &[f64; 10],
        duration: f64,
        steps: usize,
    ) -> Result<ThermalSolution, InvalidParameter> {
        Ok(ThermalSolution::from(
            &self.network.transient(initial, duration, steps)?,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 30 × 62 × 16 bearing of Lei et al. 2023 with a steel housing.
    pub(crate) fn inputs() -> ThermalInputs {
        ThermalInputs {
            bore: 30e-3,
            outside_diameter: 62e-3,
            width: 16e-3,
            ball_diameter: 9.525e-3,
            pitch_diameter: 46e-3,
            ball_count: 11,
            ball: Solid::STEEL,
            ring: Solid::STEEL,
            housing: Solid::STEEL,
            housing_diameter: 100e-3,
            housing_width: 30e-3,
            shaft_length: 50e-3,
            ambient_temperature: 293.15,
            oil_inlet_temperature: 313.15,
            oil_flow: 2e-3 / 60.0,
            oil_density: 860.0,
            oil_specific_heat: 2000.0,
            oil_conductivity: 0.14,
            oil_kinematic_viscosity: 20e-6,
            housing_convection: 15.0,
            shaft_convection: 30.0,
            oil_convection: None,
        }
    }

    fn heat() -> HeatSources {
        HeatSources {
            inner_contacts: 33.0,
            outer_contacts: 21.0,
            balls: 2.0,
            oil: 4.0,
            inner_ellipse: (1.4e-3, 0.2e-3),
            outer_ellipse: (1.5e-3, 0.18e-3),
            entrainment_speed: [12.0, 12.0],
            loaded_contacts: [11, 11],
            cage_speed: 400.0,
        }
    }

    /// Heat in = heat out; the contacts are the hottest; equal materials
    /// share each contact's heat 1:1 between ball and ring (Burton–Staph).
    #[test]
    fn bearing_network_balances_and_splits_evenly() {
        let t = BearingThermal::new(&inputs(), &heat()).unwrap();
        let s = t.steady().unwrap();
        assert!(
            (s.to_ambient + s.to_oil - 60.0).abs() < 1e-9,
            "{} + {}",
            s.to_ambient,
            s.to_oil
        );
        let temp = |n| s.temperature(n).unwrap();
        assert!(temp("inner_contact") > temp("inner_ring"));
        assert!(temp("outer_contact") > temp("outer_ring"));
        let net = &t.network;
        let (c, b, r) = (1, 0, 2);
        assert!(
            (net.conductance_between(c, b) / net.conductance_between(c, r) - 1.0).abs() < 1e-12
        );
    }

    /// A huge oil flow pins the oil at its inlet temperature; without heat
    /// the whole bearing sits between ambient and inlet.
    #[test]
    fn bearing_network_limits() {
        let mut i = inputs();
        i.oil_flow = 1.0;
        let s = BearingThermal::new(&i, &heat()).unwrap().steady().unwrap();
        assert!((s.temperature("oil").unwrap() - 313.15).abs() < 1e-3);
        let none = HeatSources {
            inner_contacts: 0.0,
            outer_contacts: 0.0,
            balls: 0.0,
            oil: 0.0,
            ..heat()
        };
        let s = BearingThermal::new(&inputs(), &none)
            .unwrap()
            .steady()
            .unwrap();
        assert!(
            s.temperatures[..8]
                .iter()
                .all(|&t| (293.15 - 1e-9..=313.15 + 1e-9).contains(&t))
        );
    }

    /// The transient from ambient approaches the steady state.
    #[test]
    fn bearing_transient_tends_to_steady() {
        let t = BearingThermal::new(&inputs(), &heat()).unwrap();
        let steady = t.steady().unwrap();
        let start = [293.15; 10];
        let late = t.transient(&start, 20_000.0, 2000).unwrap();
        for (a, b) in late.temperatures.iter().zip(&steady.temperatures) {
            assert!((a - b).abs() < 1e-3, "{a} vs {b}");
        }
        let early = t.transient(&start, 60.0, 60).unwrap();
        assert!(
            early.temperature("outer_ring").unwrap()
                < steady.temperature("outer_ring").unwrap() - 1.0
        );
    }
}
