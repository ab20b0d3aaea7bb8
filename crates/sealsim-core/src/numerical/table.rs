//! The numerical level as a table of the effective gap against the reduced pressure, so that
//! it can drive a pressure sweep or a life run (thousands of states) at the cost of a handful
//! of ensemble solves.
//!
//! The contact-and-flow problem is scale-free in `s = P0/E*` (linear elasticity: the gap field
//! at (P0, E*) equals the one at (s, 1)) and the viscosity cancels from `u_eff³ = 12 η σ_eff`,
//! so one table per surface serves every rubber, temperature and fluid. Nodes are placed at
//! fixed fractions of the critical-junction sealing pressure of the same spectrum
//! ([`NODE_FRACTIONS`]); between nodes `ln u_eff` is linear in `ln s`; below the first node it
//! is held at the first node's slope; between the last percolating node and the first sealed
//! one `u_eff` falls linearly in s to zero (the transition is not resolved finer than the
//! nodes — an approximation, stated in docs/src/reference/fidelity.md); above it, sealed.

use super::HeightMap;
use super::reference::{NumericalError, NumericalSettings, Surfaces, evaluate};
use crate::contact::FullContact;
use crate::surface::Spectrum;

/// Node pressures as fractions of the critical-junction sealing pressure `s_seal` of the
/// spectrum (PY08: A(ζ1)/A0 = a_c). The numerical level seals near there too, so the nodes
/// bracket its own transition.
pub const NODE_FRACTIONS: [f64; 10] = [0.01, 0.03, 0.1, 0.2, 0.35, 0.5, 0.65, 0.8, 1.0, 1.25];

/// One tabulated node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// Reduced pressure P0/E*.
    pub s: f64,
    /// `u_eff³ = 12 η σ̄_eff` (m³), the ensemble mean; 0 when nothing percolates.
    pub cubed_gap: f64,
    /// Mean contact fraction A/A0.
    pub contact_fraction: f64,
    /// Mean interfacial separation ū (m), the ensemble mean.
    pub mean_gap: f64,
}

/// `u_eff(s)` of the numerical level for one surface.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericalTable {
    nodes: Vec<Node>,
    /// Index of the last node with a positive conductance (`None`: sealed at every node).
    last_open: Option<usize>,
    failures: Vec<(f64, NumericalError)>,
}

impl NumericalTable {
    /// Solves the ensemble at the reduced pressures `nodes` (E* = 1, η = 1; sorted here);
    /// `progress(done, total)` counts realisations over all nodes. A node whose solve fails is
    /// left out and its error kept ([`Self::failures`]). At a node the table returns the
    /// node's own ensemble value exactly.
    pub fn build(
        surfaces: Surfaces<'_>,
        nodes: &[f64],
        settings: &NumericalSettings,
        progress: &mut dyn FnMut(usize, usize),
    ) -> NumericalTable {
        let mut at: Vec<f64> = nodes
            .iter()
            .copied()
            .filter(|s| s.is_finite() && *s > 0.0)
            .collect();
        at.sort_by(f64::total_cmp);
        at.dedup();
        let per_node = match surfaces {
            Surfaces::Map(_) => 1,
            Surfaces::Synthetic(_) => settings.realisations,
        };
        let total = per_node * at.len();
        let mut table = Vec::with_capacity(at.len());
        let mut failures = Vec::new();
        for (k, &s) in at.iter().enumerate() {
            let mut inner = |done: usize, _: usize| progress(k * per_node + done, total);
            match evaluate(surfaces, 1.0, s, 1.0, settings, &mut inner) {
                Ok(state) => table.push(Node {
                    s,
                    cubed_gap: 12.0 * state.conductance.mean,
                    contact_fraction: state.contact_fraction.mean,
                    mean_gap: state.mean_gap.mean,
                }),
                Err(e) => failures.push((s, e)),
            }
        }
        let last_open = table.iter().rposition(|n| n.cubed_gap > 0.0);
        NumericalTable {
            nodes: table,
            last_open,
            failures,
        }
    }

    /// A table for a synthetic spectrum or a height map, at the given reduced pressures or, by
    /// default, at `s_seal · NODE_FRACTIONS` (`s_seal`: the critical-junction sealing reduced
    /// pressure of the spectrum).
    pub fn for_surface(
        spectrum: &Spectrum,
        map: Option<&HeightMap>,
        nodes: Option<&[f64]>,
        s_seal: f64,
        settings: &NumericalSettings,
        progress: &mut dyn FnMut(usize, usize),
    ) -> NumericalTable {
        let surfaces = match map {
            Some(m) => Surfaces::Map(m),
            None => Surfaces::Synthetic(spectrum),
        };
        let default: Vec<f64> = NODE_FRACTIONS.iter().map(|f| f * s_seal).collect();
        Self::build(surfaces, nodes.unwrap_or(&default), settings, progress)
    }

