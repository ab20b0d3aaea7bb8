//! Aggregation algebraic multigrid with geometric guidance for the periodic five-point operator
//! [`GridLaplacian`], used as the preconditioner of flexible conjugate gradients
//! ([`super::cg`]).
//!
//! * Aggregates are the strongly connected components of the nodes of 2 × 2 blocks (a face is
//!   strong when its conductance is at least 0.25 of the largest face of both its cells, so no
//!   aggregate straddles a constriction; a node left alone joins the neighbour it is most
//!   strongly tied to);
//! * Galerkin coarse operators (piecewise-constant prolongation: the coarse conductance between
//!   two aggregates is the sum of the fine faces between them);
//! * symmetric Gauss–Seidel smoothing;
//! * K-cycle on the coarse levels (Notay & Vassilevski, Numer. Linear Algebra Appl. 15 (2008)
//!   473): two recursive cycles combined by two steps of flexible conjugate gradients, which keeps
//!   the rate of unsmoothed aggregation independent of the number of levels without a tuned
//!   over-correction;
//! * dense Cholesky ([`DenseCholesky`]) on the coarsest level (≤ 400 unknowns).
//!
//! On the Reynolds flow of the numerical reference (`numerical::flow`) this takes about 25–40
//! iterations independent of the grid size on rough gap fields with 20–30 % contact, and just
//! above the percolation threshold.

use super::cg::Preconditioner;
use super::cholesky::DenseCholesky;
use super::dot;
use super::laplacian::GridLaplacian;
/// Aggregation strength threshold: a face joins two nodes into one aggregate only if its
/// conductance is at least this fraction of the largest face of *both* nodes, so aggregates do
/// not straddle constrictions (weak links would otherwise be short-circuited on the coarse grids).
const STRENGTH: f64 = 0.25;
/// The hierarchy stops at a level with at most this many unknowns (dense Cholesky).
const COARSEST_NODES: usize = 400;
/// The K-cycle skips its second step when the first reduced the residual below this fraction.
const KRYLOV_SKIP: f64 = 0.25;
/// Symmetric Gauss–Seidel sweeps before and after the coarse correction.
const SWEEPS: usize = 1;

const NONE: u32 = u32::MAX;

/// A coarse level: graph Laplacian with sinks in compressed rows,
/// `(A x)_i = d_i x_i − Σ_e w_e x_col(e)`, `d_i = Σ_e w_e + sink_i`. Its nodes belong to the
/// blocks of a `side × side` periodic grid of cell blocks and are sorted by block.
#[derive(Debug, Clone)]
struct Sparse {
    side: usize,
    /// First node of every block (`side² + 1` entries).
    block_start: Vec<u32>,
    /// First edge of every node (`nodes + 1` entries).
    start: Vec<u32>,
    col: Vec<u32>,
    weight: Vec<f64>,
    sink: Vec<f64>,
    diag: Vec<f64>,
    inv_diag: Vec<f64>,
}

impl Sparse {
    fn nodes(&self) -> usize {
        self.start.len() - 1
    }

    fn finish(
        side: usize,
        block_start: Vec<u32>,
        start: Vec<u32>,
        col: Vec<u32>,
        weight: Vec<f64>,
        sink: Vec<f64>,
    ) -> Self {
        let diag: Vec<f64> = (0..start.len() - 1)
            .map(|i| {
                weight[start[i] as usize..start[i + 1] as usize]
                    .iter()
                    .sum::<f64>()
                    + sink[i]
            })
            .collect();
        let inv_diag = diag
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        Self {
            side,
            block_start,
            start,
            col,
            weight,
            sink,
            diag,
            inv_diag,
        }
    }

    /// The fine grid as a graph (one node per cell with a non-zero diagonal, in cell order),
    /// with the node of every cell (`NONE` for cells out of the system).
    fn from_grid(grid: &GridLaplacian) -> (Self, Vec<u32>) {
        let cells = grid.cells();
        let mut node = vec![NONE; cells];
        let mut block_start = Vec::with_capacity(cells + 1);
        let mut count = 0u32;
        for (i, slot) in node.iter_mut().enumerate() {
            block_start.push(count);
            if grid.diagonal()[i] > 0.0 {
                *slot = count;
                count += 1;
            }
        }
        block_start.push(count);
        let mut start = Vec::with_capacity(count as usize + 1);
        start.push(0u32);
        let mut col = Vec::with_capacity(4 * count as usize);
        let mut weight = Vec::with_capacity(4 * count as usize);
        let mut sink = Vec::with_capacity(count as usize);
        for i in 0..cells {
            if node[i] == NONE {
                continue;
            }
            for (j, g) in grid.neighbours(i) {
                if g > 0.0 {
                    col.push(node[j]);
                    weight.push(g);
                }
            }
            sink.push(grid.sinks()[i]);
            start.push(col.len() as u32);
        }
        (
            Self::finish(grid.side(), block_start, start, col, weight, sink),
            node,
        )
    }

