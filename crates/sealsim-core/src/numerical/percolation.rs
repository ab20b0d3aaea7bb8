//! Percolation of the non-contact region along the flow direction (docs/model.md §3.5).
//!
//! The interface is the periodic `n × n` cell grid of [`super::HeightMap`] (row-major,
//! `cell = iy * n + ix`, x along the flow). A cell is *open* when the fluid can be there (gap
//! `> 0`, see [`open_mask`]); open cells are joined through their four edge neighbours only
//! (4-connectivity: two open cells that touch at a corner do not pass fluid).
//!
//! The open region *percolates along x* when one of its clusters winds around the periodic cell
//! in x: when the cell is unrolled along x (and kept periodic in y), that cluster joins the inlet
//! to the outlet. A cluster that winds around y only, an isolated lake and a closed pocket carry
//! no net flow. A cluster that winds once in x and once in y (a diagonal channel) does percolate.
//!
//! Method: union–find over the open cells in which every cell keeps its x displacement to its
//! parent *in the unrolled plane* (the wrap-around edge from `ix = n − 1` to `ix = 0` is a step
//! of +1 like any other eastward step). Joining two cells already in the same cluster closes a
//! loop; if the two displacements disagree, they differ by a non-zero multiple of `n` and the loop
//! winds around x (Newman & Ziff, PRE 64 (2001) 016706, §II.C). Cost `O(n² α(n²))`.
//!
//! [`critical_level`] gives the exact percolation threshold of a scalar field in one pass (cells
//! opened in increasing order of the field); [`percolation_threshold`] brackets it by bisection
//! for any monotone family of masks (e.g. BEM gap fields at increasing load).

/// The open mask of a gap field: `gap > 0` (m). Cells in contact carry exactly zero gap; a
/// negative or NaN value is treated as closed (the flow solver rejects them before this).
pub fn open_mask(gap: &[f64]) -> Vec<bool> {
    gap.iter().map(|&u| u > 0.0).collect()
}

/// Result of [`analyse`]: which open cells belong to a cluster that winds around the periodic
/// cell in x (these are the only ones that can carry a net flux).
#[derive(Debug, Clone, PartialEq)]
pub struct Percolation {
    /// Side of the grid.
    pub n: usize,
    /// Per cell: `Some(k)` when the cell belongs to the `k`-th spanning cluster
    /// (`k < spanning_clusters`, numbered in order of their first cell), `None` otherwise
    /// (contact, isolated lake, cluster winding in y only). Dead-end branches of a spanning
    /// cluster are part of it: they carry no flux, but they are connected to it.
    pub labels: Vec<Option<u32>>,
    /// Number of distinct spanning clusters (separate channels along x).
    pub spanning_clusters: usize,
    /// Fraction of cells closed (in contact), `A/A0`.
    pub contact_fraction: f64,
    /// Fraction of cells that belong to a spanning cluster.
    pub spanning_fraction: f64,
}

impl Percolation {
    /// True when at least one cluster winds around x (the interface leaks).
    pub fn percolates(&self) -> bool {
        self.spanning_clusters > 0
    }

    /// Mask of the cells in a spanning cluster.
    pub fn spanning_mask(&self) -> Vec<bool> {
        self.labels.iter().map(Option::is_some).collect()
    }
}

/// Union–find over the cells of an `n × n` periodic grid, with the unrolled x displacement of
/// every node to its parent and a per-root flag "this cluster winds around x".
struct WindingUnionFind {
    parent: Vec<u32>,
    /// x(node) − x(parent) in the unrolled plane.
    offset: Vec<i32>,
    size: Vec<u32>,
    wraps: Vec<bool>,
    /// Scratch for path compression.
    path: Vec<u32>,
}

impl WindingUnionFind {
    fn new(cells: usize) -> Self {
        assert!(
            cells < i32::MAX as usize,
            "grid too large for the percolation labels"
        );
        Self {
            parent: (0..cells as u32).collect(),
            offset: vec![0; cells],
            size: vec![1; cells],
            wraps: vec![false; cells],
            path: Vec::new(),
        }
    }