    /// The nodes whose ensemble solve failed: (P0/E*, error). Empty in every case measured.
    pub fn failures(&self) -> &[(f64, NumericalError)] {
        &self.failures
    }

    /// The tabulated nodes.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The ensemble-mean contact fraction A/A0 and mean gap ū (m) at a node's reduced
    /// pressure `s` exactly (a pressure sweep solves at its own pressures); `None` between
    /// nodes (the table interpolates only the effective gap) or at a node that failed.
    pub fn full_contact(&self, s: f64) -> Option<FullContact> {
        self.nodes.iter().find(|n| n.s == s).map(|n| FullContact {
            area_fraction: n.contact_fraction,
            mean_gap: n.mean_gap,
        })
    }

    /// The effective gap `u_eff` (m) at reduced pressure `s` (module docs); 0 when sealed.
    pub fn effective_gap(&self, s: f64) -> f64 {
        let Some(last) = self.last_open else {
            return 0.0;
        };
        if let Some(node) = self.nodes.iter().find(|n| n.s == s) {
            return node.cubed_gap.cbrt();
        }
        let ln_u = |n: &Node| n.cubed_gap.cbrt().ln();
        let nodes = &self.nodes;
        if s <= nodes[0].s {
            // ln u linear in ln s with the first interval's slope (flat if it is the only one)
            let slope = if last >= 1 {
                (ln_u(&nodes[1]) - ln_u(&nodes[0])) / (nodes[1].s / nodes[0].s).ln()
            } else {
                0.0
            };
            return (ln_u(&nodes[0]) + slope * (s / nodes[0].s).ln()).exp();
        }
        if s <= nodes[last].s {
            // here last ≥ 1 and nodes[0].s < s ≤ nodes[last].s
            let k = nodes.partition_point(|n| n.s < s).clamp(1, last);
            let (a, b) = (&nodes[k - 1], &nodes[k]);
            let t = (s / a.s).ln() / (b.s / a.s).ln();
            return ((1.0 - t) * ln_u(a) + t * ln_u(b)).exp();
        }
        // past the last percolating node: linear fall to 0 at the next (sealed) node
        let open = &nodes[last];
        match nodes.get(last + 1) {
            Some(closed) if s < closed.s => {
                open.cubed_gap.cbrt() * (closed.s - s) / (closed.s - open.s)
            }
            Some(_) => 0.0,
            // open at the highest node: hold its value (the table ends there)
            None => open.cubed_gap.cbrt(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(gaps: &[f64]) -> NumericalTable {
        let nodes: Vec<Node> = gaps
            .iter()
            .enumerate()
            .map(|(i, &u)| Node {
                s: 10f64.powi(i as i32),
                cubed_gap: u * u * u,
                contact_fraction: 0.0,
                mean_gap: 0.0,
            })
            .collect();
        let last_open = nodes.iter().rposition(|n| n.cubed_gap > 0.0);
        NumericalTable {
            nodes,
            last_open,
            failures: Vec::new(),
        }
    }

    #[test]
    fn interpolates_power_laws_exactly_and_falls_to_zero_past_the_last_open_node() {
        // u = 8, 4, 2 at s = 1, 10, 100: u ∝ s^{−log10 2}
        let t = table(&[8.0, 4.0, 2.0, 0.0]);
        let u = |s: f64| 8.0 * s.powf(-2f64.log10());
        for s in [0.1, 1.0, 3.0, 10.0, 50.0, 100.0] {
            assert!((t.effective_gap(s) / u(s) - 1.0).abs() < 1e-12, "s = {s}");
        }
        // halfway between the last open node (100) and the sealed one (1000)
        assert!((t.effective_gap(550.0) - 1.0).abs() < 1e-12);
        assert_eq!(t.effective_gap(1000.0), 0.0);
        assert_eq!(t.effective_gap(5000.0), 0.0);
        assert_eq!(table(&[0.0, 0.0]).effective_gap(1.0), 0.0);
    }

    #[test]
    fn full_contact_is_a_node_s_own_and_nothing_between_nodes() {
        let mut t = table(&[8.0, 4.0]);
        t.nodes[1].contact_fraction = 0.25;
        t.nodes[1].mean_gap = 3e-7;
        let at = t.full_contact(10.0).unwrap();
        assert_eq!((at.area_fraction, at.mean_gap), (0.25, 3e-7));
        assert_eq!(t.full_contact(5.0), None);
    }
}