    fn edges(&self, i: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let range = self.start[i] as usize..self.start[i + 1] as usize;
        self.col[range.clone()]
            .iter()
            .zip(&self.weight[range])
            .map(|(&j, &w)| (j as usize, w))
    }

    /// Aggregates: within every 2 × 2 super-block of blocks, the connected components of the
    /// nodes under the strong edges (`w ≥ θ · max(largest edge of either end)`). Returns the
    /// aggregate of every node, the first aggregate of every super-block and their count.
    fn aggregate(&self, theta: f64) -> (Vec<u32>, Vec<u32>, usize) {
        let nodes = self.nodes();
        let largest: Vec<f64> = (0..nodes)
            .map(|i| self.edges(i).map(|(_, w)| w).fold(0.0, f64::max))
            .collect();
        let side = self.side;
        let cs = side.div_ceil(2);
        let mut agg = vec![NONE; nodes];
        let mut stamp = vec![NONE; nodes];
        let mut coarse_start = Vec::with_capacity(cs * cs + 1);
        let mut members: Vec<usize> = Vec::new();
        let mut stack: Vec<usize> = Vec::new();
        let mut sizes: Vec<u32> = Vec::new();
        let mut renumber: Vec<u32> = Vec::new();
        let mut count = 0u32;
        for by in 0..cs {
            for bx in 0..cs {
                coarse_start.push(count);
                let s = (by * cs + bx) as u32;
                members.clear();
                for (cx, cy) in [
                    (2 * bx, 2 * by),
                    (2 * bx + 1, 2 * by),
                    (2 * bx, 2 * by + 1),
                    (2 * bx + 1, 2 * by + 1),
                ] {
                    if cx < side && cy < side {
                        let b = cy * side + cx;
                        let range = self.block_start[b]..self.block_start[b + 1];
                        members.extend(range.map(|i| i as usize));
                    }
                }
                for &i in &members {
                    stamp[i] = s;
                }
                // Phase 1: components under the strong edges, local ids from `first`.
                let first = count;
                sizes.clear();
                for &i in &members {
                    if agg[i] != NONE {
                        continue;
                    }
                    let id = count;
                    agg[i] = id;
                    let mut size = 1u32;
                    stack.push(i);
                    while let Some(k) = stack.pop() {
                        for (j, w) in self.edges(k) {
                            if stamp[j] == s
                                && agg[j] == NONE
                                && w >= theta * largest[k].max(largest[j])
                            {
                                agg[j] = id;
                                size += 1;
                                stack.push(j);
                            }
                        }
                    }
                    sizes.push(size);
                    count += 1;
                }
                // Phase 2: a node left alone joins the neighbouring aggregate of the super-block
                // it is most strongly tied to, if that tie is strong from its own side.
                let mut merged = false;
                for &i in &members {
                    if sizes[(agg[i] - first) as usize] != 1 {
                        continue;
                    }
                    let best = self
                        .edges(i)
                        .filter(|&(j, _)| stamp[j] == s && agg[j] != agg[i])
                        .max_by(|a, b| a.1.total_cmp(&b.1));
                    if let Some((j, w)) = best
                        && w >= theta * largest[i]
                    {
                        sizes[(agg[i] - first) as usize] = 0;
                        agg[i] = agg[j];
                        sizes[(agg[j] - first) as usize] += 1;
                        merged = true;
                    }
                }
                if merged {
                    // Renumber the aggregates of this super-block without the emptied ones.
                    renumber.clear();
                    let mut next = first;
                    for &size in &sizes {
                        renumber.push(next);
                        if size > 0 {
                            next += 1;
                        }
                    }
                    for &i in &members {
                        agg[i] = renumber[(agg[i] - first) as usize];
                    }
                    count = next;
                }
            }
        }
        coarse_start.push(count);
        (agg, coarse_start, count as usize)
    }