    /// Root of `a` and the unrolled displacement x(a) − x(root); compresses the path.
    fn find(&mut self, a: usize) -> (usize, i32) {
        let mut node = a as u32;
        let mut total = 0i32;
        self.path.clear();
        while self.parent[node as usize] != node {
            self.path.push(node);
            total += self.offset[node as usize];
            node = self.parent[node as usize];
        }
        let root = node;
        // Second pass: point every node on the path at the root with its full displacement.
        let mut remaining = total;
        for &p in &self.path {
            let own = self.offset[p as usize];
            self.parent[p as usize] = root;
            self.offset[p as usize] = remaining;
            remaining -= own;
        }
        (root as usize, total)
    }

    /// Joins `a` and `b`, where x(b) = x(a) + dx in the unrolled plane. Returns whether the
    /// joint cluster winds around x.
    fn union(&mut self, a: usize, b: usize, dx: i32) -> bool {
        let (ra, oa) = self.find(a);
        let (rb, ob) = self.find(b);
        if ra == rb {
            if ob - oa != dx {
                self.wraps[ra] = true;
            }
            return self.wraps[ra];
        }
        // x(rb) − x(ra) = oa + dx − ob.
        let d = oa + dx - ob;
        let wraps = self.wraps[ra] || self.wraps[rb];
        let (big, small, off) = if self.size[ra] >= self.size[rb] {
            (ra, rb, d)
        } else {
            (rb, ra, -d)
        };
        self.parent[small] = big as u32;
        self.offset[small] = off;
        self.size[big] += self.size[small];
        self.wraps[big] = wraps;
        wraps
    }
}

fn check_size(len: usize, n: usize) {
    assert!(n >= 1, "grid side must be at least 1");
    assert_eq!(len, n * n, "mask must hold n² cells");
}

/// Percolation analysis of an open mask on the periodic `n × n` grid (flow along x, periodic in
/// y, 4-connectivity). Panics if `open.len() != n²`.
pub fn analyse(open: &[bool], n: usize) -> Percolation {
    check_size(open.len(), n);
    let cells = n * n;
    let mut uf = WindingUnionFind::new(cells);
    unite_open_neighbours(open, n, &mut uf, false);
    let mut root_label: Vec<u32> = vec![u32::MAX; cells];
    let mut labels = vec![None; cells];
    let mut clusters = 0u32;
    let mut spanning_cells = 0usize;
    let mut closed = 0usize;
    for i in 0..cells {
        if !open[i] {
            closed += 1;
            continue;
        }
        let (root, _) = uf.find(i);
        if !uf.wraps[root] {
            continue;
        }
        if root_label[root] == u32::MAX {
            root_label[root] = clusters;
            clusters += 1;
        }
        labels[i] = Some(root_label[root]);
        spanning_cells += 1;
    }
    Percolation {
        n,
        labels,
        spanning_clusters: clusters as usize,
        contact_fraction: closed as f64 / cells as f64,
        spanning_fraction: spanning_cells as f64 / cells as f64,
    }
}

/// Mask of the open cells that belong to a cluster winding around the cell in x, or `None` when
/// the open region does not percolate along x. See [`analyse`].
pub fn spanning_cluster(open: &[bool], n: usize) -> Option<Vec<bool>> {
    let p = analyse(open, n);
    p.percolates().then(|| p.spanning_mask())
}

/// True when the open region percolates along x (cheaper than [`analyse`]: stops at the first
/// winding loop).
pub fn percolates(open: &[bool], n: usize) -> bool {
    check_size(open.len(), n);
    unite_open_neighbours(open, n, &mut WindingUnionFind::new(n * n), true)
}

