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
    let mut order: Vec<(u32, u32)> = keys
        .iter()
        .enumerate()
        .map(|(i, &k)| (k, i as u32))
        .collect();
    order.par_sort_unstable();
    let done: Vec<T> = order.par_iter().map(|&(_, i)| f(i as usize)).collect();
    let mut slots: Vec<Option<T>> = (0..keys.len()).map(|_| None).collect();
    for (&(_, i), r) in order.iter().zip(done) {
        slots[i as usize] = Some(r);
    }
    // `order` is a permutation of 0..keys.len(): every slot is filled.
    slots.into_iter().flatten().collect()
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