    /// Galerkin operator `Pᵀ A P` for the piecewise-constant prolongation of `agg`.
    fn galerkin(&self, agg: &[u32], coarse_start: Vec<u32>, count: usize) -> Sparse {
        // Members of every aggregate (counting sort).
        let mut first = vec![0u32; count + 1];
        for &a in agg {
            first[a as usize + 1] += 1;
        }
        for k in 0..count {
            first[k + 1] += first[k];
        }
        let mut fill = first.clone();
        let mut members = vec![0u32; agg.len()];
        for (i, &a) in agg.iter().enumerate() {
            members[fill[a as usize] as usize] = i as u32;
            fill[a as usize] += 1;
        }
        let mut position = vec![NONE; count];
        let mut start = Vec::with_capacity(count + 1);
        start.push(0u32);
        let mut col: Vec<u32> = Vec::new();
        let mut weight: Vec<f64> = Vec::new();
        let mut sink = Vec::with_capacity(count);
        for a in 0..count {
            let row = col.len();
            let mut s = 0.0;
            for &i in &members[first[a] as usize..first[a + 1] as usize] {
                s += self.sink[i as usize];
                for (j, w) in self.edges(i as usize) {
                    let b = agg[j];
                    if b as usize == a {
                        continue;
                    }
                    match position[b as usize] {
                        NONE => {
                            position[b as usize] = col.len() as u32;
                            col.push(b);
                            weight.push(w);
                        }
                        p => weight[p as usize] += w,
                    }
                }
            }
            for &b in &col[row..] {
                position[b as usize] = NONE;
            }
            sink.push(s);
            start.push(col.len() as u32);
        }
        Sparse::finish(
            self.side.div_ceil(2),
            coarse_start,
            start,
            col,
            weight,
            sink,
        )
    }

    /// y = A x.
    fn apply(&self, x: &[f64], y: &mut [f64]) {
        for i in 0..self.nodes() {
            let mut s = self.diag[i] * x[i];
            for (j, w) in self.edges(i) {
                s -= w * x[j];
            }
            y[i] = s;
        }
    }

    /// r = b − A x.
    fn residual(&self, b: &[f64], x: &[f64], r: &mut [f64]) {
        for i in 0..self.nodes() {
            let mut s = b[i] - self.diag[i] * x[i];
            for (j, w) in self.edges(i) {
                s += w * x[j];
            }
            r[i] = s;
        }
    }

    fn gauss_seidel(&self, b: &[f64], x: &mut [f64], forward: bool) {
        let mut relax = |i: usize| {
            let mut s = b[i];
            for (j, w) in self.edges(i) {
                s += w * x[j];
            }
            x[i] = s * self.inv_diag[i];
        };
        if forward {
            (0..self.nodes()).for_each(&mut relax);
        } else {
            (0..self.nodes()).rev().for_each(&mut relax);
        }
    }
}

/// Builds the coarse levels below a graph until one is small enough for the dense solve.
/// Returns the aggregate map of `fine` and the levels with the maps between them.
fn hierarchy(fine: &Sparse, theta: f64) -> (Vec<u32>, Vec<Sparse>, Vec<Vec<u32>>) {
    let mut levels: Vec<Sparse> = Vec::new();
    let mut maps: Vec<Vec<u32>> = Vec::new();
    let mut first_map = Vec::new();
    loop {
        let current = levels.last().unwrap_or(fine);
        if current.nodes() <= COARSEST_NODES || (current.side == 1 && !levels.is_empty()) {
            break;
        }
        let (mut agg, mut starts, mut count) = current.aggregate(theta);
        if count as f64 > 0.9 * current.nodes() as f64 {
            // Too little coarsening (many weak links): aggregate on the geometry alone.
            (agg, starts, count) = current.aggregate(0.0);
        }
        if count == current.nodes() && current.side == 1 {
            break;
        }
        let next = current.galerkin(&agg, starts, count);
        if levels.is_empty() {
            first_map = agg;
        } else {
            maps.push(agg);
        }
        levels.push(next);
    }
    (first_map, levels, maps)
}

