//! Sorting for the short lists the program orders: tick candidates, labels, the panels of a
//! layout, the rows of a trace bucket, the ten eigenvalues of the sampled loop, a map's grid
//! values — never more than a few hundred items.
//!
//! Why not `slice::sort_by`: the standard library's sort is generic code of ≈ 7 kB of wasm per
//! call site at opt-level 3, 56 kB in all for these call sites; this insertion sort is a few
//! hundred bytes. It is stable, and quadratic, so it is for short slices only.
//!
//! Architecture invariant: depends on nothing else in the crate.

use std::cmp::Ordering;

/// Sorts `v` stably by `compare`, as `slice::sort_by` would; O(n²), for short slices.
pub fn sort_by<T>(v: &mut [T], mut compare: impl FnMut(&T, &T) -> Ordering) {
    for i in 1..v.len() {
        let mut j = i;
        while j > 0 && compare(&v[j], &v[j - 1]) == Ordering::Less {
            v.swap(j, j - 1);
            j -= 1;
        }
    }
}

/// Sorts `v` stably by `key`, as `slice::sort_by_key` would; O(n²), for short slices.
pub fn sort_by_key<T, K: Ord>(v: &mut [T], mut key: impl FnMut(&T) -> K) {
    sort_by(v, |a, b| key(a).cmp(&key(b)));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorts_like_the_standard_library_and_keeps_ties_in_order() {
        // A deterministic scramble with many ties.
        let items: Vec<(u32, usize)> = (0..300).map(|i| ((i * 7919 % 31) as u32, i)).collect();
        let mut ours = items.clone();
        sort_by_key(&mut ours, |&(k, _)| k);
        let mut std_sorted = items;
        std_sorted.sort_by_key(|&(k, _)| k);
        assert_eq!(ours, std_sorted);
        let mut floats = [3.5, -1.0, f64::INFINITY, 0.0, -0.0, 2.0];
        sort_by(&mut floats, |a, b| a.total_cmp(b));
        assert_eq!(floats.map(f64::to_bits), [-1.0, -0.0, 0.0, 2.0, 3.5, f64::INFINITY].map(f64::to_bits));
        let mut empty: [u8; 0] = [];
        sort_by_key(&mut empty, |&x| x);
    }
}