/// Unites every open cell with its open east and north neighbours (periodic, 4-connectivity;
/// each bond once). Returns whether some union closed a loop winding around x; with
/// `stop_at_first_wrap` it returns at that union, leaving the rest un-united.
fn unite_open_neighbours(
    open: &[bool],
    n: usize,
    uf: &mut WindingUnionFind,
    stop_at_first_wrap: bool,
) -> bool {
    let mut wrapped = false;
    for iy in 0..n {
        let north_row = ((iy + 1) % n) * n;
        for ix in 0..n {
            let i = iy * n + ix;
            if !open[i] {
                continue;
            }
            for (other, dx) in [(iy * n + (ix + 1) % n, 1), (north_row + ix, 0)] {
                if open[other] && uf.union(i, other, dx) {
                    wrapped = true;
                    if stop_at_first_wrap {
                        return true;
                    }
                }
            }
        }
    }
    wrapped
}

/// Exact percolation threshold of a scalar field: see [`critical_level`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelThreshold {
    /// The field value of the cell whose opening first makes a cluster wind around x. With the
    /// cells open where `field < level`, the open region percolates for every `level` above this
    /// value and does not for any `level` at or below it.
    pub level: f64,
    /// Number of open cells at the threshold (including the cell that completes the path).
    pub open_cells: usize,
    /// Contact fraction at which percolation stops, `1 − open_cells/n²`: with one more closed
    /// cell (the one at `level`), nothing percolates.
    pub contact_fraction: f64,
}

/// Exact percolation threshold of the family of masks "open where `field < level`" on the
/// periodic `n × n` grid, as `level` rises (cells open in increasing order of `field`).
///
/// Example: a rigid flat at height `d` over a rigid rough surface `h` (gap `max(0, d − h)`, the
/// "bearing-area" model) is open where `h < d`: pass `field = h`; the result's `level` is the
/// critical height `d_c` and `contact_fraction` the closed area at which percolation stops.
/// Ties are opened in index order. One union–find pass over the sorted cells
/// (`O(n² log n)`). Returns `None` when no level percolates (cannot happen for `n ≥ 1`: the
/// all-open grid percolates).
pub fn critical_level(field: &[f64], n: usize) -> Option<LevelThreshold> {
    check_size(field.len(), n);
    let cells = n * n;
    let mut order: Vec<u32> = (0..cells as u32).collect();
    order.sort_by(|&a, &b| field[a as usize].total_cmp(&field[b as usize]));
    let mut open = vec![false; cells];
    let mut uf = WindingUnionFind::new(cells);
    for (k, &c) in order.iter().enumerate() {
        let i = c as usize;
        open[i] = true;
        let (ix, iy) = (i % n, i / n);
        let east = iy * n + (ix + 1) % n;
        let west = iy * n + (ix + n - 1) % n;
        let north = ((iy + 1) % n) * n + ix;
        let south = ((iy + n - 1) % n) * n + ix;
        let mut wraps = false;
        for (other, from, to, dx) in [
            (east, i, east, 1),
            (west, west, i, 1),
            (north, i, north, 0),
            (south, south, i, 0),
        ] {
            if open[other] {
                wraps |= uf.union(from, to, dx);
            }
        }
        if wraps {
            return Some(LevelThreshold {
                level: field[i],
                open_cells: k + 1,
                contact_fraction: 1.0 - (k + 1) as f64 / cells as f64,
            });
        }
    }
    None
}

/// A bracket on the percolation transition of a monotone family of masks; see
/// [`percolation_threshold`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThresholdBracket {
    /// Largest parameter found at which the open region still percolates.
    pub percolating: f64,
    /// Contact fraction at `percolating`.
    pub percolating_contact: f64,
    /// Smallest parameter found at which it no longer percolates.
    pub sealed: f64,
    /// Contact fraction at `sealed`.
    pub sealed_contact: f64,
    /// Number of masks evaluated.
    pub evaluations: usize,
}