/// Aggregation multigrid preconditioner (K-cycle) for a [`GridLaplacian`]; see the module docs.
#[derive(Debug, Clone)]
pub struct Multigrid {
    fine: GridLaplacian,
    /// Level-1 node of every fine cell (`NONE` outside the system), or, without coarse levels,
    /// the unknown of the dense solve.
    fine_map: Vec<u32>,
    /// Coarse levels 1, 2, … (the last one is solved directly).
    levels: Vec<Sparse>,
    /// `maps[k]`: node of `levels[k + 1]` for every node of `levels[k]`.
    maps: Vec<Vec<u32>>,
    dense: DenseCholesky,
    fine_res: Vec<f64>,
    scratch: Vec<f64>,
    /// Per coarse level, work vectors of the K-cycle: rhs copy, v1, A v1, A v2.
    krylov: Vec<[Vec<f64>; 4]>,
    /// Per coarse level: iterate, right-hand side, residual.
    x: Vec<Vec<f64>>,
    rhs: Vec<Vec<f64>>,
    res: Vec<Vec<f64>>,
}

impl Multigrid {
    /// Builds the hierarchy below the fine operator `fine` (aggregates, Galerkin coarse
    /// operators, the dense factor of the coarsest level).
    pub fn new(fine: GridLaplacian) -> Self {
        let (graph, node) = Sparse::from_grid(&fine);
        let (first_map, levels, maps) = hierarchy(&graph, STRENGTH);
        let (fine_map, dense) = match levels.last() {
            None => (node, dense_factor(&graph)),
            Some(coarsest) => {
                let map = node
                    .iter()
                    .map(|&k| {
                        if k == NONE {
                            NONE
                        } else {
                            first_map[k as usize]
                        }
                    })
                    .collect();
                (map, dense_factor(coarsest))
            }
        };
        drop(graph);
        let x = levels.iter().map(|g| vec![0.0; g.nodes()]).collect();
        let rhs = levels.iter().map(|g| vec![0.0; g.nodes()]).collect();
        let res = levels.iter().map(|g| vec![0.0; g.nodes()]).collect();
        Self {
            fine_res: vec![0.0; fine.cells()],
            scratch: Vec::new(),
            krylov: levels
                .iter()
                .map(|g| std::array::from_fn(|_| vec![0.0; g.nodes()]))
                .collect(),
            fine,
            fine_map,
            levels,
            maps,
            dense,
            x,
            rhs,
            res,
        }
    }

    /// z = B r: one cycle from z = 0 (symmetric Gauss–Seidel around the coarse correction).
    pub fn apply(&mut self, r: &[f64], z: &mut [f64]) {
        if self.levels.is_empty() {
            // Small system: exact solve.
            let rhs: Vec<f64> = self.dense_gather(r);
            let mut y = vec![0.0; rhs.len()];
            self.dense.solve(&rhs, &mut y);
            z.fill(0.0);
            for (zi, &k) in z.iter_mut().zip(&self.fine_map) {
                if k != NONE {
                    *zi = y[k as usize];
                }
            }
            return;
        }
        // Fine level: smooth, restrict, coarse cycle, prolong, smooth.
        z.fill(0.0);
        for _ in 0..SWEEPS {
            self.fine.gauss_seidel(r, z, true, &mut self.scratch);
        }
        self.fine.apply(z, &mut self.fine_res);
        let rhs1 = &mut self.rhs[0];
        rhs1.fill(0.0);
        for ((&k, q), b) in self.fine_map.iter().zip(&self.fine_res).zip(r) {
            if k != NONE {
                rhs1[k as usize] += b - q;
            }
        }
        self.coarse_cycle(0);
        let x1 = &self.x[0];
        for (zi, &k) in z.iter_mut().zip(&self.fine_map) {
            if k != NONE {
                *zi += x1[k as usize];
            }
        }
        for _ in 0..SWEEPS {
            self.fine.gauss_seidel(r, z, false, &mut self.scratch);
        }
    }

