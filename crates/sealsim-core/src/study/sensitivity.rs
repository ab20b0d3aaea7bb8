//! Which input drives the life (docs/model.md §14.3): Spearman's rank correlation between each
//! numeric input and the time to failure over the cases of a study, and for an input of words
//! (compounds, levels), whose order means nothing, the correlation ratio η of the life's ranks
//! across its groups. Both lie in [0, 1] in magnitude; for a numeric input η ≥ |ρ| (ρ captures
//! only the monotone part).

/// Ranks of `values` (1 = smallest), ties given their mean rank.
pub fn ranks(values: &[f64]) -> Vec<f64> {
    let mut order: Vec<usize> = (0..values.len()).collect();
    order.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
    let mut out = vec![0.0; values.len()];
    let mut i = 0;
    while i < order.len() {
        let mut j = i;
        while j + 1 < order.len() && values[order[j + 1]] == values[order[i]] {
            j += 1;
        }
        // positions i..=j share the mean of ranks i+1 … j+1
        let mean = 0.5 * ((i + 1) + (j + 1)) as f64;
        for &k in &order[i..=j] {
            out[k] = mean;
        }
        i = j + 1;
    }
    out
}

/// Spearman's ρ of `x` and `y` (equal lengths ≥ 2): Pearson's correlation of their ranks, in
/// [−1, 1]; `None` when either is constant or the lengths differ.
pub fn spearman(x: &[f64], y: &[f64]) -> Option<f64> {
    if x.len() != y.len() || x.len() < 2 {
        return None;
    }
    let (rx, ry) = (ranks(x), ranks(y));
    let n = rx.len() as f64;
    let (mx, my) = (rx.iter().sum::<f64>() / n, ry.iter().sum::<f64>() / n);
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (a, b) in rx.iter().zip(&ry) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx) * (a - mx);
        syy += (b - my) * (b - my);
    }
    (sxx > 0.0 && syy > 0.0).then(|| (sxy / (sxx * syy).sqrt()).clamp(-1.0, 1.0))
}

/// The correlation ratio η of `y`'s ranks over the groups `group` (equal lengths):
/// `η² = Σ_g n_g (r̄_g − r̄)² / Σ_i (r_i − r̄)²`, in [0, 1]: 1 when the group decides the rank
/// entirely, 0 when every group has the same mean rank. `None` with one group or a constant `y`.
pub fn correlation_ratio(group: &[usize], y: &[f64]) -> Option<f64> {
    if group.len() != y.len() || y.len() < 2 {
        return None;
    }
    let r = ranks(y);
    let n = r.len() as f64;
    let mean = r.iter().sum::<f64>() / n;
    let groups = group.iter().max().map_or(0, |m| m + 1);
    let (mut sum, mut count) = (vec![0.0; groups], vec![0usize; groups]);
    for (&g, &ri) in group.iter().zip(&r) {
        sum[g] += ri;
        count[g] += 1;
    }
    if count.iter().filter(|&&c| c > 0).count() < 2 {
        return None;
    }
    let between: f64 = sum
        .iter()
        .zip(&count)
        .filter(|(_, c)| **c > 0)
        .map(|(s, &c)| c as f64 * (s / c as f64 - mean).powi(2))
        .sum();
    let total: f64 = r.iter().map(|v| (v - mean).powi(2)).sum();
    (total > 0.0).then(|| (between / total).sqrt().clamp(0.0, 1.0))
}

/// One varied input's values over the cases.
#[derive(Debug, Clone, PartialEq)]
pub enum Column {
    /// Numbers: Spearman's ρ.
    Numeric(Vec<f64>),
    /// Group indices (words): the correlation ratio η.
    Categorical(Vec<usize>),
}

