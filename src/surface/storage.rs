//! Storage order and memory locality of the pseudo-surface: ψ_v's control points are stored in
//! breadth-first order over the links, and batches of evaluations run in that order
//! (neighbouring charts share cache lines). Affects speed only, never results.

use crate::mesh::VertexId;
use rayon::prelude::*;

/// Prefetch the cache line holding `x` (x86-64 only; a hint without effect on results).
#[inline(always)]
pub(super) fn prefetch(x: &f64) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: PREFETCHT0 is an SSE instruction (baseline on x86-64) that never faults and
    // does not access memory architecturally; the pointer comes from a valid reference.
    unsafe {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        _mm_prefetch::<_MM_HINT_T0>(x as *const f64 as *const i8);
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = x;
}

/// `f(i)` for i = 0..keys.len(), evaluated in parallel in the order of increasing `keys[i]`
/// (locality), returned in index order.
pub(crate) fn map_in_key_order<T: Send>(
    keys: &[u32],
    f: impl Fn(usize) -> T + Sync + Send,
) -> Vec<T> {
    let order = key_order(keys);
    let mut done: Vec<Option<T>> = order.par_iter().map(|&i| Some(f(i as usize))).collect();
    // pos[i]: where the result of i is in `done`.
    let mut pos = vec![0u32; keys.len()];
    for (p, &i) in order.iter().enumerate() {
        pos[i as usize] = p as u32;
    }
    // `order` is a permutation of 0..keys.len(): every result is taken once.
    pos.iter()
        .filter_map(|&p| done[p as usize].take())
        .collect()
}

/// The indices 0..keys.len() by increasing (key, index). The keys are storage ranks (below the
/// number of vertex slots) or `u32::MAX` (an unknown face, last): a counting sort, stable in
/// the index, gives the order of sorting the pairs (key, index) in O(n) (the comparison sort
/// of 800k pairs was a few per cent of a level-2 sampling); keys spread far beyond the number
/// of points are sorted.
fn key_order(keys: &[u32]) -> Vec<u32> {
    let top = keys
        .iter()
        .copied()
        .filter(|&k| k != u32::MAX)
        .max()
        .map_or(0, |k| k as usize + 1);
    if top > 4 * keys.len() + 1024 {
        let mut order: Vec<(u32, u32)> = keys
            .iter()
            .enumerate()
            .map(|(i, &k)| (k, i as u32))
            .collect();
        order.par_sort_unstable();
        return order.into_iter().map(|(_, i)| i).collect();
    }
    // start[k]: where the indices of key k begin; the last bucket holds u32::MAX.
    let bucket = |k: u32| if k == u32::MAX { top } else { k as usize };
    let mut start = vec![0u32; top + 2];
    for &k in keys {
        start[bucket(k) + 1] += 1;
    }
    for b in 1..start.len() {
        start[b] += start[b - 1];
    }
    let mut order = vec![0u32; keys.len()];
    for (i, &k) in keys.iter().enumerate() {
        let at = &mut start[bucket(k)];
        order[*at as usize] = i as u32;
        *at += 1;
    }
    order
}

/// The vertices of degree ≥ 3 in breadth-first order over the links (component by component,
/// each from its smallest vertex id), followed by the other slots.
pub(super) fn bfs_order(degree: &[u32], nbr_start: &[usize], nbr: &[VertexId]) -> Vec<VertexId> {
    let slots = degree.len();
    let mut seen = vec![false; slots];
    let mut order = Vec::with_capacity(slots);
    for s in 0..slots {
        if seen[s] || degree[s] < 3 {
            continue;
        }
        seen[s] = true;
        let mut head = order.len();
        order.push(VertexId(s as u32));
        while head < order.len() {
            let v = order[head].idx();
            head += 1;
            for &u in &nbr[nbr_start[v]..nbr_start[v + 1]] {
                if !seen[u.idx()] {
                    seen[u.idx()] = true;
                    order.push(u);
                }
            }
        }
    }
    for (s, done) in seen.iter().enumerate() {
        if !done {
            order.push(VertexId(s as u32));
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::key_order;

    /// The counting sort gives the order of sorting the pairs (key, index), unknown faces
    /// (`u32::MAX`) last, on dense keys and on keys that take the comparison sort.
    #[test]
    fn key_order_is_the_sorted_pairs_order() {
        let mut x = 12345u64;
        for (n, spread) in [
            (0usize, 1u32),
            (1, 1),
            (1000, 50),
            (5000, 2000),
            (300, u32::MAX - 1),
        ] {
            let keys: Vec<u32> = (0..n)
                .map(|_| {
                    x = x
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    let r = (x >> 33) as u32;
                    if r % 17 == 0 {
                        u32::MAX
                    } else {
                        r % spread
                    }
                })
                .collect();
            let mut want: Vec<(u32, u32)> = keys
                .iter()
                .enumerate()
                .map(|(i, &k)| (k, i as u32))
                .collect();
            want.sort_unstable();
            let want: Vec<u32> = want.into_iter().map(|(_, i)| i).collect();
            assert_eq!(key_order(&keys), want, "n {n}, spread {spread}");
        }
    }
}