/// Why [`percolation_threshold`] could not bracket the transition.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ThresholdError {
    /// The mask at the lower parameter does not percolate.
    SealedAtLow,
    /// The mask at the upper parameter still percolates.
    OpenAtHigh,
    /// The bounds or the tolerance are not finite and ordered.
    InvalidBounds,
}

impl std::fmt::Display for ThresholdError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::SealedAtLow => write!(f, "the open region does not percolate at the lower bound"),
            Self::OpenAtHigh => write!(f, "the open region still percolates at the upper bound"),
            Self::InvalidBounds => write!(f, "percolation threshold: invalid bounds or tolerance"),
        }
    }
}

impl std::error::Error for ThresholdError {}

/// Brackets the parameter at which percolation along x stops, for a family of open masks
/// `mask(t)` (each `n²` cells) whose contact grows with `t` — e.g. `t` the load (or its log) and
/// `mask(t)` the open mask of the BEM gap field at that load. Bisection on `t` in `[low, high]`
/// until the bracket is narrower than `tolerance` (in `t`); `mask(low)` must percolate and
/// `mask(high)` must not. Each step costs one evaluation of `mask` (one contact solve), so use a
/// loose tolerance; for a scalar field thresholded at increasing levels use the exact
/// [`critical_level`] instead.
///
/// The family needs to be monotone only near the transition for the bracket to be the
/// transition; otherwise it is *a* crossing from percolating to sealed.
pub fn percolation_threshold<F>(
    n: usize,
    mut mask: F,
    low: f64,
    high: f64,
    tolerance: f64,
) -> Result<ThresholdBracket, ThresholdError>
where
    F: FnMut(f64) -> Vec<bool>,
{
    if !(low.is_finite() && high.is_finite() && low < high && tolerance > 0.0) {
        return Err(ThresholdError::InvalidBounds);
    }
    let mut evaluate = |t: f64| {
        let m = mask(t);
        check_size(m.len(), n);
        let closed = m.iter().filter(|&&o| !o).count() as f64 / (n * n) as f64;
        (percolates(&m, n), closed)
    };
    let (open_low, contact_low) = evaluate(low);
    if !open_low {
        return Err(ThresholdError::SealedAtLow);
    }
    let (open_high, contact_high) = evaluate(high);
    if open_high {
        return Err(ThresholdError::OpenAtHigh);
    }
    let mut b = ThresholdBracket {
        percolating: low,
        percolating_contact: contact_low,
        sealed: high,
        sealed_contact: contact_high,
        evaluations: 2,
    };
    while b.sealed - b.percolating > tolerance {
        let mid = 0.5 * (b.percolating + b.sealed);
        if mid <= b.percolating || mid >= b.sealed {
            break;
        }
        let (open, contact) = evaluate(mid);
        b.evaluations += 1;
        if open {
            b.percolating = mid;
            b.percolating_contact = contact;
        } else {
            b.sealed = mid;
            b.sealed_contact = contact;
        }
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand_chacha::ChaCha8Rng;
    use rand_core::{RngCore, SeedableRng};

    fn grid(n: usize, open: impl Fn(usize, usize) -> bool) -> Vec<bool> {
        (0..n * n).map(|i| open(i % n, i / n)).collect()
    }

    fn uniform(rng: &mut ChaCha8Rng) -> f64 {
        (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn random_sites(n: usize, p_open: f64, seed: u64) -> Vec<bool> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        (0..n * n).map(|_| uniform(&mut rng) < p_open).collect()
    }

    #[test]
    fn all_open_percolates_all_closed_does_not() {
        let n = 16;
        let open = vec![true; n * n];
        let p = analyse(&open, n);
        assert!(p.percolates());
        assert_eq!(p.spanning_clusters, 1);
        assert_eq!(p.contact_fraction, 0.0);
        assert_eq!(p.spanning_fraction, 1.0);
        assert!(percolates(&open, n));
        let closed = vec![false; n * n];
        let p = analyse(&closed, n);
        assert!(!p.percolates());
        assert_eq!(p.contact_fraction, 1.0);
        assert!(spanning_cluster(&closed, n).is_none());
        assert!(!percolates(&closed, n));
    }

    #[test]
    fn straight_channel_along_x_percolates_along_y_does_not() {
        let n = 12;
        let along_x = grid(n, |_, iy| iy == 5);
        let mask = spanning_cluster(&along_x, n).expect("a row channel spans x");
        assert_eq!(mask, along_x);
        let p = analyse(&along_x, n);
        assert_eq!(p.spanning_clusters, 1);
        assert!((p.contact_fraction - 11.0 / 12.0).abs() < 1e-15);
        let along_y = grid(n, |ix, _| ix == 5);
        assert!(spanning_cluster(&along_y, n).is_none());
        assert!(!percolates(&along_y, n));
        // Two separate channels along x are two spanning clusters.
        let two = grid(n, |_, iy| iy == 2 || iy == 7);
        assert_eq!(analyse(&two, n).spanning_clusters, 2);
    }

    #[test]
    fn channel_through_the_periodic_boundary_percolates() {
        // A channel that reaches x = L only through the wrap, shifted in y on the way.
        let n = 10;
        let open = grid(n, |ix, iy| {
            (iy == 3 && ix <= 6) || (ix == 6 && (3..=8).contains(&iy)) || (iy == 8 && ix >= 6)
        });
        // Unrolled: row 3 from x = 0..6, up column 6 to row 8, then row 8 to x = 9 — but row 8
        // at x = 9 wraps to (0, 8), which is closed: no spanning path.
        assert!(!percolates(&open, n));
        let closed_loop = grid(n, |ix, iy| {
            (iy == 3 && ix <= 6)
                || (ix == 6 && (3..=8).contains(&iy))
                || (iy == 8 && ix >= 6)
                || (ix == 0 && (3..=8).contains(&iy))
        });
        assert!(percolates(&closed_loop, n));
    }

    #[test]
    fn winding_around_y_only_does_not_percolate() {
        // A zig-zag channel that winds around y but spans only half of x.
        let n = 16;
        let open = grid(n, |ix, iy| {
            let centre = if iy < n / 2 {
                2 + iy / 2
            } else {
                2 + (n - iy) / 2
            };
            ix == centre || ix == centre + 1
        });
        let p = analyse(&open, n);
        assert!(!p.percolates());
        assert!(p.labels.iter().all(Option::is_none));
        // The same channel plus a row across x percolates, and the zig-zag (a dead end in x,
        // connected to the row) belongs to the spanning cluster.
        let with_row = grid(n, |ix, iy| open[iy * n + ix] || iy == 0);
        let p = analyse(&with_row, n);
        assert_eq!(p.spanning_clusters, 1);
        assert_eq!(p.spanning_mask(), with_row);
    }

    #[test]
    fn corner_contacts_do_not_connect() {
        let n = 8;
        let diagonal = grid(n, |ix, iy| ix == iy);
        assert!(!percolates(&diagonal, n));
        assert!(analyse(&diagonal, n).labels.iter().all(Option::is_none));
        // A 4-connected staircase along the diagonal winds once in x and once in y: it percolates.
        let staircase = grid(n, |ix, iy| ix == iy || ix == (iy + 1) % n);
        let mask = spanning_cluster(&staircase, n).expect("the staircase spans x");
        assert_eq!(mask, staircase);
        // A staircase that winds twice around y per turn around x still percolates.
        let steep = grid(n, |ix, iy| (iy + n - (2 * ix) % n) % n <= 2);
        assert!(percolates(&steep, n));
        assert!(!percolates(
            &grid(n, |ix, iy| (iy + n - (2 * ix) % n) % n <= 1),
            n
        ));
    }

    #[test]
    fn isolated_lakes_are_not_in_the_spanning_cluster() {
        let n = 12;
        let open = grid(n, |ix, iy| {
            iy == 0 || ((5..=7).contains(&ix) && (4..=6).contains(&iy))
        });
        let p = analyse(&open, n);
        assert_eq!(p.spanning_clusters, 1);
        let mask = p.spanning_mask();
        for iy in 0..n {
            for ix in 0..n {
                assert_eq!(mask[iy * n + ix], iy == 0, "cell ({ix}, {iy})");
            }
        }
        assert!((p.spanning_fraction - 1.0 / 12.0).abs() < 1e-15);
    }

    #[test]
    fn tiny_grids() {
        assert!(percolates(&[true], 1));
        assert!(!percolates(&[false], 1));
        assert!(percolates(&[true, true, false, false], 2));
        assert!(!percolates(&[true, false, true, false], 2));
        assert!(!percolates(&[true, false, false, true], 2));
    }

    #[test]
    fn random_site_percolation_far_from_threshold() {
        // Square-lattice site percolation threshold p_c = 0.592746.
        let n = 128;
        let trials = 20;
        let low = (0..trials)
            .filter(|&s| percolates(&random_sites(n, 0.3, s), n))
            .count();
        let high = (0..trials)
            .filter(|&s| percolates(&random_sites(n, 0.8, 1000 + s), n))
            .count();
        assert_eq!(low, 0);
        assert_eq!(high, trials as usize);
        // analyse agrees with percolates
        for s in 0..5 {
            let m = random_sites(64, 0.59, 77 + s);
            assert_eq!(analyse(&m, 64).percolates(), percolates(&m, 64));
        }
    }

    #[test]
    fn critical_level_of_a_random_field_is_the_site_threshold() {
        let n = 256;
        let seeds = 8;
        let mut mean = 0.0;
        for s in 0..seeds {
            let mut rng = ChaCha8Rng::seed_from_u64(500 + s);
            let field: Vec<f64> = (0..n * n).map(|_| uniform(&mut rng)).collect();
            let t = critical_level(&field, n).expect("non-empty");
            // Consistency with the direct test on either side of the level.
            let above: Vec<bool> = field.iter().map(|&f| f <= t.level).collect();
            let below: Vec<bool> = field.iter().map(|&f| f < t.level).collect();
            assert!(percolates(&above, n));
            assert!(!percolates(&below, n));
            assert_eq!(above.iter().filter(|&&o| o).count(), t.open_cells);
            mean += (1.0 - t.contact_fraction) / seeds as f64;
        }
        // Wrapping threshold on a 256² torus: p_c ± O(n^{-3/4}) per sample.
        assert!((mean - 0.5927).abs() < 0.015, "mean open fraction {mean}");
    }

    #[test]
    fn bisection_brackets_the_exact_level() {
        let n = 64;
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let field: Vec<f64> = (0..n * n).map(|_| uniform(&mut rng)).collect();
        let exact = critical_level(&field, n).unwrap();
        // Parameter t = closing level: open where field < 1 − t (contact grows with t).
        let b = percolation_threshold(
            n,
            |t| field.iter().map(|&f| f < 1.0 - t).collect(),
            0.0,
            1.0,
            1e-9,
        )
        .unwrap();
        assert!(1.0 - b.percolating > exact.level && 1.0 - b.sealed <= exact.level);
        assert!(b.sealed - b.percolating <= 1e-9);
        assert!((b.percolating_contact - exact.contact_fraction).abs() <= 1.0 / (n * n) as f64);
        assert!(b.sealed_contact > b.percolating_contact);
        assert_eq!(
            percolation_threshold(n, |_| vec![false; n * n], 0.0, 1.0, 0.1),
            Err(ThresholdError::SealedAtLow)
        );
        assert_eq!(
            percolation_threshold(n, |_| vec![true; n * n], 0.0, 1.0, 0.1),
            Err(ThresholdError::OpenAtHigh)
        );
    }
}