    /// Approximate solve of coarse level `l` (`x[l]` from `rhs[l]`, starting from 0):
    /// symmetric Gauss–Seidel around a correction from level `l + 1`, exact on the coarsest
    /// level. Above it the correction is the K-cycle of Notay & Vassilevski (Numer. Linear
    /// Algebra Appl. 15 (2008) 473): two recursive cycles combined by two steps of flexible
    /// conjugate gradients on level `l + 1`, which keeps the rate of unsmoothed aggregation
    /// independent of the number of levels without a tuned over-correction.
    fn coarse_cycle(&mut self, l: usize) {
        let last = self.levels.len() - 1;
        if l == last {
            self.dense.solve(&self.rhs[l], &mut self.x[l]);
            return;
        }
        self.x[l].fill(0.0);
        for _ in 0..SWEEPS {
            self.levels[l].gauss_seidel(&self.rhs[l], &mut self.x[l], true);
        }
        self.levels[l].residual(&self.rhs[l], &self.x[l], &mut self.res[l]);
        let next = l + 1;
        {
            let coarse = &mut self.rhs[next];
            coarse.fill(0.0);
            for (&k, q) in self.maps[l].iter().zip(&self.res[l]) {
                coarse[k as usize] += q;
            }
        }
        if next < last {
            self.krylov_correction(next);
        } else {
            self.coarse_cycle(next);
        }
        let (head, tail) = self.x.split_at_mut(next);
        for (xi, &k) in head[l].iter_mut().zip(&self.maps[l]) {
            *xi += tail[0][k as usize];
        }
        for _ in 0..SWEEPS {
            self.levels[l].gauss_seidel(&self.rhs[l], &mut self.x[l], false);
        }
    }

    /// K-cycle correction on level `m`: `x[m]` ≈ A⁻¹ `rhs[m]` from two preconditioned steps.
    fn krylov_correction(&mut self, m: usize) {
        // The work vectors of level m are not touched by the cycles below it.
        let mut work = std::mem::take(&mut self.krylov[m]);
        self.krylov_steps(m, &mut work);
        self.krylov[m] = work;
    }

    fn krylov_steps(&mut self, m: usize, [rc, v1, w1, w2]: &mut [Vec<f64>; 4]) {
        rc.copy_from_slice(&self.rhs[m]);
        self.coarse_cycle(m);
        v1.copy_from_slice(&self.x[m]);
        self.levels[m].apply(v1, w1);
        let rho1 = dot(v1, w1);
        if rho1.is_nan() || rho1 <= 0.0 {
            self.rhs[m].copy_from_slice(rc);
            return;
        }
        let alpha1 = dot(v1, rc) / rho1;
        // Second step on r2 = rc − α1 A v1, unless the first one left little residual.
        let r2 = &mut self.rhs[m];
        for ((r, c), w) in r2.iter_mut().zip(rc.iter()).zip(w1.iter()) {
            *r = c - alpha1 * w;
        }
        if dot(r2, r2) <= KRYLOV_SKIP * KRYLOV_SKIP * dot(rc, rc) {
            for (x, v) in self.x[m].iter_mut().zip(v1.iter()) {
                *x = alpha1 * v;
            }
            self.rhs[m].copy_from_slice(rc);
            return;
        }
        self.coarse_cycle(m);
        let v2 = &self.x[m];
        self.levels[m].apply(v2, w2);
        let gamma = dot(v2, w1);
        let beta = dot(v2, w2);
        let alpha2 = dot(v2, &self.rhs[m]);
        let rho2 = beta - gamma * gamma / rho1;
        let (c1, c2) = if rho2 > 0.0 {
            (alpha1 - gamma * alpha2 / (rho1 * rho2), alpha2 / rho2)
        } else {
            (alpha1, 0.0)
        };
        for (x, v) in self.x[m].iter_mut().zip(v1.iter()) {
            *x = c1 * v + c2 * *x;
        }
        self.rhs[m].copy_from_slice(rc);
    }

    fn dense_gather(&self, r: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.dense.size()];
        for (&k, &v) in self.fine_map.iter().zip(r) {
            if k != NONE {
                out[k as usize] = v;
            }
        }
        out
    }
}

impl Preconditioner for Multigrid {
    fn apply(&mut self, r: &[f64], z: &mut [f64]) {
        Multigrid::apply(self, r, z);
    }
}

/// Dense Cholesky factor of a (small) graph operator.
fn dense_factor(graph: &Sparse) -> DenseCholesky {
    let m = graph.nodes();
    let mut a = vec![0.0; m * m];
    for i in 0..m {
        a[i * m + i] += graph.diag[i];
        for (j, w) in graph.edges(i) {
            a[i * m + j] -= w;
        }
    }
    DenseCholesky::new(m, a)
}