/// The inputs ordered by the magnitude of their measure (ρ or η) with the output, largest
/// first: `(index, measure)`; inputs with none (constant) last.
pub fn ranking(inputs: &[Column], output: &[f64]) -> Vec<(usize, Option<f64>)> {
    let mut out: Vec<(usize, Option<f64>)> = inputs
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let m = match x {
                Column::Numeric(x) => spearman(x, output),
                Column::Categorical(g) => correlation_ratio(g, output),
            };
            (i, m)
        })
        .collect();
    out.sort_by(|a, b| {
        let key = |r: &Option<f64>| r.map_or(-1.0, f64::abs);
        key(&b.1).total_cmp(&key(&a.1)).then(a.0.cmp(&b.0))
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::SplitMix64;

    #[test]
    fn ranks_average_ties_and_rho_has_its_limits() {
        assert_eq!(ranks(&[3.0, 1.0, 3.0, 2.0]), vec![3.5, 1.0, 3.5, 2.0]);
        let x = [1.0, 2.0, 3.0, 4.0, 5.0];
        // any increasing transform: ρ = 1; decreasing: −1
        let y: Vec<f64> = x.iter().map(|v: &f64| v.exp()).collect();
        assert_eq!(spearman(&x, &y), Some(1.0));
        let z: Vec<f64> = x.iter().map(|v| -v * v * v).collect();
        assert_eq!(spearman(&x, &z), Some(-1.0));
        assert_eq!(spearman(&x, &[1.0; 5]), None);
        // the textbook value: ranks (1,2,3,4,5) vs (2,1,4,3,5): 1 − 6Σd²/(n(n²−1)) = 0.8
        let w = [2.0, 1.0, 4.0, 3.0, 5.0];
        assert!((spearman(&x, &w).unwrap() - 0.8).abs() < 1e-15);
    }

    #[test]
    fn the_dominant_input_is_ranked_first() {
        // life = 10 − 8·squeeze-like input + 1·finish-like input + noise, the third input
        // irrelevant: the ranking must be 0, 1, 2 and the first ρ negative
        let mut rng = SplitMix64(7);
        let n = 500;
        let mut inputs: Vec<Vec<f64>> = (0..3).map(|_| Vec::with_capacity(n)).collect();
        let mut life = Vec::with_capacity(n);
        for _ in 0..n {
            let a = rng.uniform();
            let b = rng.uniform();
            let c = rng.uniform();
            let (noise, _) = rng.normal_pair();
            inputs[0].push(a);
            inputs[1].push(b);
            inputs[2].push(c);
            life.push(10.0 - 8.0 * a + 1.0 * b + 0.3 * noise);
        }
        let columns: Vec<Column> = inputs.into_iter().map(Column::Numeric).collect();
        let r = ranking(&columns, &life);
        assert_eq!(r.iter().map(|(i, _)| *i).collect::<Vec<_>>(), vec![0, 1, 2]);
        assert!(r[0].1.unwrap() < -0.9);
        assert!(r[2].1.unwrap().abs() < 0.15);
    }

    #[test]
    fn the_correlation_ratio_has_its_limits_and_ranks_a_decisive_compound_first() {
        // the group decides the life entirely (no spread within groups): η = 1; ranks 1…4 in
        // two groups: η² = 4/5 (between 2·1² + 2·1², total 5); equal group mean ranks: η = 0
        assert_eq!(
            correlation_ratio(&[0, 0, 1, 1], &[1.0, 1.0, 3.0, 3.0]),
            Some(1.0)
        );
        let eta = correlation_ratio(&[0, 0, 1, 1], &[1.0, 2.0, 3.0, 4.0]).unwrap();
        assert!((eta - 0.8f64.sqrt()).abs() < 1e-15);
        assert_eq!(
            correlation_ratio(&[0, 1, 1, 0], &[1.0, 2.0, 3.0, 4.0]),
            Some(0.0)
        );
        assert_eq!(correlation_ratio(&[0, 0, 0], &[1.0, 2.0, 3.0]), None);
        // three compounds in an order that means nothing: lives 1, 10, 3 (× noise); a numeric
        // input with a weak effect; the compound must come first although its ρ would be small
        let mut rng = SplitMix64(11);
        let n = 600;
        let (mut compound, mut weak, mut life) = (vec![], vec![], vec![]);
        for i in 0..n {
            let g = i % 3;
            let w = rng.uniform();
            let (noise, _) = rng.normal_pair();
            compound.push(g);
            weak.push(w);
            life.push([1.0, 10.0, 3.0][g] * (1.0 + 0.3 * w) * (0.2 * noise).exp());
        }
        let columns = vec![Column::Numeric(weak), Column::Categorical(compound)];
        let r = ranking(&columns, &life);
        assert_eq!(r[0].0, 1);
        assert!(r[0].1.unwrap() > 0.8, "η = {:?}", r[0].1);
    }
}
